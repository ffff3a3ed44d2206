"""FLAC3D grids (.f3grid, text and binary) through tetsmooth, checked against an
independent implementation of the format: meshio's FLAC3D reader and writer
(meshio 5.0), and a small parser of this file's own.

What is checked, and why:
- A grid that meshio writes (tabs, ids right-aligned, two zone groups) is
  smoothed into the same grid line for line but for the G lines of moved
  gridpoints, written "G id x y z" in the shortest decimals that read back
  exactly: a user's grid must come back as it went in, whatever else it
  holds. Gridpoints on the boundary, on the interface between the groups (or
  between groups of another slot) and those that a pin comment or a face
  names keep their G text byte for byte; the worst radius ratio does not
  fall; meshio reads the smoothed grid with the input's cells and groups.
- Bricks, wedges and pyramids (B8, W6, P5), which meshio writes in FLAC3D's
  order, reach VTU and MSH output as the same cells, right side out (as
  meshio reads them, and for MSH as Gmsh's Jacobians say), and their
  gridpoints stay fixed: a converted grid must not turn zones inside out,
  and smoothing must not move nodes of zones it does not smooth.
- A new grid written from MSH has meshio's points, tets, faces and groups
  ("zone:NAME:SLOT"), the file's element numbers as zone and face ids, and
  right-handed zones: FLAC3D takes a zone's first four gridpoints as a
  right-handed frame, and a left-handed one is an inside-out zone. Read
  back into MSH, every cell is right side out again.
- Ids in any order and with gaps, groups in several slots, and the
  lenient spellings flac3d_io.hpp allows (case, commas, quotes, CRLF, a
  byte order mark, blank lines) read as meshio's plain grid does.
- A binary grid (meshio's layout) smooths to the coordinates its text twin
  does, and comes back binary, byte for byte but for those coordinates.
- Bad grids (undefined or repeated ids, a binary grid cut short, ...) are
  refused with exit status 3 and their file and line (or byte), leaving no
  output and an existing output file as it was; a record of another kind is
  kept in the smoothed grid and named in a warning.

Volumes are computed here by splitting each cell into tets, in meshio's
node order, which is VTK's for hexahedra and pyramids and Gmsh's for wedges
(meshio 5 adopts the Gmsh prism: its first triangle's normal points into the
cell; see meshio/_vtk_common.py).

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import os
import re
import unittest

import meshio
import numpy as np

from test_cli import EXIT_INPUT, CliTestCase, kuhn_lattice, radius_ratio, run, signed_volume6
from test_independent_readers import boundary_nodes, gmsh_session, require_gmsh

# The tets each cell is split into, in meshio's node order; each is
# positively oriented (signed_volume6 > 0) in a cell that is right side out.
# A hexahedron around its diagonal 0-6; a pyramid across the base's
# diagonal 0-2; a wedge whose triangle (0, 1, 2) faces the triangle
# (3, 4, 5), as Gmsh's prism does.
SPLITS = {
    "tetra": [(0, 1, 2, 3)],
    "hexahedron": [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)],
    "wedge": [(0, 1, 2, 3), (1, 4, 5, 3), (1, 5, 2, 3)],
    "pyramid": [(0, 1, 2, 4), (0, 2, 3, 4)],
}
# The same cell turned inside out.
FLIPS = {"hexahedron": [4, 5, 6, 7, 0, 1, 2, 3], "wedge": [3, 4, 5, 0, 1, 2], "pyramid": [0, 3, 2, 1, 4]}
# meshio's order from FLAC3D's, built here from the layouts of the FLAC3D
# manual: a brick's corners are origin, x, y, z, xy, yz, xz, xyz; a wedge
# and a pyramid are the first six and five of those (the triangle origin, x,
# z drawn out along y; the quad origin, x, xy, y under the apex z).
FROM_FLAC3D = {
    "T4": ("tetra", [0, 1, 2, 3]),
    "B8": ("hexahedron", [0, 1, 4, 2, 3, 6, 7, 5]),
    "W6": ("wedge", [0, 3, 1, 2, 5, 4]),
    "P5": ("pyramid", [0, 1, 4, 2, 3]),
    "T3": ("triangle", [0, 1, 2]),
}
# Gmsh's element types of the cells, for its Jacobians.
GMSH_TYPES = {"tetra": 4, "hexahedron": 5, "wedge": 6, "pyramid": 7}
# FLAC3D's values: split at blanks and commas, a quoted value kept whole.
VALUE = re.compile(r"\"[^\"]*\"|'[^']*'|[^\s,]+")


def sub_volumes(xyz, kind, cells):
    """6 x the signed volumes of the tets of each cell (one row per cell)."""
    cells = np.asarray(cells)
    return np.stack([signed_volume6(xyz, cells[:, list(t)]) for t in SPLITS[kind]], axis=1)


def significant_digits(token):
    """The significant digits of a decimal number's text ("0.0125" has 3)."""
    mantissa = re.split("[eE]", token)[0].lstrip("+-").replace(".", "")
    return len(mantissa.strip("0")) or 1


def read_text(path):
    with open(path, newline="") as f:
        return f.read()


