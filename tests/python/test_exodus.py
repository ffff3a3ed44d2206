"""Exodus II files (.exo, .e, .g) through tetsmooth, checked against two
independent implementations of the format: the netCDF4 Python package
(Debian python3-netcdf4), with which this file writes Exodus files of its own
and reads every variable, dimension and attribute back, and meshio 5.0's
Exodus reader and writer.

What is checked, and why:
- A file as Cubit or SEACAS would write it (two TETRA blocks with ids and
  names, a TRI3 and a SHELL4 block, two node sets, a side set on interior
  tet faces, node and element number maps, QA and info records, a global
  attribute, nodal and element results over two time steps), in netCDF-4
  (HDF5, compressed coordinates) and in the 64-bit offset format, and in
  the other netCDF formats: a smoothed file must be the input with new
  coordinates and nothing else changed (same netCDF format; every
  dimension, attribute and variable as it was, compression included; for
  the classic formats, the same bytes outside the coordinates), since a
  simulation reads its blocks, sets, maps and results from it. Nodes on the
  boundary, on the interface between the blocks, on the surface blocks, in
  a node set or on a side of a side set keep their coordinates bit for bit;
  each of those reasons alone holds a node that moves without it; the
  worst radius ratio does not fall; a warning says that the results were
  computed on the mesh as it was.
- The pins are exactly those the file's sets and surface blocks name
  (tetsmooth:fixed in VTU output): this catches a side numbered other than
  by Exodus's rule (side 1 = nodes 1,2,4; 2 = 2,3,4; 3 = 1,3,4; 4 = 1,2,3),
  an element of a side set counted within its block instead of across the
  file, and node sets read through the number map instead of by index.
- Coordinates in 4-byte floats are written back as floats: moved nodes are
  the double result rounded to float, unmoved ones bit-identical; the older
  `coord` variable (num_dim x num_nodes) smooths as coordx/y/z do.
- A TETRA10 block (midside nodes on the edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4):
  the midside nodes stay at their edges' midpoints, and corners do move
  (a reader taking Gmsh's order, with the last two swapped, would see every
  edge curved and move nothing).
- New files from MSH (physical names and tags), Medit (required vertices)
  and VTU: meshio reads the points and cells; blocks are named and numbered
  by the regions, elem_type is TETRA or TRI3, tets are right side out,
  elem_num_map holds the MSH element numbers, and pinned nodes that no
  element keeps are the node set "tetsmooth_pinned" (1-based). A file
  through VTU and back keeps its blocks (ids, elements, the pins as that
  node set), through MSH also their names and the number maps; 10-node tets
  keep their midside nodes on the right edges both ways.
- Files that meshio writes (coord, 64-bit connectivity in netCDF-4, block
  ids from 0, point sets) are read and smoothed, their point sets pinned.
- Bad files (not netCDF, num_dim 2, a node number out of range, side 7 of
  a tet, ...) are refused with exit status 3 and one line naming the file
  and the variable at fault, leaving no output and an existing output file
  as it was. A classic file cut short is refused as cut short, not blamed
  on "Operation not permitted" (the system error netCDF's in-memory reader
  gives when it reads past the end).

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import contextlib
import io
import os
import unittest

import meshio
import numpy as np

from test_cli import (BIN, EXIT_INPUT, CliTestCase, kuhn_lattice, missing, radius_ratio, require_binary, run,
                      signed_volume6)
from test_independent_readers import boundary_nodes

try:
    import netCDF4
except ImportError:  # scripts/install_deps.sh installs python3-netcdf4
    netCDF4 = None

# Exodus II's sides of a tet (its manual, "Side set node ordering"), as
# 0-based local nodes: side 1 = (1, 2, 4), 2 = (2, 3, 4), 3 = (1, 3, 4),
# 4 = (1, 2, 3) in the manual's 1-based numbers.
TET_SIDES = np.array([[0, 1, 3], [1, 2, 3], [0, 2, 3], [0, 1, 2]])
# The corners at the ends of a TETRA10's midside nodes 5..10 (1-based):
# edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4.
TETRA10_EDGES = np.array([[0, 1], [1, 2], [2, 0], [0, 3], [1, 3], [2, 3]])
# Exodus's lengths of names (32 characters and a terminating zero), lines
# of info records, and QA strings.
LEN_NAME, LEN_LINE, LEN_STRING = 33, 81, 33
FORMATS = ["NETCDF4", "NETCDF4_CLASSIC", "NETCDF3_CLASSIC", "NETCDF3_64BIT_OFFSET", "NETCDF3_64BIT_DATA"]
HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"


def meshio_read(path, **kw):
    """meshio.read, without the warning meshio prints for each file with
    more than one time step (it reads the first), or the blank line of its
    MSH reader."""
    with contextlib.redirect_stderr(io.StringIO()), contextlib.redirect_stdout(io.StringIO()):
        return meshio.read(path, **kw)


def require_exodus():
    """The netCDF4 package, and a tetsmooth built with Exodus support (a
    build without netCDF says so for any Exodus file, even one that is not
    there)."""
    if netCDF4 is None:
        missing("the netCDF4 Python package (Debian: python3-netcdf4) is not installed")
    probe = run("quality", os.path.join(os.path.dirname(BIN) or ".", "no-such-file.exo"), check=False)
    if "built without netCDF" in probe.stderr:
        missing("this tetsmooth was built without Exodus support (netCDF): " + probe.stderr.strip())


def text_rows(rows, width):
    """Rows of text as netCDF's char table: one row of `width` bytes each,
    padded with zeros."""
    table = np.zeros((len(rows), width), dtype="S1")
    for r, row in enumerate(rows):
        data = row.encode()
        assert len(data) < width, row
        table[r, :len(data)] = np.frombuffer(data, dtype="S1")
    return table


def row_strings(table):
    """The rows of a char table as strings, each up to its first zero."""
    return [bytes(row.tobytes()).split(b"\0")[0].decode() for row in np.asarray(table)]


class Model:
    """An Exodus file's contents, which write_exodus writes: `xyz` (nodes x
    num_dim); `blocks` [(elem_type, id, name, rows of 0-based nodes,
    attributes or None)]; `node_sets` [(id, name, 0-based nodes)];
    `side_sets` [(id, name, 0-based element indices across the blocks,
    1-based sides)]; number maps (or None); QA and info records; nodal
    results {name: (steps x nodes)} and element results {name: (steps x
    elements of every block)} at `times`; `coord_type` "f8" or "f4"; `layout`
    "xyz" (coordx, coordy, coordz) or "coord"; extra global attributes."""

    def __init__(self, xyz, blocks, **kw):
        self.xyz, self.blocks = np.asarray(xyz, dtype=float), blocks
        self.node_sets, self.side_sets = kw.pop("node_sets", []), kw.pop("side_sets", [])
        self.node_ids, self.elem_ids = kw.pop("node_ids", None), kw.pop("elem_ids", None)
        self.qa, self.info = kw.pop("qa", []), kw.pop("info", [])
        self.nodal, self.elemental = kw.pop("nodal", {}), kw.pop("elemental", {})
        self.times = kw.pop("times", [])
        self.coord_type, self.layout = kw.pop("coord_type", "f8"), kw.pop("layout", "xyz")
        self.attributes = kw.pop("attributes", {})
        assert not kw, kw


def write_exodus(path, model, file_format="NETCDF4", compress=False):
    """Writes `model` as an Exodus II file in netCDF format `file_format`,
    laid out as the Exodus II manual's appendix on its netCDF implementation
    has it (and as SEACAS writes it), with coordinates compressed where the
    format allows and `compress`. Returns `path`."""
    ints = "i4"
    hdf5 = file_format.startswith("NETCDF4")
    with netCDF4.Dataset(path, "w", format=file_format) as nc:
        word = 8 if model.coord_type == "f8" else 4
        nc.setncatts({"title": "tetsmooth test mesh", "api_version": np.float32(8.03), "version": np.float32(8.03),
                      "floating_point_word_size": np.int32(word), "file_size": np.int32(1),
                      "maximum_name_length": np.int32(32), "int64_status": np.int32(0)})
        nc.setncatts(model.attributes)
        dims = model.xyz.shape[1]
        for name, length in (("len_string", LEN_STRING), ("len_line", LEN_LINE), ("four", 4), ("len_name", LEN_NAME),
                             ("time_step", None), ("num_dim", dims), ("num_nodes", len(model.xyz)),
                             ("num_elem", sum(len(b[3]) for b in model.blocks)), ("num_el_blk", len(model.blocks))):
            nc.createDimension(name, length)
        if model.qa:
            nc.createDimension("num_qa_rec", len(model.qa))
            qa = nc.createVariable("qa_records", "S1", ("num_qa_rec", "four", "len_string"))
            qa[:] = np.stack([text_rows(record, LEN_STRING) for record in model.qa])
        if model.info:
            nc.createDimension("num_info", len(model.info))
            nc.createVariable("info_records", "S1", ("num_info", "len_line"))[:] = text_rows(model.info, LEN_LINE)
        nc.createVariable("time_whole", "f8", ("time_step",))[:] = np.asarray(model.times, dtype=float)
        nc.createVariable("eb_status", ints, ("num_el_blk",))[:] = np.ones(len(model.blocks), dtype=int)
        prop = nc.createVariable("eb_prop1", ints, ("num_el_blk",))
        prop.setncattr("name", "ID")
        prop[:] = [b[1] for b in model.blocks]
        nc.createVariable("eb_names", "S1", ("num_el_blk", "len_name"))[:] = text_rows([b[2] for b in model.blocks],
                                                                                      LEN_NAME)
        packed = dict(zlib=True, complevel=4) if hdf5 and compress else {}
        if model.layout == "xyz":
            for c in range(dims):
                nc.createVariable("coord" + "xyz"[c], model.coord_type, ("num_nodes",), **packed)[:] = model.xyz[:, c]
        else:
            nc.createVariable("coord", model.coord_type, ("num_dim", "num_nodes"), **packed)[:] = model.xyz.T
        nc.createVariable("coor_names", "S1", ("num_dim", "len_name"))[:] = text_rows(list("XYZ"[:dims]), LEN_NAME)
        if model.node_ids is not None:
            nc.createVariable("node_num_map", ints, ("num_nodes",))[:] = model.node_ids
        if model.elem_ids is not None:
            nc.createVariable("elem_num_map", ints, ("num_elem",))[:] = model.elem_ids
        for b, (elem_type, _, _, rows, attributes) in enumerate(model.blocks, start=1):
            rows = np.asarray(rows)
            nc.createDimension(f"num_el_in_blk{b}", len(rows))
            nc.createDimension(f"num_nod_per_el{b}", rows.shape[1])
            connect = nc.createVariable(f"connect{b}", ints, (f"num_el_in_blk{b}", f"num_nod_per_el{b}"))
            connect.setncattr("elem_type", elem_type)
            connect[:] = rows + 1
            if attributes is not None:
                nc.createDimension(f"num_att_in_blk{b}", attributes.shape[1])
                nc.createVariable(f"attrib{b}", "f8", (f"num_el_in_blk{b}", f"num_att_in_blk{b}"))[:] = attributes
        for kind, sets in (("ns", model.node_sets), ("ss", model.side_sets)):
            if not sets:
                continue
            nc.createDimension(f"num_{'node' if kind == 'ns' else 'side'}_sets", len(sets))
            count = f"num_{'node' if kind == 'ns' else 'side'}_sets"
            nc.createVariable(f"{kind}_status", ints, (count,))[:] = np.ones(len(sets), dtype=int)
            prop = nc.createVariable(f"{kind}_prop1", ints, (count,))
            prop.setncattr("name", "ID")
            prop[:] = [s[0] for s in sets]
            nc.createVariable(f"{kind}_names", "S1", (count, "len_name"))[:] = text_rows([s[1] for s in sets], LEN_NAME)
        for s, (_, _, nodes) in enumerate(model.node_sets, start=1):
            nc.createDimension(f"num_nod_ns{s}", len(nodes))
            nc.createVariable(f"node_ns{s}", ints, (f"num_nod_ns{s}",))[:] = np.asarray(nodes) + 1
            nc.createVariable(f"dist_fact_ns{s}", "f8", (f"num_nod_ns{s}",))[:] = np.ones(len(nodes))
        for s, (_, _, elements, sides) in enumerate(model.side_sets, start=1):
            nc.createDimension(f"num_side_ss{s}", len(elements))
            nc.createVariable(f"elem_ss{s}", ints, (f"num_side_ss{s}",))[:] = np.asarray(elements) + 1
            nc.createVariable(f"side_ss{s}", ints, (f"num_side_ss{s}",))[:] = sides
            nc.createDimension(f"num_df_ss{s}", 3 * len(elements))
            nc.createVariable(f"dist_fact_ss{s}", "f8", (f"num_df_ss{s}",))[:] = np.full(3 * len(elements), 2.5)
        if model.nodal:
            nc.createDimension("num_nod_var", len(model.nodal))
            names = nc.createVariable("name_nod_var", "S1", ("num_nod_var", "len_name"))
            names[:] = text_rows(list(model.nodal), LEN_NAME)
            for k, values in enumerate(model.nodal.values(), start=1):
                nc.createVariable(f"vals_nod_var{k}", "f8", ("time_step", "num_nodes"))[:] = values
        if model.elemental:
            nc.createDimension("num_elem_var", len(model.elemental))
            nc.createVariable("name_elem_var", "S1", ("num_elem_var", "len_name"))[:] = text_rows(list(model.elemental),
                                                                                                LEN_NAME)
            table = np.ones((len(model.blocks), len(model.elemental)), dtype=int)
            nc.createVariable("elem_var_tab", ints, ("num_el_blk", "num_elem_var"))[:] = table
            for k, values in enumerate(model.elemental.values(), start=1):
                first = 0
                for b, block in enumerate(model.blocks, start=1):
                    count = len(block[3])
                    nc.createVariable(f"vals_elem_var{k}eb{b}", "f8", ("time_step", f"num_el_in_blk{b}"))[:] = \
                        values[:, first:first + count]
                    first += count
    return path


def contents(path):
    """Everything netCDF4 reads in a file: its data model; dimensions
    (length, unlimited); global attributes; and per variable, in file order,
    its type, dimensions, attributes, storage (HDF5 filters and chunks) and
    values."""
    with netCDF4.Dataset(path) as nc:
        nc.set_auto_mask(False)
        hdf5 = nc.data_model.startswith("NETCDF4")
        variables = {}
        for name, v in nc.variables.items():
            storage = (v.filters(), v.chunking()) if hdf5 else None
            variables[name] = (str(v.dtype), v.dimensions, {a: v.getncattr(a) for a in v.ncattrs()}, storage,
                               np.array(v[...]))
        return dict(model=nc.data_model,
                    dimensions={n: (len(d), d.isunlimited()) for n, d in nc.dimensions.items()},
                    attributes={a: nc.getncattr(a) for a in nc.ncattrs()}, variables=variables)


def same_value(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and np.array_equal(a, b)


def coordinates(path):
    """The node coordinates of an Exodus file (nodes x 3) in the file's own
    type, from coordx/y/z or coord."""
    with netCDF4.Dataset(path) as nc:
        nc.set_auto_mask(False)
        if "coordx" in nc.variables:
            return np.stack([nc.variables["coord" + c][:] for c in "xyz"], axis=1)
        return np.array(nc.variables["coord"][:]).T


def block_table(path):
    """[(elem_type, id, name, rows of 0-based nodes)] of an Exodus file."""
    with netCDF4.Dataset(path) as nc:
        nc.set_auto_mask(False)
        ids = nc.variables["eb_prop1"][:].tolist()
        names = row_strings(nc.variables["eb_names"][:]) if "eb_names" in nc.variables else [""] * len(ids)
        return [(nc.variables[f"connect{b}"].getncattr("elem_type"), ids[b - 1], names[b - 1],
                 np.array(nc.variables[f"connect{b}"][:]) - 1) for b in range(1, len(ids) + 1)]


def lattice_node(n, i, j, k):
    """kuhn_lattice's index of the lattice point (i, j, k)."""
    return (i * (n + 1) + j) * (n + 1) + k


