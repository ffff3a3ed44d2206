"""LS-DYNA keyword decks (.k, .key, .dyn) through tetsmooth, checked against
an independent reader of the format, lsdyna-mesh-reader 0.2.1 (PyPI, from
the PyAnsys project; Debian has none, so scripts/install_deps.sh puts it in
.deps/python and CTest puts that on PYTHONPATH), and against a parser of
this file's own (Fortran's rules: fixed columns, free format at commas).

lsdyna-mesh-reader reads only the standard layout, with solids on one card:
it hangs on free-format (comma) *NODE cards and on the long layout
("*KEYWORD LONG=Y", 20-column fields), and misreads the I10 layout and
two-card solids, so it is never given those (tests/test_io_lsdyna.cpp reads
and writes back the long layout), and it always runs in a child
process with a time limit (ReaderDeck). It also takes a coordinate that
starts with its point (".5", which Fortran reads) for garbage, and the
character after an exponent's letter for its sign ("1.35E2" reads as
1.35), so tetsmooth must write a digit before the point and a sign before
an exponent's digits.

What is checked, and why:
- New decks (a Gmsh mesh of two named volumes and a named embedded square,
  first and second order; `tetsmooth generate lattice-4`): lsdyna-mesh-reader
  reads the MSH node and element tags as NIDs and EIDs, the physical tags as
  PIDs, tets in LS-DYNA's form N1 N2 N3 N4 N4 N4 N4 N4 and the square's
  triangles as shells (N3 = N4) of its PID; *PART headings are the physical
  names; coordinates are the MSH file's to what 15 columns hold
  (WRITTEN_RTOL, WRITTEN_ATOL), in a model in millimetres too. 10-node tets, on two cards, which
  lsdyna-mesh-reader cannot read, are checked by this file's parser (the
  midside nodes in LS-DYNA's edge order, at their edges' midpoints) and by
  tetsmooth reading the deck back; the 6-node triangles that a new deck
  cannot hold have their nodes in the node set TETSMOOTH_PINNED.
- Smoothed decks (written here: a jittered Kuhn lattice with node ids that
  jump, other keywords around the mesh): the output is the input line for
  line and byte for byte but for the *NODE cards of moved nodes, which keep
  their NID and the columns after Z as read; a coordinate that did not
  change keeps its text. The coordinates written are tetsmooth's result
  (the same run written as VTU) to 15 columns, in as many characters on
  free-format cards. lsdyna-mesh-reader reads the smoothed deck with the
  same ids, parts, tets and coordinates, and `tetsmooth convert out.k
  out.vtu` (read with meshio) gives exactly the coordinates the deck's text
  holds.
- Pins: *SET_NODE_LIST, *SET_NODE_LIST_GENERATE, *SET_SEGMENT,
  *BOUNDARY_SPC_NODE, *LOAD_NODE_POINT, *INITIAL_VELOCITY_NODE,
  *DATABASE_HISTORY_NODE, *CONSTRAINED_EXTRA_NODES_NODE,
  *CONSTRAINED_SPOTWELD, TC and RC in *NODE (also written as reals),
  shells (with blank option cards too), beams (and their orientation node),
  mass and discrete elements each pin exactly their nodes (tetsmooth:fixed
  in VTU output) and the nodes they name stay put, where each of those
  nodes moves when nothing pins it. Keywords that name nodes and are not
  read (the _ID forms, other node sets) are named in a warning. *PART
  headings name the regions (also headings that start with '$' or '*' in a
  new deck), and two parts keep their interface.
- Layouts and forms: free-format *NODE cards, the I10 layout ("*NODE %",
  "*KEYWORD I10=Y", and both layouts in one deck), short cards, the tet
  forms and *ELEMENT_SOLID_ORTHO, 10-node tets on two cards, *INCLUDE
  (written inline; an included file's *END; "*INCLUDE %" and "*INCLUDE -"
  for a file in the other layout), left-handed tets (inverted, kept as
  written), lower-case keywords, comments inside *NODE, lines after *END,
  CRLF line ends; bricks, wedges and pyramids beside the tets pass through
  and pin their nodes; shells and beams reach other formats.
- The example decks of lsdyna-mesh-reader (EXP_SC_JOINT_SCREW.key,
  birdball.k) hold bricks and shells and no tets: tetsmooth refuses them
  with exit 3 and one line, and writes nothing. Their bricks cut into tets
  (the rest of each deck as it is) give real decks to smooth: birdball's
  *set_node_list_generate (free format), *INITIAL_VELOCITY_NODE and TC/RC
  pin its nodes.
- Refusals (standard cards under the long layout, LONG=S, *NODE_TRANSFORM,
  *INCLUDE_PATH, undefined and
  duplicate nodes, and more) exit 3 with one line naming file:line, write
  nothing and leave an existing output as it was. The help and the message
  for an unknown extension name the format.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import os
import re
import subprocess
import sys
import tempfile
import unittest

import meshio
import numpy as np

from test_cli import (EXIT_INPUT, EXIT_USAGE, CliTestCase, RefusedDecks, kuhn_lattice, quality_json, radius_ratio, run,
                      signed_volume6)
from test_independent_readers import GmshScratchCase, boundary_nodes, gmsh_session, two_layers

try:
    import lsdyna_mesh_reader  # noqa: F401 (read in a child process; imported here to find it and its examples)
    from lsdyna_mesh_reader import examples as dyna_examples
    READER_PATH = os.path.dirname(os.path.dirname(os.path.abspath(lsdyna_mesh_reader.__file__)))
    READER_ERROR = ""
except Exception as e:  # a compiled module can fail to import in more ways than ImportError
    dyna_examples = READER_PATH = None
    READER_ERROR = f"{type(e).__name__}: {e}"

# The midside nodes N5..N10 of LS-DYNA's 10-node tet, on these edges of
# N1..N4 (as VTK's).
DYNA_EDGES = np.array([[0, 1], [1, 2], [2, 0], [0, 3], [1, 3], [2, 3]])
# Gmsh's 10-node tet (type 11) has the last two midside nodes the other way
# round; this permutation is its own inverse.
GMSH_DYNA_ORDER = [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]
# A coordinate in 16 columns after a blank: 15 characters, which hold 14
# significant digits of a positive value and 13 of a negative one (whose
# sign takes a column: -1.484906305271 for -1.4849063052705296, 3.2e-13
# off). A zero before a leading point (lsdyna-mesh-reader needs it) leaves
# 14 columns for the rest: 12 decimals of a negative value below 1 in size
# (-0.123456789012).
WRITTEN_RTOL, WRITTEN_ATOL = 5e-12, 5e-13
# The same run each time: the serial one, which CTest's parallel jobs slow
# down least.
SMOOTH_OPTIONS = ("--device", "cpu", "--threads", "1", "-q")
READER_TIMEOUT = 60


def require_reader():
    """Fails (not skips: a skip would pass) without lsdyna-mesh-reader."""
    if dyna_examples is None:
        raise RuntimeError(f"cannot import lsdyna_mesh_reader ({READER_ERROR}): run scripts/install_deps.sh, which "
                           "installs lsdyna-mesh-reader 0.2.1 into .deps/python for /usr/bin/python3")


# --- lsdyna-mesh-reader, in a child process ---------------------------------------

READER_SCRIPT = r"""
import sys
import numpy as np
import lsdyna_mesh_reader
deck = lsdyna_mesh_reader.Deck(sys.argv[1])
out = {}
for k, s in enumerate(deck.node_sections):
    out[f"node{k}_nid"] = np.asarray(s.nid)
    out[f"node{k}_xyz"] = np.asarray(s.coordinates).reshape(-1, 3)
    out[f"node{k}_tc"] = np.asarray(s.tc)
    out[f"node{k}_rc"] = np.asarray(s.rc)
for kind in ("solid", "shell"):
    for k, s in enumerate(getattr(deck, f"element_{kind}_sections")):
        out[f"{kind}{k}_eid"] = np.asarray(s.eid)
        out[f"{kind}{k}_pid"] = np.asarray(s.pid)
        out[f"{kind}{k}_nodes"] = np.asarray(s.node_ids)
        out[f"{kind}{k}_offsets"] = np.asarray(s.node_id_offsets)
np.savez(sys.argv[2], **out)
"""


def reader_environment():
    """The environment for the child process: this process's, with the
    folder this process imported lsdyna_mesh_reader from first on
    PYTHONPATH."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (READER_PATH, env.get("PYTHONPATH")) if p)
    return env


class ReaderDeck:
    """lsdyna-mesh-reader's reading of a deck, its sections joined: `nid`,
    `xyz`, `tc`, `rc` (arrays in deck order), `solids` and `shells` ({EID:
    (PID, [node ids])}), `solid_sections` and `shell_sections` (counts)."""

    def __init__(self, path):
        with tempfile.TemporaryDirectory(prefix="tetsmooth_lsdyna_reader_") as tmp:
            self._read(path, os.path.join(tmp, "deck.npz"))

    def _read(self, path, npz):
        try:
            proc = subprocess.run([sys.executable, "-c", READER_SCRIPT, path, npz], capture_output=True, text=True,
                                  timeout=READER_TIMEOUT, env=reader_environment())
        except subprocess.TimeoutExpired:
            raise AssertionError(f"lsdyna-mesh-reader did not finish reading {path} in {READER_TIMEOUT} s")
        if proc.returncode != 0:
            raise AssertionError(f"lsdyna-mesh-reader failed on {path}:\n{proc.stderr}")
        with np.load(npz) as data:
            arrays = dict(data)
        sections = [f"node{k}" for k in range(sum(key.endswith("_nid") for key in arrays))]
        self.nid = np.concatenate([arrays[s + "_nid"] for s in sections]).astype(np.int64)
        self.xyz = np.concatenate([arrays[s + "_xyz"] for s in sections])
        self.tc = np.concatenate([arrays[s + "_tc"] for s in sections])
        self.rc = np.concatenate([arrays[s + "_rc"] for s in sections])
        for kind in ("solid", "shell"):
            elements, count = {}, 0
            while f"{kind}{count}_eid" in arrays:
                prefix = f"{kind}{count}_"
                offsets, nodes = arrays[prefix + "offsets"], arrays[prefix + "nodes"]
                for k, (eid, pid) in enumerate(zip(arrays[prefix + "eid"].tolist(), arrays[prefix + "pid"].tolist())):
                    elements[eid] = (pid, nodes[offsets[k]:offsets[k + 1]].tolist())
                count += 1
            setattr(self, kind + "s", elements)
            setattr(self, kind + "_sections", count)

    def coordinates(self, ids):
        where = {n: k for k, n in enumerate(self.nid.tolist())}
        return self.xyz[[where[n] for n in ids]]


# --- Reading decks here --------------------------------------------------------------

