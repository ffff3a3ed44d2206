#pragma once
// The writers' check that MeshFields fit the mesh they are written with.
#include "mesh/io/mesh_io.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// Throws std::invalid_argument naming the field when a node scalar does not
// have one value per node or a tet scalar one value per tet: a caller's
// mistake, not a property of any file.
void check_field_sizes(const TetMesh& mesh, const MeshFields& fields);

}  // namespace tetsmooth
