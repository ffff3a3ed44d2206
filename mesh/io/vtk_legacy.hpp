#pragma once
// Legacy VTK (.vtk), DATASET UNSTRUCTURED_GRID: written in ASCII, read in
// ASCII or BINARY.
//
// Writing: version 4.2 layout ("CELLS n size" with a count before each
// cell's nodes), cells as in vtk_cells.hpp, coordinates in the shortest form
// that reads back exactly. MeshFields become SCALARS double in POINT_DATA and
// CELL_DATA (NaN on pass-through cells, as in VTU); tags and fixed nodes
// become "tetsmooth:tag" / "tetsmooth:fixed" int SCALARS when present. Names
// are percent-encoded where VTK requires it (spaces, '%', non-printables).
//
// Reading: versions up to 5.1, including 5.1's OFFSETS/CONNECTIVITY cells;
// FIELD, SCALARS, VECTORS, NORMALS, TENSORS, TEXTURE_COORDINATES,
// COLOR_SCALARS, LOOKUP_TABLE and METADATA sections are understood. As for
// .vtu, region tags come from one cell-data array (tetsmooth:tag, or another
// tool's name for them: vtk_arrays.hpp) and fixed nodes from tetsmooth:fixed,
// as SCALARS or FIELD arrays; every other point and cell data array is
// dropped with a note in FileExtras::read_notes.
//
// BINARY files (meshio's default for .vtk) hold each data block as raw
// big-endian values of the type its keyword line names (vtk_scalars.hpp),
// right after that line; CELLS of versions up to 4.2 and CELL_TYPES as int,
// LOOKUP_TABLE and COLOR_SCALARS values as unsigned char. A keyword's
// arguments must be on its line, and a line break must follow each block (a
// block that does not end there was not as long as its count and type say).
// bit arrays are skipped where they are not wanted; string arrays, and
// SCALARS without its LOOKUP_TABLE line, are refused. Errors in a BINARY file
// name the byte offset of the line or value at fault instead of a line
// number.
#include <istream>
#include <ostream>
#include <string>

#include "mesh/io/mesh_io.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

TetMesh read_vtk(std::istream& in, const std::string& source);
TetMesh read_vtk_file(const std::string& path);

// Throws std::invalid_argument for fields of the wrong size, OutputError for
// a block kind VTK cannot hold.
void write_vtk(const TetMesh& mesh, std::ostream& out, const MeshFields& fields);
void write_vtk_file(const TetMesh& mesh, const std::string& path, const MeshFields& fields);

}  // namespace tetsmooth
