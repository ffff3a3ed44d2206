#!/usr/bin/python3
"""Regenerates vtu_zlib_meshio.vtu and vtu_lzma_meshio.vtu with meshio
(Debian's python3-meshio): the two tets and boundary triangle of the other
vtu_*.vtu fixtures, written as meshio writes by default (inline base64,
zlib, no header_type: UInt32) and with LZMA and UInt64 headers. Run from
tests/data."""
import meshio
import numpy as np

points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], dtype=float)
mesh = meshio.Mesh(points, [("tetra", np.array([[0, 1, 2, 3], [1, 2, 3, 4]])), ("triangle", np.array([[2, 3, 4]]))])
meshio.write("vtu_zlib_meshio.vtu", mesh)
meshio.write("vtu_lzma_meshio.vtu", mesh, compression="lzma", header_type="UInt64")
