"""ANSYS Mechanical APDL archives (.cdb) through tetsmooth, checked against
Ansys's own reader of the format, mapdl-archive 0.4.2 (PyPI; Debian has
none, so scripts/install_deps.sh puts it in .deps/python and CTest puts that
on PYTHONPATH), and against decks written here by hand.

What is checked, and why:
- TetBeam.cdb, a deck that ANSYS wrote (it ships with mapdl-archive; its
  NBLOCK is in (3i8,6e20.13)): a smoothed file must be the input line for
  line and byte for byte but for the NBLOCK records of nodes that moved, and
  only nodes off the boundary may move, since a simulation reads everything
  else in the file (element types, materials, solution settings) as it was.
  A moved record keeps its integers and the fields after Z as read, and its
  X, Y and Z are tetsmooth's result (the same run written as VTU) correctly
  rounded to the block's format. mapdl-archive reads the smoothed file with
  the same node numbers and element records, and coordinates within the 14
  significant digits the format holds; the worst radius ratio does not
  fall (beyond 1e-12, the rounding of the written digits) and no tet turns
  over. Converting the deck to .cdb gives back its
  bytes. The other example decks hold no tets and are refused.
- Decks written here (a jittered Kuhn lattice, node numbers with a jump):
  SOLID185 degenerate tets (I,J,K,K,M,M,M,M) smooth as 4-node tets; SOLID187
  10-node tets and SOLID186 20-node degenerate tets read as 10-node tets
  whose midside nodes stay at their edges' midpoints; two MATs keep the
  nodes of their interface; an element component splitting one MAT keeps
  its boundary, the note about renumbered regions is printed and the
  component names its region; node components (a range "a -b" and single
  nodes), D, F, BF, IC, M, CP and CE on interior nodes, a non-solid EBLOCK
  (SURF154, "EBLOCK,10,,,n") and a SHELL181 pin exactly their nodes (as
  tetsmooth:fixed in VTU output shows), and some of those nodes move when
  nothing pins them, so that a pin is told from a node that stays anyway;
  D,ALL is noted as a selection tetsmooth does not follow; D and F with
  NEND and NINC pin the whole range they name; a moved record keeps its
  rotation angles (mapdl-archive reads them), and a record with Z left off
  is written whole. Decks as recent releases write them, with the NBLOCK
  closed by "N,UNBL,LOC,-1" or the element types in an ETBLOCK, which
  mapdl-archive reads, are read too.
- New decks: a Gmsh mesh of two named volumes and a named embedded surface
  becomes a .cdb that mapdl-archive reads with the MSH node and element
  numbers, SOLID285 (or SOLID187 with midside nodes on the right edges),
  MAT = physical tag, element components named after the volumes and node
  components TETSMOOTH_PINNED and one for the surface; back to .msh, the
  volumes keep their tags and (APDL's) names.
- Bad decks (an N or E command, a bad NBLOCK number, a node defined twice,
  an undefined node or element type, 4- and 10-node tets mixed, a file cut
  inside an NBLOCK, a short CMBLOCK, an EBLOCK format with reals) are
  refused with exit 3 and one line naming the file and line, writing
  nothing and leaving an existing output as it was.
- A deck with CRLF line ends smooths to the same bytes as its LF twin with
  CRLF line ends, the rewritten records included.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import os
import re
import unittest

import meshio
import numpy as np

from test_cli import (EXIT_INPUT, CliTestCase, RefusedDecks, kuhn_lattice, quality_json, radius_ratio, run,
                      signed_volume6)
from test_independent_readers import GmshScratchCase, boundary_nodes, gmsh_session, two_layers

try:
    import mapdl_archive
    from mapdl_archive import examples as mapdl_examples
    MAPDL_ERROR = ""
except Exception as e:  # a compiled module can fail to import in more ways than ImportError
    mapdl_archive = mapdl_examples = None
    MAPDL_ERROR = f"{type(e).__name__}: {e}"

# The corners of the midside nodes of a SOLID187, in the order it lists them
# after I, J, K, L: the edges IJ, JK, KI, IL, JL, KL.
ANSYS_EDGES = np.array([[0, 1], [1, 2], [2, 0], [0, 3], [1, 3], [2, 3]])
# Gmsh's 10-node tet (type 11) has the last two midside nodes the other way
# round (edges 3-2 and 3-1); this permutation is its own inverse.
GMSH_ANSYS_ORDER = [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]
# e21.13 and e20.13 hold 14 significant digits: a value read back is within
# half a unit of the 14th digit, 5e-14 of its size, of the double written.
FORMAT_RTOL = 5.5e-14
# The same run each time (the result does not depend on the thread count).
SMOOTH_OPTIONS = ("--device", "cpu", "--threads", "2", "-q")
FORMAT_LINE = re.compile(r"\(\s*(\d*)i(\d+)\s*(?:,\s*(\d*)[edg](\d+)\.(\d+)(?:e(\d+))?)?\s*\)", re.IGNORECASE)


def require_mapdl_archive():
    """Fails (not skips: a skip would pass) without mapdl-archive."""
    if mapdl_archive is None:
        raise RuntimeError(f"cannot import mapdl_archive ({MAPDL_ERROR}): run scripts/install_deps.sh, which "
                           "installs mapdl-archive 0.4.2 into .deps/python for /usr/bin/python3")


def read_archive(path):
    """mapdl-archive's reading of a deck: raw records, no VTK grid."""
    return mapdl_archive.Archive(path, parse_vtk=False)


def components(mapping):
    """mapdl-archive's components as {name: set of numbers}; it keeps the
    blanks that pad names in CDWRITE's files."""
    return {name.strip(): set(np.asarray(items).tolist()) for name, items in mapping.items()}


# --- Writing decks -------------------------------------------------------------

