"""Second-order (10-node) tets through tetsmooth, on a mesh made by the real
Gmsh: tests/data/gmsh_order2_41.msh, a unit box with a spherical cavity
raised to second order, and tests/data/vtu_meshio_order2.vtu, meshio's copy
of it (both from tests/data/gmsh_order2_make.py).

Smoothing moves corner nodes only and carries each midside node along with
its edge's corners, so every straight edge stays straight and keeps its
midside node where it was relative to the edge; tets with a curved edge (the
ones on the cavity) keep all ten nodes; the boundary, its 6-node triangles
and 3-node lines stay as they were. The outputs are read back with meshio
and, the .msh ones, with the Gmsh API, which also checks that no tet's
Jacobian turns non-positive. Formats that hold 4-node tets only refuse the
mesh (exit 4, no file), and a file mixing 4-node and 10-node tets is refused
on reading (exit 3).

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import json
import os
import re
import unittest

import meshio
import numpy as np

from test_cli import EXIT_INPUT, EXIT_OUTPUT, radius_ratio, run
from test_independent_readers import GmshScratchCase, elements_by_tag, gmsh_session

SOURCE_DIR = os.environ.get("TETSMOOTH_SOURCE_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                                    "..", "..")
DATA = os.path.join(SOURCE_DIR, "tests", "data")
MSH_FIXTURE = os.path.join(DATA, "gmsh_order2_41.msh")
VTU_FIXTURE = os.path.join(DATA, "vtu_meshio_order2.vtu")

# The corners at the ends of the midside nodes 4..9 of a tetra10 in VTK's
# order, which meshio uses too.
VTK_EDGES = np.array([[0, 1], [1, 2], [0, 2], [0, 3], [1, 3], [2, 3]])
# Gmsh's type 11 has midside nodes 8 and 9 the other way round (on edges
# 2-3 and 1-3); this permutation is its own inverse.
GMSH_VTK_ORDER = [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]
GMSH_EDGES = VTK_EDGES[np.array(GMSH_VTK_ORDER[4:]) - 4]

# tetsmooth's rule: an edge is curved when its midside node is farther than
# this times the edge's length from the edge's midpoint.
CURVED = 1e-4
# The box is 1 wide: a midside node carried along with its corners keeps its
# offset from the midpoint up to a few roundings of coordinates below 1.
OFFSET_ATOL = 1e-12

# (file name, --output-format, meshio can read it). meshio 5.0 cannot read
# $ElementData from MSH 2.2 at all (its cell_data_from_raw takes the length
# of each (type, cells) pair, 2, for the number of cells), so the MSH 2.2
# output is read with the Gmsh API only.
OUTPUTS = [("smooth41.msh", "msh41", True), ("smooth41-binary.msh", "msh41-binary", True),
           ("smooth22.msh", "msh22", False), ("smooth.vtu", "vtu", True), ("smooth.vtk", "vtk", True)]


def midside_offsets(xyz, tets):
    """(tets, 6, 3): each midside node's position less its edge's midpoint,
    for tets (n, 10) in VTK's node order."""
    ends = xyz[tets[:, VTK_EDGES]]  # (tets, 6, 2, 3)
    return xyz[tets[:, 4:]] - 0.5 * (ends[:, :, 0] + ends[:, :, 1])


def curved_tets(xyz, tets):
    """Mask of the tets with an edge that tetsmooth takes as curved."""
    ends = xyz[tets[:, VTK_EDGES]]
    length = np.linalg.norm(ends[:, :, 1] - ends[:, :, 0], axis=2)
    offset = np.linalg.norm(midside_offsets(xyz, tets), axis=2)
    return np.any(offset > CURVED * length, axis=1)


def read_gmsh(gmsh, path):
    """What the Gmsh API reads in `path`: node tags in ascending order, their
    coordinates, the 10-node tets as rows into them in VTK's order, every
    element by tag (elements_by_tag), and the Jacobian determinants of the
    tets at the Gauss points of a degree-4 rule."""
    with gmsh_session(gmsh):
        gmsh.open(path)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        order = np.argsort(tags)
        tags = np.asarray(tags)[order]
        xyz = np.asarray(coords, dtype=np.float64).reshape(-1, 3)[order]
        _, tet_nodes = gmsh.model.mesh.getElementsByType(11)
        tets = np.searchsorted(tags, np.asarray(tet_nodes).reshape(-1, 10))[:, GMSH_VTK_ORDER]
        points, _ = gmsh.model.mesh.getIntegrationPoints(11, "Gauss4")
        _, determinants, _ = gmsh.model.mesh.getJacobians(11, points)
        return dict(tags=tags, xyz=xyz, tets=tets, elements=elements_by_tag(gmsh),
                    determinants=np.asarray(determinants))