IMPLICIT_EXPONENT = re.compile(r"([+-]?(?:\d+\.?\d*|\.\d+))([+-]\d+)")


def fortran_real(text):
    """A real as Fortran reads it: "1.5", ".5", "1.5E-3", "1.5D-3", "1.5-3"
    (the exponent's letter left out); blank is 0."""
    text = text.strip().upper().replace("D", "E")
    if not text:
        return 0.0
    implicit = IMPLICIT_EXPONENT.fullmatch(text)
    return float(implicit.group(1) + "E" + implicit.group(2) if implicit else text)


def card_fields(line, widths):
    """The fields of a data card: split at commas (free format), else in
    the columns of `widths`; each without its blanks."""
    if "," in line:
        return [f.strip() for f in line.split(",")], True
    starts = np.cumsum([0] + list(widths))
    return [line[a:b].strip() for a, b in zip(starts, starts[1:])], False


def file_lines(path):
    """The file's lines as text ('\\r' kept where the file has it)."""
    with open(path, newline="") as f:
        lines = f.read().split("\n")
    return lines[:-1] if lines and lines[-1] == "" else lines


NODE_WIDTHS = {"standard": (8, 16, 16, 16, 8, 8), "i10": (10, 16, 16, 16, 10, 10)}


class KeywordDeck:
    """A deck parsed here. `lines`; for each node (by NID): `line` (index
    into lines), `layout` ("standard", "i10" or "free"), `xyz` and `tc`,
    `rc`; `order` (NIDs as listed); `solids`, `shells`, `beams` ({EID: (PID,
    [nodes])}, solids on one card or two); `parts` ({PID: heading}); `sets`
    ({title or id: [node ids]}) of *SET_NODE_LIST(_TITLE)."""

    def __init__(self, path):
        self.lines = file_lines(path)
        self.line, self.layout, self.xyz, self.tc, self.rc = {}, {}, {}, {}, {}
        self.order = []
        self.solids, self.shells, self.beams, self.parts, self.sets = {}, {}, {}, {}, {}
        keyword, deck_i10, pending, part_card, set_name, set_cards = None, False, None, 0, None, 0
        for i, raw in enumerate(self.lines):
            line = raw.rstrip("\r")
            if line.startswith("$"):
                continue
            if line.startswith("*"):
                words = line[1:].split() or [""]
                keyword = words[0].upper().rstrip("%+-")
                # The layout: a mark after the name ("*NODE %", "*NODE%"), else the deck's.
                mark = words[0][-1] if words[0][-1:] in ("%", "+", "-") else words[1] if len(words) > 1 and \
                    words[1] in ("%", "+", "-") else None
                i10 = mark == "%" or (mark is None and deck_i10)
                if keyword == "KEYWORD" and "I10=Y" in line.upper():
                    deck_i10 = i10 = True
                if keyword == "END":
                    break
                widths = (10 if i10 else 8,) * 10
                layout = "i10" if i10 else "standard"
                pending, part_card, set_cards = None, 0, 0
                continue
            if keyword is None or (not line.strip() and keyword != "PART"):  # a blank heading is a heading
                continue
            if keyword == "NODE":
                fields, free = card_fields(line, NODE_WIDTHS[layout])
                fields += [""] * 6
                nid = int(fields[0])
                self.line[nid] = i
                self.layout[nid] = "free" if free else layout
                self.xyz[nid] = np.array([fortran_real(f) for f in fields[1:4]])
                self.tc[nid], self.rc[nid] = (int(fortran_real(f)) for f in fields[4:6])
                self.order.append(nid)
            elif keyword == "ELEMENT_SOLID":
                fields = card_fields(line, widths)[0] + [""] * 10
                if pending is not None:
                    self.solids[pending[0]] = (pending[1], [int(f) for f in fields[:10] if f and int(f)])
                    pending = None
                elif not any(fields[2:10]):
                    pending = (int(fields[0]), int(fields[1]))
                else:
                    self.solids[int(fields[0])] = (int(fields[1]), [int(f or 0) for f in fields[2:10]])
            elif keyword in ("ELEMENT_SHELL", "ELEMENT_BEAM"):
                fields = card_fields(line, widths)[0] + [""] * 10
                count = 4 if keyword == "ELEMENT_SHELL" else 3
                target = self.shells if keyword == "ELEMENT_SHELL" else self.beams
                target[int(fields[0])] = (int(fields[1]), [int(f or 0) for f in fields[2:2 + count]])
            elif keyword == "PART":
                if part_card == 0:
                    heading = line.strip()
                else:
                    self.parts[int(card_fields(line, (10,) * 8)[0][0])] = heading
                part_card = 1 - part_card
            elif keyword in ("SET_NODE_LIST", "SET_NODE_LIST_TITLE"):
                if keyword.endswith("TITLE") and set_cards == 0:
                    set_name = line.strip()
                elif set_cards == (1 if keyword.endswith("TITLE") else 0):
                    sid = card_fields(line, (10,) * 8)[0][0]
                    set_name = set_name if keyword.endswith("TITLE") else sid
                    self.sets[set_name] = []
                else:
                    self.sets[set_name] += [int(f) for f in card_fields(line, (10,) * 8)[0] if f and int(f)]
                set_cards += 1

    def coordinates(self, ids):
        return np.array([self.xyz[n] for n in ids])


def positions(order, ids):
    """The positions in `order` (node ids) of the ids in `ids` (any
    shape)."""
    where = {int(n): k for k, n in enumerate(order)}
    return np.vectorize(where.__getitem__, otypes=[int])(np.asarray(ids))


def vtu_result(path):
    """tetsmooth's coordinates (in the order of the file's nodes), tets (as
    rows), tags and pins (node positions), from a VTU it wrote."""
    mesh = meshio.read(path)
    fixed = mesh.point_data.get("tetsmooth:fixed")
    tets = [(block.type, block.data) for block in mesh.cells if block.type.startswith("tetra")]
    tags = np.concatenate([np.asarray(t).ravel() for b, t in zip(mesh.cells, mesh.cell_data["tetsmooth:tag"])
                           if b.type.startswith("tetra")]) if "tetsmooth:tag" in mesh.cell_data else None
    return (mesh.points, np.concatenate([t for _, t in tets]), tags,
            set() if fixed is None else set(np.flatnonzero(np.asarray(fixed).ravel()).tolist()))


# --- Writing decks ------------------------------------------------------------------

def node_card(nid, p, tc=None, rc=None, layout="standard"):
    """A *NODE card: fixed columns (coordinates as pre-processors print them,
    with a leading 0) or free format."""
    if layout == "free":
        fields = [str(nid)] + [repr(float(v)) for v in p] + ([str(tc or 0), str(rc or 0)] if tc or rc else [])
        return ",".join(fields)
    w = 10 if layout == "i10" else 8
    card = f"{nid:{w}d}" + "".join(f"{v:16.8f}" for v in p)
    if tc is not None or rc is not None:
        card += f"{tc or 0:{w}d}{rc or 0:{w}d}"
    return card


def solid_card(eid, pid, nodes, width=8):
    """An *ELEMENT_SOLID card of a tet in LS-DYNA's form (N4 repeated), or
    of 8 nodes as given."""
    nodes = list(nodes)
    if len(nodes) == 4:
        nodes += [nodes[3]] * 4
    return "".join(f"{int(v):{width}d}" for v in [eid, pid] + nodes)


def two_card_solid(eid, pid, nodes, width=8):
    """A 10-node tet: EID PID alone, then N1..N10."""
    return [f"{eid:{width}d}{pid:{width}d}", "".join(f"{int(v):{width}d}" for v in nodes)]


def ints_card(values, width=10):
    return "".join(f"{int(v):{width}d}" for v in values)


def set_node_list(sid, nodes, title=None):
    """*SET_NODE_LIST(_TITLE): 8 nodes a card."""
    lines = ["*SET_NODE_LIST" + ("_TITLE" if title else "")] + ([title] if title else [])
    lines += ["$#     sid       da1       da2       da3       da4    solver", ints_card([sid])]
    return lines + [ints_card(nodes[k:k + 8]) for k in range(0, len(nodes), 8)]


def with_midside_nodes(xyz, tets):
    """The 4-node tets with a node at the midpoint of each edge: the
    coordinates and 10-node tets in LS-DYNA's order."""
    points, rows, made = list(xyz), [], {}
    for tet in tets.tolist():
        row = list(tet)
        for a, b in DYNA_EDGES:
            edge = (min(tet[a], tet[b]), max(tet[a], tet[b]))
            if edge not in made:
                made[edge] = len(points)
                points.append(0.5 * (xyz[tet[a]] + xyz[tet[b]]))
            row.append(made[edge])
        rows.append(row)
    return np.array(points), np.array(rows)


def node_ids(count, first=1, jump_after=60, jump=1000):
    """Ids for `count` nodes: first, first + 1, ... with a jump after the
    60th, as a deck whose parts were meshed apart has."""
    k = np.arange(count)
    return k + first + jump * (k >= jump_after)


# Keywords around the mesh that tetsmooth keeps and does not read.
HEAD = ["$ written by test_lsdyna.py", "*KEYWORD", "*TITLE", "lattice for tetsmooth",
        "*CONTROL_TERMINATION", "$#  endtim    endcyc     dtmin    endeng    endmas",
        "       1.0         0       0.0       0.0       0.0",
        "*MAT_ELASTIC", "$#     mid        ro         e        pr", "         1    7.8E-9  210000.0       0.3",
        "*SECTION_SOLID", "         1        10", "*DEFINE_CURVE", "         1", "0.0,0.0", "1.0,1.0"]