def fortran_e(value, width=21, decimals=13, exponent_digits=3):
    """`value` as Fortran's 1PEw.dEe writes it (what CDWRITE writes):
    "-5.0000000000000E-001", right-aligned in `width`."""
    mantissa, exponent = f"{value:.{decimals}E}".split("E")
    e = int(exponent)
    return f"{mantissa}E{'-' if e < 0 else '+'}{abs(e):0{exponent_digits}d}".rjust(width)


def int_fields(values, width=9):
    return "".join(f"{int(v):{width}d}" for v in values)


def nblock_lines(numbers, xyz, record=None):
    """An NBLOCK in (3i9,6e21.13e3) closed as CDWRITE closes it. `record`
    may give the text of some nodes' records ({number: text})."""
    record = record or {}
    lines = [f"NBLOCK,6,SOLID,{max(numbers):10d},{len(numbers):10d}", "(3i9,6e21.13e3)"]
    for n, p in zip(numbers, xyz):
        lines.append(record.get(int(n)) or int_fields([n, 0, 0]) + "".join(fortran_e(v) for v in p))
    return lines + ["N,R5.3,LOC,       -1,"]


def eblock_lines(elements):
    """A solid EBLOCK in (19i9) of (MAT, TYPE, element number, nodes): the
    eleven attributes and eight nodes on the first line, the rest on the
    next, as CDWRITE lays them out."""
    lines = [f"EBLOCK,19,SOLID,{max(e[2] for e in elements):10d},{len(elements):10d}", "(19i9)"]
    for mat, etype, number, nodes in elements:
        nodes = [int(n) for n in nodes]
        lines.append(int_fields([mat, etype, 1, 1, 0, 0, 0, 0, len(nodes), 0, number] + nodes[:8]))
        if len(nodes) > 8:
            lines.append(int_fields(nodes[8:]))
    return lines + [int_fields([-1])]


def cmblock_lines(name, entity, items):
    lines = [f"CMBLOCK,{name},{entity},{len(items):8d}", "(8i10)"]
    return lines + [int_fields(items[k:k + 8], 10) for k in range(0, len(items), 8)]


def node_numbers(count):
    """Numbers for `count` nodes: 1, 2, ... with a jump of 1000 after the
    60th, as a deck whose parts were meshed apart has."""
    k = np.arange(count)
    return k + 1 + 1000 * (k >= 60)


def as_ranges(numbers):
    """Sorted numbers as CMBLOCK items: a run of two or more as (first,
    -last)."""
    items = []
    for n in sorted(numbers):
        if items and items[-1] < 0 and -items[-1] == n - 1:
            items[-1] = -n
        elif items and items[-1] == n - 1:
            items.append(-n)
        else:
            items.append(n)
    return items


def deck_lines(numbers, xyz, elements, ets=("ET,1,285",), more=(), record=None):
    return ["/COM,written by test_ansys.py", "/PREP7", *ets, *nblock_lines(numbers, xyz, record),
            *eblock_lines(elements), *more, "FINISH"]


def with_midside_nodes(xyz, tets):
    """The 4-node tets with a node at the midpoint of each edge: the
    coordinates and 10-node tets in SOLID187's order."""
    points, rows, made = list(xyz), [], {}
    for tet in tets.tolist():
        row = list(tet)
        for a, b in ANSYS_EDGES:
            edge = (min(tet[a], tet[b]), max(tet[a], tet[b]))
            if edge not in made:
                made[edge] = len(points)
                points.append(0.5 * (xyz[tet[a]] + xyz[tet[b]]))
            row.append(made[edge])
        rows.append(row)
    return np.array(points), np.array(rows)


def solid186_tet(row):
    """A SOLID186's 20 nodes for a 10-node tet (corners I, J, K, M then the
    midside nodes of IJ, JK, KI, IM, JM, KM): K = L = S, M = N = O = P = U
    = V = W = X and A = B, by the element reference's degenerate tet."""
    i, j, k, m, ij, jk, ki, im, jm, km = row
    return [i, j, k, k, m, m, m, m, ij, jk, k, ki, m, m, m, m, im, jm, km, km]


# --- Reading decks ---------------------------------------------------------------

def file_lines(path):
    """The file's lines as bytes, each with its '\\r' if it has one."""
    with open(path, "rb") as f:
        return f.read().split(b"\n")


class NodeRecords:
    """The NBLOCK records of a deck, parsed here from the format line of each
    block: `order` (node numbers as listed), `line` ({number: index into
    `lines`}), `layout` ({number: (end of the integers, real width,
    decimals, exponent digits)}) and `xyz` ({number: coordinates})."""

    def __init__(self, path):
        self.lines = file_lines(path)
        self.order, self.line, self.layout, self.xyz = [], {}, {}, {}
        text = [raw.decode("latin-1").rstrip("\r") for raw in self.lines]
        i = 0
        while i < len(text):
            if not text[i].strip().upper().startswith("NBLOCK"):
                i += 1
                continue
            m = FORMAT_LINE.fullmatch(text[i + 1].strip())
            ints, iw, _, rw, decimals, exponent = (int(g) if g else None for g in m.groups())
            layout = ((ints or 1) * iw, rw, decimals, exponent or 2)
            i += 2
            while not text[i].strip().upper().startswith("N,"):
                number = int(text[i][:iw])
                if number == -1:
                    break
                fields = [text[i][layout[0] + c * rw:layout[0] + (c + 1) * rw].strip() for c in range(3)]
                self.xyz[number] = np.array([float(f.upper().replace("D", "E")) if f else 0.0 for f in fields])
                self.order.append(number)
                self.line[number] = i
                self.layout[number] = layout
                i += 1

    def coordinates(self, numbers):
        return np.array([self.xyz[n] for n in numbers])


def vtu_result(path):
    """tetsmooth's coordinates (in the order of the file's nodes) and its
    pins, from a VTU it wrote."""
    mesh = meshio.read(path)
    fixed = mesh.point_data.get("tetsmooth:fixed")
    return mesh.points, set() if fixed is None else set(np.flatnonzero(fixed).tolist())