def interior_faces(tets):
    """The sorted node triples of faces shared by two tets."""
    faces = np.sort(np.concatenate([tets[:, side] for side in TET_SIDES]), axis=1)
    unique, counts = np.unique(faces, axis=0, return_counts=True)
    return {tuple(f) for f in unique[counts == 2].tolist()}


def moved_nodes(before, after):
    return set(np.flatnonzero(np.any(before != after, axis=1)).tolist())


class ExodusCase(CliTestCase):
    SCRATCH_PREFIX = "tetsmooth_test_exodus_"

    @classmethod
    def setUpClass(cls):
        require_binary()
        require_exodus()  # before the scratch folder, which a skip would leave behind
        super().setUpClass()

    def smooth(self, src, out, *extra):
        return run("smooth", src, "-o", out, "--device", "cpu", *extra)


def rich_model(n=5, seed=5):
    """The file of a Cubit user: a Kuhn lattice of n^3 cubes, its tets in two
    TETRA blocks (x < 2: id 10 "left rock", the rest: id 20 "right rock"),
    then a TRI3 block (id 30) and a SHELL4 block with a thickness attribute
    (id 40) on faces inside the lattice; node sets "support" (the bottom
    face and two interior nodes) and "sensor" (one interior node); a side set
    "pressure" on four interior faces of right-block tets, one of each side
    number, each tet's fourth node free; node and element number maps that
    are not positions; QA and info records, a global attribute, a nodal and
    an element result over two time steps. Returns (model, facts), facts a
    dict of the node sets that explain which nodes must stay."""
    xyz, tets = kuhn_lattice(n, seed=seed)
    left = xyz[tets].mean(axis=1)[:, 0] < 2
    tets = np.concatenate([tets[left], tets[~left]])
    n_left = int(left.sum())
    node = lambda i, j, k: lattice_node(n, i, j, k)  # noqa: E731
    interior = set(np.flatnonzero(np.all((xyz > 0) & (xyz < n), axis=1)).tolist())
    interface = (set(tets[:n_left].ravel().tolist()) & set(tets[n_left:].ravel().tolist())) & interior
    # A triangle (a tet face) around (1, 1, n - 1), a quad of a cube face
    # around (n - 1, 1, 1), each with its other nodes on the boundary.
    faces = np.sort(np.concatenate([tets[:, s] for s in TET_SIDES]), axis=1)
    target = node(1, 1, n - 1)
    triangle = next(f for f in faces.tolist() if target in f and len(set(f) & interior) == 1)
    quad = [node(n - 1, 0, 0), node(n - 1, 1, 0), node(n - 1, 1, 1), node(n - 1, 0, 1)]
    support = sorted({node(i, j, 0) for i in range(n + 1) for j in range(n + 1)} | {node(1, n - 1, n - 1),
                                                                                   node(1, n - 1, 1)})
    sensor = [node(n - 2, n - 2, n - 2)]
    others = set(support) | set(sensor) | set(triangle) | set(quad)
    # The side set: for each side number, the first interior face of a
    # right-block tet with a node that nothing else pins, whose fourth node
    # is interior, off the interface and pinned by nothing.
    shared = interior_faces(tets)
    elements, sides, side_nodes, fourth = [], [], set(), set()
    for side in range(4):
        for t in range(n_left, len(tets)):
            face = tets[t, TET_SIDES[side]].tolist()
            opposite = int(tets[t, 6 - TET_SIDES[side].sum()])
            free = interior - interface - others - side_nodes
            if (tuple(sorted(face)) in shared and opposite in free - fourth and set(face) & free
                    and not set(face) & fourth and opposite not in side_nodes):
                elements.append(t)
                sides.append(side + 1)
                side_nodes |= set(face)
                fourth.add(opposite)
                break
    assert sides == [1, 2, 3, 4], sides
    assert not fourth & (side_nodes | others), "a side's fourth node is pinned: misnumbered sides would not show"
    model = Model(
        xyz,
        [("TETRA", 10, "left rock", tets[:n_left], None), ("TETRA", 20, "right rock", tets[n_left:], None),
         ("TRI3", 30, "baffle", np.array([triangle]), None),
         ("SHELL4", 40, "membrane", np.array([quad]), np.array([[0.25]]))],
        node_sets=[(1, "support", support), (7, "sensor", sensor)],
        side_sets=[(3, "pressure", elements, sides)],
        node_ids=3 * np.arange(len(xyz)) + 1000,
        elem_ids=np.arange(len(tets) + 2)[::-1] * 2 + 501,
        qa=[("CUBIT", "2022.4", "05/03/2022", "12:00:00"), ("MOOSE", "7.0", "06/01/2022", "08:30:15")],
        info=["a mesh for tetsmooth's tests", "second line of information"],
        nodal={"temperature": np.stack([xyz[:, 0] + 20, xyz[:, 2] * 3])},
        elemental={"stress": np.stack([np.arange(len(tets) + 2.0), np.arange(len(tets) + 2.0) ** 2])},
        times=[0.0, 0.5],
        attributes={"job": "tetsmooth exodus test", "revision": np.int32(3)})
    facts = dict(tets=tets, interior=interior, interface=interface, boundary=boundary_nodes(tets),
                 pins={"node set support": set(support), "node set sensor": set(sensor),
                       "TRI3 block": set(triangle), "SHELL4 block": set(quad), "side set": side_nodes},
                 fourth=fourth)
    return model, facts


