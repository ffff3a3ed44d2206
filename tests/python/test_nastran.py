"""Nastran bulk data decks (.bdf) through tetsmooth, against decks written by
the real Gmsh (in its three field formats: free, small and large field, first
and second order), by meshio, and by hand (loads and constraints); and
tetsmooth's own decks read back by the Gmsh API and meshio.

The decks are parsed here by a reader of this file's own (small, large and
free field, continuation lines), which the Gmsh API checks on Gmsh's decks.
A smoothed deck must be the input deck line for line but for the GRID
entries of moved nodes, rewritten in large field with their other fields as
read; a node that did not move (on the boundary, on the CTRIA3/CTRIA6
elements, on the interface between the two volumes, named by SPC1 or FORCE,
or with a PS) keeps its GRID text byte for byte; the worst radius ratio does
not fall; midside nodes move with their edges' midpoints. Decks that
tetsmooth does not read (CP other than 0, an INCLUDE of a file that is not
there, superelements, ids defined twice, undefined grid points) are refused
with their file and line, and nothing is written.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import os
import re
import unittest

import meshio
import numpy as np

from test_cli import EXIT_INPUT, kuhn_lattice, radius_ratio, run
from test_independent_readers import GmshScratchCase, boundary_nodes, gmsh_session, two_layers

# The midside nodes G5..G10 of a CTETRA, on these edges of G1..G4 (as VTK's).
EDGES = np.array([[0, 1], [1, 2], [0, 2], [0, 3], [1, 3], [2, 3]])
# Gmsh's 10-node tet has G9 and G10 the other way round.
GMSH_NASTRAN_ORDER = [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]
# Gmsh's Mesh.BdfFieldFormat values, and how far the midside nodes of its
# decks may be from their edges' midpoints by the rounding of the coordinates
# it prints (8 characters in free and small field, 9 digits in large field)
# in a box 2 wide.
FIELD_FORMATS = {"free": 0, "small": 1, "large": 2}
GMSH_ROUNDING = {"free": 2e-6, "small": 2e-6, "large": 2e-8}
# tetsmooth writes moved coordinates in 16 characters, 10 significant digits
# or more: what they may be off by in a box 2 wide, with room to spare.
WRITTEN = 1e-9
REAL = re.compile(r"([+-]?(?:\d+\.?\d*|\.\d+))([+-]\d+)")


def nastran_real(text):
    """A real in any Nastran form ("1.5", ".5", "1.5E-3", "1.5-3", "1.5D-3",
    "0"); blank is 0."""
    text = text.strip().upper().replace("D", "E")
    if not text:
        return 0.0
    implicit = REAL.fullmatch(text)
    return float(implicit.group(1) + "E" + implicit.group(2) if implicit else text)


def line_fields(line):
    """(the fields of one line, the first included; whether large field)."""
    if "," in line:
        return [f.strip() for f in line.split(",")], False
    large = line.startswith("*") or line[:8].rstrip().endswith("*")
    widths = [8, 16, 16, 16, 16, 8] if large else [8] * 10
    starts = np.cumsum([0] + widths)
    return [line[a:b].strip() for a, b in zip(starts, starts[1:])], large


def deck_lines(path):
    with open(path, newline="") as f:
        lines = f.read().split("\n")
    return lines[:-1] if lines[-1] == "" else lines


class Deck:
    """A deck parsed here: `lines`; `entries`, [name, data fields, first
    line, end line]; `nodes` {id: xyz}; `grids` {id: GRID entry};
    `elements` {name: [(id, PID, node ids)]}; `skeleton`, the lines with
    each GRID entry in place of its lines."""

    def __init__(self, path):
        self.lines = deck_lines(path)
        self.entries = []
        bulk = not any(line.upper().startswith("BEGIN BULK") for line in self.lines)  # as Gmsh writes
        for i, line in enumerate(self.lines):
            if not bulk:
                bulk = line.upper().startswith("BEGIN BULK")
                continue
            if line.upper().startswith("ENDDATA"):
                break
            if not line.strip() or line.startswith("$"):
                continue
            fields, large = line_fields(line)
            data = fields[1:5] if large else fields[1:9]
            if line[0] in "+*, ":
                self.entries[-1][1] += data
                self.entries[-1][3] = i + 1
            else:
                self.entries.append([fields[0].rstrip("*").upper(), data, i, i + 1])
        self.nodes, self.grids, self.elements = {}, {}, {}
        for entry in self.entries:
            name, data = entry[:2]
            if name == "GRID":
                self.grids[int(data[0])] = entry
                self.nodes[int(data[0])] = np.array([nastran_real(x) for x in data[2:5]])
            elif name in ("CTETRA", "CTRIA3", "CTRIA6"):
                self.elements.setdefault(name, []).append(
                    (int(data[0]), int(data[1] or 0), [int(x) for x in data[2:] if x]))
        self.skeleton, i = [], 0
        starts = {entry[2]: entry for entry in self.grids.values()}
        while i < len(self.lines):
            if i in starts:
                self.skeleton.append(("GRID", starts[i][1][0]))
                i = starts[i][3]
            else:
                self.skeleton.append(self.lines[i])
                i += 1

    def grid_text(self, node):
        _, _, first, end = self.grids[node]
        return "\n".join(self.lines[first:end])

    def grid_fields(self, node):
        """CP, CD, PS and SEID as values (blank CP, CD, SEID are 0)."""
        data = self.grids[node][1] + [""] * 8
        return int(data[1] or 0), int(data[5] or 0), data[6], int(data[7] or 0)

    def xyz(self, ids):
        return np.array([self.nodes[n] for n in ids])


def gmsh_read(gmsh, path):
    """({node tag: xyz}, {element type: count}) as the Gmsh API reads `path`."""
    with gmsh_session(gmsh):
        gmsh.open(path)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        types, elements, _ = gmsh.model.mesh.getElements()
        return (dict(zip(tags.tolist(), np.asarray(coords).reshape(-1, 3))),
                {int(t): len(e) for t, e in zip(types, elements)})


class NastranCase(GmshScratchCase):
    def smooth(self, src, out, *extra):
        run("smooth", src, "-o", out, "--device", "cpu", *extra)
        return Deck(src), Deck(out)

    def assert_only_moved_grids_changed(self, before, after):
        """The decks agree but for the GRID text of moved nodes, which is
        large field with the fields other than coordinates as read; returns
        the ids of the nodes whose text changed."""
        self.assertEqual(before.skeleton, after.skeleton)
        self.assertEqual(sorted(before.nodes), sorted(after.nodes))
        changed = {n for n in before.nodes if before.grid_text(n) != after.grid_text(n)}
        for n in changed:
            lines = after.grid_text(n).split("\n")
            self.assertEqual(len(lines), 2, lines)
            self.assertTrue(lines[0].startswith("GRID*") and lines[1].startswith("*"), lines)
            self.assertEqual(after.grid_fields(n), before.grid_fields(n))
        return changed

    def write(self, name, text):
        with open(self.path(name), "w", newline="") as f:
            f.write(text)
        return self.path(name)


class GmshDecks(NastranCase):
    SCRATCH_PREFIX = "tetsmooth_test_nastran_"

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        gmsh = cls.gmsh
        with gmsh_session(gmsh):
            # Two volumes stacked in a 2 x 2 x 2 box, each its own physical
            # group, and a physical surface of one boundary face and a square
            # embedded in the lower volume (CTRIA3 elements inside the mesh).
            lower, upper = two_layers(gmsh)
            square = gmsh.model.occ.addRectangle(0.5, 0.5, 0.5, 1, 1)
            gmsh.model.occ.synchronize()
            gmsh.model.mesh.embed(2, [square], 3, lower)
            gmsh.model.addPhysicalGroup(3, [lower], 11)
            gmsh.model.addPhysicalGroup(3, [upper], 12)
            gmsh.model.addPhysicalGroup(2, [1, square], 5)
            gmsh.option.setNumber("Mesh.MeshSizeMax", 0.35)
            gmsh.model.mesh.generate(3)
            for order in (1, 2):
                gmsh.model.mesh.setOrder(order)
                gmsh.write(cls.path(f"order{order}.msh"))
                for name, value in FIELD_FORMATS.items():
                    gmsh.option.setNumber("Mesh.BdfFieldFormat", value)
                    gmsh.write(cls.path(f"order{order}-{name}.bdf"))

    def smoothed(self, order, field):
        name = f"order{order}-{field}.bdf"
        return self.smooth(self.path(name), self.path("smooth-" + name))

    def check_smoothed(self, order, field):
        before, after = self.smoothed(order, field)
        changed = self.assert_only_moved_grids_changed(before, after)
        self.assertTrue(changed, "no node moved")
        tets = np.array([nodes for _, _, nodes in before.elements["CTETRA"]])
        pids = np.array([pid for _, pid, _ in before.elements["CTETRA"]])
        self.assertEqual(tets.shape[1], 4 if order == 1 else 10)
        self.assertEqual(sorted(set(pids.tolist())), [1, 2])  # Gmsh's volume tags
        corners = tets[:, :4]
        interface = set(corners[pids == 1].ravel().tolist()) & set(corners[pids == 2].ravel().tolist())
        surface = {n for name in ("CTRIA3", "CTRIA6") for _, _, nodes in before.elements.get(name, []) for n in nodes}
        self.assertTrue(surface - boundary_nodes(corners), "the embedded square has no nodes inside")
        fixed = boundary_nodes(corners) | interface | surface
        for n in sorted(fixed):
            self.assertEqual(after.grid_text(n), before.grid_text(n), f"node {n} on a fixed part moved")
        ids = sorted(before.nodes)
        rows = np.searchsorted(ids, tets)
        xyz_in, xyz_out = before.xyz(ids), after.xyz(ids)
        # The input's coordinates are what tetsmooth read; the output's are
        # rounded to 16 characters, which may lose a little of the worst.
        self.assertGreaterEqual(radius_ratio(xyz_out, rows[:, :4]).min(),
                                radius_ratio(xyz_in, rows[:, :4]).min() - WRITTEN)
        if order == 2:
            ends = rows[:, EDGES]
            offset_in = xyz_in[rows[:, 4:]] - 0.5 * (xyz_in[ends[..., 0]] + xyz_in[ends[..., 1]])
            offset_out = xyz_out[rows[:, 4:]] - 0.5 * (xyz_out[ends[..., 0]] + xyz_out[ends[..., 1]])
            # Gmsh's midside nodes are at their midpoints up to its rounding
            # (which also checks the edge order read here), and each keeps
            # its offset as its edge's corners move.
            self.assertLess(np.abs(offset_in).max(), GMSH_ROUNDING[field])
            np.testing.assert_allclose(offset_out, offset_in, rtol=0, atol=2 * WRITTEN)
            # An edge whose corners stayed keeps its midside node's text.
            still = ~np.isin(tets[:, :4], list(changed))[:, EDGES].any(axis=2)
            for n in set(tets[:, 4:][still].tolist()):
                self.assertEqual(after.grid_text(n), before.grid_text(n), f"midside node {n} moved")

    def test_gmsh_decks_in_every_field_format(self):
        for order in (1, 2):
            for field in FIELD_FORMATS:
                with self.subTest(order=order, field=field):
                    self.check_smoothed(order, field)

    def test_gmsh_reads_the_smoothed_decks(self):
        for order in (1, 2):
            for field in FIELD_FORMATS:
                with self.subTest(order=order, field=field):
                    before, after = self.smoothed(order, field)
                    nodes_in, elements_in = gmsh_read(self.gmsh, self.path(f"order{order}-{field}.bdf"))
                    nodes_out, elements_out = gmsh_read(self.gmsh, self.path(f"smooth-order{order}-{field}.bdf"))
                    self.assertEqual(elements_out, elements_in)
                    self.assertEqual(sorted(nodes_out), sorted(nodes_in))
                    # Gmsh and the parser here read the same coordinates. (Gmsh
                    # 4.8 takes no blank continuation line: it reads the
                    # 10-node CTETRA of its own large-field decks as 4-node
                    # ones, and only their corners' nodes.)
                    for deck, nodes in ((before, nodes_in), (after, nodes_out)):
                        ids = sorted(nodes)
                        np.testing.assert_allclose(np.array([nodes[n] for n in ids]), deck.xyz(ids),
                                                   rtol=0, atol=1e-12)

    def test_meshio_and_gmsh_read_a_new_deck(self):
        gmsh = self.gmsh
        for order, per_tet in ((1, 4), (2, 10)):
            with self.subTest(order=order), gmsh_session(gmsh):
                gmsh.open(self.path(f"order{order}.msh"))
                tags, coords, _ = gmsh.model.mesh.getNodes()
                xyz = dict(zip(tags.tolist(), np.asarray(coords).reshape(-1, 3)))
                tets = {}  # element tag: (physical tag, node tags in Nastran's order)
                for dim, entity in gmsh.model.getEntities(3):
                    physical = gmsh.model.getPhysicalGroupsForEntity(dim, entity)[0]
                    _, etags, enodes = gmsh.model.mesh.getElements(dim, entity)
                    rows = np.asarray(enodes[0]).reshape(-1, per_tet)[:, GMSH_NASTRAN_ORDER[:per_tet]]
                    tets.update((tag, (int(physical), nodes)) for tag, nodes in zip(etags[0].tolist(), rows.tolist()))
                triangles = sum(len(t) for t in gmsh.model.mesh.getElements(2)[1])
            with self.subTest(order=order):
                # A new deck: GRID* in 16-character fields, CTETRA with the
                # physical tags as PIDs and the Gmsh element tags as ids.
                out = self.path(f"new{order}.bdf")
                run("convert", self.path(f"order{order}.msh"), out)
                self.assertIn("BEGIN BULK", deck_lines(out))
                mesh = meshio.read(out)
                self.assertEqual(sorted(mesh.points_id.tolist()), sorted(xyz))
                np.testing.assert_allclose(mesh.points, np.array([xyz[n] for n in mesh.points_id.tolist()]),
                                           rtol=0, atol=2e-10)
                read, surface = {}, []
                for block, ids, refs in zip(mesh.cells, mesh.cells_id, mesh.cell_data["nastran:ref"]):
                    if block.type.startswith("tetra"):
                        self.assertEqual(block.data.shape[1], per_tet)
                        read.update((tag, (ref, nodes)) for tag, nodes, ref
                                    in zip(ids.tolist(), mesh.points_id[block.data].tolist(), refs.tolist()))
                    else:
                        surface += refs.tolist()
                self.assertEqual(len(read), len(tets))
                self.assertEqual(read, tets)
                self.assertEqual(surface, [5] * triangles)
                # The Gmsh API reads the deck too, with its elements' types.
                nodes, elements = gmsh_read(gmsh, out)
                types = (2, 4) if order == 1 else (9, 11)  # 3- or 6-node triangles, 4- or 10-node tets
                self.assertEqual(elements, {types[0]: triangles, types[1]: len(tets)})
                self.assertEqual(sorted(nodes), sorted(xyz))
                np.testing.assert_allclose(np.array([nodes[n] for n in xyz]), np.array(list(xyz.values())),
                                           rtol=0, atol=2e-10)

    def test_gmsh_reads_a_new_deck_of_a_mesh_without_regions(self):
        # Gmsh 4.8 misreads a CTETRA with a blank PID: such tets get one.
        out = self.path("lattice.bdf")
        run("generate", "lattice-3", "-o", out)
        nodes, elements = gmsh_read(self.gmsh, out)
        self.assertEqual(elements, {4: 6 * 3 ** 3})
        self.assertEqual(len(nodes), 4 ** 3)


class HandWrittenDecks(NastranCase):
    SCRATCH_PREFIX = "tetsmooth_test_nastran_hand_"
    FIRST_ID = 101
    # Ids of interior nodes of the 4 x 4 x 4 lattice of kuhn_lattice.
    THRU = (132, 134)
    LISTED, FORCED, PS, CD = 137, 163, 188, 168

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        xyz, cls.tets = kuhn_lattice(4, seed=5)
        cls.xyz = np.round(xyz, 5)  # what 8 characters hold
        cls.ids = np.arange(len(xyz)) + cls.FIRST_ID

    def small_deck(self, bulk=(), ps=None, cd=None, cp=None):
        """The lattice as a small-field deck, with `bulk` lines after the GRIDs."""
        grids = []
        for n, (x, y, z) in zip(self.ids, self.xyz):
            line = f"GRID    {n:<8d}{5 if n == cp else '':<8}{x:8.5f}{y:8.5f}{z:8.5f}"
            if n in (ps, cd):
                line += f"{7 if n == cd else '':<8}{3456 if n == ps else '':<8}"
            grids.append(line)
        tets = [f"CTETRA  {t + 1:<8d}1       " + "".join(f"{n:<8d}" for n in self.ids[row])
                for t, row in enumerate(self.tets)]
        return "\n".join(["SOL 101", "CEND", "SPC = 1", "LOAD = 2", "BEGIN BULK", "$ lattice",
                          "CORD2R  7               0.      0.      0.      0.      0.      1.",
                          "        1.      0.      0.", *grids, *tets, *bulk, "ENDDATA", "$ not read:",
                          "GRID    1       9"]) + "\n"

    def interior(self, first_id=FIRST_ID):
        inside = np.all((self.xyz > 0) & (self.xyz < 4), axis=1)
        return set((np.flatnonzero(inside) + first_id).tolist())

    def test_loads_and_constraints_pin_their_grid_points(self):
        pinned = [*range(self.THRU[0], self.THRU[1] + 1), self.LISTED, self.FORCED, self.PS]
        self.assertTrue(set(pinned) | {self.CD} <= self.interior())
        # Without the loads and constraints, these nodes move.
        free = self.write("free.bdf", self.small_deck(cd=self.CD))
        before, after = self.smooth(free, self.path("free-out.bdf"))
        changed = self.assert_only_moved_grids_changed(before, after)
        self.assertTrue(set(pinned) | {self.CD} <= changed)
        # A node in another output system moves and keeps its CD (checked by
        # assert_only_moved_grids_changed).
        self.assertEqual(after.grid_fields(self.CD)[1], 7)
        bulk = [f"SPC1    1       123     {self.THRU[0]:<8d}THRU    {self.THRU[1]:<8d}",
                "SPC1    1       123     101     102     103     104     105     106     +S1",
                f"+S1     {self.LISTED:<8d}",
                f"FORCE   2       {self.FORCED:<8d}0       1.0     0.      0.      -1."]
        # CRLF line ends, which the output turns into '\n'.
        pins = self.write("pins.bdf", self.small_deck(bulk, ps=self.PS, cd=self.CD).replace("\n", "\r\n"))
        out = self.path("pins-out.bdf")
        run("smooth", pins, "-o", out, "--device", "cpu")
        with open(out, "rb") as f:
            self.assertNotIn(b"\r", f.read())
        self.write("pins-lf.bdf", self.small_deck(bulk, ps=self.PS, cd=self.CD))
        before, after = Deck(self.path("pins-lf.bdf")), Deck(out)
        changed = self.assert_only_moved_grids_changed(before, after)
        self.assertTrue(changed)
        self.assertFalse(changed & set(pinned), "a node named by SPC1, FORCE or a PS moved")

    def test_tetsmooth_reads_meshios_deck(self):
        xyz = np.round(self.xyz * 12.5 * 256) / 256  # written exactly in 12 digits
        # Two regions, either side of x = 2.
        refs = 7 + (self.xyz[self.tets, 0].mean(axis=1) > 2)
        src = self.path("meshio.bdf")
        meshio.write(src, meshio.Mesh(xyz, [("tetra", self.tets)], cell_data={"nastran:ref": [refs]}))
        run("convert", src, self.path("meshio.vtu"))
        back = meshio.read(self.path("meshio.vtu"))
        np.testing.assert_array_equal(back.points, xyz)
        np.testing.assert_array_equal(back.cells_dict["tetra"], self.tets)
        np.testing.assert_array_equal(np.concatenate(back.cell_data["tetsmooth:tag"]).ravel(), refs)
        # Smoothed, meshio's deck is meshio's but for the moved GRID* entries.
        before, after = self.smooth(src, self.path("meshio-smooth.bdf"))
        changed = self.assert_only_moved_grids_changed(before, after)
        self.assertTrue(changed)
        on_interface = set(self.tets[refs == 7].ravel() + 1) & set(self.tets[refs == 8].ravel() + 1)
        self.assertTrue(changed <= self.interior(1) - on_interface)
        mesh = meshio.read(self.path("meshio-smooth.bdf"))
        np.testing.assert_array_equal(mesh.cells_dict["tetra"], self.tets)
        np.testing.assert_array_equal(mesh.points, after.xyz(range(1, len(xyz) + 1)))

    def test_refused_decks_name_their_line_and_leave_nothing(self):
        deck = self.small_deck().split("\n")
        first_grid = deck.index(next(line for line in deck if line.startswith("GRID")))
        first_tet = deck.index(next(line for line in deck if line.startswith("CTETRA")))
        cases = {
            "cp.bdf": (self.small_deck(cp=self.FORCED), first_grid + self.FORCED - self.FIRST_ID),
            "include.bdf": ("\n".join(deck[:first_tet] + ["INCLUDE 'more.bdf'"] + deck[first_tet:]), first_tet),
            "super.bdf": ("\n".join(deck).replace("BEGIN BULK", "BEGIN BULK SUPER=2"), deck.index("BEGIN BULK")),
            "twice.bdf": ("\n".join(deck[:first_tet] + [deck[first_grid]] + deck[first_tet:]), first_tet),
            "undefined.bdf": ("\n".join(deck).replace(f"CTETRA  1       1       {self.ids[self.tets[0][0]]:<8d}",
                                                      "CTETRA  1       1       99999   "), first_tet),
        }
        for name, (text, index) in cases.items():
            with self.subTest(deck=name):
                src, out = self.write(name, text), self.path("out-" + name)
                proc = run("smooth", src, "-o", out, check=False)
                self.assertEqual(proc.returncode, EXIT_INPUT, proc.stderr)
                self.assertIn(f"{name}:{index + 1}:", proc.stderr)
                self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    unittest.main()