class Grid:
    """A FLAC3D grid parsed here: `lines` (split at '\\n' only, so a '\\r'
    stays with its line); `points` {id: xyz} and `point_line` {id: line
    index}; `zones` and `faces`, [(type, id, gridpoint ids)] in file order;
    `groups`, [(record, name, slot, ids)]; `pins`, the ids of the pin
    comments."""

    def __init__(self, path):
        text = read_text(path)
        self.lines = text.split("\n")
        self.lines[0] = self.lines[0].lstrip("\ufeff")
        self.points, self.point_line, self.zones, self.faces, self.groups, self.pins = {}, {}, [], [], [], []
        group = None
        for i, line in enumerate(self.lines):
            stripped = line.strip()
            if stripped.startswith("*"):
                group = None
                words = stripped[1:].split()
                if words[:2] == ["TETSMOOTH", "PINNED"]:
                    self.pins += [int(w) for w in words[2:]]
                continue
            values = [v.strip("\"'") for v in VALUE.findall(line)]
            if not values:
                continue
            key = values[0].upper()
            if key == "G":
                self.points[int(values[1])] = np.array([float(v) for v in values[2:5]])
                self.point_line[int(values[1])] = i
            elif key in ("Z", "F"):
                (self.zones if key == "Z" else self.faces).append(
                    (values[1].upper(), int(values[2]), [int(v) for v in values[3:]]))
            elif key in ("ZGROUP", "FGROUP"):
                group = (key[0], values[1], values[3] if len(values) > 3 else "", [])
                self.groups.append(group)
            else:
                group[3].extend(int(v) for v in values)

    def xyz(self, ids):
        return np.array([self.points[n] for n in ids])

    def cells(self, record="Z"):
        """{meshio type: rows of gridpoint ids in meshio's order}."""
        cells = {}
        for code, _, gps in (self.zones if record == "Z" else self.faces):
            kind, order = FROM_FLAC3D[code]
            cells.setdefault(kind, []).append([gps[k] for k in order])
        return {kind: np.array(rows) for kind, rows in cells.items()}