class RichFiles(ExodusCase):
    """The file of rich_model in every netCDF format, smoothed."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.model, cls.facts = rich_model()
        cls.tets = cls.facts["tets"]
        cls.src, cls.out, cls.proc = {}, {}, {}
        for fmt in FORMATS:
            cls.src[fmt] = write_exodus(cls.path(f"rich-{fmt}.exo"), cls.model, fmt, compress=True)
            cls.out[fmt] = cls.path(f"rich-{fmt}-out.exo")
            cls.proc[fmt] = run("smooth", cls.src[fmt], "-o", cls.out[fmt], "--device", "cpu")
        # The same lattice in one block with nothing else: which nodes move
        # when nothing pins them.
        plain = Model(cls.model.xyz, [("TETRA", 1, "", cls.tets, None)])
        src = write_exodus(cls.path("plain.exo"), plain, "NETCDF3_64BIT_OFFSET")
        run("smooth", src, "-o", cls.path("plain-out.exo"), "--device", "cpu", "-q")
        cls.free_moves = moved_nodes(cls.model.xyz, coordinates(cls.path("plain-out.exo")))

    def test_the_file_is_as_meant(self):
        # The premises of the checks below, read back with netCDF4 and
        # meshio: the blocks, maps and side numbers written.
        src = self.src["NETCDF4"]
        blocks = block_table(src)
        self.assertEqual([(t, i, n) for t, i, n, _ in blocks],
                         [("TETRA", 10, "left rock"), ("TETRA", 20, "right rock"), ("TRI3", 30, "baffle"),
                          ("SHELL4", 40, "membrane")])
        np.testing.assert_array_equal(np.concatenate([blocks[0][3], blocks[1][3]]), self.tets)
        self.assertTrue(np.all(signed_volume6(self.model.xyz, self.tets) > 0))
        theirs = meshio_read(src)
        np.testing.assert_array_equal(theirs.points, self.model.xyz)
        self.assertEqual([c.type for c in theirs.cells], ["tetra", "tetra", "triangle", "quad"])
        self.assertEqual(sorted(theirs.point_sets), ["sensor", "support"])
        # Every reason to stay holds nodes that move when nothing pins them.
        for reason, nodes in self.facts["pins"].items():
            only = nodes - set().union(*(v for k, v in self.facts["pins"].items() if k != reason)) - \
                self.facts["interface"]
            with self.subTest(reason=reason):
                self.assertTrue(only & self.facts["interior"] & self.free_moves, f"{reason} pins nothing of its own")
        self.assertTrue(self.facts["interface"] & self.free_moves)

    def test_smoothing_keeps_the_format_and_everything_but_the_coordinates(self):
        for fmt in FORMATS:
            with self.subTest(format=fmt):
                before, after = contents(self.src[fmt]), contents(self.out[fmt])
                self.assertEqual(after["model"], fmt)
                self.assertEqual(after["dimensions"], before["dimensions"])
                self.assertEqual(list(after["attributes"]), list(before["attributes"]))
                for name, value in before["attributes"].items():
                    self.assertTrue(same_value(after["attributes"][name], value), name)
                self.assertEqual(list(after["variables"]), list(before["variables"]))
                for name, (dtype, dims, attributes, storage, values) in before["variables"].items():
                    a_dtype, a_dims, a_attributes, a_storage, a_values = after["variables"][name]
                    self.assertEqual((a_dtype, a_dims, a_storage), (dtype, dims, storage), name)
                    self.assertEqual(list(a_attributes), list(attributes), name)
                    for key, value in attributes.items():
                        self.assertTrue(same_value(a_attributes[key], value), f"{name}:{key}")
                    if name not in ("coordx", "coordy", "coordz"):
                        self.assertTrue(same_value(a_values, values), f"{name} changed")
                with open(self.out[fmt], "rb") as f:
                    head = f.read(8)
                self.assertEqual(head == HDF5_SIGNATURE, fmt.startswith("NETCDF4"))

    def test_classic_files_change_only_in_the_coordinate_bytes(self):
        # In the classic formats each variable is one run of big-endian
        # values: the bytes that differ must lie in the runs of coordx, y, z.
        xyz = self.model.xyz
        for fmt in FORMATS:
            if fmt.startswith("NETCDF4"):
                continue
            with self.subTest(format=fmt):
                with open(self.src[fmt], "rb") as f:
                    before = f.read()
                with open(self.out[fmt], "rb") as f:
                    after = f.read()
                self.assertEqual(len(after), len(before))
                runs = []
                for c in range(3):
                    data = xyz[:, c].astype(">f8").tobytes()
                    start = before.find(data)
                    self.assertGreaterEqual(start, 0)
                    self.assertEqual(before.find(data, start + 1), -1)
                    runs.append((start, start + len(data)))
                differ = np.flatnonzero(np.frombuffer(before, np.uint8) != np.frombuffer(after, np.uint8))
                self.assertGreater(len(differ), 0)
                inside = np.zeros(len(differ), dtype=bool)
                for a, b in runs:
                    inside |= (differ >= a) & (differ < b)
                self.assertTrue(np.all(inside), f"bytes {differ[~inside][:5].tolist()} outside the coordinates changed")

    def test_nodes_that_must_stay_do_and_the_others_move(self):
        xyz = self.model.xyz
        stay = self.facts["boundary"] | self.facts["interface"] | set().union(*self.facts["pins"].values())
        results = {}
        for fmt in FORMATS:
            with self.subTest(format=fmt):
                after = coordinates(self.out[fmt])
                self.assertEqual(after.dtype, np.float64)
                moved = moved_nodes(xyz, after)
                for reason, nodes in [("boundary", self.facts["boundary"]), ("interface", self.facts["interface"])] + \
                        list(self.facts["pins"].items()):
                    self.assertFalse(moved & nodes, f"nodes on the {reason} moved: {sorted(moved & nodes)}")
                self.assertTrue(moved, "no node moved")
                # The fourth nodes of the side-set tets are free (though
                # pinned neighbours may keep some where they are).
                self.assertTrue(moved & self.facts["fourth"], "no fourth node of a side-set tet moved")
                self.assertLessEqual(moved, self.facts["interior"] - stay)
                q_before, q_after = radius_ratio(xyz, self.tets), radius_ratio(after, self.tets)
                self.assertGreaterEqual(q_after.min(), q_before.min() - 1e-12)
                self.assertGreater(q_after.mean(), q_before.mean())
                results[fmt] = after
        # Every format holds the same mesh, which smooths alike.
        for fmt in FORMATS[1:]:
            np.testing.assert_array_equal(results[fmt], results[FORMATS[0]])

    def test_results_over_time_steps_are_named_in_a_warning(self):
        for fmt in FORMATS:
            with self.subTest(format=fmt):
                stderr = self.proc[fmt].stderr
                self.assertIn(f"warning: {self.src[fmt]}: ", stderr)
                self.assertIn("results over 2 time steps", stderr)
        # A file without results smooths without that warning.
        plain = run("smooth", self.path("plain.exo"), "-o", self.path("plain-again.exo"), "--device", "cpu")
        self.assertNotIn("time step", plain.stderr)
        # Nor does one whose results are defined before any time step: a
        # classic file with two record variables and no records, whose
        # second record variable netCDF places past the end of the file (a
        # header check once took that for a file cut short).
        blank = Model(self.model.xyz, [("TETRA", 1, "", self.tets, None)],
                      nodal={"temp": np.zeros((0, len(self.model.xyz))), "pore": np.zeros((0, len(self.model.xyz)))})
        for fmt in ("NETCDF3_CLASSIC", "NETCDF3_64BIT_OFFSET", "NETCDF3_64BIT_DATA", "NETCDF4"):
            with self.subTest(format=fmt):
                src = write_exodus(self.path(f"blank-{fmt}.exo"), blank, fmt)
                proc = run("smooth", src, "-o", self.path(f"blank-{fmt}-out.exo"), "--device", "cpu")
                self.assertNotIn("time step", proc.stderr)
                self.assertEqual(contents(self.path(f"blank-{fmt}-out.exo"))["dimensions"]["time_step"][0], 0)

    def test_the_pins_are_exactly_what_the_file_names(self):
        # VTU output marks the file's pins as tetsmooth:fixed (the boundary
        # and the interface stay by themselves and are not marked).
        expected = set().union(*self.facts["pins"].values())
        for fmt in ("NETCDF4", "NETCDF3_64BIT_OFFSET"):
            with self.subTest(format=fmt):
                out = self.path(f"rich-{fmt}.vtu")
                run("convert", self.src[fmt], out, "-q")
                mesh = meshio_read(out)
                fixed = set(np.flatnonzero(np.asarray(mesh.point_data["tetsmooth:fixed"]).ravel()).tolist())
                self.assertEqual(fixed - expected, set(), "pinned, but named by no set or surface block")
                self.assertEqual(expected - fixed, set(), "named by a set or surface block, but not pinned")
                np.testing.assert_array_equal(mesh.points, self.model.xyz)
                np.testing.assert_array_equal(mesh.cells_dict["tetra"], self.tets)

    def test_meshio_reads_the_smoothed_file(self):
        for fmt in ("NETCDF4", "NETCDF3_64BIT_OFFSET"):
            with self.subTest(format=fmt):
                theirs, before = meshio_read(self.out[fmt]), meshio_read(self.src[fmt])
                np.testing.assert_array_equal(theirs.points, coordinates(self.out[fmt]))
                self.assertEqual(len(theirs.cells), len(before.cells))
                for a, b in zip(theirs.cells, before.cells):
                    self.assertEqual(a.type, b.type)
                    np.testing.assert_array_equal(a.data, b.data)
                for name, nodes in before.point_sets.items():
                    np.testing.assert_array_equal(theirs.point_sets[name], nodes)
                np.testing.assert_array_equal(theirs.point_data["temperature"], before.point_data["temperature"])
                self.assertEqual(theirs.info, before.info)


class Coordinates(ExodusCase):
    """Coordinates in floats, and in the older `coord` variable."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        xyz, cls.tets = kuhn_lattice(4, seed=8)
        # Coordinates that floats hold exactly, so that a file of doubles
        # and a file of floats hold the same mesh.
        cls.xyz = xyz.astype(np.float32).astype(np.float64)
        cls.interior = np.flatnonzero(np.all((cls.xyz > 0) & (cls.xyz < 4), axis=1))
        cls.pinned = cls.interior[[0, 5]]

    def model(self, **kw):
        return Model(self.xyz, [("TETRA4", 1, "soil", self.tets, None)],
                     node_sets=[(1, "pins", self.pinned)], **kw)

    def smoothed(self, name, model, fmt="NETCDF3_64BIT_OFFSET"):
        src, out = self.path(name + ".exo"), self.path(name + "-out.exo")
        write_exodus(src, model, fmt)
        proc = self.smooth(src, out, "--threads", "1")
        return src, out, proc

    def test_float_coordinates_are_written_back_as_floats(self):
        _, double_out, _ = self.smoothed("doubles", self.model())
        doubles = coordinates(double_out)
        moved = moved_nodes(self.xyz, doubles)
        self.assertTrue(moved)
        # The doubles' result must not be all floats already, or rounding
        # would not show.
        self.assertFalse(np.array_equal(doubles.astype(np.float32).astype(np.float64), doubles))
        for fmt in ("NETCDF4", "NETCDF3_64BIT_OFFSET"):
            with self.subTest(format=fmt):
                src, out, proc = self.smoothed(f"floats-{fmt}", self.model(coord_type="f4"), fmt)
                self.assertIn("4-byte floats", proc.stderr)
                floats = coordinates(out)
                self.assertEqual(floats.dtype, np.float32)
                # Moved nodes: the double result rounded to float. Unmoved
                # ones: the input's floats, bit for bit.
                np.testing.assert_array_equal(floats, doubles.astype(np.float32))
                unmoved = sorted(set(range(len(self.xyz))) - moved)
                before = coordinates(src)
                self.assertEqual(before[unmoved].tobytes(), floats[unmoved].tobytes())
                self.assertFalse(moved & set(self.pinned.tolist()))
                self.assertEqual(moved_nodes(before.astype(np.float64), floats.astype(np.float64)), moved)
                self.assertEqual(contents(out)["variables"]["coordx"][0], "float32")

    def test_the_older_coord_variable(self):
        _, twin_out, _ = self.smoothed("xyz", self.model())
        for fmt in ("NETCDF4", "NETCDF3_64BIT_OFFSET"):
            with self.subTest(format=fmt):
                src, out, _ = self.smoothed(f"coord-{fmt}", self.model(layout="coord"), fmt)
                before, after = contents(src), contents(out)
                self.assertNotIn("coordx", after["variables"])
                self.assertEqual(after["variables"]["coord"][1], ("num_dim", "num_nodes"))
                for name, value in before["variables"].items():
                    if name != "coord":
                        self.assertTrue(same_value(after["variables"][name][4], value[4]), name)
                np.testing.assert_array_equal(coordinates(out), coordinates(twin_out))
                self.assertTrue(moved_nodes(self.xyz, coordinates(out)))


