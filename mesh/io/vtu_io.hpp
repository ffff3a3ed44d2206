#pragma once
// VTK XML UnstructuredGrid (.vtu).
//
// Writing: version 1.0, header_type UInt64, little-endian, every array in one
// raw appended block. Points Float64; connectivity Int32, offsets Int64,
// types UInt8 (tetra 10, or quadratic tetra 24 for second-order tets, then
// pass-through blocks as vertex 1, line 3, triangle 5, quad 9, quadratic
// edge 21 or quadratic triangle 22; see vtk_cells.hpp). MeshFields::node_scalars become
// Float64 PointData, tet_scalars Float64 CellData holding NaN on the
// pass-through cells (NaN, not 0, so a viewer shows "no value" rather than a
// plausible one). Tags are written as Int32 CellData "tetsmooth:tag" and
// fixed nodes as UInt8 PointData "tetsmooth:fixed" when the mesh has any.
//
// Reading: one Piece; DataArrays in ascii, binary (base64) or appended
// (raw or base64) form, header_type UInt32 or UInt64, either byte order,
// any numeric type; binary data uncompressed or compressed with
// vtkZLibDataCompressor or vtkLZMADataCompressor (vtu_blocks.hpp), other
// compressors (vtkLZ4DataCompressor) rejected with a message naming them.
// Cells must be tetra or quadratic tetra (not both), or vertex, line,
// triangle, quad, hexahedron, wedge, pyramid, quadratic edge or quadratic
// triangle, which are passed through with their nodes fixed. Region tags come from one cell-data array
// (tetsmooth:tag, or another tool's name for them: vtk_arrays.hpp) and fixed
// nodes from tetsmooth:fixed; every other PointData and CellData array is
// dropped with a note in FileExtras::read_notes.
#include <istream>
#include <ostream>
#include <string>

#include "mesh/io/mesh_io.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

TetMesh read_vtu(std::istream& in, const std::string& source);
TetMesh read_vtu_file(const std::string& path);

// Throws std::invalid_argument when a field does not have one value per node
// (per tet), OutputError for a block kind VTK cannot hold.
void write_vtu(const TetMesh& mesh, std::ostream& out, const MeshFields& fields);
void write_vtu_file(const TetMesh& mesh, const std::string& path, const MeshFields& fields);

}  // namespace tetsmooth