def msh41_text(blocks, xyz):
    """A minimal MSH 4.1 ASCII file: one volume entity, nodes tagged from 1,
    and element blocks [(Gmsh type, rows of 1-based node tags)]."""
    lines = ["$MeshFormat", "4.1 0 8", "$EndMeshFormat",
             "$Entities", "0 0 0 1", "1 0 0 0 3 1 1 0 0", "$EndEntities",
             "$Nodes", f"1 {len(xyz)} 1 {len(xyz)}", f"3 1 0 {len(xyz)}"]
    lines += [str(k + 1) for k in range(len(xyz))]
    lines += [f"{x!r} {y!r} {z!r}" for x, y, z in xyz]
    lines += ["$EndNodes", "$Elements"]
    count = sum(len(rows) for _, rows in blocks)
    lines.append(f"{len(blocks)} {count} 1 {count}")
    tag = 0
    for gmsh_type, rows in blocks:
        lines.append(f"3 1 {gmsh_type} {len(rows)}")
        for row in rows:
            tag += 1
            lines.append(" ".join(str(n) for n in [tag, *row]))
    lines.append("$EndElements")
    return "\n".join(lines) + "\n"


class SecondOrderSmoothing(GmshScratchCase):
    SCRATCH_PREFIX = "tetsmooth_test_order2_"

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        source = meshio.read(MSH_FIXTURE)
        cls.xyz = source.points
        cls.tets = source.cells_dict["tetra10"]
        cls.triangles = source.cells_dict["triangle6"]
        cls.lines = source.cells_dict["line3"]
        # Every boundary face is in a physical group, so the triangles' nodes
        # are the boundary nodes, midside ones included.
        cls.boundary = np.unique(cls.triangles)
        cls.corners = np.unique(cls.tets[:, :4])
        cls.curved = curved_tets(cls.xyz, cls.tets)
        cls.held = np.setdiff1d(np.unique(cls.tets[cls.curved, :4]), cls.boundary)
        cls.movable = np.setdiff1d(np.setdiff1d(cls.corners, cls.boundary), cls.held)
        cls.q_before = radius_ratio(cls.xyz, cls.tets[:, :4])
        cls.gmsh_before = read_gmsh(cls.gmsh, MSH_FIXTURE)
        # Without these the tests below would pass for want of anything to check.
        assert cls.curved.sum() > 0 and len(cls.held) > 0 and len(cls.movable) > 0, \
            (cls.curved.sum(), len(cls.held), len(cls.movable))
        assert cls.gmsh_before["determinants"].min() > 0
        # Gmsh and meshio read the fixture alike (nodes in tag order, tets
        # in VTK's order), so either reader's output can be set against it.
        assert np.array_equal(cls.gmsh_before["xyz"], cls.xyz)
        assert np.array_equal(cls.gmsh_before["tets"], cls.tets)

        cls.smoothed = {}
        for name, fmt, _ in OUTPUTS:
            out = cls.path(name)
            report = cls.path(name + ".json")
            proc = run("smooth", MSH_FIXTURE, "-o", out, "--output-format", fmt, "--report", report)
            with open(report, encoding="utf-8") as handle:
                cls.smoothed[fmt] = (out, proc, json.load(handle))

    def assert_smoothed(self, xyz, tets):
        """Checks a smoothed mesh (nodes and 10-node tets in VTK order, read
        back by meshio or Gmsh) against the fixture."""
        self.assertEqual(xyz.shape, self.xyz.shape)
        np.testing.assert_array_equal(tets, self.tets)
        # Midside nodes kept their place relative to their edges.
        np.testing.assert_allclose(midside_offsets(xyz, tets), midside_offsets(self.xyz, self.tets),
                                   rtol=0, atol=OFFSET_ATOL)
        # The boundary is where it was, bit for bit.
        np.testing.assert_array_equal(xyz[self.boundary], self.xyz[self.boundary])
        # Something was smoothed, and only movable corners moved by
        # themselves (midside nodes follow them).
        moved = np.flatnonzero(np.any(xyz[self.corners] != self.xyz[self.corners], axis=1))
        self.assertGreater(len(moved), 0)
        self.assertTrue(set(self.corners[moved]) <= set(self.movable))
        # The corner tets got no worse.
        self.assertGreaterEqual(radius_ratio(xyz, tets[:, :4]).min(), self.q_before.min())

    def test_meshio_reads_the_smoothed_outputs(self):
        for name, fmt, readable in OUTPUTS:
            if not readable:
                continue
            with self.subTest(format=fmt):
                m = meshio.read(self.smoothed[fmt][0])
                self.assertEqual(set(m.cells_dict), {"tetra10", "triangle6", "line3"})
                self.assert_smoothed(m.points, m.cells_dict["tetra10"])
                # The triangles and lines come back as they were.
                np.testing.assert_array_equal(m.cells_dict["triangle6"], self.triangles)
                np.testing.assert_array_equal(m.cells_dict["line3"], self.lines)
                # "boundary" is 1 on exactly the triangles' nodes.
                flag = np.zeros(len(self.xyz))
                flag[self.boundary] = 1
                np.testing.assert_array_equal(np.asarray(m.point_data["boundary"]).ravel(), flag)

    def test_gmsh_reads_the_smoothed_msh_files(self):
        for name, fmt, _ in OUTPUTS:
            if not name.endswith(".msh"):
                continue
            with self.subTest(format=fmt):
                after = read_gmsh(self.gmsh, self.smoothed[fmt][0])
                # Every element, tets (type 11), triangles (9) and lines (8),
                # keeps its tag, type and nodes.
                self.assertEqual(after["elements"], self.gmsh_before["elements"])
                self.assertEqual({etype for block in after["elements"].values() for etype, _ in block.values()},
                                 {8, 9, 11})
                np.testing.assert_array_equal(after["tags"], self.gmsh_before["tags"])
                self.assert_smoothed(after["xyz"], after["tets"])
                # A midside node out of place bends its tets: one could then
                # fold inside although its corners did not. Gmsh's Jacobians
                # at the Gauss points say none did.
                self.assertGreater(after["determinants"].min(), 0)

    def smoothed_nodes(self, fmt):
        """The nodes of the smoothed output in format `fmt`, as meshio reads
        them or, where it cannot, Gmsh."""
        out, _, _ = self.smoothed[fmt]
        readable = next(r for _, f, r in OUTPUTS if f == fmt)
        return meshio.read(out).points if readable else read_gmsh(self.gmsh, out)["xyz"]

    def test_curved_tets_keep_all_their_nodes(self):
        nodes = np.unique(self.tets[self.curved])
        for _, fmt, _ in OUTPUTS:
            with self.subTest(format=fmt):
                np.testing.assert_array_equal(self.smoothed_nodes(fmt)[nodes], self.xyz[nodes])
        # The note counts the same curved tets and held corners.
        stderr = self.smoothed["msh41"][1].stderr
        note = re.search(r"([\d,]+) second-order tets have curved edges and keep their shape: "
                         r"([\d,]+) corner nodes off the boundary stay fixed", stderr)
        self.assertIsNotNone(note, stderr)
        self.assertEqual(int(note[1].replace(",", "")), int(self.curved.sum()))
        self.assertEqual(int(note[2].replace(",", "")), len(self.held))

    def test_report_measures_the_corner_tets(self):
        _, _, report = self.smoothed["msh41"]
        xyz = meshio.read(self.smoothed["msh41"][0]).points
        self.assertEqual(report["input"]["tets"], len(self.tets))
        self.assertEqual(report["movable_nodes"], len(self.movable))
        quality = report["quality"]
        self.assertAlmostEqual(quality["before"]["min"], self.q_before.min(), delta=1e-12)
        self.assertAlmostEqual(quality["after"]["min"], radius_ratio(xyz, self.tets[:, :4]).min(), delta=1e-12)
        self.assertGreaterEqual(quality["after"]["min_movable"], quality["before"]["min_movable"])

    def test_meshio_vtu_gives_the_same_result(self):
        # The VTU has the same doubles, its tets in VTK's order: read right,
        # it is the same mesh, so it smooths to the same nodes.
        out = self.path("from_vtu.vtu")
        run("smooth", VTU_FIXTURE, "-o", out, "-q")
        from_vtu = meshio.read(out)
        from_msh = meshio.read(self.smoothed["vtu"][0])
        np.testing.assert_array_equal(from_vtu.cells_dict["tetra10"], self.tets)
        np.testing.assert_allclose(from_vtu.points, from_msh.points, rtol=0, atol=1e-12)
        # A reader and writer that both missed the reorder would undo each
        # other above; the VTU's tets written as MSH must be Gmsh's.
        msh = self.path("from_vtu.msh")
        run("convert", VTU_FIXTURE, msh, "-q")
        np.testing.assert_array_equal(read_gmsh(self.gmsh, msh)["tets"], self.gmsh_before["tets"])

    def test_other_variants_give_the_same_result(self):
        # The fixture as Gmsh writes its other MSH variants and as meshio
        # writes legacy VTK (cell type 24): the same mesh each time, so the
        # same smoothed nodes as from the MSH 4.1 fixture.
        gmsh = self.gmsh
        sources = []
        with gmsh_session(gmsh):
            gmsh.open(MSH_FIXTURE)
            for name, version, binary in [("gmsh41-binary.msh", 4.1, 1), ("gmsh22.msh", 2.2, 0),
                                          ("gmsh22-binary.msh", 2.2, 1)]:
                gmsh.option.setNumber("Mesh.MshFileVersion", version)
                gmsh.option.setNumber("Mesh.Binary", binary)
                sources.append(self.path(name))
                gmsh.write(sources[-1])
        mesh = meshio.read(MSH_FIXTURE)
        mesh.cell_sets = {}  # meshio's own "gmsh:bounding_entities", which its VTK writers cannot place
        for name, kwargs in [("meshio51.vtk", dict(binary=False)),
                             ("meshio42-binary.vtk", dict(file_format="vtk42", binary=True))]:
            sources.append(self.path(name))
            meshio.write(sources[-1], mesh, **kwargs)
        reference = meshio.read(self.smoothed["vtu"][0]).points
        for src in sources:
            with self.subTest(input=os.path.basename(src)):
                out = src + ".out.vtu"
                run("smooth", src, "-o", out, "-q")
                m = meshio.read(out)
                np.testing.assert_array_equal(m.cells_dict["tetra10"], self.tets)
                np.testing.assert_allclose(m.points, reference, rtol=0, atol=1e-12)

    def test_formats_of_4_node_tets_refuse_the_mesh(self):
        out = self.path
        # (what is run, the files it must not leave)
        refusals = [(["convert", MSH_FIXTURE, out("out.mesh")], ["out.mesh"]),
                    (["convert", MSH_FIXTURE, out("out.tsm")], ["out.tsm"]),
                    (["smooth", MSH_FIXTURE, "-o", out("out.mesh"), "-q"], ["out.mesh"])]
        for args, made in refusals:
            with self.subTest(command=args[0], output=made[0]):
                before = set(os.listdir(self.tmp))
                proc = run(*args, check=False)
                self.assertEqual(proc.returncode, EXIT_OUTPUT, proc.stderr)
                self.assertIn("holds 4-node tets only", proc.stderr)
                # No output, nor any temporary file, is left behind.
                for name in made:
                    self.assertFalse(os.path.exists(out(name)), name)
                self.assertEqual(set(os.listdir(self.tmp)), before)

    def test_tetgen_keeps_the_10_node_tets(self):
        # TetGen's .ele holds 10-node tets in its own node order (-o2); a
        # trip through it and back to MSH gives every tet the same ten points.
        node = self.path("trip.node")
        back = self.path("back.msh")
        run("convert", MSH_FIXTURE, node, "-q")
        with open(self.path("trip.ele"), encoding="utf-8") as handle:
            self.assertEqual(handle.readline().split()[:2], [str(len(self.tets)), "10"])
        run("convert", node, back, "-q")
        original = meshio.read(MSH_FIXTURE)
        trip = meshio.read(back)
        np.testing.assert_array_equal(trip.points[trip.cells_dict["tetra10"]],
                                      original.points[original.cells_dict["tetra10"]])

    def test_refusal_leaves_an_existing_output_alone(self):
        out = self.path("existing.mesh")
        with open(out, "w", encoding="utf-8") as handle:
            handle.write("kept\n")
        proc = run("convert", MSH_FIXTURE, out, check=False)
        self.assertEqual(proc.returncode, EXIT_OUTPUT, proc.stderr)
        with open(out, encoding="utf-8") as handle:
            self.assertEqual(handle.read(), "kept\n")

    def test_mixed_4_and_10_node_tets_are_refused(self):
        # Two tets apart from each other, both positively oriented: nodes
        # 1-4 for the linear one, 5-8 corners and 9-14 midside nodes (Gmsh's
        # order) for the quadratic one.
        unit = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
        corners = unit + [2, 0, 0]
        midsides = 0.5 * (corners[GMSH_EDGES[:, 0]] + corners[GMSH_EDGES[:, 1]])
        xyz = np.vstack([unit, corners, midsides])
        linear = (4, [[1, 2, 3, 4]])
        quadratic = (11, [list(range(5, 15))])
        # The same file with either tet alone is read, so it is the mix that
        # is refused. A lone 4-node tet leaves nodes 5-14 unused, which may
        # warn but is no error.
        for name, blocks, code in [("linear.msh", [linear], 0), ("quadratic.msh", [quadratic], 0),
                                   ("mixed.msh", [linear, quadratic], EXIT_INPUT),
                                   ("mixed_other_way.msh", [quadratic, linear], EXIT_INPUT)]:
            with self.subTest(input=name):
                src = self.path(name)
                with open(src, "w", encoding="utf-8") as handle:
                    handle.write(msh41_text(blocks, xyz))
                proc = run("quality", src, "--json", check=False)
                self.assertEqual(proc.returncode, code, proc.stderr)
                if code:
                    self.assertIn("4-node", proc.stderr)
                    self.assertIn("10-node", proc.stderr)


if __name__ == "__main__":
    unittest.main()