def tetra10(xyz, tets):
    """Nodes and 10-node tets (Exodus order) of the 4-node tets: a midside
    node at the midpoint of each edge, numbered after the corners."""
    edges = np.sort(tets[:, TETRA10_EDGES].reshape(-1, 2), axis=1)
    unique, inverse = np.unique(edges, axis=0, return_inverse=True)
    mid = 0.5 * (xyz[unique[:, 0]] + xyz[unique[:, 1]])
    return np.concatenate([xyz, mid]), np.hstack([tets, len(xyz) + inverse.reshape(-1, 6)])


class SecondOrder(ExodusCase):
    def test_midside_nodes_stay_at_their_edges_midpoints(self):
        corners_xyz, corner_tets = kuhn_lattice(4, seed=12)
        xyz, tets = tetra10(corners_xyz, corner_tets)
        boundary = boundary_nodes(corner_tets)
        pinned = lattice_node(4, 2, 2, 2)
        model = Model(xyz, [("TETRA10", 1, "concrete", tets, None)], node_sets=[(1, "anchor", [pinned])])
        for fmt in ("NETCDF4", "NETCDF3_64BIT_OFFSET"):
            with self.subTest(format=fmt):
                src, out = self.path(f"tetra10-{fmt}.exo"), self.path(f"tetra10-{fmt}-out.exo")
                write_exodus(src, model, fmt)
                # meshio reads the block as 10-node tets, as written.
                np.testing.assert_array_equal(meshio_read(src).cells_dict["tetra10"], tets)
                self.smooth(src, out, "-q")
                after = coordinates(out)
                ends = after[tets[:, TETRA10_EDGES]]
                np.testing.assert_allclose(after[tets[:, 4:]], 0.5 * (ends[:, :, 0] + ends[:, :, 1]), rtol=0,
                                           atol=1e-12)
                moved = moved_nodes(xyz, after)
                corners_moved = {n for n in moved if n < len(corners_xyz)}
                self.assertTrue(corners_moved, "no corner moved")
                self.assertFalse(corners_moved & (boundary | {pinned}))
                self.assertGreaterEqual(radius_ratio(after, tets[:, :4]).min(),
                                        radius_ratio(xyz, tets[:, :4]).min() - 1e-12)
                self.assertTrue(np.all(signed_volume6(after, tets[:, :4]) > 0))
        # Converted, the 10-node tets keep their midside nodes on the right
        # edges: VTU and MSH as meshio reads them (in VTK's order, which is
        # Exodus's), and a new Exodus file made from the MSH file.
        src = self.path("tetra10-NETCDF4.exo")
        for suffix in ("vtu", "msh"):
            with self.subTest(output=suffix):
                out = self.path("tetra10." + suffix)
                run("convert", src, out, "-q")
                np.testing.assert_array_equal(meshio_read(out).cells_dict["tetra10"], tets)
        # Back to Exodus: from MSH with the block's name, from VTU with the
        # pinned node (which MSH does not keep) as a node set.
        for suffix, name, node_set in (("msh", "concrete", None), ("vtu", "", [pinned + 1])):
            with self.subTest(back_from=suffix):
                back = self.path(f"tetra10-{suffix}-back.exo")
                run("convert", self.path("tetra10." + suffix), back, "-q")
                self.assertEqual([(t, n) for t, _, n, _ in block_table(back)], [("TETRA10", name)])
                np.testing.assert_array_equal(block_table(back)[0][3], tets)
                found = variable(back, "node_ns1")
                self.assertEqual(None if found is None else found.tolist(), node_set)


