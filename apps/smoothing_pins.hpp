#pragma once
// What the command line keeps in place besides the boundary and the file's
// own pins. While a SmoothingPins lives, these nodes are pinned in
// mesh.fixed, as if the file had pinned them:
//  * material interfaces: the nodes on faces between tets of different
//    regions or Gmsh volumes, and the nodes Gmsh classified on points,
//    curves and surfaces inside the mesh (region_interface_nodes);
//  * the corners of curved second-order tets, and of edges whose midside
//    node is pinned (curved_tet_pins), which smooth() would pin anyway;
//    pinned here too, they count in the movable nodes `quality` reports.
// It puts back the file's own pins when it ends, so that the written file
// carries only what was read.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth::cli {

class SmoothingPins {
 public:
  // `threads` sorts the faces (0 all cores, as --threads).
  SmoothingPins(TetMesh& mesh, int threads);
  ~SmoothingPins();
  SmoothingPins(const SmoothingPins&) = delete;
  SmoothingPins& operator=(const SmoothingPins&) = delete;

  // Nodes that the file had not pinned already, off the boundary (which
  // stays in place anyway): on interfaces (kOnInterface), and on Gmsh
  // features inside the mesh (kOnGmshFeature, on no interface).
  std::size_t added_on_interfaces() const { return added_interface_; }
  std::size_t added_on_features() const { return added_features_; }
  // Corners that curved_tet_pins keeps, off the boundary and pinned by
  // neither of the above nor the file, and how many tets have curved
  // edges.
  std::size_t added_at_curved_tets() const { return added_curved_; }
  std::size_t curved_tets() const { return curved_tets_; }

 private:
  TetMesh& mesh_;
  std::vector<std::uint8_t> file_pins_;
  std::size_t added_interface_ = 0;
  std::size_t added_features_ = 0;
  std::size_t added_curved_ = 0;
  std::size_t curved_tets_ = 0;
};

}  // namespace tetsmooth::cli
