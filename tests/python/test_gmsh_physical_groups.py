"""Gmsh volumes in several physical groups, and partitioned MSH 2.2 files,
through tetsmooth: two boxes fragmented with the Gmsh API, in groups
(3,11)=[1], (3,12)=[2] and (3,13)=[1,2], are smoothed into MSH 2.2, which
gives an element one physical tag a line. Gmsh must read every group with
all its elements, and tetsmooth must read its own file back without
duplicated tets. Formats with one tag per element warn about the groups
they drop, and partition tags of MSH 2.2 are dropped with a warning.

Geometry that no physical group sets apart stays put too: two boxes
stacked and fragmented, both volumes in one group (3,7)=[1,2], keep the
surface between them, from MSH 4.1, MSH 2.2 and MSH 2.2 with
Mesh.SaveParametric (nodes in $ParametricNodes, ASCII and binary); a box
keeps a surface and a point embedded in it (MSH 4.1, nodes classified on
them), also through meshio's VTU of it and MSH 4.1 written from that.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import json
import os
import unittest

import meshio
import numpy as np

from test_cli import run
from test_independent_readers import GmshScratchCase, gmsh_session, physical_groups

GROUPS = {(3, 11): [1], (3, 12): [2], (3, 13): [1, 2]}


def groups_and_tets(gmsh, path):
    """({group: entities}, {group: elements}, tets) as Gmsh reads `path`."""
    with gmsh_session(gmsh):
        gmsh.open(path)
        entities = {g: sorted(int(e) for e in gmsh.model.getEntitiesForPhysicalGroup(*g))
                    for g in gmsh.model.getPhysicalGroups()}
        tets = sum(len(t) for t in gmsh.model.mesh.getElements(3)[1])
        return entities, physical_groups(gmsh), tets


def mesh_boxes(gmsh):
    """Meshes the two boxes with their groups in the session's model."""
    gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
    gmsh.model.occ.addBox(1, 0, 0, 1, 1, 1)
    gmsh.model.occ.fragment([(3, 1)], [(3, 2)])
    gmsh.model.occ.synchronize()
    for (dim, tag), entities in GROUPS.items():
        gmsh.model.addPhysicalGroup(dim, entities, tag)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.4)
    gmsh.model.mesh.generate(3)


class SeveralPhysicalGroups(GmshScratchCase):
    SCRATCH_PREFIX = "tetsmooth_test_groups_"

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        gmsh = cls.gmsh
        cls.src = os.path.join(cls.tmp, "boxes.msh")
        with gmsh_session(gmsh):
            mesh_boxes(gmsh)
            gmsh.write(cls.src)
        cls.before = groups_and_tets(gmsh, cls.src)
        assert cls.before[0] == GROUPS, cls.before[0]

    def test_msh22_keeps_every_group_without_duplicating_tets(self):
        tets = self.before[2]
        out = self.path("smooth22.msh")
        run("smooth", self.src, "-o", out, "--output-format", "msh22", "-q")
        # Gmsh: the same groups, each with its elements, every tet once.
        self.assertEqual(groups_and_tets(self.gmsh, out), self.before)
        # tetsmooth: its own file read back is the mesh, without repeats.
        proc = run("quality", out, "--json")
        self.assertEqual(json.loads(proc.stdout)["input"]["tets"], tets)
        self.assertNotIn("repeat", proc.stderr)
        # ... and written as MSH 4.1 still has every group.
        again = self.path("again41.msh")
        run("convert", out, again, "-q")
        self.assertEqual(groups_and_tets(self.gmsh, again), self.before)
        # meshio takes an element line as a cell: one per group, each with
        # its field value.
        m = meshio.read(out)
        self.assertEqual(len(m.cells_dict["tetra"]), tets + self.before[1][(3, 13)])
        self.assertEqual(sum(len(q) for q in m.cell_data["quality"]), len(m.cells_dict["tetra"]))

    def test_one_tag_formats_warn_about_the_groups_they_drop(self):
        tets = self.before[2]
        for name in ("one.vtu", "one.vtk", "one.mesh", "one.node"):
            with self.subTest(output=name):
                proc = run("convert", self.src, self.path(name))
                self.assertIn(f"{tets} elements in several Gmsh physical groups will keep only the first",
                              proc.stderr)

    def test_partitioned_msh22_is_noted(self):
        gmsh = self.gmsh
        src = self.path("part22.msh")
        with gmsh_session(gmsh):
            mesh_boxes(gmsh)
            gmsh.model.mesh.partition(3)
            gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
            gmsh.write(src)
        out = self.path("part22_out.msh")
        proc = run("convert", src, out, "--output-format", "msh22")
        self.assertIn("the partition tags of", proc.stderr)
        self.assertIn("the written file is not partitioned", proc.stderr)
        # Every element line of the output has its two tags only.
        with open(out, encoding="utf-8") as handle:
            text = handle.read()
        lines = text[text.index("$Elements\n"):text.index("$EndElements")].splitlines()[2:]
        self.assertTrue(lines)
        self.assertEqual({line.split()[2] for line in lines}, {"2"})


