#pragma once
// The fields written along with a mesh so that an engineer can see in
// ParaView or Gmsh where the bad tets are and which nodes were held.
#include "mesh/io/mesh_io.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::cli {

// True for the formats whose writers carry MeshFields (VTU, VTK, MSH).
bool format_carries_fields(MeshFormat format);

// Per tet "quality" (radius ratio), per node "boundary" (1 on the boundary
// surface, 0 inside).
MeshFields quality_fields(const TetMesh& mesh);

// Writes `mesh` to `path`, with quality_fields when the format carries them.
void write_mesh_with_fields(const TetMesh& mesh, const std::string& path, MeshFormat format);

}  // namespace tetsmooth::cli
