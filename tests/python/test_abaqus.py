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

    def test_a_deck_of_parts_is_refused_and_nothing_written(self):
        with open(self.path("parts.inp"), "w") as f:
            f.write("*Heading\n*Part, name=Block\n*Node\n1, 0, 0, 0\n*End Part\n")
        proc = run("smooth", self.path("parts.inp"), "-o", self.path("out.inp"), check=False)
        self.assertEqual(proc.returncode, EXIT_INPUT)
        self.assertIn("parts.inp:2: *PART: decks of parts and assemblies are not read", proc.stderr)
        self.assertFalse(os.path.exists(self.path("out.inp")))


if __name__ == "__main__":
    unittest.main()