def exodus_names(path, variable):
    with netCDF4.Dataset(path) as nc:
        nc.set_auto_mask(False)
        return row_strings(nc.variables[variable][:])


def variable(path, name):
    with netCDF4.Dataset(path) as nc:
        nc.set_auto_mask(False)
        return np.array(nc.variables[name][:]) if name in nc.variables else None


class NewFiles(ExodusCase):
    """Exodus files that tetsmooth writes from other formats."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        # An MSH 2.2 file (ASCII, so that its element numbers can be read
        # here): a lattice's tets in the volumes "sand" (1, the cubes of
        # x < 1) and "clay" (2), the triangles of its bottom in the surface
        # "bottom" (5) and of its top in an unnamed surface (6), the
        # triangles first, so that the tets' element numbers do not start
        # at 1.
        cls.xyz, tets = kuhn_lattice(3, seed=21)
        cls.tet_tags = np.where(cls.xyz[tets].mean(axis=1)[:, 0] < 1, 1, 2)
        cls.tets = tets
        faces = np.concatenate([tets[:, s] for s in TET_SIDES])
        _, index, counts = np.unique(np.sort(faces, axis=1), axis=0, return_index=True, return_counts=True)
        outer = faces[index[counts == 1]]
        z = cls.xyz[outer, 2]
        cls.triangles = outer[(z == 0).all(axis=1) | (z == 3).all(axis=1)]
        cls.triangle_tags = np.where(cls.xyz[cls.triangles, 2].mean(axis=1) > 0, 6, 5)
        cls.msh = cls.path("layers.msh")
        physical = [cls.triangle_tags, cls.tet_tags]
        meshio.write(cls.msh, meshio.Mesh(cls.xyz, [("triangle", cls.triangles), ("tetra", tets)],
                                          cell_data={"gmsh:physical": physical, "gmsh:geometrical": physical},
                                          field_data={"sand": np.array([1, 3]), "clay": np.array([2, 3]),
                                                      "bottom": np.array([5, 2])}),
                     file_format="gmsh22", binary=False)
        with open(cls.msh) as f:
            elements = f.read().split("$Elements\n")[1].split("$EndElements")[0].split("\n")[1:-1]
        cls.numbers = np.array([int(e.split()[0]) for e in elements])
        cls.exo = cls.path("layers.exo")
        run("convert", cls.msh, cls.exo, "-q")

    def test_meshio_reads_the_points_and_cells(self):
        theirs = meshio_read(self.exo)
        np.testing.assert_array_equal(theirs.points, self.xyz)
        # A block per region, in the order met: the tets of each volume,
        # then the triangles of each surface.
        order = [np.flatnonzero(self.tet_tags == t) for t in (1, 2)]
        self.assertEqual([c.type for c in theirs.cells], ["tetra", "tetra", "triangle", "triangle"])
        for cells, rows in zip(theirs.cells, order):
            np.testing.assert_array_equal(cells.data, self.tets[rows])
        for cells, tag in zip(theirs.cells[2:], (5, 6)):
            np.testing.assert_array_equal(cells.data, self.triangles[self.triangle_tags == tag])

    def test_blocks_are_named_and_numbered_by_the_physical_groups(self):
        blocks = block_table(self.exo)
        self.assertEqual([(t, i, n) for t, i, n, _ in blocks],
                         [("TETRA", 1, "sand"), ("TETRA", 2, "clay"), ("TRI3", 5, "bottom"), ("TRI3", 6, "")])
        tets = np.concatenate([b[3] for b in blocks[:2]])
        self.assertTrue(np.all(signed_volume6(self.xyz, tets) > 0))
        # The file's netCDF format is the 64-bit offset one, and it is an
        # Exodus file as the manual has it.
        data = contents(self.exo)
        self.assertEqual(data["model"], "NETCDF3_64BIT_OFFSET")
        self.assertEqual(data["dimensions"]["num_dim"], (3, False))
        self.assertEqual(data["dimensions"]["num_elem"][0], len(self.tets) + len(self.triangles))
        self.assertEqual(exodus_names(self.exo, "coor_names"), ["X", "Y", "Z"])
        for name in ("api_version", "version", "floating_point_word_size"):
            self.assertIn(name, data["attributes"])
        # elem_num_map holds the MSH element numbers in the blocks' order.
        triangle_numbers, tet_numbers = self.numbers[:len(self.triangles)], self.numbers[len(self.triangles):]
        expected = np.concatenate([tet_numbers[self.tet_tags == 1], tet_numbers[self.tet_tags == 2],
                                   triangle_numbers[self.triangle_tags == 5],
                                   triangle_numbers[self.triangle_tags == 6]])
        np.testing.assert_array_equal(variable(self.exo, "elem_num_map"), expected)
        # Every node is on an element written: no node set.
        self.assertNotIn("num_node_sets", data["dimensions"])

    def test_a_new_file_smooths_and_converts_back(self):
        out = self.path("layers-out.exo")
        self.smooth(self.exo, out, "-q")
        after = coordinates(out)
        moved = moved_nodes(self.xyz, after)
        self.assertTrue(moved)
        self.assertFalse(moved & boundary_nodes(self.tets))
        # Nor do the nodes of the interface x = 1 between sand and clay.
        sand, clay = (set(self.tets[self.tet_tags == tag].ravel().tolist()) for tag in (1, 2))
        self.assertTrue(sand & clay - boundary_nodes(self.tets))
        self.assertFalse(moved & sand & clay)
        # Back to MSH, the physical groups are as they were.
        back = self.path("layers-back.msh")
        run("convert", out, back, "-q")
        theirs = meshio_read(back)
        self.assertEqual({k: v.tolist() for k, v in theirs.field_data.items()},
                         {"sand": [1, 3], "clay": [2, 3], "bottom": [5, 2]})
        tags = np.concatenate([d for c, d in zip(theirs.cells, theirs.cell_data["gmsh:physical"]) if c.type == "tetra"])
        tets = theirs.cells_dict["tetra"]
        for tag in (1, 2):
            self.assertEqual(sorted(map(tuple, tets[tags == tag].tolist())),
                             sorted(map(tuple, self.tets[self.tet_tags == tag].tolist())))

    def test_the_g_name_is_exodus_too(self):
        out = self.path("layers.g")
        run("convert", self.msh, out, "-q")
        with open(out, "rb") as f:
            self.assertEqual(f.read(4), b"CDF\x02")
        np.testing.assert_array_equal(meshio_read(out, file_format="exodus").points, self.xyz)

    def test_pins_no_element_keeps_are_a_node_set(self):
        # A Medit file whose RequiredVertices name two interior nodes and a
        # node of a triangle (inside the lattice, too): the triangle keeps
        # its node pinned in a new file; the other two need a node set.
        xyz, tets = kuhn_lattice(4, seed=4)
        a, b, c = lattice_node(4, 1, 1, 1), lattice_node(4, 3, 2, 2), lattice_node(4, 2, 3, 3)
        faces = np.sort(np.concatenate([tets[:, s] for s in TET_SIDES]), axis=1).tolist()
        triangle = next(f for f in faces if c in f)
        self.assertFalse({a, b} & set(triangle))
        src = self.path("required.mesh")
        meshio.write(src, meshio.Mesh(xyz, [("tetra", tets), ("triangle", np.array([triangle]))]))
        with open(src) as f:
            text = f.read()
        with open(src, "w") as f:
            f.write(text.replace("\nEnd", f"\nRequiredVertices\n3\n{a + 1}\n{b + 1}\n{c + 1}\n\nEnd"))
        exo = self.path("required.exo")
        run("convert", src, exo, "-q")
        self.assertEqual(exodus_names(exo, "ns_names"), ["tetsmooth_pinned"])
        np.testing.assert_array_equal(variable(exo, "node_ns1"), [a + 1, b + 1])
        self.assertEqual(sorted(meshio_read(exo).point_sets["tetsmooth_pinned"].tolist()), [a, b])
        # Smoothed, the file keeps them, and the triangle's nodes.
        out = self.path("required-out.exo")
        self.smooth(exo, out, "-q")
        moved = moved_nodes(xyz, coordinates(out))
        self.assertTrue(moved)
        self.assertFalse(moved & ({a, b} | set(triangle)))
        # Without the node set they move: the set is what holds them.
        loose = write_exodus(self.path("loose.exo"), Model(xyz, [("TETRA", 1, "", tets, None),
                                                                 ("TRI3", 2, "", np.array([triangle]), None)]))
        self.smooth(loose, self.path("loose-out.exo"), "-q")
        self.assertTrue({a, b} <= moved_nodes(xyz, coordinates(self.path("loose-out.exo"))))

    def test_exodus_through_vtu_and_back_keeps_the_blocks(self):
        # VTU keeps the blocks' ids as region tags (not their names, with a
        # warning); the new file has a block per region, in the same order
        # and with the same elements, the SHELL4 block as QUAD4 (its
        # thickness attribute is lost).
        model, facts = rich_model(5, seed=6)
        src = write_exodus(self.path("trip.exo"), model, "NETCDF4")
        vtu, back = self.path("trip.vtu"), self.path("trip-back.exo")
        proc = run("convert", src, vtu)
        self.assertIn("element block names) will not be written", proc.stderr)
        self.assertIn("2 node sets, 1 side set, results over 2 time steps", proc.stderr)
        run("convert", vtu, back, "-q")
        before, after = block_table(src), block_table(back)
        self.assertEqual([(t, i, n) for t, i, n, _ in after],
                         [("TETRA", 10, ""), ("TETRA", 20, ""), ("TRI3", 30, ""), ("QUAD4", 40, "")])
        for a, b in zip(after, before):
            np.testing.assert_array_equal(a[3], b[3])
        np.testing.assert_array_equal(coordinates(back), model.xyz)
        # Pins that no element written keeps (the node and side sets') are
        # the node set tetsmooth_pinned.
        pins = facts["pins"]
        listed = pins["node set support"] | pins["node set sensor"] | pins["side set"]
        kept = pins["TRI3 block"] | pins["SHELL4 block"]
        self.assertEqual(exodus_names(back, "ns_names"), ["tetsmooth_pinned"])
        self.assertEqual(set((variable(back, "node_ns1") - 1).tolist()), listed - kept)
        # Smoothed, the new file keeps what the first one kept.
        out = self.path("trip-back-out.exo")
        self.smooth(back, out, "-q")
        moved = moved_nodes(model.xyz, coordinates(out))
        self.assertTrue(moved)
        self.assertFalse(moved & (facts["boundary"] | facts["interface"] | listed | kept))

    def test_exodus_through_msh_and_back_keeps_names_and_numbers(self):
        # MSH keeps the names (physical names) and the node and element
        # numbers (tags) too; the pins of the node and side sets are lost,
        # with a warning.
        model, _ = rich_model(5, seed=6)
        src = write_exodus(self.path("trip-msh.exo"), model, "NETCDF3_64BIT_OFFSET")
        msh, back = self.path("trip.msh"), self.path("trip-msh-back.exo")
        proc = run("convert", src, msh)
        self.assertIn("pinned nodes will not be pinned in the msh41 output", proc.stderr)
        run("convert", msh, back, "-q")
        before = {i: (t, n, rows) for t, i, n, rows in block_table(src)}
        after = {i: (t, n, rows) for t, i, n, rows in block_table(back)}
        self.assertEqual(sorted(after), sorted(before))
        for block_id, (elem_type, name, rows) in before.items():
            with self.subTest(block=block_id):
                self.assertEqual(after[block_id][:2], ({"SHELL4": "QUAD4"}.get(elem_type, elem_type), name))
                np.testing.assert_array_equal(after[block_id][2], rows)
        np.testing.assert_array_equal(variable(back, "node_num_map"), model.node_ids)
        # Element numbers follow their elements, whatever the new order of
        # the blocks.
        order_before = [i for t, i, n, rows in block_table(src) for _ in rows]
        order_after = [i for t, i, n, rows in block_table(back) for _ in rows]
        numbers_before, numbers_after = variable(src, "elem_num_map"), variable(back, "elem_num_map")
        for block_id in before:
            np.testing.assert_array_equal(numbers_after[np.array(order_after) == block_id],
                                          numbers_before[np.array(order_before) == block_id])


class MeshioFiles(ExodusCase):
    """Exodus files as meshio writes them: the `coord` variable, 64-bit
    connectivity in netCDF-4, block ids from 0, and point sets."""

    def test_tetsmooth_smooths_what_meshio_writes(self):
        xyz, tets = kuhn_lattice(4, seed=17)
        interior = np.flatnonzero(np.all((xyz > 0) & (xyz < 4), axis=1))
        held = interior[[3, 10]]
        src, out = self.path("meshio.exo"), self.path("meshio-out.exo")
        faces = np.sort(np.concatenate([tets[:, s] for s in TET_SIDES]), axis=1)
        _, index, counts = np.unique(faces, axis=0, return_index=True, return_counts=True)
        triangles = faces[index[counts == 1]][:10]
        meshio.write(src, meshio.Mesh(xyz, [("tetra", tets), ("triangle", triangles)],
                                      point_sets={"held": held}), file_format="exodus")
        data = contents(src)
        self.assertEqual(data["model"], "NETCDF4")
        self.assertIn("coord", data["variables"])
        self.assertEqual(data["variables"]["connect1"][0], "int64")
        proc = self.smooth(src, out)
        self.assertIn("before", proc.stderr)
        after = coordinates(out)
        moved = moved_nodes(xyz, after)
        self.assertTrue(moved)
        self.assertFalse(moved & (boundary_nodes(tets) | set(held.tolist())))
        self.assertGreaterEqual(radius_ratio(after, tets).min(), radius_ratio(xyz, tets).min() - 1e-12)
        theirs = meshio_read(out)
        np.testing.assert_array_equal(theirs.points, after)
        np.testing.assert_array_equal(theirs.cells_dict["tetra"], tets)
        np.testing.assert_array_equal(theirs.cells_dict["triangle"], triangles)
        np.testing.assert_array_equal(theirs.point_sets["held"], held)
        # The points held are what the point set holds: without it, they move.
        bare = self.path("meshio-bare.exo")
        meshio.write(bare, meshio.Mesh(xyz, [("tetra", tets)]), file_format="exodus")
        self.smooth(bare, self.path("meshio-bare-out.exo"), "-q")
        self.assertTrue(set(held.tolist()) & moved_nodes(xyz, coordinates(self.path("meshio-bare-out.exo"))))

    def test_meshio_block_ids_from_zero_are_two_regions(self):
        # meshio numbers its blocks 0, 1, ...: two tet blocks are two regions,
        # whose interface stays.
        xyz, tets = kuhn_lattice(4, seed=2)
        left = xyz[tets].mean(axis=1)[:, 0] < 2
        src = self.path("meshio-two.exo")
        meshio.write(src, meshio.Mesh(xyz, [("tetra", tets[left]), ("tetra", tets[~left])]), file_format="exodus")
        np.testing.assert_array_equal(variable(src, "eb_prop1"), [0, 1])
        out = self.path("meshio-two-out.exo")
        self.smooth(src, out, "-q")
        moved = moved_nodes(xyz, coordinates(out))
        self.assertTrue(moved)
        self.assertFalse(moved & set(tets[left].ravel().tolist()) & set(tets[~left].ravel().tolist()))
        vtu = self.path("meshio-two.vtu")
        run("convert", src, vtu, "-q")
        tags = meshio_read(vtu).cell_data["tetsmooth:tag"][0].ravel()
        self.assertEqual(len(set(tags[left].tolist())), 1)
        self.assertEqual(len(set(tags[~left].tolist())), 1)
        self.assertNotEqual(tags[left][0], tags[~left][0])
        # A new file keeps block 0 (MOOSE's first subdomain) as 0.
        back = self.path("meshio-two-back.exo")
        run("convert", vtu, back, "-q")
        self.assertEqual(sorted(variable(back, "eb_prop1").tolist()), [0, 1])


class Refusals(ExodusCase):
    """Files tetsmooth must refuse (exit 3, one line naming the file and the
    variable), leaving no output and an existing output as it was."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.xyz, cls.tets = kuhn_lattice(2, seed=1)

    def model(self, **kw):
        return Model(self.xyz, [("TETRA", 1, "a", self.tets, None)], **kw)

    def edited(self, name, model, edit, fmt="NETCDF3_64BIT_OFFSET"):
        """Writes `model`, then lets `edit` change the file (opened with
        netCDF4 to append)."""
        path = write_exodus(self.path(name), model, fmt)
        with netCDF4.Dataset(path, "a") as nc:
            nc.set_auto_mask(False)
            edit(nc)
        return path

    def cases(self):
        """{name: (path, fragments the message must hold)}."""
        def connect(nc):
            nc.variables["connect1"][3, 2] = len(self.xyz) + 1
        def side(nc):
            nc.variables["side_ss1"][1] = 7
        def element(nc):
            nc.variables["elem_ss1"][0] = len(self.tets) + 5
        def node_set(nc):
            nc.variables["node_ns1"][0] = 0
        sides = [(1, "load", [0, 1], [1, 2])]
        text = self.path("text.exo")
        with open(text, "w") as f:
            f.write("a mesh, but not netCDF\n")
        flat = Model(self.xyz[:, :2], [("TRI3", 1, "", np.array([[0, 1, 3]]), None)])
        hexes = Model(self.xyz, [("HEX8", 1, "", np.array([[0, 9, 12, 3, 1, 10, 13, 4]]), None)])
        with open(write_exodus(self.path("whole.exo"), self.model(), "NETCDF4"), "rb") as f:
            whole = f.read()
        with open(self.path("cut.exo"), "wb") as f:
            f.write(whole[:len(whole) // 2])
        with open(write_exodus(self.path("whole3.exo"), self.model(), "NETCDF3_64BIT_OFFSET"), "rb") as f:
            whole3 = f.read()
        with open(self.path("cut3.exo"), "wb") as f:
            f.write(whole3[:len(whole3) - 200])
        return {
            "not netCDF": (text, ["netCDF"]),
            "num_dim 2": (write_exodus(self.path("flat.exo"), flat), ["num_dim", "2"]),
            "connect out of range": (self.edited("connect.exo", self.model(), connect),
                                     ["connect1", str(len(self.xyz) + 1)]),
            "side 7": (self.edited("side.exo", self.model(side_sets=sides), side), ["side_ss1", "7"]),
            "side-set element out of range": (self.edited("element.exo", self.model(side_sets=sides), element),
                                              ["elem_ss1", str(len(self.tets) + 5)]),
            "node set entry 0": (self.edited("nodeset.exo", self.model(node_sets=[(1, "n", [0, 1])]), node_set),
                                 ["node_ns1", "0"]),
            "no tets": (write_exodus(self.path("hexes.exo"), hexes), ["TETRA"]),
            "cut HDF5": (self.path("cut.exo"), ["netCDF"]),
            "cut classic": (self.path("cut3.exo"), ["the data of variable", "cut short"]),
        }

    def test_bad_files_are_refused_and_leave_the_output_alone(self):
        for case, (src, fragments) in self.cases().items():
            with self.subTest(case=case):
                out = self.path("never.exo")
                for target, args in ((out, ["smooth", src, "-o", out, "--device", "cpu"]),
                                     (self.path("never.vtu"), ["convert", src, self.path("never.vtu")])):
                    proc = run(*args, check=False)
                    self.assert_one_error_line(proc, EXIT_INPUT, src, *fragments)
                    self.assertFalse(os.path.exists(target))
                self.assert_refused_output_kept(("smooth", src, "-o", out, "--device", "cpu"), out, "an older mesh\n")
        self.assertEqual(sorted(f for f in os.listdir(self.tmp) if f.startswith("never")), [])

    def test_a_cut_file_is_not_blamed_on_permissions(self):
        """A classic netCDF file cut short (a copy or download that stopped)
        is refused as cut short. netCDF's in-memory reader answers a read
        past the end of the bytes with EPERM, "Operation not permitted",
        which would send the user after file permissions."""
        whole = write_exodus(self.path("whole-cut.exo"), self.model(), "NETCDF3_64BIT_OFFSET")
        with open(whole, "rb") as f:
            data = f.read()
        for size in (100, len(data) // 2, len(data) - 200):
            with self.subTest(size=size):
                cut = self.path(f"cut-{size}.exo")
                with open(cut, "wb") as f:
                    f.write(data[:size])
                proc = run("quality", cut, check=False)
                self.assertEqual(proc.returncode, EXIT_INPUT, proc.stderr)
                self.assertNotIn("Operation not permitted", proc.stderr)
                self.assertIn("cut short", proc.stderr)


if __name__ == "__main__":
    unittest.main()