class AnsysCase(CliTestCase):
    SCRATCH_PREFIX = "tetsmooth_test_ansys_"

    @classmethod
    def setUpClass(cls):
        require_mapdl_archive()  # before the scratch folder, which an error would leave behind
        super().setUpClass()

    @classmethod
    def write(cls, name, lines, newline="\n"):
        with open(cls.path(name), "w", newline="") as f:
            f.write(newline.join(lines) + newline)
        return cls.path(name)

    def smoothed(self, src, *extra):
        """Smooths `src` to a .cdb and, in the same way, to a VTU, and checks
        that the .cdb is `src` but for the NBLOCK records of moved nodes,
        each rewritten as the format says from tetsmooth's result: its
        integers and the fields after Z as read, X, Y and Z as Fortran
        writes the VTU's doubles. Returns (records before, records after,
        numbers of the moved nodes, numbers of the nodes tetsmooth pinned)."""
        out, vtu = src[:-4] + "-out.cdb", src[:-4] + "-out.vtu"
        run("smooth", src, "-o", out, *SMOOTH_OPTIONS, *extra)
        run("smooth", src, "-o", vtu, *SMOOTH_OPTIONS, *extra)
        before, after = NodeRecords(src), NodeRecords(out)
        points, fixed = vtu_result(vtu)
        self.assertEqual(len(after.lines), len(before.lines))
        self.assertEqual(after.order, before.order)
        self.assertEqual(len(points), len(before.order))
        records = {i: n for n, i in before.line.items()}
        moved = set()
        for i, (a, b) in enumerate(zip(before.lines, after.lines)):
            if a == b:
                continue
            self.assertIn(i, records, f"line {i + 1} changed and is no NBLOCK record:\n{a!r}\n{b!r}")
            n = records[i]
            moved.add(n)
            ints_end, rw, decimals, exponent = before.layout[n]
            old, new = a.decode("latin-1"), b.decode("latin-1")
            self.assertEqual(new[:ints_end], old[:ints_end].ljust(ints_end), f"node {n}'s integers changed")
            expected = "".join(fortran_e(v, rw, decimals, exponent) for v in points[before.order.index(n)])
            self.assertEqual(new[ints_end:ints_end + 3 * rw], expected, f"node {n}'s coordinates")
            self.assertEqual(new[ints_end + 3 * rw:], old[ints_end + 3 * rw:], f"node {n}'s fields after Z")
        # The records that stayed hold tetsmooth's result too.
        still = [k for k, n in enumerate(before.order) if n not in moved]
        np.testing.assert_array_equal(before.coordinates(np.array(before.order)[still]), points[still])
        return before, after, moved, {before.order[k] for k in fixed}


# --- A deck ANSYS wrote --------------------------------------------------------------