def two_layers(n=4, seed=11):
    """A Kuhn lattice of n^3 cubes as (xyz, tets, lower), lower the indices
    of the tets in the cubes under z = n / 2: two soil layers."""
    xyz, tets = kuhn_lattice(n, seed=seed)
    # A tet's centroid lies inside its cube (the jitter is small), so the
    # floor of its z is the cube's layer.
    layer = np.floor(xyz[tets].mean(axis=1)[:, 2])
    return xyz, tets, np.flatnonzero(layer < n // 2)


def mixed_block(n=4, seed=7):
    """A Kuhn lattice of tets in [0, n]^3 with bricks against x = 0, wedges
    under the triangles of z = 0 and pyramids over the squares of z = n,
    sharing the lattice's nodes; and one brick, wedge and pyramid over
    interior nodes of the lattice (overlapping its tets: FLAC3D would not
    make them, but they show the pins on nodes that would otherwise move).
    Every other cell of each kind is inside out, so that writers must
    turn them. Returns (xyz, {kind: cells}, {kind: index of the overlapping
    cell})."""
    xyz, tets = kuhn_lattice(n, seed=seed)
    points = list(xyz)

    def add(p):
        points.append(np.array(p, dtype=float))
        return len(points) - 1

    def lattice(i, j, k):
        return (i * (n + 1) + j) * (n + 1) + k

    west = {(j, k): add((-1, j, k)) for j in range(n + 1) for k in range(n + 1)}
    below = {(i, j): add((i, j, -1)) for i in range(n + 1) for j in range(n + 1)}
    apex = {(i, j): add((i + 0.5, j + 0.5, n + 1)) for i in range(n) for j in range(n)}
    hexes = [[west[j, k], west[j + 1, k], west[j + 1, k + 1], west[j, k + 1],
              lattice(0, j, k), lattice(0, j + 1, k), lattice(0, j + 1, k + 1), lattice(0, j, k + 1)]
             for j in range(n) for k in range(n)]
    faces = np.concatenate([tets[:, f] for f in ([1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2])])
    unique, counts = np.unique(np.sort(faces, axis=1), axis=0, return_counts=True)
    wedges = [[below[tuple(xyz[v, :2].astype(int))] for v in f] + list(f)
              for f in unique[counts == 1] if np.all(xyz[f, 2] == 0)]
    pyramids = [[lattice(i, j, n), lattice(i + 1, j, n), lattice(i + 1, j + 1, n), lattice(i, j + 1, n), apex[i, j]]
                for i in range(n) for j in range(n)]
    # Over interior nodes (1 <= i, j, k <= n - 1).
    hexes.append([lattice(1, 1, 1), lattice(2, 1, 1), lattice(2, 2, 1), lattice(1, 2, 1),
                  lattice(1, 1, 2), lattice(2, 1, 2), lattice(2, 2, 2), lattice(1, 2, 2)])
    wedges.append([lattice(2, 1, 1), lattice(3, 1, 1), lattice(2, 2, 1),
                   lattice(2, 1, 2), lattice(3, 1, 2), lattice(2, 2, 2)])
    pyramids.append([lattice(1, 2, 1), lattice(2, 2, 1), lattice(2, 3, 1), lattice(1, 3, 1), lattice(2, 3, 2)])
    xyz = np.array(points)
    cells = {"tetra": tets}
    for kind, rows in (("hexahedron", hexes), ("wedge", wedges), ("pyramid", pyramids)):
        rows = np.array(rows)
        # Right side out first, then every other one inside out.
        wrong = sub_volumes(xyz, kind, rows).sum(axis=1) < 0
        rows[wrong] = rows[wrong][:, FLIPS[kind]]
        rows[1::2] = rows[1::2][:, FLIPS[kind]]
        v = sub_volumes(xyz, kind, rows)
        assert np.all(v[0::2] > 0) and np.all(v[1::2] < 0), f"a {kind} is not convex"
        cells[kind] = rows
    return xyz, cells, {kind: len(cells[kind]) - 1 for kind in FLIPS}


def assert_cells_right_side_out(test, xyz, kind, rows, what):
    v = sub_volumes(xyz, kind, rows)
    bad = np.flatnonzero(~np.all(v > 0, axis=1))
    test.assertEqual(len(bad), 0, f"{len(bad)} of {len(rows)} {kind} cells of {what} inside out or tangled, "
                                  f"the first: {rows[bad[0]].tolist() if len(bad) else None}")


class VolumeFormula(unittest.TestCase):
    def test_reference_elements_of_gmsh_are_right_side_out(self):
        # Gmsh's reference elements (its manual, "Node ordering"), whose
        # Jacobians are positive by definition; and each turned inside out.
        cells = {
            "hexahedron": [[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                           [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]],
            "wedge": [[0, 0, -1], [1, 0, -1], [0, 1, -1], [0, 0, 1], [1, 0, 1], [0, 1, 1]],
            "pyramid": [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0], [0, 0, 1]],
        }
        for kind, corners in cells.items():
            xyz, rows = np.array(corners, dtype=float), np.arange(len(corners))[None]
            self.assertTrue(np.all(sub_volumes(xyz, kind, rows) > 0), kind)
            self.assertTrue(np.all(sub_volumes(xyz, kind, rows[:, FLIPS[kind]]) < 0), kind)
            # The tets fill the cell: 8 for the cube, 1 for the prism, 4/3
            # for the pyramid.
            volume = {"hexahedron": 8, "wedge": 1, "pyramid": 4 / 3}[kind]
            self.assertAlmostEqual(sub_volumes(xyz, kind, rows).sum() / 6, volume)


class Flac3dCase(CliTestCase):
    """The tetsmooth binary and a scratch folder (cls.tmp; path() names a
    file in it)."""

    SCRATCH_PREFIX = "tetsmooth_test_flac3d_"

    @classmethod
    def write(cls, name, text):
        with open(cls.path(name), "w", newline="") as f:
            f.write(text)
        return cls.path(name)

    def smooth(self, src, out, *extra):
        run("smooth", src, "-o", out, "--device", "cpu", "-q", *extra)
        return Grid(src), Grid(out)

    def assert_only_moved_gridpoints_changed(self, before, after):
        """The grids agree line for line but for G lines of moved gridpoints,
        which are "G id x y z" with the same id, in the shortest decimals
        that read back; returns the ids of the gridpoints whose line changed."""
        self.assertEqual(len(after.lines), len(before.lines))
        line_of = {i: n for n, i in before.point_line.items()}
        changed = set()
        for i, (a, b) in enumerate(zip(before.lines, after.lines)):
            if a == b:
                continue
            self.assertIn(i, line_of, f"line {i + 1}, not a G line, changed: {a!r} became {b!r}")
            n = line_of[i]
            self.assertEqual(after.point_line.get(n), i)
            ending = "\r" if a.endswith("\r") else ""
            self.assertRegex(b, rf"^G {n} \S+ \S+ \S+{ending}$")
            self.assertFalse(np.array_equal(after.points[n], before.points[n]), f"gridpoint {n} rewritten unmoved")
            for token, value in zip(b.split()[2:], after.points[n]):
                self.assertLessEqual(significant_digits(token), significant_digits(repr(float(value))), b)
            changed.add(n)
        self.assertEqual(sorted(after.points), sorted(before.points))
        return changed


class MeshioGrids(Flac3dCase):
    """Grids written by meshio, smoothed and read by tetsmooth."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.xyz, cls.tets, lower = two_layers()
        cls.lower = lower
        cls.upper = np.setdiff1d(np.arange(len(cls.tets)), lower)
        # meshio numbers gridpoints and zones 1, 2, ... in order; its groups
        # are SLOT 1. (Its writer may shift the index arrays it is given in
        # place, so it gets copies.)
        cls.src = cls.path("layers.f3grid")
        meshio.write(cls.src, meshio.Mesh(cls.xyz, [("tetra", cls.tets)],
                                          cell_sets={"lower": [lower.copy()], "upper": [cls.upper.copy()]}),
                     file_format="flac3d")
        cls.interface = set(cls.tets[lower].ravel().tolist()) & set(cls.tets[cls.upper].ravel().tolist())
        cls.fixed_ids = {n + 1 for n in boundary_nodes(cls.tets) | cls.interface}

    def test_smoothed_grid_is_the_input_but_for_moved_gridpoints(self):
        out = self.path("layers-out.f3grid")
        before, after = self.smooth(self.src, out)
        # meshio's G lines are tab-separated: a rewritten line is told apart.
        self.assertTrue(before.lines[before.point_line[1]].startswith("G\t"))
        changed = self.assert_only_moved_gridpoints_changed(before, after)
        self.assertTrue(changed, "no gridpoint moved")
        self.assertFalse(changed & self.fixed_ids, "a gridpoint on the boundary or the groups' interface moved")
        # The interface is a plane of interior nodes, which move when the
        # grid has no groups.
        self.assertEqual(len(self.interface - boundary_nodes(self.tets)), 9)
        meshio.write(self.path("no-groups.f3grid"), meshio.Mesh(self.xyz, [("tetra", self.tets)]), file_format="flac3d")
        free = self.assert_only_moved_gridpoints_changed(
            *self.smooth(self.path("no-groups.f3grid"), self.path("no-groups-out.f3grid")))
        self.assertTrue(free & {n + 1 for n in self.interface})
        ids = np.arange(1, len(self.xyz) + 1)
        xyz_in, xyz_out = before.xyz(ids), after.xyz(ids)
        np.testing.assert_array_equal(xyz_in, self.xyz)  # meshio's 17 digits read back exactly
        # The coordinates written are those tetsmooth computed; this
        # file's formula may differ from tetsmooth's in the last bits.
        self.assertGreaterEqual(radius_ratio(xyz_out, self.tets).min(), radius_ratio(xyz_in, self.tets).min() - 1e-12)
        self.assertGreater(radius_ratio(xyz_out, self.tets).mean(), radius_ratio(xyz_in, self.tets).mean())
        # meshio reads the smoothed grid: the same cells and groups, the new
        # coordinates.
        theirs_in, theirs_out = meshio.read(self.src), meshio.read(out)
        np.testing.assert_array_equal(theirs_out.points, xyz_out)
        np.testing.assert_array_equal(theirs_out.cells_dict["tetra"], self.tets)
        self.assertEqual(sorted(theirs_out.cell_sets), ["zone:lower:1", "zone:upper:1"])
        for key, blocks in theirs_in.cell_sets.items():
            for a, b in zip(blocks, theirs_out.cell_sets[key]):
                np.testing.assert_array_equal(a, b)
        np.testing.assert_array_equal(np.sort(theirs_out.cell_sets["zone:lower:1"][0]), self.lower)

    def test_a_binary_grid_comes_back_binary_with_the_same_coordinates_as_text(self):
        # meshio's binary layout (FLAC3D's zone export ... binary) holds the
        # same grid: smoothed, it must give the coordinates the text grid
        # gives, written back in the same bytes but for the coordinates.
        binary, out = self.path("layers-bin.f3grid"), self.path("layers-bin-out.f3grid")
        meshio.write(binary, meshio.Mesh(self.xyz, [("tetra", self.tets)],
                                         cell_sets={"lower": [self.lower.copy()], "upper": [self.upper.copy()]}),
                     file_format="flac3d", binary=True)
        run("smooth", binary, "-o", out, "--device", "cpu", "--threads", "1")
        text_out = self.path("layers-text-out.f3grid")
        run("smooth", self.src, "-o", text_out, "--device", "cpu", "--threads", "1")
        with open(binary, "rb") as f:
            before = f.read()
        with open(out, "rb") as f:
            after = f.read()
        self.assertEqual(len(after), len(before))
        theirs = meshio.read(out)
        np.testing.assert_array_equal(theirs.points, meshio.read(text_out).points)
        self.assertFalse(np.array_equal(theirs.points, self.xyz), "no gridpoint moved")
        np.testing.assert_array_equal(theirs.cells_dict["tetra"], self.tets)
        np.testing.assert_array_equal(np.sort(theirs.cell_sets["zone:lower:Default"][0]), self.lower)
        # Only the 24 bytes of each moved gridpoint's coordinates differ:
        # records of 28 bytes (id, x, y, z) after 12 bytes of header.
        differ = [i for i in range(len(before)) if before[i] != after[i]]
        self.assertTrue(all(12 <= i < 12 + 28 * len(self.xyz) and (i - 12) % 28 >= 4 for i in differ))

    def test_groups_of_every_slot_keep_their_interfaces(self):
        # A second slot (an excavation stage, say) over the cubes x < 2
        # splits both layers: four regions, whose interfaces x = 2 and z = 2
        # stay in place. Its name is quoted, with a blank in it.
        stage = np.flatnonzero(np.floor(self.xyz[self.tets].mean(axis=1)[:, 0]) < 2)
        ids = (stage + 1).tolist()
        text = read_text(self.src).rstrip("\n") + "\nZGROUP 'stage 1' SLOT 2\n" + "".join(
            " " + " ".join(map(str, ids[k:k + 15])) + "\n" for k in range(0, len(ids), 15))
        src = self.write("slots.f3grid", text)
        # meshio sees the group in its slot.
        mesh = meshio.read(src)
        np.testing.assert_array_equal(mesh.cell_sets["zone:stage 1:2"][0], stage)
        before, after = self.smooth(src, self.path("slots-out.f3grid"))
        changed = self.assert_only_moved_gridpoints_changed(before, after)
        self.assertTrue(changed)
        staged = set(self.tets[stage].ravel().tolist())
        rest = set(self.tets[np.setdiff1d(np.arange(len(self.tets)), stage)].ravel().tolist())
        between = {n + 1 for n in staged & rest}
        self.assertFalse(changed & (self.fixed_ids | between), "a gridpoint between two groups of slot 2 moved")
        # Those gridpoints move without the group of slot 2.
        free = self.assert_only_moved_gridpoints_changed(*self.smooth(self.src, self.path("slot1-out.f3grid")))
        self.assertTrue(free & between)
        # The region tags are the four intersections, numbered in zone
        # order, and MSH output names them by their groups.
        run("convert", src, self.path("slots.msh"), "-q")
        msh = meshio.read(self.path("slots.msh"))
        tags = np.concatenate([d for c, d in zip(msh.cells, msh.cell_data["gmsh:physical"]) if c.type == "tetra"])
        np.testing.assert_array_equal(msh.cells_dict["tetra"], self.tets)
        in_lower, in_stage = np.isin(np.arange(len(self.tets)), self.lower), np.isin(np.arange(len(self.tets)), stage)
        key = 2 * in_lower + in_stage
        _, first = np.unique(key, return_index=True)
        expected = np.empty(len(key), dtype=int)
        for tag, k in enumerate(key[np.sort(first)], start=1):
            expected[key == k] = tag
        np.testing.assert_array_equal(tags, expected)
        names = {int(tag): name for name, (tag, dim) in msh.field_data.items() if dim == 3}
        # (FLAC3D's "slot=group" outside the default slot.)
        for k, name in ((3, "lower + 2=stage 1"), (2, "lower"), (1, "upper + 2=stage 1"), (0, "upper")):
            self.assertEqual(names[expected[key == k][0]], name)

    def test_format_variants_read_alike(self):
        # The rules of flac3d_io.hpp that meshio's writer does not use: a
        # byte order mark, CRLF line ends, keywords and zone types in lower
        # case, commas between values, blank lines (also among a group's
        # ids), comments, and a group name in single quotes with a blank.
        plain = read_text(self.src).split("\n")
        varied = []
        for line in plain:
            values = line.split()
            if values[:1] == ["G"]:
                varied.append("g " + ", ".join(values[1:]))
            elif values[:1] == ["Z"]:
                varied.append("  z t4," + ",".join(values[2:]))
            elif values[:1] == ["ZGROUP"]:
                varied.append("zgroup 'upper layer' slot 1" if "upper" in line else "ZGroup lower")
            elif line.startswith(" ") and len(values) > 10:
                varied += [" ".join(values[:10]), "", "  " + " ".join(values[10:])]
            else:
                varied.append(line)
        text = "\ufeff* a comment\n\n" + "\r\n".join(varied)
        with open(self.path("varied.f3grid"), "w", encoding="utf-8", newline="") as f:
            f.write(text)
        for name in ("layers", "varied"):
            run("convert", self.path(f"{name}.f3grid"), self.path(f"{name}.vtu"), "-q")
        a, b = meshio.read(self.path("layers.vtu")), meshio.read(self.path("varied.vtu"))
        np.testing.assert_array_equal(b.points, a.points)
        np.testing.assert_array_equal(b.cells_dict["tetra"], a.cells_dict["tetra"])
        np.testing.assert_array_equal(b.cell_data["tetsmooth:tag"][0], a.cell_data["tetsmooth:tag"][0])
        self.assertEqual(len(set(a.cell_data["tetsmooth:tag"][0].ravel().tolist())), 2)
        # Smoothed, the grid keeps its byte order mark, its CRLFs (moved G
        # lines too) and its other lines.
        out = self.path("varied-out.f3grid")
        run("smooth", self.path("varied.f3grid"), "-o", out, "--device", "cpu", "-q")
        with open(out, "rb") as f:
            data = f.read()
        self.assertTrue(data.startswith("\ufeff* a comment\n\n".encode()))
        self.assertEqual(data.count(b"\n") - 2, data.count(b"\r\n"))
        changed = [k for k, (x, y) in enumerate(zip(text.encode().split(b"\n"), data.split(b"\n"))) if x != y]
        self.assertTrue(changed)
        self.assertTrue(all(data.split(b"\n")[k].startswith(b"G ") for k in changed))

    def test_ids_in_any_order_and_with_gaps(self):
        # Gridpoint ids shuffled and spread, zone ids descending with gaps:
        # tetsmooth and meshio must pair the same gridpoints with each zone.
        rng = np.random.default_rng(4)
        order = rng.permutation(len(self.xyz))
        point_ids = 7 * np.arange(len(self.xyz)) + 1000  # point_ids[k]: the id of node k
        zone_ids = 3 * (len(self.tets) - np.arange(len(self.tets))) + 5
        lines = ["* GRIDPOINTS"]
        lines += [f"G {point_ids[k]} {x!r} {y!r} {z!r}" for k in order for x, y, z in [self.xyz[k]]]
        lines += ["* ZONES"] + [f"Z T4 {zone_ids[t]} " + " ".join(map(str, point_ids[row]))
                                for t, row in enumerate(self.tets)]
        lines += ['ZGROUP "lower" SLOT 1', " " + " ".join(map(str, zone_ids[self.lower])), "* end"]
        src = self.write("ids.f3grid", "\n".join(lines) + "\n")
        theirs = meshio.read(src)
        run("convert", src, self.path("ids.vtu"), "-q")
        ours = meshio.read(self.path("ids.vtu"))
        np.testing.assert_array_equal(ours.points, theirs.points)
        np.testing.assert_array_equal(ours.points, self.xyz[order])
        np.testing.assert_array_equal(ours.cells_dict["tetra"], theirs.cells_dict["tetra"])
        # A grid with one group: two regions, the group's zones and the rest.
        tags = ours.cell_data["tetsmooth:tag"][0].ravel()
        lower = theirs.cell_sets["zone:lower:1"][0]
        self.assertEqual(set(tags[lower].tolist()), {int(tags[lower[0]])})
        self.assertEqual(len(set(tags.tolist())), 2)
        # A new grid (from MSH, which keeps them as node and element tags)
        # keeps both numberings.
        run("convert", src, self.path("ids.msh"), "-q")
        run("convert", self.path("ids.msh"), self.path("ids-new.f3grid"), "-q")
        new = Grid(self.path("ids-new.f3grid"))
        self.assertEqual(list(new.points), list(point_ids[order]))
        self.assertEqual([z[1] for z in new.zones], list(zone_ids))

    def test_pins_keep_interior_gridpoints_in_place(self):
        # Interior gridpoints off the interface, which move without a pin.
        _, plain = self.smooth(self.src, self.path("plain-out.f3grid"))
        ids = np.arange(1, len(self.xyz) + 1)
        moved = [int(n) for n in ids if not np.array_equal(plain.points[n], self.xyz[n - 1])]
        self.assertGreaterEqual(len(moved), 6)
        pinned, face = moved[:3], moved[3:6]
        lines = read_text(self.src).rstrip("\n").split("\n")
        # Pin comments as the writer makes them and in another case, and a
        # face (a fault, say) over three more: faces pin their gridpoints.
        lines.insert(3, f"* TETSMOOTH PINNED {pinned[0]} {pinned[1]}")
        lines += [f"*tetsmooth pinned {pinned[2]}", f"F T3 1 {face[0]} {face[1]} {face[2]}",
                  'FGROUP "fault" SLOT 1', " 1"]
        src = self.write("pins.f3grid", "\n".join(lines) + "\n")
        before, after = self.smooth(src, self.path("pins-out.f3grid"))
        changed = self.assert_only_moved_gridpoints_changed(before, after)
        self.assertTrue(changed)
        self.assertFalse(changed & set(pinned + face), "a pinned gridpoint or one on a face moved")
        # meshio reads the face and its group.
        mesh = meshio.read(self.path("pins-out.f3grid"))
        np.testing.assert_array_equal(mesh.cells_dict["triangle"], [np.array(face) - 1])
        self.assertIn("face:fault:1", mesh.cell_sets)
        # VTU keeps the pins as tetsmooth:fixed...
        run("convert", src, self.path("pins.vtu"), "-q")
        fixed = meshio.read(self.path("pins.vtu")).point_data["tetsmooth:fixed"]
        self.assertEqual(set((np.flatnonzero(fixed) + 1).tolist()), set(pinned + face))
        # ...and a new grid from it lists those that no face pins, so that a
        # later run keeps them.
        run("convert", self.path("pins.vtu"), self.path("pins-new.f3grid"), "-q")
        new = Grid(self.path("pins-new.f3grid"))
        self.assertEqual(sorted(new.pins), sorted(pinned))
        self.assertEqual([f[2] for f in new.faces], [face])
        before, after = self.smooth(self.path("pins-new.f3grid"), self.path("pins-new-out.f3grid"))
        changed = self.assert_only_moved_gridpoints_changed(before, after)
        self.assertTrue(changed)
        self.assertFalse(changed & set(pinned + face))

    def test_refused_grids_name_their_line_and_leave_nothing(self):
        plain = read_text(self.src).rstrip("\n").split("\n")
        first_g = next(i for i, line in enumerate(plain) if line.startswith("G"))
        last_g = max(i for i, line in enumerate(plain) if line.startswith("G"))
        first_z = next(i for i, line in enumerate(plain) if line.startswith("Z "))
        last_z = max(i for i, line in enumerate(plain) if line.startswith("Z "))
        group = next(i for i, line in enumerate(plain) if line.startswith("ZGROUP"))
        z = plain[first_z].split()

        def edited(index, *new, drop=0):
            return "\n".join(plain[:index] + list(new) + plain[index + drop:]) + "\n"

        # name: (text, the line at fault (1-based), what the message names)
        cases = {
            "undefined.f3grid": (edited(first_z, " ".join(z[:-1] + ["99999"]), drop=1), first_z + 1, "99999"),
            "twice.f3grid": (edited(last_g + 1, plain[first_g].replace("0.0", "5.0")), last_g + 2, "second time"),
            "zone-twice.f3grid": (edited(last_z + 1, plain[first_z]), last_z + 2, "second time"),
            "count.f3grid": (edited(first_z, " ".join(z[:-1]), drop=1), first_z + 1, "T4"),
            "zero.f3grid": (edited(first_g, "G 0 9 9 9"), first_g + 1, "not positive"),
            "group.f3grid": (edited(group + 1, plain[group + 1] + " 99999", drop=1), group + 2, "99999"),
            "quote.f3grid": (edited(group, 'ZGROUP "lower SLOT 1', drop=1), group + 1, "quote"),
            "outside.f3grid": (edited(first_z + 1, " 1 2"), first_z + 2, "outside"),
            "pin.f3grid": (edited(len(plain), "* TETSMOOTH PINNED 99999"), len(plain) + 1, "99999"),
        }
        for name, (text, line, fragment) in cases.items():
            with self.subTest(grid=name):
                src, out = self.write(name, text), self.path("out-" + name)
                proc = run("smooth", src, "-o", out, "--device", "cpu", check=False)
                self.assertEqual(proc.returncode, EXIT_INPUT, proc.stderr)
                self.assertEqual(len(proc.stderr.splitlines()), 1, proc.stderr)
                self.assertIn(f"{name}:{line}: ", proc.stderr)
                self.assertIn(fragment, proc.stderr)
                self.assertFalse(os.path.exists(out))
        # A record of another kind is kept, and named in a warning.
        src, out = self.write("record.f3grid", edited(last_z + 1, "ATTACH 1 2", " 3 4")), self.path("out-record.f3grid")
        proc = run("smooth", src, "-o", out, "--device", "cpu", check=False)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn(f"'ATTACH' (line {last_z + 2})", proc.stderr)
        self.assertIn("\nATTACH 1 2\n 3 4\n", read_text(out))
        # A binary grid cut short names its byte; a grid without tets has no
        # line to blame.
        meshio.write(self.path("binary.f3grid"), meshio.read(self.src), file_format="flac3d", binary=True)
        with open(self.path("binary.f3grid"), "rb") as f:
            cut = f.read()[:1000]
        with open(self.path("cut.f3grid"), "wb") as f:
            f.write(cut)
        cube = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
        meshio.write(self.path("bricks.f3grid"), meshio.Mesh(cube, [("hexahedron", np.arange(8)[None])]),
                     file_format="flac3d")
        for name, fragment in (("cut.f3grid", "cut.f3grid, byte 8: gridpoint count 125 is more than the rest of the file holds"),
                               ("bricks.f3grid", "bricks.f3grid: no T4 zones")):
            with self.subTest(grid=name):
                out = self.path("out-" + name)
                proc = self.assert_refused_output_kept(("smooth", self.path(name), "-o", out, "--device", "cpu"),
                                                       out, "an older grid\n")
                self.assertIn(fragment, proc.stderr)


class MixedGrids(Flac3dCase):
    """Grids of tets with bricks, wedges and pyramids."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.xyz, cls.cells, cls.overlapping = mixed_block()
        # meshio writes the cells in FLAC3D's order, each right-handed
        # (turned where its first four gridpoints would be left-handed).
        cls.src = cls.path("mixed.f3grid")
        meshio.write(cls.src, meshio.Mesh(cls.xyz, list(cls.cells.items())), file_format="flac3d")
        cls.grid = Grid(cls.src)

    def test_meshio_writes_right_handed_zones(self):
        # The premise of the checks below: meshio's zones are right side out
        # by this file's reading of FLAC3D's layouts, and hold the cells'
        # nodes.
        self.assertEqual({z[0] for z in self.grid.zones}, {"T4", "B8", "W6", "P5"})
        ids = np.arange(1, len(self.xyz) + 1)
        for kind, rows in self.grid.cells().items():
            with self.subTest(kind=kind):
                assert_cells_right_side_out(self, self.grid.xyz(ids), kind, rows - 1, "meshio's grid")
                self.assertEqual(sorted(map(sorted, (rows - 1).tolist())),
                                 sorted(map(sorted, self.cells[kind].tolist())))

    def check_converted(self, suffix):
        """The grid converted to `suffix` as meshio reads it: meshio's points
        and cells (the same nodes, cell by cell, in zone order), each cell
        right side out in meshio's order (which meshio's VTU reader makes of
        VTK's, turning wedges; its MSH reader takes Gmsh's as it is)."""
        out = self.path("mixed." + suffix)
        run("convert", self.src, out, "-q")
        ours, theirs = meshio.read(out), meshio.read(self.src)
        np.testing.assert_array_equal(ours.points, theirs.points)
        for kind in ("tetra", "hexahedron", "wedge", "pyramid"):
            with self.subTest(output=suffix, kind=kind):
                rows, expected = ours.cells_dict[kind], theirs.cells_dict[kind]
                self.assertEqual(list(map(sorted, rows.tolist())), list(map(sorted, expected.tolist())))
                assert_cells_right_side_out(self, ours.points, kind, rows, f"the {suffix} output")

    def test_vtu_output_has_meshios_cells_right_side_out(self):
        self.check_converted("vtu")

    def test_msh_output_has_meshios_cells_right_side_out(self):
        self.check_converted("msh")

    def test_gmsh_finds_positive_jacobians_in_msh_output(self):
        # Gmsh itself judges the cells of the MSH output: the determinant of
        # each cell's Jacobian at a point inside it is positive for a cell
        # right side out.
        gmsh = require_gmsh()

        def determinants(path):
            with gmsh_session(gmsh):
                gmsh.open(path)
                return {kind: np.asarray(gmsh.model.mesh.getJacobians(etype, [0.2, 0.2, 0.2])[1])
                        for kind, etype in GMSH_TYPES.items()}

        # First, Gmsh agrees with this file's volumes on the cells as built
        # (every other one inside out), which meshio writes to MSH as they
        # are, on one entity so that Gmsh keeps their order.
        direct = self.path("mixed-meshio.msh")
        ones = [np.ones(len(rows), dtype=int) for rows in self.cells.values()]
        meshio.write(direct, meshio.Mesh(self.xyz, list(self.cells.items()),
                                         cell_data={"gmsh:physical": ones, "gmsh:geometrical": ones}),
                     file_format="gmsh22", binary=False)
        for kind, found in determinants(direct).items():
            np.testing.assert_array_equal(found > 0, sub_volumes(self.xyz, kind, self.cells[kind]).sum(axis=1) > 0)
        out = self.path("mixed-gmsh.msh")
        run("convert", self.src, out, "-q")
        for kind, found in determinants(out).items():
            with self.subTest(kind=kind):
                self.assertEqual(len(found), len(self.cells[kind]))
                self.assertEqual(int(np.sum(found <= 0)), 0,
                                 f"{kind}: {np.sum(found <= 0)} of {len(found)} inside out in Gmsh")

    def test_gridpoints_of_other_zones_stay_fixed(self):
        out = self.path("mixed-out.f3grid")
        before, after = self.smooth(self.src, out)
        changed = self.assert_only_moved_gridpoints_changed(before, after)
        self.assertTrue(changed)
        others = {int(n) + 1 for kind, rows in self.cells.items() if kind != "tetra" for n in rows.ravel()}
        self.assertFalse(changed & others, "a gridpoint of a B8, W6 or P5 zone moved")
        # The overlapping cells' gridpoints are interior to the tets: only
        # their zones keep them. Without those three zones, they move.
        inside = {int(n) + 1 for kind, k in self.overlapping.items() for n in self.cells[kind][k]}
        self.assertFalse(inside & {n + 1 for n in boundary_nodes(self.cells["tetra"])})
        zone_ids = {z[1] for z in self.grid.zones if {*z[2]} <= inside and z[0] != "T4"}
        self.assertEqual(len(zone_ids), 3)
        text = "\n".join(line for line in before.lines
                         if not (line.startswith("Z ") and int(line.split()[2]) in zone_ids))
        _, free = self.smooth(self.write("mixed-free.f3grid", text), self.path("mixed-free-out.f3grid"))
        self.assertTrue(any(not np.array_equal(free.points[n], before.points[n]) for n in inside))
        # meshio reads the smoothed grid with its cells as they were.
        theirs_in, theirs_out = meshio.read(self.src), meshio.read(out)
        for kind in self.cells:
            np.testing.assert_array_equal(theirs_out.cells_dict[kind], theirs_in.cells_dict[kind])


class NewGrids(Flac3dCase):
    """Grids that tetsmooth writes from other formats, read by meshio."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        # An MSH file (2.2, ASCII, so that its element numbers can be read
        # here) of the mixed block: the tets in two named volumes, the
        # other cells in an unnamed one, and triangles of the top and bottom
        # faces of the lattice in a named and an unnamed surface.
        cls.xyz, cls.cells, _ = mixed_block(3, seed=9)
        tets = cls.cells["tetra"]
        cls.tet_tags = np.where(cls.xyz[tets].mean(axis=1)[:, 0] < 1.5, 1, 2)
        faces = np.concatenate([tets[:, f] for f in ([1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2])])
        unique, index, counts = np.unique(np.sort(faces, axis=1), axis=0, return_index=True, return_counts=True)
        z = cls.xyz[faces[index[counts == 1]], 2]
        cls.triangles = faces[index[counts == 1]][(z == 0).all(axis=1) | (z == 3).all(axis=1)]
        cls.triangle_tags = np.where(cls.xyz[cls.triangles, 2].mean(axis=1) > 0, 5, 6)
        blocks = [("tetra", tets), ("triangle", cls.triangles)] + [(k, cls.cells[k]) for k in FLIPS]
        physical = [cls.tet_tags, cls.triangle_tags] + [np.full(len(cls.cells[k]), 3) for k in FLIPS]
        cls.src = cls.path("mixed.msh")
        meshio.write(cls.src, meshio.Mesh(cls.xyz, blocks,
                                          cell_data={"gmsh:physical": physical, "gmsh:geometrical": physical},
                                          field_data={"sand": np.array([1, 3]), "clay": np.array([2, 3]),
                                                      "top": np.array([5, 2])}),
                     file_format="gmsh22", binary=False)
        # The element numbers of each block, as the file has them.
        with open(cls.src) as f:
            text = f.read()
        elements = text.split("$Elements\n")[1].split("$EndElements")[0].split("\n")[1:-1]
        cls.numbers = {}
        for kind, rows in blocks:
            cls.numbers[kind] = [int(e.split()[0]) for e in elements[:len(rows)]]
            elements = elements[len(rows):]
        cls.out = cls.path("new.f3grid")
        run("convert", cls.src, cls.out, "-q")
        cls.grid = Grid(cls.out)

    def test_meshio_reads_the_points_cells_and_groups(self):
        mesh = meshio.read(self.out)
        np.testing.assert_array_equal(mesh.points, self.xyz)
        np.testing.assert_array_equal(mesh.cells_dict["tetra"], self.cells["tetra"])
        np.testing.assert_array_equal(mesh.cells_dict["triangle"], self.triangles)
        for kind in FLIPS:
            self.assertEqual(list(map(sorted, mesh.cells_dict[kind].tolist())),
                             list(map(sorted, self.cells[kind].tolist())))
        # Groups named as the physical names; the one volume and the one
        # surface without a name are in no group, which tells them apart.
        self.assertEqual(sorted(mesh.cell_sets), ["face:top:Default", "zone:clay:Default", "zone:sand:Default"])
        members = {key: np.concatenate(blocks) for key, blocks in mesh.cell_sets.items()}
        offset = {c.type: sum(len(b.data) for b in mesh.cells[:k]) for k, c in enumerate(mesh.cells)}
        np.testing.assert_array_equal(members["zone:sand:Default"] - offset["tetra"], np.flatnonzero(self.tet_tags == 1))
        np.testing.assert_array_equal(members["zone:clay:Default"] - offset["tetra"], np.flatnonzero(self.tet_tags == 2))
        np.testing.assert_array_equal(members["face:top:Default"] - offset["triangle"],
                                      np.flatnonzero(self.triangle_tags == 5))
        grouped = len(members["zone:sand:Default"]) + len(members["zone:clay:Default"])
        self.assertEqual(sum(len(c.data) for c in mesh.cells if c.type != "triangle") - grouped,
                         sum(len(self.cells[k]) for k in FLIPS))
        # Faces are T3 records, and their groups FGROUPs.
        self.assertEqual({f[0] for f in self.grid.faces}, {"T3"})
        self.assertEqual(sorted(g[1] for g in self.grid.groups if g[0] == "F"), ["top"])
        # Every node that the MSH file pins is on a zone or face written,
        # which pins it again: no pin comments.
        self.assertEqual(self.grid.pins, [])

    def test_zone_and_face_ids_are_the_element_numbers(self):
        zone_ids = {kind: [] for kind in self.cells}
        for code, number, _ in self.grid.zones:
            zone_ids[FROM_FLAC3D[code][0]].append(number)
        for kind in self.cells:
            self.assertEqual(zone_ids[kind], self.numbers[kind])
        self.assertEqual([f[1] for f in self.grid.faces], self.numbers["triangle"])
        self.assertEqual(sorted(self.grid.points), list(range(1, len(self.xyz) + 1)))

    def test_zones_are_right_handed(self):
        # FLAC3D's rule: the first four gridpoints of each zone are a
        # right-handed frame; and the whole zone, read by this file's
        # layouts, is right side out, although every other cell of the MSH
        # file is inside out.
        ids = np.arange(1, len(self.xyz) + 1)
        xyz = self.grid.xyz(ids)
        firsts = np.array([z[2][:4] for z in self.grid.zones]) - 1
        self.assertTrue(np.all(signed_volume6(xyz, firsts) > 0))
        for kind, rows in self.grid.cells().items():
            with self.subTest(kind=kind):
                assert_cells_right_side_out(self, xyz, kind, rows - 1, "the new grid")

    def test_a_round_trip_keeps_the_cells_right_side_out(self):
        # MSH -> FLAC3D -> MSH: each cell of the first MSH file that was
        # right side out is right side out again.
        back = self.path("back.msh")
        run("convert", self.out, back, "-q")
        mesh = meshio.read(back)
        np.testing.assert_array_equal(mesh.cells_dict["tetra"], self.cells["tetra"])
        for kind in FLIPS:
            with self.subTest(kind=kind):
                rows = mesh.cells_dict[kind]
                self.assertEqual(list(map(sorted, rows.tolist())), list(map(sorted, self.cells[kind].tolist())))
                assert_cells_right_side_out(self, mesh.points, kind, rows, "MSH -> FLAC3D -> MSH")


if __name__ == "__main__":
    unittest.main()