def nodes_of(gmsh, path):
    """{node tag: coordinates as 24 bytes} of every node Gmsh reads in `path`:
    equal bytes are the same doubles, bit for bit."""
    with gmsh_session(gmsh):
        gmsh.open(path)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        xyz = np.asarray(coords, dtype=np.float64).reshape(-1, 3)
        return {int(t): xyz[k].tobytes() for k, t in enumerate(tags)}


def entity_nodes(gmsh, entities):
    """Tags of the nodes on `entities` [(dim, tag)] of the session's model,
    with those of their boundaries, and of those without."""
    closed, open_ = set(), set()
    for dim, tag in entities:
        closed.update(int(t) for t in gmsh.model.mesh.getNodes(dim, tag, includeBoundary=True)[0])
        open_.update(int(t) for t in gmsh.model.mesh.getNodes(dim, tag, includeBoundary=False)[0])
    return closed, open_


def classified_nodes(gmsh, path):
    """{(dim, tag): sorted tags of the nodes classified on it} of every entity
    Gmsh reads in `path`, which must open without a warning or an error."""
    with gmsh_session(gmsh):
        gmsh.logger.start()
        gmsh.open(path)
        complaints = [m for m in gmsh.logger.get() if m.startswith(("Warning", "Error"))]
        gmsh.logger.stop()
        assert not complaints, complaints
        return {(dim, tag): sorted(int(t) for t in gmsh.model.mesh.getNodes(dim, tag, includeBoundary=False)[0])
                for dim, tag in gmsh.model.getEntities()}


