#pragma once
// Material interfaces of a mesh whose tets carry region tags
// (FileExtras::tet_tags: Gmsh physical groups, TetGen region attributes,
// Medit references, VTK tag arrays).
#include <cstdint>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// 1 for the nodes of every face shared by two tets of different regions;
// all 0 when the mesh has no tags. A tet listed more than once (Gmsh's MSH
// 2.2 writer repeats the tets of a volume in two physical groups, under
// both tags) is one tet with all of its tags: a face is an interface when
// its two tets' sets of tags differ.
std::vector<std::uint8_t> region_interface_nodes(const TetMesh& mesh);

}  // namespace tetsmooth
