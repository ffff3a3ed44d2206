"""Partitioned Gmsh meshes through tetsmooth: a box meshed and cut into
partitions with the Gmsh API (MSH 4.1, ASCII and binary) is smoothed, and
Gmsh reads the result with the physical groups the mesh had before it was
partitioned, the same number of elements in each, and the boundary nodes
where they were.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import json
import unittest

import meshio
import numpy as np

from test_cli import run
from test_independent_readers import GmshScratchCase, boundary_nodes, gmsh_session, physical_groups

INPUTS = [("part-ascii.msh", 0), ("part-binary.msh", 1)]


def nodes_by_tag(gmsh):
    tags, coords, _ = gmsh.model.mesh.getNodes()
    return dict(zip(np.asarray(tags).tolist(), np.asarray(coords).reshape(-1, 3)))


def boundary_node_tags(gmsh):
    """Tags of the nodes on faces that belong to one tet only."""
    types, _, node_tags = gmsh.model.mesh.getElements(dim=3)
    tets = np.concatenate([np.asarray(n).reshape(-1, 4) for t, n in zip(types, node_tags) if t == 4])
    return boundary_nodes(tets)


class PartitionedGmshMeshes(GmshScratchCase):
    SCRATCH_PREFIX = "tetsmooth_test_partitions_"

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        gmsh = cls.gmsh
        with gmsh_session(gmsh):
            gmsh.model.add("box")
            gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
            gmsh.model.occ.synchronize()
            gmsh.model.addPhysicalGroup(3, [1], 1)
            gmsh.model.addPhysicalGroup(2, [1], 2)
            gmsh.option.setNumber("Mesh.MeshSizeMax", 0.3)
            gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
            gmsh.model.mesh.generate(3)
            # The reference: the groups before partitioning. (Gmsh reads a
            # partitioned file with more: the elements it puts on the
            # boundaries between partitions carry their parents' tags.)
            cls.groups = physical_groups(gmsh)
            gmsh.write(cls.path("whole.msh"))
            gmsh.model.mesh.partition(3)
            for name, binary in INPUTS:
                gmsh.option.setNumber("Mesh.Binary", binary)
                gmsh.write(cls.path(name))
        assert set(cls.groups) == {(2, 2), (3, 1)}, cls.groups
        # Nodes as each file holds them (ASCII has 16 digits), and the
        # smoothed files.
        cls.nodes, cls.boundary, cls.smoothed = {}, {}, {}
        for name, _ in INPUTS:
            with gmsh_session(gmsh):
                gmsh.open(cls.path(name))
                cls.nodes[name] = nodes_by_tag(gmsh)
                cls.boundary[name] = boundary_node_tags(gmsh)
            out = cls.path("smoothed-" + name)
            cls.smoothed[name] = (out, run("smooth", cls.path(name), "-o", out))

    def test_gmsh_reads_the_groups_and_the_unmoved_boundary(self):
        gmsh = self.gmsh
        for name, _ in INPUTS:
            with self.subTest(input=name):
                out, _ = self.smoothed[name]
                with gmsh_session(gmsh):
                    gmsh.open(out)
                    groups = physical_groups(gmsh)
                    xyz = nodes_by_tag(gmsh)
                self.assertEqual(groups, self.groups)
                before, boundary = self.nodes[name], self.boundary[name]
                self.assertEqual(set(xyz), set(before))
                for tag in boundary:
                    np.testing.assert_array_equal(xyz[tag], before[tag], err_msg=f"boundary node {tag}")
                moved = [t for t in xyz if t not in boundary and not np.array_equal(xyz[t], before[t])]
                self.assertGreater(len(moved), 0, "smoothing moved no interior node")

    def test_meshio_reads_the_groups(self):
        for name, _ in INPUTS:
            with self.subTest(input=name):
                m = meshio.read(self.smoothed[name][0])
                physical = {}
                for block, tags in zip(m.cells, m.cell_data["gmsh:physical"]):
                    for tag in np.asarray(tags).tolist():
                        key = ({"triangle": 2, "tetra": 3}[block.type], tag)
                        physical[key] = physical.get(key, 0) + 1
                self.assertEqual(physical, self.groups)

    def test_user_is_told_the_partitions_are_merged(self):
        for name, _ in INPUTS:
            with self.subTest(input=name):
                stderr = self.smoothed[name][1].stderr
                self.assertIn(f"warning: {self.path(name)}: the partitions are merged and ", stderr)
                self.assertIn("elements on partition boundaries dropped; the written file is not partitioned", stderr)

    # The elements on the boundaries between partitions are dropped, so they
    # pin no node: as many nodes may move as in the mesh before partitioning.
    def test_partition_boundaries_pin_no_nodes(self):
        whole = json.loads(run("quality", self.path("whole.msh"), "--json").stdout)["input"]
        for name, _ in INPUTS:
            with self.subTest(input=name):
                part = json.loads(run("quality", self.path(name), "--json").stdout)["input"]
                self.assertEqual(part["movable_nodes"], whole["movable_nodes"])
                self.assertEqual(part["boundary_nodes"], whole["boundary_nodes"])


if __name__ == "__main__":
    unittest.main()