class GeometryWithinOnePhysicalGroup(GmshScratchCase):
    """Interfaces and embedded entities that only Gmsh's entities tell of."""

    SCRATCH_PREFIX = "tetsmooth_test_one_group_"

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        gmsh = cls.gmsh
        cls.stacked = {}
        with gmsh_session(gmsh):
            gmsh.model.occ.addBox(0, 0, 0, 1, 1, 0.5)
            gmsh.model.occ.addBox(0, 0, 0.5, 1, 1, 0.5)
            gmsh.model.occ.fragment([(3, 1)], [(3, 2)])
            gmsh.model.occ.synchronize()
            gmsh.model.addPhysicalGroup(3, [1, 2], 7)
            gmsh.option.setNumber("Mesh.MeshSizeMax", 0.12)
            gmsh.model.mesh.generate(3)
            lower = {t for _, t in gmsh.model.getBoundary([(3, 1)], oriented=False)}
            upper = {t for _, t in gmsh.model.getBoundary([(3, 2)], oriented=False)}
            shared = lower & upper
            assert len(shared) == 1, shared
            cls.shared, cls.shared_inside = entity_nodes(gmsh, [(2, shared.pop())])
            for name, version, binary, parametric in [("stacked41.msh", 4.1, 0, 0), ("stacked22.msh", 2.2, 0, 0),
                                                      ("stacked_param22.msh", 2.2, 0, 1),
                                                      ("stacked_param_binary22.msh", 2.2, 1, 1)]:
                gmsh.option.setNumber("Mesh.MshFileVersion", version)
                gmsh.option.setNumber("Mesh.Binary", binary)
                gmsh.option.setNumber("Mesh.SaveParametric", parametric)
                cls.stacked[name] = os.path.join(cls.tmp, name)
                gmsh.write(cls.stacked[name])
        with gmsh_session(gmsh):
            gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
            surface = gmsh.model.occ.addRectangle(0.25, 0.25, 0.5, 0.5, 0.5)
            point = gmsh.model.occ.addPoint(0.5, 0.5, 0.2)
            gmsh.model.occ.synchronize()
            gmsh.model.mesh.embed(2, [surface], 3, 1)
            gmsh.model.mesh.embed(0, [point], 3, 1)
            gmsh.model.addPhysicalGroup(3, [1], 7)
            gmsh.option.setNumber("Mesh.MeshSizeMax", 0.12)
            gmsh.model.mesh.generate(3)
            cls.embedded, _ = entity_nodes(gmsh, [(2, surface), (0, point)])
            cls.with_embedded = os.path.join(cls.tmp, "embedded41.msh")
            gmsh.write(cls.with_embedded)

    def smooth_keeps(self, src, kept):
        """Smooths `src` into MSH 4.1; returns the run after checking that the
        nodes tagged in `kept` did not move and that others did."""
        out = os.path.join(self.tmp, "out_" + os.path.basename(src))
        proc = run("smooth", src, "-o", out)
        before, after = nodes_of(self.gmsh, src), nodes_of(self.gmsh, out)
        self.assertEqual(before.keys(), after.keys())
        self.assertEqual({t for t in kept if after[t] != before[t]}, set())
        self.assertGreater(sum(after[t] != before[t] for t in before), 0)
        with open(out, "rb") as handle:
            self.assertNotIn(b"$ParametricNodes", handle.read())
        return proc

    def test_surface_between_volumes_of_one_group_stays_put(self):
        self.assertGreater(len(self.shared_inside), 0)
        for name, src in self.stacked.items():
            with self.subTest(input=name):
                proc = self.smooth_keeps(src, self.shared)
                # The note counts the surface's nodes off the boundary.
                self.assertIn(f"{len(self.shared_inside)} nodes on interfaces between regions", proc.stderr)
                if name == "stacked41.msh":
                    # meshio's VTU and VTK of it keep the volumes apart
                    # (gmsh:geometrical): the same nodes stay in place.
                    mesh = meshio.read(src)
                    for suffix in ("vtu", "vtk"):
                        copy = os.path.join(self.tmp, f"stacked_meshio.{suffix}")
                        meshio.write(copy, mesh)
                        smoothed = run("smooth", copy, "-o", copy + ".out.vtu")
                        self.assertIn(f"{len(self.shared_inside)} nodes on interfaces between regions",
                                      smoothed.stderr)
                self.assertEqual("parametric coordinates of" in proc.stderr, "param" in name, proc.stderr)
                # quality counts the surface's nodes out of the movable ones.
                report = json.loads(run("quality", src, "--json").stdout)["input"]
                self.assertEqual(report["movable_nodes"],
                                 report["nodes"] - report["boundary_nodes"] - len(self.shared_inside))

    def test_surface_and_point_embedded_in_a_volume_stay_put(self):
        proc = self.smooth_keeps(self.with_embedded, self.embedded)
        feature_note = f"{len(self.embedded)} nodes on Gmsh points, curves or surfaces inside the mesh stay fixed"
        self.assertIn(feature_note, proc.stderr)
        # VTU keeps the nodes' classification as meshio's gmsh:dim_tags, so a
        # run on tetsmooth's VTU, or on meshio's, keeps them in place too.
        ours = os.path.join(self.tmp, "embedded.vtu")
        converted = run("convert", self.with_embedded, ours)
        self.assertNotIn("Gmsh's entities keep in place", converted.stderr)
        theirs = os.path.join(self.tmp, "embedded_meshio.vtu")
        meshio.write(theirs, meshio.read(self.with_embedded))
        for vtu in (ours, theirs):
            with self.subTest(vtu=os.path.basename(vtu)):
                self.assertIn(feature_note, run("smooth", vtu, "-o", vtu + ".out.vtu").stderr)
        # MSH 4.1 from meshio's VTU, where only gmsh:dim_tags names the
        # points, curves and surfaces (no element is on them), declares them
        # with their nodes as Gmsh wrote them, so a later run keeps the
        # embedded nodes in place too.
        again = os.path.join(self.tmp, "embedded_from_vtu.msh")
        self.assertNotIn("Gmsh's entities keep in place", run("convert", theirs, again).stderr)
        self.assertEqual(classified_nodes(self.gmsh, again), classified_nodes(self.gmsh, self.with_embedded))
        self.assertIn(feature_note, self.smooth_keeps(again, self.embedded).stderr)
        # A format without Gmsh's entities says what a later run may move.
        medit = run("convert", self.with_embedded, os.path.join(self.tmp, "embedded.mesh"))
        self.assertIn(f"{len(self.embedded)} nodes that Gmsh's entities keep in place", medit.stderr)


if __name__ == "__main__":
    unittest.main()
