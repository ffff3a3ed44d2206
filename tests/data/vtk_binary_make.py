#!/usr/bin/python3
"""Regenerates vtk_binary42.vtk and vtk_binary51.vtk with meshio (Debian's
python3-meshio), whose legacy VTK writer is BINARY by default: two tets and a
vertex cell on five points, a region tag per cell (int32) and a fixed-node
flag (uint8) as FIELD arrays, and a float64 point array that is not carried
over. Run from tests/data."""
import meshio
import numpy as np

points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], dtype=np.float64)
points[4] = [1.25, 0.75, 1.0 / 3.0]  # a coordinate no short decimal holds
cells = [("tetra", np.array([[0, 1, 2, 3], [1, 2, 3, 4]])), ("vertex", np.array([[4]]))]
mesh = meshio.Mesh(points, cells,
                   point_data={"tetsmooth:fixed": np.array([0, 0, 0, 0, 1], dtype=np.uint8),
                               "pressure": np.arange(5, dtype=np.float64) / 4},
                   cell_data={"tetsmooth:tag": [np.array([5, 6], dtype=np.int32), np.array([9], dtype=np.int32)]})
for version in ("4.2", "5.1"):
    meshio.vtk.write(f"vtk_binary{version.replace('.', '')}.vtk", mesh, binary=True, fmt_version=version)
