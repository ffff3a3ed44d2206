#pragma once
// The command line keeps material interfaces in place: while a
// RegionInterfacePins lives, the nodes on faces between tets of different
// regions or Gmsh volumes, and the nodes Gmsh classified on points, curves
// and surfaces inside the mesh (region_interface_nodes), are pinned in
// mesh.fixed, as if the file had pinned them; it puts back the file's own
// pins when it ends, so that the written file carries only what was read.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth::cli {

class RegionInterfacePins {
 public:
  // `threads` sorts the faces (0 all cores, as --threads).
  RegionInterfacePins(TetMesh& mesh, int threads);
  ~RegionInterfacePins();
  RegionInterfacePins(const RegionInterfacePins&) = delete;
  RegionInterfacePins& operator=(const RegionInterfacePins&) = delete;

  // Nodes that the file had not pinned already, off the boundary (which
  // stays in place anyway): on interfaces (kOnInterface), and on Gmsh
  // features inside the mesh (kOnGmshFeature, on no interface).
  std::size_t added_on_interfaces() const { return added_interface_; }
  std::size_t added_on_features() const { return added_features_; }

 private:
  TetMesh& mesh_;
  std::vector<std::uint8_t> file_pins_;
  std::size_t added_interface_ = 0;
  std::size_t added_features_ = 0;
};

}  // namespace tetsmooth::cli
