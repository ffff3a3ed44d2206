"""Abaqus/CalculiX decks (.inp) through tetsmooth, with decks written by the
real Gmsh and by meshio, and tetsmooth's own decks read back by meshio.

A smoothed deck must be the input deck line for line except the coordinates
of its *NODE lines; nodes on the boundary, on the surface elements and on
the interface between the two materials (two volumes, two *ELEMENT element
sets) keep their coordinates bit for bit; the worst radius ratio does not
fall; the midside nodes of C3D10 tets stay at their edges' midpoints.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import os
import re
import unittest

import meshio
import numpy as np

from test_cli import EXIT_INPUT, radius_ratio, run
from test_independent_readers import GmshScratchCase, boundary_nodes, gmsh_session, two_layers

NODE_LINE = re.compile(r"^\d+, [^,]+, [^,]+, [^,]+$")
# The midside nodes of a C3D10, after its corners: kTetEdges, VTK's order.
EDGES = np.array([[0, 1], [1, 2], [0, 2], [0, 3], [1, 3], [2, 3]])


def deck_lines(path):
    with open(path) as f:
        return f.read().splitlines()


def parse_deck(path):
    """{node id: (x, y, z)}, and {element set: [(type, ids...)]} of a flat
    deck, parsed here independently of tetsmooth."""
    nodes, elements = {}, {}
    block, current, pending = None, None, []
    for line in deck_lines(path):
        if line.startswith("**") or not line.strip():
            continue
        if line.startswith("*"):
            fields = [f.strip() for f in line.split(",")]
            params = dict(f.upper().split("=", 1) for f in fields[1:] if "=" in f)
            block = fields[0].upper()
            if block == "*ELEMENT":
                current = elements.setdefault(params.get("ELSET", ""), [])
                current_type = params["TYPE"]
            continue
        values = [v for v in (f.strip() for f in line.split(",")) if v]
        if block == "*NODE":
            nodes[int(values[0])] = tuple(float(v) for v in values[1:4])
        elif block == "*ELEMENT":
            pending += [int(v) for v in values]
            if not line.rstrip().endswith(","):
                current.append((current_type, *pending))
                pending = []
    return nodes, elements


class GmshDecks(GmshScratchCase):
    SCRATCH_PREFIX = "tetsmooth_test_abaqus_"

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        gmsh = cls.gmsh
        with gmsh_session(gmsh):
            # Two layers of soil in a 2 x 2 x 2 block, meshed finely enough to
            # have interior nodes in both.
            lower, upper = two_layers(gmsh)
            gmsh.model.occ.synchronize()
            gmsh.model.addPhysicalGroup(3, [lower], 11)
            gmsh.model.addPhysicalGroup(3, [upper], 12)
            gmsh.model.addPhysicalGroup(2, [1], 5)
            gmsh.option.setNumber("Mesh.MeshSizeMax", 0.35)
            gmsh.option.setNumber("Mesh.SaveGroupsOfNodes", 1)
            gmsh.model.mesh.generate(3)
            gmsh.write(cls.path("order1.inp"))
            gmsh.model.mesh.setOrder(2)
            gmsh.write(cls.path("order2.inp"))

    def smooth(self, name):
        src, out = self.path(name), self.path("smooth-" + name)
        run("smooth", src, "-o", out, "--device", "cpu")
        return src, out

    def assert_only_node_lines_changed(self, src, out):
        before, after = deck_lines(src), deck_lines(out)
        self.assertEqual(len(before), len(after))
        changed = 0
        for a, b in zip(before, after):
            if a == b:
                continue
            self.assertTrue(NODE_LINE.match(a) and NODE_LINE.match(b), f"{a!r} became {b!r}")
            self.assertEqual(a.split(",")[0], b.split(",")[0])
            changed += 1
        self.assertGreater(changed, 0)

    def check_smoothed(self, name, corners):
        src, out = self.smooth(name)
        self.assert_only_node_lines_changed(src, out)
        nodes_in, elements = parse_deck(src)
        nodes_out, _ = parse_deck(out)
        tet_type = "C3D4" if corners == 4 else "C3D10"
        volumes = {name: np.array([e[2:] for e in elems]) for name, elems in elements.items()
                   if elems and elems[0][0] == tet_type}
        self.assertEqual(len(volumes), 2)
        tets = np.concatenate(list(volumes.values()))
        fixed = boundary_nodes(tets[:, :4])
        a, b = (set(v[:, :4].ravel().tolist()) for v in volumes.values())
        fixed |= a & b  # the interface between the materials
        for name, elems in elements.items():
            if elems and elems[0][0] != tet_type:
                fixed |= {n for e in elems for n in e[2:]}
        moved = [n for n in nodes_in if nodes_in[n] != nodes_out[n]]
        self.assertTrue(moved)
        self.assertFalse(fixed & set(moved), "a boundary, surface or interface node moved")
        ids = sorted(nodes_in)
        index = {n: i for i, n in enumerate(ids)}
        xyz_in = np.array([nodes_in[n] for n in ids])
        xyz_out = np.array([nodes_out[n] for n in ids])
        corner_tets = np.vectorize(index.get)(tets[:, :4])
        self.assertGreaterEqual(radius_ratio(xyz_out, corner_tets).min(), radius_ratio(xyz_in, corner_tets).min())
        return xyz_out, np.vectorize(index.get)(tets)

    def test_smoothing_changes_only_the_coordinates_of_movable_nodes(self):
        xyz, tets = self.check_smoothed("order1.inp", 4)
        # meshio reads the smoothed deck as it is.
        mesh = meshio.read(self.path("smooth-order1.inp"))
        np.testing.assert_array_equal(mesh.points, xyz)
        self.assertEqual(sum(len(c.data) for c in mesh.cells if c.type == "tetra"), len(tets))

    def test_second_order_midside_nodes_stay_at_their_edges_midpoints(self):
        xyz, tets = self.check_smoothed("order2.inp", 10)
        midpoints = 0.5 * (xyz[tets[:, EDGES[:, 0]]] + xyz[tets[:, EDGES[:, 1]]])
        np.testing.assert_allclose(xyz[tets[:, 4:]], midpoints, atol=1e-12)

    def test_other_formats_take_the_mesh_and_its_regions(self):
        run("convert", self.path("order1.inp"), self.path("order1.vtu"))
        mesh = meshio.read(self.path("order1.vtu"))
        nodes, elements = parse_deck(self.path("order1.inp"))
        np.testing.assert_array_equal(mesh.points, np.array([nodes[n] for n in nodes]))
        tags = np.concatenate([d for c, d in zip(mesh.cells, mesh.cell_data["tetsmooth:tag"]) if c.type == "tetra"])
        # Gmsh names the volumes' element sets Volume1 and Volume2.
        self.assertEqual(sorted(set(tags.ravel().tolist())), [1, 2])
        # In MSH output the regions keep those names, for Gmsh to read.
        run("convert", self.path("order1.inp"), self.path("order1.msh"))
        with gmsh_session(self.gmsh):
            self.gmsh.open(self.path("order1.msh"))
            names = {(dim, tag): self.gmsh.model.getPhysicalName(dim, tag)
                     for dim, tag in self.gmsh.model.getPhysicalGroups()}
        self.assertEqual(names[(3, 1)], "Volume1")
        self.assertEqual(names[(3, 2)], "Volume2")


class MeshioDecks(GmshScratchCase):
    SCRATCH_PREFIX = "tetsmooth_test_abaqus_meshio_"

    def test_meshio_reads_new_decks_and_tetsmooth_reads_meshios(self):
        run("generate", "lattice-4", "-o", self.path("lattice.vtu"))
        run("convert", self.path("lattice.vtu"), self.path("lattice.inp"))
        ours = meshio.read(self.path("lattice.vtu"))
        theirs = meshio.read(self.path("lattice.inp"))
        np.testing.assert_array_equal(theirs.points, ours.points)
        np.testing.assert_array_equal(theirs.cells_dict["tetra"], ours.cells_dict["tetra"])
        # meshio's own deck (its *NODE and *ELEMENT layout) read by tetsmooth,
        # with two materials as meshio writes cell sets: *ELSET lists alone.
        tets = ours.cells_dict["tetra"]
        rock = np.arange(0, len(tets), 3)
        soil = np.setdiff1d(np.arange(len(tets)), rock)
        meshio.write(self.path("meshio.inp"),
                     meshio.Mesh(ours.points, [("tetra", tets)], cell_sets={"Soil": [soil], "Rock": [rock]}))
        run("convert", self.path("meshio.inp"), self.path("back.vtu"))
        back = meshio.read(self.path("back.vtu"))
        np.testing.assert_array_equal(back.points, ours.points)
        np.testing.assert_array_equal(back.cells_dict["tetra"], tets)
        tags = np.concatenate(back.cell_data["tetsmooth:tag"]).ravel()
        self.assertEqual(len(set(tags[rock].tolist())), 1)
        self.assertEqual(len(set(tags[soil].tolist())), 1)
        self.assertNotEqual(tags[rock[0]], tags[soil[0]])
        # The regions keep the sets' names: MSH output has them as physical
        # names of the right tets.
        run("convert", self.path("meshio.inp"), self.path("back.msh"))
        msh = meshio.read(self.path("back.msh"))
        physical = np.concatenate(msh.cell_data["gmsh:physical"]).ravel()
        names = {int(tag): name for name, (tag, dim) in msh.field_data.items() if dim == 3}
        self.assertEqual(names[int(physical[rock[0]])], "Rock")
        self.assertEqual(names[int(physical[soil[0]])], "Soil")

    def test_a_new_deck_names_its_element_sets_after_the_regions(self):
        """Physical names that are plain Abaqus set names become the element
        sets' names, which meshio reads as cell sets and tetsmooth reads back
        as the regions' names; one that would need quotes stays REGION_<tag>,
        with a warning that names it alone."""
        with gmsh_session(self.gmsh):
            lower, upper = two_layers(self.gmsh)
            self.gmsh.model.occ.synchronize()
            self.gmsh.model.addPhysicalGroup(3, [lower], 100)
            self.gmsh.model.setPhysicalName(3, 100, "granite")
            self.gmsh.model.addPhysicalGroup(3, [upper], 200)
            self.gmsh.model.setPhysicalName(3, 200, "soft clay")
            self.gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
            self.gmsh.model.mesh.generate(3)
            self.gmsh.write(self.path("named.msh"))
        proc = run("convert", self.path("named.msh"), self.path("named.inp"))
        self.assertNotIn("has no place for", proc.stderr)
        self.assertIn('the names of 1 region (Gmsh physical names: "soft clay") will not be written', proc.stderr)
        ours = meshio.read(self.path("named.msh"))
        physical = np.concatenate([d for c, d in zip(ours.cells, ours.cell_data["gmsh:physical"])
                                   if c.type == "tetra"]).ravel()
        deck = meshio.read(self.path("named.inp"))
        sets = {name: sum(len(ids) for ids in blocks) for name, blocks in deck.cell_sets.items()}
        self.assertEqual(sets, {"granite": int((physical == 100).sum()), "REGION_200": int((physical == 200).sum())})
        run("convert", self.path("named.inp"), self.path("back.msh"))
        back = meshio.read(self.path("back.msh"))
        self.assertEqual(sorted(back.field_data), ["REGION_200", "granite"])
        tags = np.concatenate(back.cell_data["gmsh:physical"]).ravel()
        granite = back.field_data["granite"][0]
        np.testing.assert_array_equal(tags == granite, physical == 100)

    def test_a_part_twice_instanced_is_refused_and_nothing_written(self):
        with open(self.path("parts.inp"), "w") as f:
            f.write("*Heading\n*Part, name=Block\n*Node\n1, 0, 0, 0\n*End Part\n*Assembly, name=A\n"
                    "*Instance, name=B-1, part=Block\n*End Instance\n*Instance, name=B-2, part=Block\n")
        proc = run("smooth", self.path("parts.inp"), "-o", self.path("out.inp"), check=False)
        self.assertEqual(proc.returncode, EXIT_INPUT)
        self.assertIn("parts.inp:9: part Block is instanced a second time", proc.stderr)
        self.assertFalse(os.path.exists(self.path("out.inp")))


def real_text(v):
    """A coordinate as tetsmooth writes it (the shortest text that reads back
    to the same double), so that a node that does not move keeps its line."""
    text = repr(float(v))
    return text[:-2] if text.endswith(".0") else text


def rotation(a, b, degrees):
    """Rodrigues' rotation about the axis from a to b, right-handed."""
    u = (np.asarray(b) - np.asarray(a)) / np.linalg.norm(np.asarray(b) - np.asarray(a))
    t = np.radians(degrees)
    k = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    return np.eye(3) + np.sin(t) * k + (1 - np.cos(t)) * k @ k


