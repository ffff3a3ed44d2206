"""Gmsh volumes in several physical groups, and partitioned MSH 2.2 files,
through tetsmooth: two boxes fragmented with the Gmsh API, in groups
(3,11)=[1], (3,12)=[2] and (3,13)=[1,2], are smoothed into MSH 2.2, which
gives an element one physical tag a line. Gmsh must read every group with
all its elements, and tetsmooth must read its own file back without
duplicated tets. Formats with one tag per element warn about the groups
they drop, and partition tags of MSH 2.2 are dropped with a warning.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import json
import os
import unittest

import meshio

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

    def path(self, name):
        return os.path.join(self.tmp, name)

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


if __name__ == "__main__":
    unittest.main()
