"""Region tags written by other programs reach tetsmooth's output: a Gmsh mesh
with physical groups, converted by meshio to VTU (and legacy VTK), where the
tags are the cell-data array "gmsh:physical" (and the Gmsh entities
"gmsh:geometrical"), is converted by `tetsmooth convert` back to MSH and read
with the Gmsh API, which must find the same physical groups with the same
element counts as in the original, and with meshio, which must find the
elements on the same entities.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import unittest

import meshio

from test_cli import run
from test_independent_readers import GmshScratchCase, gmsh_session, physical_groups


def physical_group_sizes(gmsh, path):
    """{(dim, physical tag): number of elements} of the mesh file at path."""
    with gmsh_session(gmsh):
        gmsh.open(path)
        return physical_groups(gmsh)


def entity_counts(path):
    """{(cell type, Gmsh entity tag): number of elements} of the mesh file at
    path, as meshio reads its gmsh:geometrical data."""
    mesh = meshio.read(path)
    counts = {}
    for block, entities in zip(mesh.cells, mesh.cell_data["gmsh:geometrical"]):
        for entity in entities:
            key = (block.type, int(entity))
            counts[key] = counts.get(key, 0) + 1
    return counts


def write_box_with_groups(gmsh, path, version):
    """A coarse box, the volume in physical group 7, two faces in 3, an edge
    in 5 and a corner in 9: tets, triangles, lines and a vertex, each kind
    tagged (Gmsh saves only the elements of physical groups)."""
    with gmsh_session(gmsh):
        gmsh.model.occ.addBox(0, 0, 0, 1, 2, 3)
        gmsh.model.occ.synchronize()
        gmsh.model.addPhysicalGroup(3, [1], 7)
        gmsh.model.addPhysicalGroup(2, [1, 2], 3)
        gmsh.model.addPhysicalGroup(1, [1], 5)
        gmsh.model.addPhysicalGroup(0, [1], 9)
        gmsh.option.setNumber("Mesh.MeshSizeMax", 0.6)
        gmsh.model.mesh.generate(3)
        gmsh.option.setNumber("Mesh.MshFileVersion", version)
        gmsh.write(path)


class ForeignTags(GmshScratchCase):
    SCRATCH_PREFIX = "tetsmooth_test_tags_"

    # meshio's VTU (binary uncompressed and ASCII) and legacy VTK (ASCII, and
    # BINARY in the 5.1 and 4.2 layouts), whose cell data are FIELD arrays.
    VIA = [("vtu", dict(binary=True, compression=None)), ("ascii.vtu", dict(binary=False)),
           ("vtk", dict(binary=False)), ("bin.vtk", dict(binary=True)),
           ("bin42.vtk", dict(binary=True, fmt_version="4.2"))]

    def test_gmsh_physical_groups_survive_meshio_and_tetsmooth(self):
        for version in (2.2, 4.1):
            original = self.path(f"box{version}.msh")
            write_box_with_groups(self.gmsh, original, version)
            expected = physical_group_sizes(self.gmsh, original)
            self.assertEqual(set(expected), {(3, 7), (2, 3), (1, 5), (0, 9)})
            mesh = meshio.read(original)
            self.assertIn("gmsh:physical", mesh.cell_data)
            for suffix, kwargs in self.VIA:
                with self.subTest(msh=version, via=suffix):
                    middle = self.path(f"box{version}.{suffix}")
                    # meshio.write does not pass fmt_version on; its VTK writer takes it.
                    write = meshio.vtk.write if "fmt_version" in kwargs else meshio.write
                    write(middle, mesh, **kwargs)
                    out = middle + ".msh"
                    proc = run("convert", middle, out)
                    self.assertEqual(physical_group_sizes(self.gmsh, out), expected)
                    # Both tag arrays are carried over, and named in no
                    # warning: the elements keep their volumes and surfaces.
                    self.assertNotIn("'gmsh:geometrical'", proc.stderr)
                    self.assertNotIn("'gmsh:physical'", proc.stderr)
                    self.assertEqual(entity_counts(out), entity_counts(original))


if __name__ == "__main__":
    unittest.main()