def parse_parts_deck(path):
    """{part: ({node: xyz}, [tet node ids])} and {instance: (part, placement
    function)} of a deck with parts, parsed here independently of tetsmooth:
    an instance translates its part, then turns it about the axis a-b."""
    parts, instances = {}, {}
    block, part, instance = None, None, None
    for line in deck_lines(path):
        if line.startswith("**"):
            continue
        fields = [f.strip() for f in line.split(",")]
        if line.startswith("*"):
            block = fields[0].upper()
            params = dict(f.upper().split("=", 1) for f in fields[1:] if "=" in f)
            if block == "*PART":
                part = params["NAME"]
                parts[part] = ({}, [])
            elif block == "*INSTANCE":
                instance = params["NAME"]
                instances[instance] = [params["PART"], []]
            continue
        values = [float(v) for v in fields if v] if block in ("*NODE", "*INSTANCE") else fields
        if block == "*NODE":
            parts[part][0][int(values[0])] = np.array(values[1:4])
        elif block == "*ELEMENT":
            parts[part][1].append([int(v) for v in values[1:]])
        elif block == "*INSTANCE":
            instances[instance][1].append(values)
    placed = {}
    for name, (part_name, lines) in instances.items():
        shift = np.array(lines[0]) if lines else np.zeros(3)
        if len(lines) > 1:
            a, b, angle = lines[1][:3], lines[1][3:6], lines[1][6]
            turn = rotation(a, b, angle)
            placed[name] = (part_name, lambda p, s=shift, r=turn, a=np.array(a): (p + s - a) @ r.T + a)
        else:
            placed[name] = (part_name, lambda p, s=shift: p + s)
    return parts, placed