class TetBeam(AnsysCase):
    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.src = mapdl_examples.tetarchivefile
        cls.archive = read_archive(cls.src)
        cls.nodes = cls.archive.nnum
        # mapdl-archive's element records: MAT, TYPE, REAL, SECNUM, ESYS,
        # birth/death, solid model reference, shape, element number, a 0 of
        # its own, then the nodes (it drops the node count and exclude key).
        cls.tets = np.searchsorted(cls.nodes, np.array([e[10:] for e in cls.archive.elem]))

    def test_the_example_is_what_this_file_expects(self):
        self.assertEqual(len(self.nodes), 1041)
        self.assertEqual(self.tets.shape, (3913, 4))
        self.assertEqual(set(self.archive.etype.tolist()), {187})
        self.assertTrue(np.all(signed_volume6(self.archive.nodes, self.tets) > 0))

    def test_smoothed_deck_changes_only_the_records_of_moved_interior_nodes(self):
        before, after, moved, pinned = self.smoothed(self.src)
        self.assertEqual(before.order, self.nodes.tolist())
        interior = set(self.nodes.tolist()) - set(self.nodes[list(boundary_nodes(self.tets))].tolist())
        self.assertGreater(len(moved), len(interior) // 3)
        self.assertLessEqual(moved, interior)
        self.assertEqual(pinned, set())
        # Its (3i8,6e20.13): rewritten with two exponent digits, not the e3
        # of new files (smoothed() checked the text against this layout).
        self.assertEqual({before.layout[n] for n in moved}, {(24, 20, 13, 2)})

    def test_mapdl_archive_reads_the_smoothed_deck(self):
        out = self.path("beam.cdb")
        vtu = self.path("beam.vtu")
        run("smooth", self.src, "-o", out, *SMOOTH_OPTIONS)
        run("smooth", self.src, "-o", vtu, *SMOOTH_OPTIONS)
        smoothed = read_archive(out)
        np.testing.assert_array_equal(smoothed.nnum, self.nodes)
        self.assertEqual(len(smoothed.elem), len(self.archive.elem))
        for a, b in zip(smoothed.elem, self.archive.elem):
            np.testing.assert_array_equal(a, b)
        np.testing.assert_array_equal(smoothed.ekey, self.archive.ekey)
        points, _ = vtu_result(vtu)
        np.testing.assert_allclose(smoothed.nodes, points, rtol=FORMAT_RTOL, atol=1e-300)
        self.assertGreater(np.abs(smoothed.nodes - self.archive.nodes).max(), 1e-3, "nothing moved")
        q_in = radius_ratio(self.archive.nodes, self.tets)
        q_out = radius_ratio(smoothed.nodes, self.tets)
        # The worst tet may lose a rounding of the 14 digits written.
        self.assertGreaterEqual(q_out.min(), q_in.min() - 1e-12)
        self.assertGreater(q_out.mean(), q_in.mean())
        self.assertTrue(np.all(signed_volume6(smoothed.nodes, self.tets) > 0))

    def test_convert_to_cdb_gives_the_deck_back(self):
        out = self.path("copy.cdb")
        run("convert", self.src, out, "-q")
        with open(self.src, "rb") as a, open(out, "rb") as b:
            self.assertEqual(b.read(), a.read())

    def test_example_decks_without_tets_are_refused(self):
        for name in ("HexBeam.cdb", "sector.cdb", "academic_rotor.cdb"):
            with self.subTest(deck=name):
                src = os.path.join(os.path.dirname(self.src), name)
                self.assertGreater(len(read_archive(src).elem), 0)
                out = self.path("never.cdb")
                proc = run("smooth", src, "-o", out, "--device", "cpu", check=False)
                self.assert_one_error_line(proc, EXIT_INPUT, src, "no tets")
                self.assertFalse(os.path.exists(out))


# --- Decks written here -----------------------------------------------------------------

class HandWrittenDecks(AnsysCase):
    SCRATCH_PREFIX = "tetsmooth_test_ansys_hand_"

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        xyz, cls.tets = kuhn_lattice(4, seed=7)
        cls.xyz = np.round(xyz, 6)  # a few digits, so that midpoints are exact in 14
        cls.numbers = node_numbers(len(xyz))
        inside = np.all((cls.xyz > 0) & (cls.xyz < 4), axis=1)
        cls.interior = set(cls.numbers[inside].tolist())
        cls.elements = [(1, 1, 11 + t, cls.numbers[row]) for t, row in enumerate(cls.tets)]
        # Which nodes move when nothing pins them: every pin below must hold
        # some of these, or the test could not tell a pin from a node that
        # stays anyway.
        free = cls.write("free.cdb", deck_lines(cls.numbers, cls.xyz, cls.elements))
        run("smooth", free, "-o", cls.path("free-out.cdb"), *SMOOTH_OPTIONS)
        before, after = NodeRecords(free), NodeRecords(cls.path("free-out.cdb"))
        cls.free = {n for n in before.order if before.lines[before.line[n]] != after.lines[after.line[n]]}

    def number_of(self, i, j, k):
        """The number of the lattice point (i, j, k)."""
        return int(self.numbers[(i * 5 + j) * 5 + k])

    def tets_where(self, axis, below):
        """Mask of the tets of the lattice cubes whose index along `axis` is
        below `below` (jitter keeps every centroid inside its cube's middle
        80%)."""
        return self.xyz[self.tets].mean(axis=1)[:, axis] < below

    def shared_nodes(self, mask):
        """Numbers of the nodes of tets in `mask` and of tets outside it."""
        rows = set(self.tets[mask].ravel().tolist()) & set(self.tets[~mask].ravel().tolist())
        return set(self.numbers[sorted(rows)].tolist())

    def test_free_lattice_moves_its_interior(self):
        self.assertEqual(len(self.interior), 27)
        _, _, moved, pinned = self.smoothed(self.path("free.cdb"))
        self.assertEqual(moved, self.free)
        self.assertLessEqual(self.free, self.interior)
        self.assertGreaterEqual(len(self.free), 20)
        self.assertEqual(pinned, set())

    def test_solid185_degenerate_tets(self):
        elements = [(1, 1, number, [n[0], n[1], n[2], n[2], n[3], n[3], n[3], n[3]])
                    for _, _, number, n in self.elements]
        src = self.write("solid185.cdb", deck_lines(self.numbers, self.xyz, elements, ets=("ET,1,185",)))
        read = quality_json(src)["input"]
        self.assertEqual((read["tets"], read["nodes_per_tet"]), (len(self.tets), 4))
        _, after, moved, _ = self.smoothed(src)
        self.assertEqual(moved, self.free)
        # The elements stay SOLID185 bricks with their repeated nodes.
        archive = read_archive(self.path("solid185-out.cdb"))
        self.assertEqual(set(archive.etype.tolist()), {185})
        self.assertEqual([e[10:].tolist() for e in archive.elem], [[int(x) for x in e[3]] for e in elements])
        np.testing.assert_allclose(archive.nodes, after.coordinates(archive.nnum), rtol=1e-15)

    def check_ten_node(self, name, ets, elements, xyz10, tets10, numbers10):
        src = self.write(name, deck_lines(numbers10, xyz10, elements, ets=ets))
        read = quality_json(src)["input"]
        self.assertEqual((read["tets"], read["nodes_per_tet"]), (len(tets10), 10))
        before, after, moved, _ = self.smoothed(src)
        corners = set(numbers10[:len(self.xyz)].tolist())
        self.assertLessEqual(moved & corners, self.interior)
        self.assertGreater(len(moved & corners), len(self.interior) // 2)
        self.assertTrue(moved - corners, "no midside node moved")
        for records in (before, after):
            xyz = records.coordinates(numbers10)
            ends = xyz[tets10[:, ANSYS_EDGES]]
            offset = xyz[tets10[:, 4:]] - 0.5 * (ends[:, :, 0] + ends[:, :, 1])
            self.assertLess(np.abs(offset).max(), 1e-12)
        archive = read_archive(src[:-4] + "-out.cdb")
        self.assertEqual([e[10:].tolist() for e in archive.elem], [[int(x) for x in e[3]] for e in elements])
        np.testing.assert_array_equal(archive.nnum, np.sort(numbers10))

    def test_solid187_ten_node_tets(self):
        xyz10, tets10 = with_midside_nodes(self.xyz, self.tets)
        numbers10 = node_numbers(len(xyz10))
        elements = [(1, 1, 11 + t, numbers10[row]) for t, row in enumerate(tets10)]
        self.check_ten_node("solid187.cdb", ("ET,1,SOLID187",), elements, xyz10, tets10, numbers10)

    def test_solid186_degenerate_twenty_node_tets(self):
        xyz10, tets10 = with_midside_nodes(self.xyz, self.tets)
        numbers10 = node_numbers(len(xyz10))
        elements = [(1, 1, 11 + t, numbers10[solid186_tet(row)]) for t, row in enumerate(tets10)]
        self.check_ten_node("solid186.cdb", ("ET,1,186",), elements, xyz10, tets10, numbers10)

    def test_two_materials_keep_their_interface(self):
        west = self.tets_where(0, 2)
        interface = self.shared_nodes(west) & self.interior
        self.assertEqual(len(interface), 9)
        self.assertTrue(interface & self.free)
        elements = [(1 if w else 2, 1, number, nodes) for w, (_, _, number, nodes) in zip(west, self.elements)]
        src = self.write("two-mats.cdb", deck_lines(self.numbers, self.xyz, elements))
        _, _, moved, pinned = self.smoothed(src)
        self.assertFalse(moved & interface, "a node of the interface between the MATs moved")
        self.assertTrue(moved)
        self.assertEqual(pinned, set())
        # The MATs are the regions: a VTU keeps them as its tags.
        run("convert", src, self.path("two-mats.vtu"), "-q")
        tags = meshio.read(self.path("two-mats.vtu")).cell_data["tetsmooth:tag"][0].ravel()
        np.testing.assert_array_equal(tags, np.where(west, 1, 2))

    def test_element_component_splitting_a_material(self):
        # One MAT, and an element component of the tets with y < 2 (given
        # as ranges of element numbers where they run on).
        south = self.tets_where(1, 2)
        items = as_ranges(e[2] for e, s in zip(self.elements, south) if s)
        self.assertTrue(any(i < 0 for i in items))
        more = cmblock_lines("SOUTH", "ELEM", items)
        src = self.write("split.cdb", deck_lines(self.numbers, self.xyz, self.elements, more=more))
        proc = run("smooth", src, "-o", self.path("split-note.cdb"), "--device", "cpu")
        self.assertIn("element components divide materials", proc.stderr)
        self.assertIn("2 regions", proc.stderr)
        _, _, moved, _ = self.smoothed(src)
        boundary = self.shared_nodes(south) & self.interior
        self.assertTrue(boundary & self.free)
        self.assertFalse(moved & boundary, "a node between the component and the rest of its MAT moved")
        self.assertTrue(moved)
        # The component names its region in an MSH file.
        run("convert", src, self.path("split.msh"), "-q")
        with open(self.path("split.msh")) as f:
            self.assertRegex(f.read(), r'\$PhysicalNames\n1\n3 \d+ "SOUTH"\n')

    def test_node_components_pin_exactly_their_nodes(self):
        # The nodes (1, 1..2, 0..4) are numbers 31 to 40, given as the range
        # "31 -40" (boundary nodes among them); (2, 2, 2) and (3, 2, 1),
        # numbered past the jump, alone.
        first, last = self.number_of(1, 1, 0), self.number_of(1, 2, 4)
        self.assertEqual((first, last), (31, 40))
        alone = [self.number_of(2, 2, 2), self.number_of(3, 2, 1)]
        expected = set(range(first, last + 1)) | set(alone)
        self.assertTrue(expected & self.free)
        more = cmblock_lines("HELD", "NODE", [first, -last]) + cmblock_lines("ALSO_HELD", "NODE", alone)
        # A component of keypoints is no node component.
        more += cmblock_lines("SOME_KP", "KP", [1, -200])
        src = self.write("ncomp.cdb", deck_lines(self.numbers, self.xyz, self.elements, more=more))
        _, _, moved, pinned = self.smoothed(src)
        self.assertEqual(pinned, expected)
        self.assertFalse(moved & expected)
        self.assertTrue(moved)
        # mapdl-archive reads the components as tetsmooth does.
        archive = read_archive(src)
        self.assertEqual(components(archive.node_components),
                         {"HELD": set(range(first, last + 1)), "ALSO_HELD": set(alone)})

    def test_d_and_f_pin_the_nodes_they_name(self):
        held = [self.number_of(1, 2, 3), self.number_of(2, 1, 1), self.number_of(3, 3, 2)]
        more = [f"D,{held[0]},UX,0.0", f"d,{held[1]} , all", f"F,{held[2]},FZ,-1.5  ! a load", "D,ALL,UY,0"]
        src = self.write("loads.cdb", deck_lines(self.numbers, self.xyz, self.elements, more=more))
        proc = run("smooth", src, "-o", self.path("loads-note.cdb"), "--device", "cpu")
        self.assertRegex(proc.stderr, r"D commands name nodes through APDL's selection")
        _, _, moved, pinned = self.smoothed(src)
        self.assertTrue(set(held) <= self.free)
        self.assertEqual(pinned, set(held), "D,ALL pins nothing: tetsmooth does not follow the selection")
        self.assertFalse(moved & set(held))
        self.assertTrue(moved)

    def test_d_and_f_node_ranges_pin_every_node_they_name(self):
        # D,NODE,Lab,VALUE,VALUE2,NEND,NINC and F likewise apply to NODE,
        # NODE + NINC, ..., NEND: here the interior nodes (1, 1..3, 1) and
        # (3, 1..3, 3), numbers 5 apart.
        d = [self.number_of(1, j, 1) for j in (1, 2, 3)]
        f = [self.number_of(3, j, 3) for j in (1, 2, 3)]
        self.assertEqual(np.diff(d + f).tolist(), [5, 5, f[0] - d[2], 5, 5])
        more = [f"D,{d[0]},UX,0,,{d[2]},5", f"F,{f[0]},FX,1.0,,{f[2]},5"]
        src = self.write("ranges.cdb", deck_lines(self.numbers, self.xyz, self.elements, more=more))
        self.assertTrue(set(d + f) & self.free)
        _, _, moved, pinned = self.smoothed(src)
        self.assertEqual(pinned, set(d + f))
        self.assertFalse(moved & set(d + f))

    def test_other_commands_pin_the_nodes_they_name(self):
        # BF, IC and M name one node; CP lists nodes from its fourth field on,
        # CE in its fourth, seventh and tenth.
        node = {name: self.number_of(*ijk) for name, ijk in
                (("bf", (1, 1, 1)), ("ic", (1, 3, 2)), ("m", (2, 1, 3)), ("cp1", (2, 2, 2)), ("cp2", (3, 1, 1)),
                 ("ce1", (3, 3, 3)), ("ce2", (1, 2, 2)))}
        more = [f"BF,{node['bf']},TEMP,20.0", f"IC,{node['ic']},UZ,0.01", f"M,{node['m']},UX",
                f"CP,1,UX,{node['cp1']},{node['cp2']}", f"CE,1,0.0,{node['ce1']},UY,1.0,{node['ce2']},UY,-1.0"]
        src = self.write("others.cdb", deck_lines(self.numbers, self.xyz, self.elements, more=more))
        self.assertTrue(set(node.values()) & self.free)
        _, _, moved, pinned = self.smoothed(src)
        self.assertEqual(pinned, set(node.values()))
        self.assertFalse(moved & pinned)
        self.assertTrue(moved)

    def test_surface_eblock_pins_its_nodes(self):
        # SURF154 elements in a non-solid EBLOCK ("EBLOCK,10,,,n", one line
        # a record: number, TYPE, REAL, MAT, SECNUM, nodes) on interior nodes.
        faces = [[self.number_of(1, 1, 1), self.number_of(2, 1, 1), self.number_of(2, 2, 1)],
                 [self.number_of(3, 3, 3), self.number_of(2, 3, 3), self.number_of(2, 3, 2), self.number_of(3, 2, 2)]]
        more = ["EBLOCK,10,,,2", "(15i9)"] + [int_fields([900 + k, 2, 1, 1, 0] + f) for k, f in enumerate(faces)]
        more += [int_fields([-1])]
        src = self.write("surf154.cdb", deck_lines(self.numbers, self.xyz, self.elements, more=more,
                                                   ets=("ET,1,285", "ET,2,SURF154")))
        expected = {n for f in faces for n in f}
        self.assertTrue(expected <= self.free)
        _, _, moved, pinned = self.smoothed(src)
        self.assertEqual(pinned, expected)
        self.assertFalse(moved & expected)
        self.assertTrue(moved)
        # mapdl-archive reads solid EBLOCKs only: it sees the tets.
        archive = read_archive(src[:-4] + "-out.cdb")
        self.assertEqual(len(archive.elem), len(self.elements))

    def test_shell_elements_pin_their_nodes(self):
        shell = [self.number_of(1, 3, 2), self.number_of(2, 3, 2), self.number_of(2, 3, 3), self.number_of(1, 3, 3)]
        elements = self.elements + [(3, 2, 5000, shell)]
        # (mapdl-archive reads ET's type as a number only: 181, not SHELL181.)
        src = self.write("shell181.cdb", deck_lines(self.numbers, self.xyz, elements, ets=("ET,1,285", "ET,2,181")))
        self.assertTrue(set(shell) & self.free)
        _, _, moved, pinned = self.smoothed(src)
        self.assertEqual(pinned, set(shell))
        self.assertFalse(moved & set(shell))
        self.assertTrue(moved)
        archive = read_archive(src[:-4] + "-out.cdb")
        self.assertEqual(archive.etype[-1], 181)
        self.assertEqual(archive.elem[-1][10:].tolist(), shell)

    def test_moved_records_keep_their_other_fields(self):
        # Node (2, 2, 2) with rotation angles, node (2, 2, 1) moved onto the
        # plane z = 1 and its Z left off the record (blank fields and
        # missing ones are 0: the lattice is shifted down by 1 here), and
        # solid model references in the integers of every record.
        xyz = self.xyz - [0, 0, 1]
        turned, flat = self.number_of(2, 2, 2), self.number_of(2, 2, 1)
        xyz[list(self.numbers).index(flat), 2] = 0.0
        records = {}
        for k, (n, p) in enumerate(zip(self.numbers, xyz)):
            ints = int_fields([n, 7 + k % 3, 1000 + k])
            if n == turned:
                records[n] = ints + "".join(fortran_e(v) for v in (*p, 30.0, -12.5, 0.0))
            elif n == flat:
                records[n] = ints + fortran_e(p[0]) + fortran_e(p[1])
            else:
                records[n] = ints + "".join(fortran_e(v) for v in p)
        src = self.write("fields.cdb", deck_lines(self.numbers, xyz, self.elements, record=records))
        before, after, moved, _ = self.smoothed(src)
        self.assertIn(turned, moved)
        self.assertIn(flat, moved)
        self.assertEqual(len(after.lines[after.line[flat]]), 9 * 3 + 3 * 21)
        np.testing.assert_array_equal(before.xyz[flat][2], 0.0)
        archive = read_archive(src[:-4] + "-out.cdb")
        k = list(archive.nnum).index(turned)
        np.testing.assert_array_equal(archive.node_angles[k], [30.0, -12.5, 0.0])
        np.testing.assert_allclose(archive.nodes, after.coordinates(archive.nnum), rtol=1e-15)

    def check_read_like_mapdl_archive(self, name, lines):
        """`lines`, which mapdl-archive reads as this lattice, smooth as the
        lattice does."""
        src = self.write(name, lines)
        archive = read_archive(src)
        np.testing.assert_array_equal(archive.nnum, self.numbers)
        # (mapdl-archive's reading of a real may be a unit in the last place
        # off.)
        np.testing.assert_allclose(archive.nodes, self.xyz, rtol=1e-15, atol=1e-300)
        self.assertEqual(set(archive.etype.tolist()), {285})
        self.assertEqual([e[10:].tolist() for e in archive.elem], [e[3].tolist() for e in self.elements])
        _, _, moved, _ = self.smoothed(src)
        self.assertEqual(moved, self.free)

    def test_nblock_closed_by_n_unbl(self):
        # Recent releases close an NBLOCK with "N,UNBL,LOC,-1" where older
        # ones wrote "N,R5.3,LOC,-1": a mark (node -1), not an N command.
        lines = deck_lines(self.numbers, self.xyz, self.elements)
        closing = lines.index("N,R5.3,LOC,       -1,")
        lines[closing] = "N,UNBL,LOC,       -1,"
        self.check_read_like_mapdl_archive("unbl.cdb", lines)

    def test_element_types_from_an_etblock(self):
        # Recent releases write the element types as an ETBLOCK (type number,
        # element number, then its 19 KEYOPTs) instead of ET lines.
        etblock = ["ETBLOCK,        1,        1", "(2i9,19a9)", int_fields([1, 285] + [0] * 19), int_fields([-1])]
        lines = deck_lines(self.numbers, self.xyz, self.elements, ets=etblock)
        self.check_read_like_mapdl_archive("etblock.cdb", lines)

    def test_crlf_deck_keeps_its_line_ends(self):
        lines = deck_lines(self.numbers, self.xyz, self.elements)
        lf, crlf = self.write("lf.cdb", lines), self.write("crlf.cdb", lines, newline="\r\n")
        _, _, moved, _ = self.smoothed(crlf)
        self.assertEqual(moved, self.free)
        run("smooth", lf, "-o", self.path("lf-out.cdb"), *SMOOTH_OPTIONS)
        with open(self.path("lf-out.cdb"), "rb") as a, open(self.path("crlf-out.cdb"), "rb") as b:
            lf_out, crlf_out = a.read(), b.read()
        self.assertEqual(crlf_out, lf_out.replace(b"\n", b"\r\n"))
        self.assertEqual(crlf_out.count(b"\n"), crlf_out.count(b"\r\n"))


# --- New decks ---------------------------------------------------------------------------

class NewDecks(GmshScratchCase):
    SCRATCH_PREFIX = "tetsmooth_test_ansys_new_"

    @classmethod
    def setUpClass(cls):
        require_mapdl_archive()
        super().setUpClass()
        gmsh = cls.gmsh
        cls.mesh = {}
        with gmsh_session(gmsh):
            # Two stacked volumes, named, and a named square embedded in the
            # lower one: its triangles are not written to a .cdb, and their
            # nodes are inside the mesh, so pinned.
            lower, upper = two_layers(gmsh)
            square = gmsh.model.occ.addRectangle(0.5, 0.5, 0.5, 1, 1)
            gmsh.model.occ.synchronize()
            gmsh.model.mesh.embed(2, [square], 3, lower)
            for dim, entity, tag, name in ((3, lower, 11, "Lower rock"), (3, upper, 12, "upper"),
                                           (2, square, 5, "fault plane")):
                gmsh.model.addPhysicalGroup(dim, [entity], tag)
                gmsh.model.setPhysicalName(dim, tag, name)
            gmsh.option.setNumber("Mesh.MeshSizeMax", 0.4)
            gmsh.model.mesh.generate(3)
            for order in (1, 2):
                gmsh.model.mesh.setOrder(order)
                gmsh.write(cls.path(f"order{order}.msh"))
                tags, coords, _ = gmsh.model.mesh.getNodes()
                tets = {}
                for volume, physical in ((lower, 11), (upper, 12)):
                    _, etags, enodes = gmsh.model.mesh.getElements(3, volume)
                    per = 4 if order == 1 else 10
                    rows = np.asarray(enodes[0]).reshape(-1, per)[:, GMSH_ANSYS_ORDER[:per]]
                    tets.update((int(t), (physical, r.tolist())) for t, r in zip(etags[0], rows))
                _, _, square_nodes = gmsh.model.mesh.getElements(2, square)
                cls.mesh[order] = (dict(zip(np.asarray(tags).tolist(), np.asarray(coords).reshape(-1, 3))), tets,
                                   set(np.asarray(square_nodes[0]).tolist()))

    def converted(self, order):
        out = self.path(f"order{order}.cdb")
        proc = run("convert", self.path(f"order{order}.msh"), out)
        self.assertIn("TETSMOOTH_PINNED", proc.stderr)  # the warning about the triangles left out
        return out, read_archive(out)

    def check_new_deck(self, order):
        xyz, tets, square = self.mesh[order]
        out, archive = self.converted(order)
        with open(out) as f:
            text = f.read()
        self.assertTrue(text.startswith("/COM,"))
        self.assertIn("\n/PREP7\n", text)
        self.assertTrue(text.endswith("\nFINISH\n"))
        self.assertIn("\n(3i9,6e21.13e3)\n", text)
        ansys_type = 285 if order == 1 else 187
        np.testing.assert_array_equal(archive.ekey, [[1, ansys_type]])
        self.assertEqual(sorted(archive.nnum.tolist()), sorted(xyz))
        np.testing.assert_allclose(archive.nodes, np.array([xyz[n] for n in archive.nnum.tolist()]),
                                   rtol=FORMAT_RTOL, atol=1e-300)
        read = {int(e[8]): (int(e[0]), e[10:].tolist()) for e in archive.elem}
        self.assertEqual(read, tets)
        self.assertEqual(set(archive.etype.tolist()), {ansys_type})
        self.assertEqual(set(archive.material_type.tolist()), {11, 12})
        self.assertEqual(components(archive.element_components),
                         {name: {t for t, (physical, _) in tets.items() if physical == tag}
                          for tag, name in ((11, "LOWER_ROCK"), (12, "UPPER"))})
        nodes = components(archive.node_components)
        self.assertEqual(nodes, {"TETSMOOTH_PINNED": square, "FAULT_PLANE": square})
        return archive

    def test_first_order_mesh_as_solid285(self):
        self.check_new_deck(1)

    def test_second_order_mesh_as_solid187(self):
        archive = self.check_new_deck(2)
        rows = np.searchsorted(archive.nnum, np.array([e[10:] for e in archive.elem]))
        self.assertEqual(rows.shape[1], 10)
        ends = archive.nodes[rows[:, ANSYS_EDGES]]
        # The box's edges are straight: each midside node is at its edge's
        # midpoint, up to Gmsh's and the format's roundings.
        offset = archive.nodes[rows[:, 4:]] - 0.5 * (ends[:, :, 0] + ends[:, :, 1])
        self.assertLess(np.abs(offset).max(), 1e-12)
        self.assertTrue(np.all(signed_volume6(archive.nodes, rows[:, :4]) > 0))

    def test_new_deck_back_to_msh_keeps_tags_and_names(self):
        gmsh = self.gmsh
        xyz, tets, _ = self.mesh[1]
        src, _ = self.converted(1)
        back = self.path("back.msh")
        run("convert", src, back, "-q")
        with gmsh_session(gmsh):
            gmsh.open(back)
            groups = {(dim, tag): gmsh.model.getPhysicalName(dim, tag) for dim, tag in gmsh.model.getPhysicalGroups()}
            self.assertEqual(groups, {(3, 11): "LOWER_ROCK", (3, 12): "UPPER"})
            found = {}
            for tag in (11, 12):
                for entity in gmsh.model.getEntitiesForPhysicalGroup(3, tag):
                    _, etags, enodes = gmsh.model.mesh.getElements(3, entity)
                    rows = np.asarray(enodes[0]).reshape(-1, 4).tolist()
                    found.update((int(t), (tag, r)) for t, r in zip(etags[0], rows))
            node_tags, coords, _ = gmsh.model.mesh.getNodes()
        self.assertEqual(found, tets)
        self.assertEqual(sorted(np.asarray(node_tags).tolist()), sorted(xyz))
        np.testing.assert_allclose(np.asarray(coords).reshape(-1, 3),
                                   np.array([xyz[n] for n in np.asarray(node_tags).tolist()]),
                                   rtol=FORMAT_RTOL, atol=1e-300)


# --- Refusals ----------------------------------------------------------------------------

class Refusals(RefusedDecks, AnsysCase):
    """Decks tetsmooth must refuse (RefusedDecks runs them): the lattice
    deck below, each case with one part of it spoilt."""

    SCRATCH_PREFIX = "tetsmooth_test_ansys_bad_"
    SUFFIX = ".cdb"

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        xyz, tets = kuhn_lattice(2, seed=2)
        cls.xyz = np.round(xyz, 6)
        cls.numbers = np.arange(len(xyz)) + 1
        cls.tets = tets
        cls.elements = [(1, 1, t + 1, cls.numbers[row]) for t, row in enumerate(tets)]
        cls.lines = deck_lines(cls.numbers, cls.xyz, cls.elements)
        cls.first_node = cls.lines.index("(3i9,6e21.13e3)") + 1  # index of the first NBLOCK record
        cls.first_element = cls.lines.index("(19i9)") + 1
        cls.finish = len(cls.lines) - 1

    def cases(self):
        """{name: (lines, 1-based line the message must name, fragments)}."""
        record = self.lines[self.first_node + 4]
        element = self.lines[self.first_element + 2]
        # A SOLID187 with its midside nodes, apart from the lattice, after
        # the lattice's 4-node SOLID285s.
        far = self.xyz + [10, 0, 0]
        ten_nodes = np.vstack([far[self.tets[0]], 0.5 * (far[self.tets[0][ANSYS_EDGES[:, 0]]] +
                                                         far[self.tets[0][ANSYS_EDGES[:, 1]]])])
        ten_numbers = np.arange(10) + 1001
        mixed = deck_lines(np.concatenate([self.numbers, ten_numbers]), np.vstack([self.xyz, ten_nodes]),
                           self.elements + [(1, 2, 999, ten_numbers)], ets=("ET,1,285", "ET,2,187"))
        return {
            "n-command": (self.edited(self.finish, ["N,500,1.0,2.0,3.0", "FINISH"]), self.finish + 1, ["N command"]),
            "e-command": (self.edited(self.finish, ["E,1,2,3,4", "FINISH"]), self.finish + 1, ["E command"]),
            "input": (self.edited(self.finish, ["/INPUT,more,cdb", "FINISH"]), self.finish + 1, ["another file"]),
            "bad-number": (self.edited(self.first_node + 4, [record[:6] + "x" + record[7:]]), self.first_node + 5,
                           ["node number"]),
            "bad-real": (self.edited(self.first_node + 4, [record[:40] + "1.2.3" + record[45:]]),
                         self.first_node + 5, ["real number"]),
            "node-twice": (self.edited(self.first_node + 6, [self.lines[self.first_node + 6], record]),
                           self.first_node + 8, ["node 5", "second time"]),
            "undefined-node": (self.edited(self.first_element + 2, [element[:-9] + "      777"]),
                               self.first_element + 3, ["node 777", "no NBLOCK"]),
            "no-et": (self.edited(self.first_element + 2, [element[:9] + "        4" + element[18:]]),
                      self.first_element + 3, ["type 4", "no ET"]),
            "mixed": (mixed, len(mixed) - 3, ["10-node tet after 4-node"]),
            "cut-nblock": (self.lines[:self.first_node + 3], self.first_node + 3, ["NBLOCK"]),
            # A count of 5 and three items.
            "short-cmblock": (self.edited(self.finish, ["CMBLOCK,FEW,NODE,       5", "(8i10)",
                                                        int_fields([1, 2, 3], 10), "FINISH"]),
                              self.finish + 3, ["FEW", "5"]),
            "eblock-reals": (self.edited(self.first_element - 1, ["(19i9,2e21.13)"]), self.first_element,
                             ["EBLOCK", "integers"]),
        }


if __name__ == "__main__":
    unittest.main()