# The faces of an LS-DYNA brick (N1..N8), each as a cycle.
BRICK_FACES = [[0, 1, 2, 3], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def bricks_cut_into_tets(path):
    """The deck at `path` with each brick of its *ELEMENT_SOLID cards (one
    card, 8 distinct nodes) cut into 6 right-handed tets in LS-DYNA's form,
    numbered 1, 2, ... with the brick's PID; every other line as it is. The
    cut is conforming: each quad face is split by the diagonal through its
    smallest node id, and the faces away from the brick's smallest node are
    joined to it. Returns (lines, {EID: (PID, [N1..N4])})."""
    deck = KeywordDeck(path)
    lines = [line.rstrip("\r") for line in deck.lines]
    ids = np.array(sorted(deck.order))
    xyz = deck.coordinates(ids)
    tets, out, eid, in_solids = {}, [], 0, False
    for line in lines:
        if line.startswith("*"):
            in_solids = line.split()[0].upper() == "*ELEMENT_SOLID"
            out.append(line)
            continue
        if not in_solids or line.startswith("$") or not line.strip():
            out.append(line)
            continue
        fields = card_fields(line, (8,) * 10)[0]
        pid, n = int(fields[1]), [int(f) for f in fields[2:10]]
        assert len(set(n)) == 8, f"not a brick: {line!r}"
        v0 = min(range(8), key=lambda k: n[k])
        for face in BRICK_FACES:
            if v0 in face:
                continue
            k = min(range(4), key=lambda i: n[face[i]])
            q = face[k:] + face[:k]
            for tri in ([q[0], q[1], q[2]], [q[0], q[2], q[3]]):
                tet = [n[v0]] + [n[i] for i in tri]
                if signed_volume6(xyz, np.searchsorted(ids, [tet]))[0] < 0:
                    tet = [tet[0], tet[2], tet[1], tet[3]]
                eid += 1
                tets[eid] = (pid, tet)
                out.append(solid_card(eid, pid, tet))
    return out, tets


# --- Checks ----------------------------------------------------------------------------

FIXED_REAL = re.compile(r"[+-]?(\d*)\.(\d*)(?:[ED]([+-]?\d+))?", re.IGNORECASE)


class DeckChecks:
    """Checks of decks that tetsmooth wrote, for a test case with a scratch
    folder (path())."""

    @classmethod
    def write(cls, name, lines, newline="\n"):
        with open(cls.path(name), "w", newline="") as f:
            f.write(newline.join(lines) + newline)
        return cls.path(name)

    def assert_rounded(self, field, value, what):
        """`field`, 16 columns of a fixed-format card, holds `value` with a
        blank before it, correctly rounded to the digits it shows and within
        what 15 columns hold, with a digit before its point and a sign
        before an exponent's digits (readers written in C,
        lsdyna-mesh-reader among them, take ".5" for garbage)."""
        self.assertEqual(len(field), 16, f"{what}: {field!r}")
        self.assertEqual(field[0], " ", f"{what}: {field!r} has no blank before it")
        text = field.strip()
        self.assertRegex(text, r"^[+-]?\d", f"{what}: {field!r} has no digit before its point")
        # (They also take the character after an exponent's letter for its
        # sign: "1.35E2" reads as 1.35.)
        self.assertNotRegex(text, r"[EeDd]\d", f"{what}: {field!r} has an exponent without its sign")
        m = FIXED_REAL.fullmatch(text)
        self.assertIsNotNone(m, f"{what}: {field!r} is not a real with a point")
        unit = 10.0 ** (int(m.group(3) or 0) - len(m.group(2)))
        read = fortran_real(text)
        self.assertLessEqual(abs(read - value), 0.5 * unit + 2 * np.spacing(abs(value)),
                             f"{what}: {field!r} is not {value!r} rounded")
        self.assertTrue(np.isclose(read, value, rtol=WRITTEN_RTOL, atol=WRITTEN_ATOL),
                        f"{what}: {field!r} holds fewer digits of {value!r} than 15 columns can")

    def smoothed(self, src, *extra):
        """Smooths `src` to a deck and, in the same way, to a VTU, converts
        the deck to a VTU, and checks that the deck is `src` but for the
        *NODE cards of moved nodes (line ends become '\\n'): each keeps its
        NID and the columns after Z (fields after Z in free format) as
        read, keeps the text of a coordinate that did not change, and has
        tetsmooth's result (the VTU's) rounded to 16 columns (15 characters in
        free format); the converted VTU has exactly the deck's values.
        Returns (deck before, deck after, NIDs of moved nodes, NIDs of the
        nodes tetsmooth pinned)."""
        stem = os.path.splitext(src)[0]
        out = stem + "-out" + os.path.splitext(src)[1]
        vtu, back = stem + "-out.vtu", stem + "-back.vtu"
        run("smooth", src, "-o", out, *SMOOTH_OPTIONS, *extra)
        run("smooth", src, "-o", vtu, *SMOOTH_OPTIONS, *extra)
        run("convert", out, back, "-q")
        before, after = KeywordDeck(src), KeywordDeck(out)
        points, _, _, fixed = vtu_result(vtu)
        with open(out, "rb") as f:
            self.assertNotIn(b"\r", f.read(), "a line end other than '\\n' in the output")
        old_lines = [line.rstrip("\r") for line in before.lines]
        self.assertEqual(len(after.lines), len(old_lines))
        self.assertEqual(after.order, before.order)
        self.assertEqual(len(points), len(before.order))
        nid_of_line = {i: n for n, i in before.line.items()}
        position = {n: k for k, n in enumerate(before.order)}
        moved = set()
        for i, (old, new) in enumerate(zip(old_lines, after.lines)):
            if old == new:
                continue
            self.assertIn(i, nid_of_line, f"line {i + 1} changed and is no *NODE card:\n{old!r}\n{new!r}")
            n = nid_of_line[i]
            moved.add(n)
            result = points[position[n]]
            self.assertFalse(np.array_equal(before.xyz[n], result), f"node {n} did not move, and its card changed")
            if before.layout[n] == "free":
                a, b = card_fields(old, ())[0], card_fields(new, ())[0]
                self.assertEqual(len(b), max(len(a), 4), f"node {n}: {new!r}")
                self.assertEqual(b[0], a[0], f"node {n}'s NID changed")
                self.assertEqual(b[4:], a[4:], f"node {n}'s fields after Z changed")
                for c in range(3):
                    if fortran_real(a[1 + c]) == result[c]:
                        self.assertEqual(b[1 + c], a[1 + c], f"node {n}: an unchanged coordinate's text changed")
                    else:
                        # As many characters as a fixed field holds.
                        self.assertLessEqual(len(b[1 + c]), 15, f"node {n}: {b[1 + c]!r}")
                        self.assert_rounded(b[1 + c].rjust(16), result[c], f"node {n}, coordinate {c + 1}")
                continue
            w = NODE_WIDTHS[before.layout[n]][0]
            self.assertEqual(new[:w], old[:w].ljust(w), f"node {n}'s NID columns changed")
            self.assertEqual(new[w + 48:], old[w + 48:], f"node {n}'s columns after Z changed")
            for c in range(3):
                a, b = old[w + 16 * c:w + 16 * (c + 1)], new[w + 16 * c:w + 16 * (c + 1)]
                if fortran_real(a) == result[c]:
                    self.assertEqual(b.strip(), a.strip(), f"node {n}: an unchanged coordinate's text changed")
                else:
                    self.assert_rounded(b, result[c], f"node {n}, coordinate {c + 1}")
        # The cards that stayed hold tetsmooth's result exactly.
        still = [k for k, n in enumerate(before.order) if n not in moved]
        np.testing.assert_array_equal(points[still], before.coordinates(np.array(before.order)[still]))
        # tetsmooth reads back exactly what the output deck says.
        np.testing.assert_array_equal(meshio.read(back).points, after.coordinates(after.order))
        return before, after, moved, {before.order[k] for k in fixed}

    def assert_reader_reads_the_smoothed_deck(self, src, out):
        """lsdyna-mesh-reader reads `out` with the ids, parts and elements
        it reads in `src`, and the coordinates that tetsmooth reads in `out`
        (up to its own rounding)."""
        a, b = ReaderDeck(src), ReaderDeck(out)
        np.testing.assert_array_equal(b.nid, a.nid)
        self.assertEqual(b.solids, a.solids)
        self.assertEqual(b.shells, a.shells)
        np.testing.assert_array_equal(b.tc, a.tc)
        np.testing.assert_array_equal(b.rc, a.rc)
        read = os.path.splitext(out)[0] + "-read.vtu"
        run("convert", out, read, "-q")
        self.assert_reader_coordinates(out, b, meshio.read(read).points, 1e-14, 1e-14)
        return a, b

    def assert_reader_coordinates(self, path, reader, expected, rtol, atol):
        """lsdyna-mesh-reader's coordinates (`reader`, a ReaderDeck of
        `path`) are `expected` (in reader.nid's order); a failure names the
        cards it misread."""
        bad = ~np.isclose(reader.xyz, expected, rtol=rtol, atol=atol)
        if bad.any():
            deck = KeywordDeck(path)
            rows = np.flatnonzero(bad.any(axis=1))
            shown = "\n".join(f"  node {reader.nid[r]}: read {reader.xyz[r].tolist()}, expected "
                              f"{expected[r].tolist()}, card {deck.lines[deck.line[int(reader.nid[r])]]!r}"
                              for r in rows[:5])
            self.fail(f"lsdyna-mesh-reader misreads {bad.sum()} coordinates of {len(rows)} nodes of {path}:\n{shown}")


# --- New decks ------------------------------------------------------------------------

class NewDecks(DeckChecks, GmshScratchCase):
    SCRATCH_PREFIX = "tetsmooth_test_lsdyna_new_"
    NAMES = {11: "Lower rock", 12: "upper", 5: "fault plane"}

    @classmethod
    def setUpClass(cls):
        require_reader()  # before the scratch folder, which an error would leave behind
        super().setUpClass()
        gmsh = cls.gmsh
        cls.mesh = {}
        with gmsh_session(gmsh):
            # Two stacked volumes and a square embedded in the lower one, all
            # named: the square's triangles inside the mesh become shells.
            lower, upper = two_layers(gmsh)
            square = gmsh.model.occ.addRectangle(0.5, 0.5, 0.5, 1, 1)
            gmsh.model.occ.synchronize()
            gmsh.model.mesh.embed(2, [square], 3, lower)
            for dim, entity, tag in ((3, lower, 11), (3, upper, 12), (2, square, 5)):
                gmsh.model.addPhysicalGroup(dim, [entity], tag)
                gmsh.model.setPhysicalName(dim, tag, cls.NAMES[tag])
            gmsh.option.setNumber("Mesh.MeshSizeMax", 0.4)
            gmsh.model.mesh.generate(3)
            for order, per in ((1, 4), (2, 10)):
                gmsh.model.mesh.setOrder(order)
                gmsh.write(cls.path(f"order{order}.msh"))
                tags, coords, _ = gmsh.model.mesh.getNodes()
                tets = {}
                for volume, physical in ((lower, 11), (upper, 12)):
                    _, etags, enodes = gmsh.model.mesh.getElements(3, volume)
                    rows = np.asarray(enodes[0]).reshape(-1, per)[:, GMSH_DYNA_ORDER[:per]]
                    tets.update((int(t), (physical, r.tolist())) for t, r in zip(etags[0], rows))
                _, etags, enodes = gmsh.model.mesh.getElements(2, square)
                rows = np.asarray(enodes[0]).reshape(len(etags[0]), -1)
                triangles = {int(t): r.tolist() for t, r in zip(etags[0], rows)}
                cls.mesh[order] = (dict(zip(np.asarray(tags).tolist(), np.asarray(coords).reshape(-1, 3))), tets,
                                   triangles)
        run("generate", "lattice-4", "-o", cls.path("lattice.msh"), "-q")

    def converted(self, order):
        out = self.path(f"order{order}.k")
        if not os.path.exists(out):
            run("convert", self.path(f"order{order}.msh"), out, "-q")
        return out

    def test_lsdyna_mesh_reader_reads_the_ids_parts_and_elements(self):
        xyz, tets, triangles = self.mesh[1]
        out = self.converted(1)
        deck = ReaderDeck(out)
        self.assertEqual(deck.nid.tolist(), list(xyz))  # Gmsh's node tags, in its order
        self.assertEqual(deck.solids, {eid: (pid, nodes + [nodes[3]] * 4) for eid, (pid, nodes) in tets.items()})
        self.assertEqual(deck.shells, {eid: (5, nodes + [nodes[2]]) for eid, nodes in triangles.items()})
        self.assertEqual((deck.solid_sections, deck.shell_sections), (1, 1))
        np.testing.assert_array_equal(deck.tc, 0)
        np.testing.assert_array_equal(deck.rc, 0)
        rows = positions(list(xyz), [nodes for _, nodes in tets.values()])
        self.assertTrue(np.all(signed_volume6(np.array(list(xyz.values())), rows) > 0))
        # The parts: the physical names as headings; the triangles, written
        # as shells, pin their own nodes, so no node set is needed.
        parsed = KeywordDeck(out)
        self.assertEqual(parsed.parts, self.NAMES)
        self.assertEqual(parsed.sets, {})
        self.assertTrue(parsed.lines[0].startswith("$"))
        self.assertEqual(parsed.lines[1], "*KEYWORD")
        self.assertEqual(parsed.lines[-1], "*END")

    def test_coordinates_hold_what_15_columns_can(self):
        xyz, _, _ = self.mesh[1]
        deck = KeywordDeck(self.converted(1))
        self.assertEqual(deck.order, list(xyz))
        for n, p in xyz.items():
            line = deck.lines[deck.line[n]]
            self.assertEqual(len(line), 8 + 48, line)
            self.assertEqual(int(line[:8]), n)
            for c in range(3):
                self.assert_rounded(line[8 + 16 * c:24 + 16 * c], p[c], f"node {n}")

    def test_lsdyna_mesh_reader_reads_the_coordinates(self):
        xyz, _, _ = self.mesh[1]
        out = self.converted(1)
        deck = ReaderDeck(out)
        self.assert_reader_coordinates(out, deck, np.array([xyz[n] for n in deck.nid.tolist()]),
                                       WRITTEN_RTOL, WRITTEN_ATOL)

    def test_lsdyna_mesh_reader_reads_coordinates_in_millimetres(self):
        # A model in millimetres: Gmsh puts nodes at 99.99999999999999 or
        # 100.00000000000001, which 15 columns round to 100.
        gmsh = self.gmsh
        src, out = self.path("millimetres.msh"), self.path("millimetres.k")
        with gmsh_session(gmsh):
            lower = gmsh.model.occ.addBox(0, 0, 0, 200, 200, 100)
            upper = gmsh.model.occ.addBox(0, 0, 100, 200, 200, 100)
            gmsh.model.occ.fragment([(3, lower)], [(3, upper)])
            gmsh.model.occ.synchronize()
            gmsh.option.setNumber("Mesh.MeshSizeMax", 40)
            gmsh.model.mesh.generate(3)
            gmsh.write(src)
            tags, coords, _ = gmsh.model.mesh.getNodes()
        xyz = dict(zip(np.asarray(tags).tolist(), np.asarray(coords).reshape(-1, 3)))
        run("convert", src, out, "-q")
        deck = ReaderDeck(out)
        self.assertEqual(deck.nid.tolist(), list(xyz))
        self.assert_reader_coordinates(out, deck, np.array(list(xyz.values())), WRITTEN_RTOL, WRITTEN_ATOL)

    def test_generated_lattice(self):
        src, out = self.path("lattice.msh"), self.path("lattice.k")
        run("convert", src, out, "-q")
        mesh = meshio.read(src)
        deck = ReaderDeck(out)
        self.assertEqual(deck.nid.tolist(), list(range(1, 126)))
        self.assertEqual(sorted(deck.solids), list(range(1, 385)))
        self.assertEqual({pid for pid, _ in deck.solids.values()}, {1})
        self.assertEqual([nodes for _, nodes in deck.solids.values()],
                         [t + [t[3]] * 4 for t in (mesh.cells_dict["tetra"] + 1).tolist()])
        self.assertEqual(KeywordDeck(out).parts, {1: ""})
        np.testing.assert_allclose(KeywordDeck(out).coordinates(range(1, 126)), mesh.points,
                                   rtol=WRITTEN_RTOL, atol=WRITTEN_ATOL)
        # The format by name, and the other extensions.
        for name, extra in (("lattice.dat", ("--output-format", "k")), ("lattice.data", ("--output-format", "lsdyna")),
                            ("lattice.key", ()), ("lattice.dyn", ()), ("lattice.K", ())):
            with self.subTest(output=name):
                run("convert", src, self.path(name), "-q", *extra)
                with open(out, "rb") as a, open(self.path(name), "rb") as b:
                    self.assertEqual(b.read(), a.read())
        run("convert", self.path("lattice.dat"), self.path("lattice-back.vtu"), "--format", "lsdyna", "-q")
        np.testing.assert_array_equal(meshio.read(self.path("lattice-back.vtu")).cells_dict["tetra"],
                                      mesh.cells_dict["tetra"])

    def test_ten_node_tets_on_two_cards(self):
        xyz, tets, triangles = self.mesh[2]
        out = self.path("order2.k")
        proc = run("convert", self.path("order2.msh"), out)
        self.assertIn("TETSMOOTH_PINNED", proc.stderr)  # the warning about the 6-node triangles left out
        deck = KeywordDeck(out)
        # Each solid: EID PID, then N1..N10 on a card of their own.
        self.assertEqual(deck.solids, tets)
        first = deck.lines.index("*ELEMENT_SOLID") + 1
        self.assertRegex(deck.lines[first], r"^ {0,7}\d+ {0,7}\d+$")
        self.assertRegex(deck.lines[first + 1], r"^( {0,7}\d+){10}$")
        self.assertEqual(deck.shells, {})
        square = {n for nodes in triangles.values() for n in nodes}
        self.assertEqual(deck.sets, {"TETSMOOTH_PINNED": sorted(square)})
        self.assertEqual(deck.parts, {11: "Lower rock", 12: "upper"})
        ids = np.array(deck.order)
        self.assertEqual(deck.order, list(xyz))
        np.testing.assert_allclose(deck.coordinates(ids), np.array(list(xyz.values())),
                                   rtol=WRITTEN_RTOL, atol=WRITTEN_ATOL)
        # The midside nodes are on LS-DYNA's edges: at their midpoints (the
        # box's edges are straight), up to Gmsh's and the format's roundings.
        rows = positions(ids, [nodes for _, nodes in tets.values()])
        points = deck.coordinates(ids)
        ends = points[rows[:, DYNA_EDGES]]
        self.assertLess(np.abs(points[rows[:, 4:]] - 0.5 * (ends[:, :, 0] + ends[:, :, 1])).max(), 1e-12)
        # tetsmooth reads the deck back: 10-node tets, the parts, the pins.
        back = self.path("order2-back.vtu")
        run("convert", out, back, "-q")
        points, read, tags, fixed = vtu_result(back)
        np.testing.assert_array_equal(read, rows)
        np.testing.assert_array_equal(tags, [pid for pid, _ in tets.values()])
        np.testing.assert_array_equal(points, deck.coordinates(ids))
        self.assertEqual({deck.order[k] for k in fixed}, square)
        self.assertEqual(quality_json(out)["input"]["nodes_per_tet"], 10)

    def test_new_deck_back_to_msh_keeps_tags_and_names(self):
        gmsh = self.gmsh
        xyz, tets, triangles = self.mesh[1]
        back = self.path("back.msh")
        run("convert", self.converted(1), back, "-q")
        with gmsh_session(gmsh):
            gmsh.open(back)
            groups = {(dim, tag): gmsh.model.getPhysicalName(dim, tag) for dim, tag in gmsh.model.getPhysicalGroups()}
            found = {}
            for tag in (11, 12):
                for entity in gmsh.model.getEntitiesForPhysicalGroup(3, tag):
                    _, etags, enodes = gmsh.model.mesh.getElements(3, entity)
                    rows = np.asarray(enodes[0]).reshape(-1, 4).tolist()
                    found.update((int(t), (tag, r)) for t, r in zip(etags[0], rows))
            node_tags, coords, _ = gmsh.model.mesh.getNodes()
        self.assertEqual(groups, {(3, 11): "Lower rock", (3, 12): "upper", (2, 5): "fault plane"})
        self.assertEqual(found, tets)
        self.assertEqual(sorted(np.asarray(node_tags).tolist()), sorted(xyz))
        np.testing.assert_allclose(np.asarray(coords).reshape(-1, 3), [xyz[n] for n in np.asarray(node_tags).tolist()],
                                   rtol=WRITTEN_RTOL, atol=WRITTEN_ATOL)

    def test_smoothing_a_new_deck(self):
        xyz, tets, triangles = self.mesh[1]
        src = self.converted(1)
        before, after, moved, pinned = self.smoothed(src)
        square = {n for nodes in triangles.values() for n in nodes}
        self.assertEqual(pinned, square)
        rows = np.array([nodes for _, nodes in tets.values()])
        pids = np.array([pid for pid, _ in tets.values()])
        ids = np.array(before.order)
        interface = set(rows[pids == 11].ravel().tolist()) & set(rows[pids == 12].ravel().tolist())
        boundary = set(ids[list(boundary_nodes(positions(ids, rows)))].tolist())
        self.assertTrue(square - boundary, "the square has no nodes inside the mesh")
        self.assertTrue(moved)
        self.assertFalse(moved & (square | interface | boundary), "a pinned, interface or boundary node moved")
        self.assert_reader_reads_the_smoothed_deck(src, self.path("order1-out.k"))
        q_in = radius_ratio(before.coordinates(ids), positions(ids, rows))
        q_out = radius_ratio(after.coordinates(ids), positions(ids, rows))
        self.assertGreaterEqual(q_out.min(), q_in.min() - 1e-12)
        self.assertGreater(q_out.mean(), q_in.mean())


# --- Decks written here ------------------------------------------------------------------

class DeckCase(DeckChecks, CliTestCase):
    @classmethod
    def setUpClass(cls):
        require_reader()  # before the scratch folder, which an error would leave behind
        super().setUpClass()


class HandWrittenDecks(DeckCase):
    SCRATCH_PREFIX = "tetsmooth_test_lsdyna_hand_"

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        xyz, cls.tets = kuhn_lattice(4, seed=7)
        cls.xyz = np.round(xyz, 6)  # so that midpoints are exact in the 8 decimals node_card writes
        cls.ids = node_ids(len(xyz))
        inside = np.all((cls.xyz > 0) & (cls.xyz < 4), axis=1)
        cls.interior = set(cls.ids[inside].tolist())
        # Which nodes move when nothing pins them: every pin below must hold
        # some of these, or the test could not tell a pin from a node that
        # stays anyway.
        free = cls.write("free.k", cls.deck_lines())
        run("smooth", free, "-o", cls.path("free-out.k"), *SMOOTH_OPTIONS)
        before, after = KeywordDeck(free), KeywordDeck(cls.path("free-out.k"))
        cls.free = {n for n in before.order if before.lines[before.line[n]] != after.lines[after.line[n]]}

    @classmethod
    def deck_lines(cls, more=(), constraints=None, layout="standard", tets=None, pids=None, parts=None,
                   node_comment=False, ids=None, xyz=None):
        """The lattice (or `xyz`) as a deck: HEAD, *PART cards (`parts`,
        {PID: heading}), *NODE (NIDs `ids`, `constraints`, {NID: (TC,
        RC)}), *ELEMENT_SOLID (`tets`, the card lines, else the lattice's
        tets in LS-DYNA's form with `pids`), `more`, *END. The I10 layout
        marks its keywords with '%'."""
        constraints = constraints or {}
        ids = cls.ids if ids is None else ids
        xyz = cls.xyz if xyz is None else xyz
        i10 = layout == "i10"
        mark = " %" if i10 else ""
        parts = parts or {1: "lattice"}
        lines = list(HEAD)
        for pid, heading in parts.items():
            lines += ["*PART", "$# title", heading, "$#     pid     secid       mid", ints_card([pid, 1, 1])]
        lines += ["*NODE" + mark, "$#   nid               x               y               z      tc      rc"]
        for k, (n, p) in enumerate(zip(ids, xyz)):
            if node_comment and k == len(ids) // 2:
                lines += ["$ the second half of the nodes", ""]
            lines.append(node_card(n, p, *constraints.get(int(n), (None, None)), layout=layout))
        if tets is None:
            pids = np.ones(len(cls.tets), dtype=int) if pids is None else pids
            tets = [solid_card(11 + t, pid, ids[row], 10 if i10 else 8)
                    for t, (row, pid) in enumerate(zip(cls.tets, pids))]
        return lines + ["*ELEMENT_SOLID" + mark] + list(tets) + list(more) + ["*END"]

    def number_of(self, i, j, k):
        """The NID of the lattice point (i, j, k)."""
        return int(self.ids[(i * 5 + j) * 5 + k])

    def test_free_lattice_moves_its_interior(self):
        self.assertEqual(len(self.interior), 27)
        before, after, moved, pinned = self.smoothed(self.path("free.k"))
        self.assertEqual(moved, self.free)
        self.assertLessEqual(self.free, self.interior)
        self.assertGreaterEqual(len(self.free), 20)
        self.assertEqual(pinned, set())
        q_in = radius_ratio(before.coordinates(self.ids), self.tets)
        q_out = radius_ratio(after.coordinates(self.ids), self.tets)
        self.assertGreaterEqual(q_out.min(), q_in.min() - 1e-12)
        self.assertGreater(q_out.mean(), q_in.mean())

    def test_lsdyna_mesh_reader_reads_the_smoothed_deck(self):
        src = self.path("free.k")
        self.smoothed(src)
        a, _ = self.assert_reader_reads_the_smoothed_deck(src, self.path("free-out.k"))
        # Its reading of the input is the lattice.
        np.testing.assert_array_equal(a.nid, self.ids)
        np.testing.assert_allclose(a.xyz, self.xyz, rtol=1e-15, atol=0)  # its own rounding
        self.assertEqual(a.solids, {11 + t: (1, self.ids[row].tolist() + [int(self.ids[row[3]])] * 4)
                                    for t, row in enumerate(self.tets)})

    def test_convert_to_a_deck_gives_the_deck_back(self):
        src, out = self.path("free.k"), self.path("copy.k")
        run("convert", src, out, "-q")
        with open(src, "rb") as a, open(out, "rb") as b:
            self.assertEqual(b.read(), a.read())

    def pin_cases(self):
        """{name: (lines after the solids, {NID: (TC, RC)}, the NIDs they
        pin)}: each names nodes inside the lattice, some of which move when
        nothing pins them."""
        n = self.number_of
        a, b, c, d = n(1, 1, 1), n(2, 2, 2), n(3, 2, 1), n(1, 3, 2)
        ranges = [(n(1, 2, 1), n(1, 2, 3)), (56, 1065)]  # the second one spans the jump in the ids
        in_ranges = {int(i) for i in self.ids for first, last in ranges if first <= i <= last}
        shell_part = ["*PART", "membrane", ints_card([2, 2, 1])]
        return {
            "set_node_list": (set_node_list(7, [a, b, c]), {}, {a, b, c}),
            "set_node_list_title": (set_node_list(8, [d, c], title="held nodes"), {}, {c, d}),
            "set_node": (["*SET_NODE", ints_card([9]), ints_card([b])], {}, {b}),
            "set_node_list_generate": (["*SET_NODE_LIST_GENERATE", ints_card([3]), ints_card(np.ravel(ranges))],
                                       {}, in_ranges),
            "set_segment": (["*SET_SEGMENT", ints_card([4]), ints_card([a, b, c, c])], {}, {a, b, c}),
            "boundary_spc_node": (["*BOUNDARY_SPC_NODE", "$#     nid       cid      dofx      dofy      dofz",
                                   ints_card([b, 0, 1, 1, 1, 0, 0, 0])], {}, {b}),
            "boundary_prescribed_motion_node": (["*BOUNDARY_PRESCRIBED_MOTION_NODE", ints_card([c, 3, 2, 1])], {},
                                                {c}),
            "load_node_point": (["*LOAD_NODE_POINT", ints_card([a, 3, 1]) + "      -1.0"], {}, {a}),
            "initial_velocity_node": (["*INITIAL_VELOCITY_NODE", f"{d:10d}       0.0       0.0    -100.0"], {}, {d}),
            "database_history_node": (["*DATABASE_HISTORY_NODE", ints_card([a, d])], {}, {a, d}),
            "constrained_extra_nodes_node": (["*CONSTRAINED_EXTRA_NODES_NODE", ints_card([1, b])], {}, {b}),
            "constrained_spotweld": (["*CONSTRAINED_SPOTWELD", ints_card([a, c])], {}, {a, c}),
            "tc": ([], {b: (7, 0)}, {b}),
            "rc": ([], {c: (0, 7)}, {c}),
            "shells": (shell_part + ["*ELEMENT_SHELL", solid_card(1, 2, [a, b, c, c])[:48],
                                     solid_card(2, 2, [a, b, d, n(2, 3, 3)])[:48]], {}, {a, b, c, d, n(2, 3, 3)}),
            "shell_thickness": (shell_part + ["*ELEMENT_SHELL_THICKNESS", solid_card(1, 2, [a, b, c, c])[:48],
                                              "            0.01            0.01            0.01            0.01"],
                                {}, {a, b, c}),
            "beam": (["*PART", "rod", ints_card([3, 3, 1]), "*ELEMENT_BEAM", ints_card([1, 3, a, b, d], 8)], {},
                     {a, b, d}),
            "element_mass": (["*ELEMENT_MASS", f"{1:8d}{c:8d}{2.5:16.4f}"], {}, {c}),
            "element_discrete": (["*ELEMENT_DISCRETE", ints_card([1, 4, a, d], 8)], {}, {a, d}),
            # Blank cards are cards of defaults: a blank title, blank
            # thicknesses (and a blank line where an element's first card
            # would come, which is skipped).
            "set_node_list_blank_title": (["*SET_NODE_LIST_TITLE", "", ints_card([8]), ints_card([d, c])], {},
                                          {c, d}),
            "shell_thickness_blank": (shell_part + ["*ELEMENT_SHELL_THICKNESS", solid_card(1, 2, [a, b, c, c])[:48],
                                                    "", "", solid_card(2, 2, [a, b, d, d])[:48], ""], {},
                                      {a, b, c, d}),
        }

    def test_pins_hold_exactly_their_nodes(self):
        for name, (more, constraints, expected) in self.pin_cases().items():
            with self.subTest(pin=name):
                self.assertTrue(expected & self.free, "the test pins no node that would move")
                src = self.write(f"pin-{name}.k", self.deck_lines(more, constraints))
                _, _, moved, pinned = self.smoothed(src)
                self.assertEqual(pinned, expected)
                self.assertFalse(moved & expected, "a pinned node moved")
                self.assertTrue(moved)

    def test_lsdyna_mesh_reader_reads_shells_and_constraints(self):
        more, constraints, _ = self.pin_cases()["shells"]
        src = self.write("reader-shells.k", self.deck_lines(more, {self.number_of(2, 2, 2): (7, 3)}))
        self.smoothed(src)
        _, deck = self.assert_reader_reads_the_smoothed_deck(src, self.path("reader-shells-out.k"))
        self.assertEqual(set(deck.shells), {1, 2})
        k = self.ids.tolist().index(self.number_of(2, 2, 2))
        self.assertEqual((deck.tc[k], deck.rc[k]), (7, 3))

    def test_keywords_not_read_are_noted(self):
        # *CONSTRAINED_LINEAR_GLOBAL names nodes that tetsmooth does not pin.
        node = self.number_of(2, 2, 2)
        more = ["*CONSTRAINED_LINEAR_GLOBAL", ints_card([1]), ints_card([node, 1]) + "       1.0"]
        src = self.write("unread.k", self.deck_lines(more))
        proc = run("quality", src)
        self.assertIn("CONSTRAINED_LINEAR_GLOBAL keywords are not read", proc.stderr)
        self.assertIn("*SET_NODE_LIST", proc.stderr)
        _, _, moved, pinned = self.smoothed(src)
        self.assertEqual(pinned, set())
        self.assertIn(node, moved)

    def test_keyword_id_variants_are_noted(self):
        # The _ID forms (an id card first) are not read: their nodes may
        # move, and a warning says so.
        node = self.number_of(2, 2, 2)
        more = ["*BOUNDARY_SPC_NODE_ID", ints_card([1]) + "held", ints_card([node, 0, 1, 1, 1, 0, 0, 0])]
        src = self.write("spc-id.k", self.deck_lines(more))
        self.assertIn("BOUNDARY_SPC_NODE_ID keywords are not read", run("quality", src).stderr)

    def test_other_node_sets_are_pinned_or_noted(self):
        # Node sets of other forms: *SET_NODE_GENERAL (its NODE option names
        # nodes) and *SET_NODE_LIST_GENERATE_INCREMENT (ranges with a step).
        # The README pins "every node set"; a set tetsmooth does not read
        # must at least be named in a warning, as the keywords that name
        # nodes are, not be dropped in silence while its nodes move.
        a, b = self.number_of(1, 1, 1), self.number_of(2, 2, 2)
        cases = {
            "SET_NODE_GENERAL": ["*SET_NODE_GENERAL", ints_card([5]), "NODE      " + ints_card([a, b])],
            "SET_NODE_LIST_GENERATE_INCREMENT": ["*SET_NODE_LIST_GENERATE_INCREMENT", ints_card([6]),
                                                 ints_card([a, a, 1, b, b, 1])],
        }
        for keyword, more in cases.items():
            with self.subTest(keyword=keyword):
                self.assertTrue({a, b} <= self.free)
                src = self.write(f"{keyword.lower()}.k", self.deck_lines(more))
                proc = run("quality", src)  # its warnings
                _, _, moved, pinned = self.smoothed(src)
                if pinned != {a, b}:
                    self.assertIn(f"{keyword} keywords are not read", proc.stderr,
                                  f"*{keyword} is dropped without a word, and nodes {sorted(moved & {a, b})} "
                                  "that it names move")

    def test_parts_name_regions_and_keep_their_interface(self):
        west = self.xyz[self.tets].mean(axis=1)[:, 0] < 2
        pids = np.where(west, 3, 5)
        interface = set(self.ids[self.tets[west]].ravel().tolist()) & set(self.ids[self.tets[~west]].ravel().tolist())
        self.assertTrue(interface & self.free)
        # One *PART of two parts (one of them unused), and a *PART_CONTACT,
        # whose heading and PID are read as a plain part's.
        parts = {3: "Rock mass", 9: "unused"}
        more = ["*PART_CONTACT", "grout", ints_card([5, 1, 1]), "       0.1       0.1"]
        src = self.write("parts.k", self.deck_lines(more, parts=parts, pids=pids))
        _, _, moved, pinned = self.smoothed(src)
        self.assertFalse(moved & interface, "a node between two parts moved")
        self.assertTrue(moved)
        self.assertEqual(pinned, set())
        _, _, tags, _ = vtu_result(self.path("parts-out.vtu"))
        np.testing.assert_array_equal(tags, pids)
        self.assertEqual({pid for pid, _ in ReaderDeck(self.path("parts-out.k")).solids.values()}, {3, 5})
        run("convert", src, self.path("parts.msh"), "-q")
        with open(self.path("parts.msh")) as f:
            self.assertIn('$PhysicalNames\n2\n3 3 "Rock mass"\n3 5 "grout"\n$EndPhysicalNames\n', f.read())

    def test_short_cards_and_real_constraints(self):
        # Node (2, 2, 1) on the plane z = 1, and the lattice shifted down by
        # 1: its card leaves Z off (blank is 0), and a moved card gets all
        # three coordinates. TC and RC written as reals ("7.") pin.
        xyz = self.xyz - [0, 0, 1]
        flat, held = self.number_of(2, 2, 1), self.number_of(2, 1, 2)
        k = self.ids.tolist().index(flat)
        xyz[k, 2] = 0.0
        lines = self.deck_lines(xyz=xyz)
        lines[lines.index(node_card(flat, xyz[k]))] = node_card(flat, xyz[k])[:8 + 32]
        card = node_card(held, xyz[self.ids.tolist().index(held)])
        lines[lines.index(card)] = card + "      7." + "      0."
        src = self.write("short.k", lines)
        before, after, moved, pinned = self.smoothed(src)
        self.assertIn(flat, moved)
        self.assertEqual(pinned, {held})
        self.assertNotIn(held, moved)
        self.assertEqual(len(after.lines[after.line[flat]]), 8 + 48)
        self.assertEqual(before.xyz[flat][2], 0.0)

    def test_shells_and_beams_reach_other_formats(self):
        # Triangles, quads and beams pass through to MSH: no warning may say
        # that shells are left out when none is.
        more = self.pin_cases()["shells"][0] + self.pin_cases()["beam"][0]
        src = self.write("shells.k", self.deck_lines(more))
        out = self.path("shells.msh")
        proc = run("convert", src, out)
        cells = {block.type: len(block.data) for block in meshio.read(out).cells}
        self.assertEqual(cells, {"tetra": len(self.tets), "triangle": 1, "quad": 1, "line": 1})
        left_out = [line for line in proc.stderr.splitlines() if "will not be written" in line and "ELEMENT_" in line]
        self.assertEqual(left_out, [], "a warning says elements are left out that are written")

    def test_free_format_nodes(self):
        # Free-format *NODE cards, some with TC and RC, and a boundary
        # node's blank X (0).
        constraints = {self.number_of(0, 0, 0): (1, 0), self.number_of(4, 4, 4): (0, 1)}
        lines = self.deck_lines(layout="free", constraints=constraints)
        first = lines.index(node_card(self.ids[1], self.xyz[1], layout="free"))
        self.assertEqual(lines[first], f"{self.ids[1]},0.0,0.0,1.0")
        lines[first] = f"{self.ids[1]},,0.0,1.0"
        src = self.write("free-format.k", lines)
        before, _, moved, pinned = self.smoothed(src)
        self.assertEqual(before.layout[int(self.ids[1])], "free")
        self.assertEqual(moved, self.free)
        self.assertEqual(pinned, set(constraints))

    def test_i10_layout(self):
        # Ids of 10 digits, past 2,147,483,647, in the I10 layout: marked
        # "*NODE %", or set for the deck by "*KEYWORD I10=Y"; and a deck of
        # both layouts, whose first nodes are in the standard one ("*NODE -"
        # where the deck is I10).
        big = node_ids(len(self.ids), first=3_000_000_001)
        mixed_ids = np.where(np.arange(len(self.ids)) < 50, self.ids, big)
        held = self.ids.tolist().index(self.number_of(2, 2, 2))
        decks = {}
        for name, ids in (("i10-marked.k", big), ("i10-keyword.k", big), ("i10-mixed.k", mixed_ids)):
            constraints = {int(ids[held]): (7, 0)}
            lines = self.deck_lines(layout="i10", constraints=constraints, ids=ids)
            if name != "i10-marked.k":
                lines = [line.replace(" %", "") for line in lines]
                lines[lines.index("*KEYWORD")] = "*KEYWORD I10=Y"
            if name == "i10-mixed.k":
                first = lines.index("*NODE") + 2
                standard = [node_card(n, p, *constraints.get(int(n), (None, None))) for n, p in
                            zip(ids[:50], self.xyz[:50])]
                lines[first:first + 50] = ["*NODE -", *standard, "*NODE"]
            decks[name] = (lines, ids)
        for name, (lines, ids) in decks.items():
            with self.subTest(deck=name):
                src = self.write(name, lines)
                before, _, moved, pinned = self.smoothed(src)
                self.assertEqual(set(before.layout.values()), {"i10"} if name != "i10-mixed.k" else {"i10", "standard"})
                free = {int(ids[k]) for k, n in enumerate(self.ids.tolist()) if n in self.free}
                pinned_here = {int(ids[held])}
                self.assertEqual(pinned, pinned_here)
                self.assertEqual(moved, free - pinned_here)
                self.assertEqual(quality_json(src)["input"]["tets"], len(self.tets))

    def test_tet_forms(self):
        # N1 N2 N3 N4 N4 N4 N4 N4, N1 N2 N3 N3 N4 N4 N4 N4, and N1..N4 with
        # N5..N8 0 or blank: all tets; and *ELEMENT_SOLID_ORTHO, whose two
        # cards of directions after each element are no elements.
        cards, ortho = [], []
        for t, row in enumerate(self.tets):
            n = self.ids[row].tolist()
            form = [n + [n[3]] * 4, n[:3] + [n[2]] + [n[3]] * 4, n + [0] * 4, n][t % 4]
            cards.append(ints_card([11 + t, 1] + form, 8))
            ortho += [cards[-1], "       1.0       0.0       0.0", "       0.0       1.0       0.0"]
        forms = self.write("forms.k", self.deck_lines(tets=cards))
        lines = self.deck_lines(tets=ortho)
        lines[lines.index("*ELEMENT_SOLID")] = "*ELEMENT_SOLID_ORTHO"
        for src in (forms, self.write("ortho.k", lines)):
            with self.subTest(deck=os.path.basename(src)):
                _, _, moved, _ = self.smoothed(src)
                self.assertEqual(moved, self.free)
                _, read, _, _ = vtu_result(src[:-2] + "-out.vtu")
                np.testing.assert_array_equal(read, self.tets)

    def test_ten_node_tets_on_two_cards(self):
        xyz10, tets10 = with_midside_nodes(self.xyz, self.tets)
        ids10 = node_ids(len(xyz10))
        cards = [card for t, row in enumerate(tets10) for card in two_card_solid(11 + t, 1, ids10[row])]
        src = self.write("tet10.k", self.deck_lines(tets=cards, ids=ids10, xyz=xyz10))
        self.assertEqual(quality_json(src)["input"]["nodes_per_tet"], 10)
        before, after, moved, _ = self.smoothed(src)
        corners = set(ids10[:len(self.xyz)].tolist())
        self.assertLessEqual(moved & corners, self.interior)
        self.assertGreater(len(moved & corners), len(self.interior) // 2)
        self.assertTrue(moved - corners, "no midside node moved")
        for deck in (before, after):
            points = deck.coordinates(ids10)
            ends = points[tets10[:, DYNA_EDGES]]
            self.assertLess(np.abs(points[tets10[:, 4:]] - 0.5 * (ends[:, :, 0] + ends[:, :, 1])).max(), 1e-12)
        _, read, _, _ = vtu_result(self.path("tet10-out.vtu"))
        np.testing.assert_array_equal(read, tets10)

    def include_decks(self, end_included=False):
        """The lattice with its nodes in two files in a folder beside the
        deck, both named by relative paths under one *INCLUDE (the first
        file headed by *KEYWORD, as pre-processors write them, the second
        ended by *END where `end_included`); and the same deck with the
        files' lines in place of the *INCLUDE, the included *KEYWORD as a
        comment (as tetsmooth writes it inline: LS-DYNA takes an included
        file's layout from its *INCLUDE, not from its *KEYWORD). Returns
        (deck, flat deck)."""
        tag = "-end" if end_included else ""
        lines = self.deck_lines()
        start, end = lines.index("*NODE"), lines.index("*ELEMENT_SOLID")
        half = start + 2 + len(self.ids) // 2
        first = ["*KEYWORD", "$ the lattice's first nodes", *lines[start:half]]
        second = ["*NODE", *lines[half:end]] + (["*END"] if end_included else [])
        os.makedirs(self.path("parts"), exist_ok=True)
        self.write(os.path.join("parts", f"first{tag}.k"), first)
        self.write(os.path.join("parts", f"second{tag}.k"), second)
        src = self.write(f"main{tag}.k", lines[:start] + ["*INCLUDE", f"parts/first{tag}.k",
                                                          f"parts/second{tag}.k"] + lines[end:])
        flat = self.write(f"flat{tag}.k", lines[:start] + ["$" + first[0]] + first[1:] + second + lines[end:])
        return src, flat

    def test_include(self):
        # The output holds the included files' lines in place of the
        # *INCLUDE, their moved nodes rewritten; the files stay as they
        # were.
        src, flat = self.include_decks()
        with open(self.path(os.path.join("parts", "first.k"))) as f:
            included = f.read()
        out = self.path("main-out.k")
        proc = run("convert", src, self.path("main-copy.k"))
        self.assertIn("parts/first.k", proc.stderr)
        self.assertIn("written inline", proc.stderr)
        run("smooth", src, "-o", out, *SMOOTH_OPTIONS)
        _, _, moved, _ = self.smoothed(flat)
        self.assertEqual(moved, self.free)
        with open(out, "rb") as a, open(self.path("flat-out.k"), "rb") as b:
            self.assertEqual(a.read(), b.read())
        with open(self.path(os.path.join("parts", "first.k"))) as f:
            self.assertEqual(f.read(), included)

    def test_include_ending_with_end(self):
        # An included file may end with *END, which ends that file alone.
        # Written inline, the *END must not end the output deck before the
        # lines after the *INCLUDE: tetsmooth (as LS-DYNA) must read the
        # output as the deck it came from.
        src, flat = self.include_decks(end_included=True)
        out = self.path("main-end-out.k")
        run("smooth", src, "-o", out, *SMOOTH_OPTIONS)
        self.assertEqual(quality_json(src)["input"]["tets"], len(self.tets))
        proc = run("quality", out, "--json", check=False)
        self.assertEqual(proc.returncode, 0, f"tetsmooth cannot read the deck it wrote: {proc.stderr}")
        self.assertEqual(quality_json(out)["input"]["tets"], len(self.tets))
        deck = KeywordDeck(out)  # which, as LS-DYNA, reads nothing after the first *END
        self.assertEqual(len(deck.solids), len(self.tets), "the output's first *END comes before its solids")

    def test_include_of_a_file_in_the_other_layout(self):
        # LS-DYNA reads an included file in the layout of the deck that
        # includes it, unless a mark on the *INCLUDE says otherwise: "*INCLUDE
        # %" for a file in I10, "*INCLUDE -" for one in the standard layout
        # under "*KEYWORD I10=Y" (the layout options on an included file's
        # own *KEYWORD line are Oasys PRIMER's, which writes them with the
        # mark). The layout of the included file stays in that file, and
        # the smoothed deck, written inline, reads back as the same mesh.
        os.makedirs(self.path("parts"), exist_ok=True)
        cards = [node_card(n, p, layout="i10") for n, p in zip(self.ids, self.xyz)]
        self.write(os.path.join("parts", "i10.k"), ["*NODE", *cards])
        self.write(os.path.join("parts", "i10-keyword.k"), ["*KEYWORD I10=Y", "*NODE", *cards, "*END"])
        # (Fields that fill their 16 columns, as LS-PrePost's do, so that a
        # card read in the wrong layout cannot read right.)
        full = [f"{n:8d}" + "".join(f"{v:16.9E}" for v in p) for n, p in zip(self.ids, self.xyz)]
        self.write(os.path.join("parts", "standard.k"), ["*NODE", *full])
        lines = self.deck_lines()
        start, end = lines.index("*NODE"), lines.index("*ELEMENT_SOLID")
        wide = [line.replace(" %", "") for line in self.deck_lines(layout="i10")]
        wide[wide.index("*KEYWORD")] = "*KEYWORD I10=Y"
        decks = {
            "include-i10.k": lines[:start] + ["*INCLUDE %", "parts/i10.k"] + lines[end:],
            "include-i10-keyword.k": lines[:start] + ["*INCLUDE %", "parts/i10-keyword.k"] + lines[end:],
            "include-standard.k": wide[:start] + ["*INCLUDE -", "parts/standard.k"] + wide[end:],
        }
        run("smooth", self.path("free.k"), "-o", self.path("layouts-free.vtu"), *SMOOTH_OPTIONS)
        expected = meshio.read(self.path("layouts-free.vtu")).points
        for name, deck in decks.items():
            with self.subTest(deck=name):
                src, out = self.write(name, deck), self.path(name[:-2] + "-out.k")
                proc = run("quality", src, "--json", check=False)
                self.assertEqual(proc.returncode, 0, proc.stderr)
                self.assertEqual(quality_json(src)["input"]["tets"], len(self.tets))
                run("smooth", src, "-o", out, *SMOOTH_OPTIONS)
                run("convert", out, self.path(name[:-2] + "-back.vtu"), "-q")
                back = meshio.read(self.path(name[:-2] + "-back.vtu"))
                np.testing.assert_array_equal(back.cells_dict["tetra"], self.tets)
                np.testing.assert_allclose(back.points, expected, rtol=WRITTEN_RTOL, atol=WRITTEN_ATOL)
        # Without the mark LS-DYNA reads the file in the deck's layout,
        # whatever its own *KEYWORD says: refused, naming the mark.
        src = self.write("include-unmarked.k", lines[:start] + ["*INCLUDE", "parts/i10-keyword.k"] + lines[end:])
        proc = run("quality", src, check=False)
        self.assert_one_error_line(proc, EXIT_INPUT, "i10-keyword.k:1:", '"*INCLUDE %"')

    def test_left_handed_tets(self):
        # Every third tet listed left-handed (N2 and N3 swapped): LS-DYNA
        # takes one order, so they are inverted tets, read as listed.
        turned = np.arange(len(self.tets)) % 3 == 0
        tets = self.tets.copy()
        tets[turned] = tets[turned][:, [0, 2, 1, 3]]
        cards = [solid_card(11 + t, 1, self.ids[row]) for t, row in enumerate(tets)]
        src = self.write("left.k", self.deck_lines(tets=cards))
        self.assertIn(f"{turned.sum()} inverted tets", run("quality", src).stderr)
        q = quality_json(src)["quality"]
        self.assertEqual(q["inverted"], turned.sum())
        run("smooth", src, "-o", self.path("left-out.vtu"), *SMOOTH_OPTIONS)
        _, read, _, _ = vtu_result(self.path("left-out.vtu"))
        np.testing.assert_array_equal(read, tets)

    def test_lower_case_keywords_comments_and_crlf(self):
        lines = [line.lower() if line.startswith("*") else line for line in self.deck_lines(node_comment=True)]
        lines += ["$ after the end: kept, not read", "*NODE", "not a node card", "*INCLUDE_PATH", "nowhere"]
        lf, crlf = self.write("lower.k", lines), self.write("lower-crlf.k", lines, newline="\r\n")
        for src in (lf, crlf):
            with self.subTest(deck=os.path.basename(src)):
                _, _, moved, _ = self.smoothed(src)
                self.assertEqual(moved, self.free)
        with open(self.path("lower-out.k"), "rb") as a, open(self.path("lower-crlf-out.k"), "rb") as b:
            self.assertEqual(b.read(), a.read())

    def test_bricks_wedges_and_pyramids_pass_through(self):
        # A brick, a wedge and a pyramid apart from the lattice: kept in the
        # deck, written to VTU as such, their nodes pinned.
        far = np.array([[10, 0, 0], [11, 0, 0], [11, 1, 0], [10, 1, 0], [10, 0, 1], [11, 0, 1], [11, 1, 1], [10, 1, 1]])
        extra_ids = np.arange(8) + 5001
        node_cards = [node_card(n, p) for n, p in zip(extra_ids, far)]
        e = extra_ids.tolist()
        solids = ["*ELEMENT_SOLID", ints_card([901, 1] + e, 8),
                  ints_card([902, 1] + [e[0], e[1], e[2], e[3], e[4], e[4], e[7], e[7]], 8),  # a wedge
                  ints_card([903, 1] + [e[0], e[1], e[2], e[3], e[6], e[6], e[6], e[6]], 8)]  # a pyramid
        lines = self.deck_lines(more=["*NODE", *node_cards, *solids])
        src = self.write("mixed.k", lines)
        _, _, moved, pinned = self.smoothed(src)
        self.assertEqual(moved, self.free)
        self.assertEqual(pinned, set(e))
        cells = {block.type: len(block.data) for block in meshio.read(self.path("mixed-out.vtu")).cells}
        self.assertEqual(cells, {"tetra": len(self.tets), "hexahedron": 1, "wedge": 1, "pyramid": 1})
        a, b = self.assert_reader_reads_the_smoothed_deck(src, self.path("mixed-out.k"))
        self.assertEqual(len(a.solids), len(self.tets) + 3)


# --- The example decks --------------------------------------------------------------------

class ExampleDecks(DeckCase):
    SCRATCH_PREFIX = "tetsmooth_test_lsdyna_examples_"

    def test_the_examples_hold_no_tets_and_are_refused(self):
        for name in ("joint_screw", "birdball", "wheel", "bracket", "simple_plate"):
            src = getattr(dyna_examples, name)
            with self.subTest(deck=os.path.basename(src)):
                deck = ReaderDeck(src)
                self.assertGreater(len(deck.nid), 0)
                self.assertGreater(len(deck.solids) + len(deck.shells), 0)
                # Bricks alone: 8 distinct nodes each.
                self.assertEqual({len(set(nodes)) for _, nodes in deck.solids.values()} - {8}, set())
                out = self.path("never.k")
                proc = run("smooth", src, "-o", out, "--device", "cpu", check=False)
                self.assert_one_error_line(proc, EXIT_INPUT, f"{src}: no tets in *ELEMENT_SOLID")
                self.assertFalse(os.path.exists(out))
        self.assertEqual(len(ReaderDeck(dyna_examples.birdball).solids), 816)
        self.assertEqual(len(ReaderDeck(dyna_examples.joint_screw).solids), 336)

    def test_birdball_cut_into_tets(self):
        lines, tets = bricks_cut_into_tets(dyna_examples.birdball)
        src = self.write("birdball-tets.k", lines)
        read = quality_json(src)
        self.assertEqual((read["input"]["nodes"], read["input"]["tets"]), (1281, len(tets)))
        self.assertEqual(read["quality"]["inverted"], 0)
        # *INITIAL_VELOCITY_NODE names every node: nothing may move, and the
        # smoothed deck is the deck.
        before, _, moved, pinned = self.smoothed(src)
        self.assertEqual((moved, pinned), (set(), set(before.order)))
        with open(src, "rb") as a, open(self.path("birdball-tets-out.k"), "rb") as b:
            self.assertEqual(b.read(), a.read())
        # Without it, the nodes of *set_node_list_generate (1 to 376, the
        # bird's, in free format), those with TC or RC and the shells' are
        # pinned; without the set too, the bird's nodes move. (The ball's
        # grid of bricks, cut alike, is already what smoothing makes it.)
        start = lines.index("*INITIAL_VELOCITY_NODE")
        end = next(i for i in range(start + 1, len(lines)) if lines[i].startswith("*"))
        lines = lines[:start] + lines[end:]
        src = self.write("birdball-set.k", lines)
        self.assertIn("CONTACT_ERODING_NODES_TO_SURFACE keywords are not read", run("quality", src).stderr)
        before, _, moved, pinned = self.smoothed(src)
        generated = set(range(1, 377)) & set(before.order)
        constrained = {n for n in before.order if before.tc[n] or before.rc[n]}
        reader = ReaderDeck(src)  # which reads TC and RC too
        self.assertEqual(constrained, set(reader.nid[(reader.tc != 0) | (reader.rc != 0)].tolist()))
        self.assertGreater(len(constrained), 100)
        shells = {n for _, nodes in before.shells.values() for n in nodes}
        self.assertEqual(pinned, generated | constrained | shells)
        self.assertFalse(moved & pinned)
        start = lines.index("*set_node_list_generate")
        src = self.write("birdball-free.k", lines[:start] + lines[start + 3:])
        before, after, moved, pinned = self.smoothed(src)
        self.assertEqual(pinned, constrained | shells)
        self.assertGreater(len(moved & generated), 50)
        self.assertFalse(moved & pinned)
        self.assert_reader_reads_the_smoothed_deck(src, self.path("birdball-free-out.k"))
        ids = np.array(sorted(before.order))
        rows = np.searchsorted(ids, [nodes[:4] for _, nodes in tets.values()])
        q_in, q_out = radius_ratio(before.coordinates(ids), rows), radius_ratio(after.coordinates(ids), rows)
        self.assertGreaterEqual(q_out.min(), q_in.min() - 1e-12)
        self.assertGreater(q_out.mean(), q_in.mean())

    def test_joint_screw_cut_into_tets(self):
        lines, tets = bricks_cut_into_tets(dyna_examples.joint_screw)
        src = self.write("screw-tets.key", lines)
        before, after, moved, pinned = self.smoothed(src)
        self.assertGreater(len(moved), 10)
        pids = np.array([pid for pid, _ in tets.values()])
        rows = np.array([nodes for _, nodes in tets.values()])
        self.assertEqual(set(pids.tolist()), {10000045, 10000046})
        ids = np.array(sorted(before.order))
        boundary = set(ids[list(boundary_nodes(np.searchsorted(ids, rows)))].tolist())
        self.assertFalse(moved & boundary, "a boundary node moved")
        shells = {n for _, nodes in before.shells.values() for n in nodes}
        self.assertLessEqual(shells, pinned)
        self.assert_reader_reads_the_smoothed_deck(src, self.path("screw-tets-out.key"))
        run("convert", src, self.path("screw.msh"), "-q")
        with open(self.path("screw.msh")) as f:
            self.assertIn('$PhysicalNames\n2\n3 10000045 "Screw in"\n3 10000046 "Screw out"\n', f.read())


# --- Refusals ------------------------------------------------------------------------------

class Refusals(RefusedDecks, DeckCase):
    """Decks tetsmooth must refuse (RefusedDecks runs them): the lattice
    deck below, each case with one part of it spoilt."""

    SCRATCH_PREFIX = "tetsmooth_test_lsdyna_bad_"
    SUFFIX = ".k"

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        xyz, cls.tets = kuhn_lattice(2, seed=2)
        cls.xyz = np.round(xyz, 6)
        cls.ids = np.arange(len(xyz)) + 1
        cls.lines = (HEAD + ["*PART", "lattice", ints_card([1, 1, 1]), "*NODE"] +
                     [node_card(n, p) for n, p in zip(cls.ids, cls.xyz)] +
                     ["*ELEMENT_SOLID"] + [solid_card(t + 1, 1, cls.ids[row]) for t, row in enumerate(cls.tets)] +
                     ["*END"])
        cls.node = cls.lines.index("*NODE")  # indices of the keywords
        cls.solid = cls.lines.index("*ELEMENT_SOLID")
        cls.end = len(cls.lines) - 1

    def before_end(self, new):
        return self.edited(self.end, list(new) + ["*END"])

    def cases(self):
        """{name: (lines, 1-based line the message must name, fragments)}."""
        node, solid, end = self.node, self.solid, self.end
        part = self.lines.index("*PART")
        first_tet = self.lines[solid + 1]
        ten = two_card_solid(99, 1, list(range(1, 11)))
        return {
            # Standard cards read in 20-column fields run into each other.
            "long-node": (self.edited(node, ["*NODE +"]), node + 2, ["node id"]),
            "long-keyword": (self.edited(1, ["*KEYWORD LONG=Y"]), part + 3, ["part id"]),
            "long-s": (self.edited(1, ["*KEYWORD LONG=S"]), 2, ["LONG=S"]),
            "node-transform": (self.before_end(["*NODE_TRANSFORM", ints_card([1, 1])]), end + 1, ["NODE_TRANSFORM"]),
            "node-merge": (self.before_end(["*NODE_MERGE", "       0.1"]), end + 1, ["NODE_MERGE"]),
            "part-move": (self.before_end(["*PART_MOVE", ints_card([1]) + "       1.0"]), end + 1, ["PART_MOVE"]),
            "include-path": (self.before_end(["*INCLUDE_PATH", "/tmp"]), end + 1, ["INCLUDE_PATH"]),
            "include-transform": (self.before_end(["*INCLUDE_TRANSFORM", "more.k"]), end + 1, ["INCLUDE_TRANSFORM"]),
            "include-missing": (self.before_end(["*INCLUDE", "missing.k"]), end + 2, ["missing.k"]),
            "undefined-node": (self.edited(solid + 1, [first_tet[:16] + "     999" + first_tet[24:]]), solid + 2,
                               ["node 999"]),
            "undefined-set-node": (self.before_end(set_node_list(1, [5, 888])), end + 4, ["node 888"]),
            "duplicate-node": (self.edited(solid, [self.lines[node + 5], "*ELEMENT_SOLID"]), solid + 1,
                               ["node 5", "second time"]),
            "duplicate-solid": (self.edited(solid + 3, [self.lines[solid + 3], first_tet]), solid + 5,
                                ["solid element 1", "second time"]),
            "parameter": (self.edited(node + 3, [self.lines[node + 3][:8] + "              &x" +
                                                 self.lines[node + 3][24:]]), node + 4, ["&x"]),
            "zero-nid": (self.edited(node + 3, ["       0" + self.lines[node + 3][8:]]), node + 4, ["node id"]),
            "mixed-tets": (self.edited(end, ten + ["*END"]), end + 2, ["10-node"]),
            "solid-option": (self.edited(solid, ["*ELEMENT_SOLID_H8TOH20"]), solid + 1, ["ELEMENT_SOLID_H8TOH20"]),
            # (Past 8 digits: in free format.)
            "pid-too-large": (self.edited(solid + 1, ["1,3000000000," + ",".join(first_tet[16:].split())]),
                              solid + 2, ["3000000000", "2,147,483,647"]),
            "cut-solid": (self.lines[:-1] + two_card_solid(99, 1, [])[:1], end + 1, ["ends inside"]),
            "short-solid": (self.edited(end, two_card_solid(99, 1, [])[:1] + ["*END"]), end + 2, ["lacks"]),
        }


class PartNames(DeckChecks, GmshScratchCase):
    SCRATCH_PREFIX = "tetsmooth_test_lsdyna_names_"

    @classmethod
    def setUpClass(cls):
        require_reader()  # before the scratch folder, which an error would leave behind
        super().setUpClass()

    def test_part_headings_that_look_like_comments_or_keywords(self):
        # A heading is a whole card: names that start with '$' or '*' must
        # not turn into a comment or a keyword in a new deck.
        gmsh = self.gmsh
        src = self.path("names.msh")
        names = {1: "$ dollar rock", 2: "*starry"}
        with gmsh_session(gmsh):
            a = gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
            b = gmsh.model.occ.addBox(1, 0, 0, 1, 1, 1)
            gmsh.model.occ.fragment([(3, a)], [(3, b)])
            gmsh.model.occ.synchronize()
            for tag, entity in ((1, a), (2, b)):
                gmsh.model.addPhysicalGroup(3, [entity], tag)
                gmsh.model.setPhysicalName(3, tag, names[tag])
            gmsh.option.setNumber("Mesh.MeshSizeMax", 0.6)
            gmsh.model.mesh.generate(3)
            gmsh.write(src)
        deck, back = self.path("names.k"), self.path("names-back.msh")
        run("convert", src, deck, "-q")
        keywords = {line.split()[0].upper() for line in file_lines(deck) if line.startswith("*")}
        self.assertEqual(keywords, {"*KEYWORD", "*PART", "*NODE", "*ELEMENT_SOLID", "*END"})
        self.assertEqual(ReaderDeck(deck).solids.keys() and {p for p, _ in ReaderDeck(deck).solids.values()}, {1, 2})
        run("convert", deck, back, "-q")
        with gmsh_session(gmsh):
            gmsh.open(back)
            read = {tag: gmsh.model.getPhysicalName(dim, tag) for dim, tag in gmsh.model.getPhysicalGroups()}
        self.assertEqual(read, names)


class FormatNames(CliTestCase):
    SCRATCH_PREFIX = "tetsmooth_test_lsdyna_help_"

    def test_help_and_messages_name_the_format(self):
        # The format lists of the help and of the message for a name
        # without a known extension are where users look for it.
        for args in (("--help",), ("help", "convert"), ("help", "smooth")):
            with self.subTest(help=args):
                proc = run(*args)
                formats = (proc.stdout + proc.stderr).partition("Formats")[2].partition("Exit status")[0]
                self.assertTrue("lsdyna" in formats and ".k" in formats,
                                f"`tetsmooth {' '.join(args)}` lists no LS-DYNA format:\n{formats}")
        src = self.path("lattice.msh")
        run("generate", "lattice-2", "-o", src, "-q")
        proc = run("convert", src, self.path("out.unknown"), check=False)
        self.assert_one_error_line(proc, EXIT_USAGE, ".k")


if __name__ == "__main__":
    unittest.main()