class PartDecks(GmshScratchCase):
    """A deck as Abaqus/CAE writes it: two parts, each numbered 1, 2, ...,
    placed by instances (one turned and moved), pins named through the
    instances. meshio 5 reads such a deck as if flat (a part's nodes
    overwrite those of another with the same numbers, and instances are
    not placed), so it is not compared here."""
    SCRATCH_PREFIX = "tetsmooth_test_abaqus_parts_"

    def write_deck(self):
        from test_cli import kuhn_lattice
        soil, pile = kuhn_lattice(3, seed=3), kuhn_lattice(3, seed=4)
        interior = [i + 1 for i, p in enumerate(soil[0]) if np.all((p > 0) & (p < 3))]
        self.pinned = {("SOIL", interior[0]), ("PILE", interior[1]), ("PILE", interior[2])}
        lines = ["*Heading", " a pile in soil"]
        for name, (xyz, tets), extra in (("Soil", soil, []),
                                         ("Pile", pile, ["*Nset, nset=Head", str(interior[1])])):
            lines += [f"*Part, name={name}", "*Node"]
            lines += [f"{i + 1}, " + ", ".join(real_text(v) for v in p) for i, p in enumerate(xyz)]
            lines += [f"*Element, type=C3D4, elset={name}Body"]
            lines += [f"{t + 1}, " + ", ".join(str(n + 1) for n in tet) for t, tet in enumerate(tets)]
            lines += extra + [f"*Solid Section, elset={name}Body, material=Rock", ",", "*End Part"]
        lines += ["*Assembly, name=Assembly", "*Instance, name=Soil-1, part=Soil", "*End Instance",
                  "*Instance, name=Pile-1, part=Pile", " 4., 0., 0.", " 4., 0., 0., 4., 0., 1., 90.",
                  "*End Instance", "*Nset, nset=Anchor, instance=Pile-1", str(interior[2]), "*End Assembly",
                  "*Material, name=Rock", "*Elastic", "1e9, 0.3", "*Step", "*Static", "*Boundary",
                  f"Soil-1.{interior[0]}, 1, 3", "Pile-1.Head, ENCASTRE", "Anchor, 1", "*End Step"]
        with open(self.path("parts.inp"), "w") as f:
            f.write("\n".join(lines) + "\n")

    def test_smoothed_deck_changes_moved_nodes_only_in_part_coordinates(self):
        self.write_deck()
        src, out = self.path("parts.inp"), self.path("smooth-parts.inp")
        run("smooth", src, "-o", out, "--device", "cpu")
        before, after = deck_lines(src), deck_lines(out)
        self.assertEqual(len(before), len(after))
        parts_in, instances = parse_parts_deck(src)
        parts_out, _ = parse_parts_deck(out)
        changed, part = set(), None  # (part, node number) of each changed line
        for a, b in zip(before, after):
            if a.upper().startswith("*PART"):
                part = a.split("=")[1].upper()
            if a != b:
                self.assertTrue(NODE_LINE.match(a) and NODE_LINE.match(b), f"{a!r} became {b!r}")
                self.assertEqual(a.split(",")[0], b.split(",")[0])
                changed.add((part, int(a.split(",")[0])))
        self.assertTrue(changed)
        self.assertFalse(changed & self.pinned, "a pinned node moved")
        worst_before, worst_after = [], []
        for name, (part_name, place) in instances.items():
            nodes_in, tets = parts_in[part_name]
            nodes_out, _ = parts_out[part_name]
            ids = sorted(nodes_in)
            index = {n: i for i, n in enumerate(ids)}
            tets = np.vectorize(index.get)(np.array(tets))
            xyz_in = place(np.array([nodes_in[n] for n in ids]))
            xyz_out = place(np.array([nodes_out[n] for n in ids]))
            worst_before.append(radius_ratio(xyz_in, tets).min())
            worst_after.append(radius_ratio(xyz_out, tets).min())
            # The body's boundary (where another body may be tied) stays.
            for n in boundary_nodes(tets):
                np.testing.assert_array_equal(nodes_out[ids[n]], nodes_in[ids[n]])
        self.assertGreaterEqual(min(worst_after), min(worst_before))
        for w_in, w_out in zip(worst_before, worst_after):
            self.assertGreaterEqual(w_out, w_in)

    def test_other_formats_take_the_bodies_in_assembly_coordinates(self):
        self.write_deck()
        proc = run("convert", self.path("parts.inp"), self.path("parts.vtu"))
        parts, instances = parse_parts_deck(self.path("parts.inp"))
        mesh = meshio.read(self.path("parts.vtu"))
        expected = np.concatenate([place(np.array([parts[p][0][n] for n in sorted(parts[p][0])]))
                                   for p, place in instances.values()])
        np.testing.assert_allclose(mesh.points, expected, atol=1e-12)
        self.assertEqual(len(mesh.cells_dict["tetra"]), sum(len(parts[p][1]) for p in parts))
        # Both parts number their nodes 1, 2, ...: MSH, which keeps numbers,
        # numbers them anew, and says so.
        proc = run("convert", self.path("parts.inp"), self.path("parts.msh"))
        self.assertIn("the node numbers of the file cannot all be kept", proc.stderr)
        self.assertIn("the element numbers of the file cannot all be kept", proc.stderr)
        msh = meshio.read(self.path("parts.msh"))
        np.testing.assert_allclose(msh.points, expected, atol=1e-12)
        names = {name for name, (tag, dim) in msh.field_data.items() if dim == 3}
        self.assertEqual(names, {"Soil.SoilBody", "Pile.PileBody"})
        # The worst tets are not given numbers that name two.
        report = run("quality", self.path("parts.inp"), "--worst", "3").stdout
        self.assertNotIn("in the file", report)

if __name__ == "__main__":
    unittest.main()
