#pragma once
// The VTK view of a TetMesh's cells, shared by the VTU and legacy VTK
// readers and writers: tets (VTK_TETRA = 10, or VTK_QUADRATIC_TETRA = 24
// for second-order tets) first, then the pass-through blocks in order, as
// vertices (1), lines (3), triangles (5), quads (9), hexahedra (12),
// wedges (13), pyramids (14), quadratic edges (21) or quadratic triangles
// (22). A VTK wedge's first triangle winds the other way from the other
// formats' (Gmsh's, Abaqus's, Nastran's; meshio's wedge): its nodes are
// reordered on the way in and out, as meshio does.
// Tags travel in a per-cell integer array named kVtkTagArray, Gmsh entity
// tags in one named kVtkEntityArray, the Gmsh entity each node is
// classified on in a per-point array of (dimension, tag) pairs named
// kVtkNodeEntityArray (meshio's names for both, so that a Gmsh mesh that
// meshio wrote keeps its volumes apart and its embedded features in place),
// and fixed nodes in a per-point 0/1 array named kVtkFixedArray; readers
// also take tags under other names (vtk_arrays.hpp).
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

inline constexpr const char* kVtkTagArray = "tetsmooth:tag";
inline constexpr const char* kVtkFixedArray = "tetsmooth:fixed";
inline constexpr const char* kVtkEntityArray = "gmsh:geometrical";
inline constexpr const char* kVtkNodeEntityArray = "gmsh:dim_tags";

// Name of a VTK cell type for messages ("hexahedron", "quadratic tetra", ...).
std::string vtk_cell_type_name(long long type);

struct VtkCells {
  std::vector<index_t> connectivity;
  std::vector<std::int64_t> offsets;  // #cells + 1 entries, offsets[0] = 0
  std::vector<std::uint8_t> types;
  std::vector<int> tags;  // one per cell (0 where absent), or empty when the mesh has no tags
  std::vector<int> entities;  // Gmsh entity tags, the same way
  std::size_t size() const { return types.size(); }
  // The per-cell integer arrays with the names they are written under (a
  // writer leaves out the empty ones).
  std::array<std::pair<const char*, const std::vector<int>*>, 2> named_int_arrays() const {
    return {{{kVtkTagArray, &tags}, {kVtkEntityArray, &entities}}};
  }
};

// Throws OutputError "<where>: ..." for a pass-through block of a kind VTK
// cannot hold here; file writers call it first, naming the file.
void check_vtk_blocks(const TetMesh& mesh, const std::string& where);

// Checks the blocks as above (where = "VTK output").
VtkCells vtk_cells_of(const TetMesh& mesh);

// The arrays of cell data that mesh_from_vtk_cells reads by index.
enum class VtkCellArray { Offsets, Connectivity };

// Where a value of a file stands, for a message about it: `where` is the
// value's own line or byte, and `entry` empty; or, where a reader cannot tell
// that, `where` is the start of the array and `entry` says which value of
// which array it is ("value 17 of the connectivity data, which start here").
struct VtkValuePlace {
  std::string where;
  std::string entry;
};

// The place of value `index` of the offsets or connectivity vector a reader
// passed to mesh_from_vtk_cells, a value of cell `cell`.
using VtkCellPlace = std::function<VtkValuePlace(VtkCellArray array, std::size_t index, std::size_t cell)>;

// Splits cells read from a file into mesh.tets and mesh.extras.blocks (one
// block per cell type, in order of first appearance) and fixes the nodes of
// the blocks. mesh.xyz must be filled; offsets has #cells + 1 entries from 0;
// tags and entities (Gmsh entity tags) are one per cell (from
// vtk_region_tags) or empty. Errors are
// InputErrors naming the cell: at the value at fault for an offset or a node
// index (`place`), else at `where` (the cell types).
void mesh_from_vtk_cells(TetMesh& mesh, const std::vector<long long>& connectivity,
                         const std::vector<long long>& offsets, const std::vector<long long>& types,
                         const std::vector<int>& tags, const std::vector<int>& entities, const std::string& where,
                         const VtkCellPlace& place);

}  // namespace tetsmooth
