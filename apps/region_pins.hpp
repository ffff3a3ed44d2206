#pragma once
// The command line keeps material interfaces in place: while a
// RegionInterfacePins lives, the nodes on faces between tets of different
// regions (region_interface_nodes) are pinned in mesh.fixed, as if the file
// had pinned them; it puts back the file's own pins when it ends, so that
// the written file carries only what was read.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth::cli {

class RegionInterfacePins {
 public:
  explicit RegionInterfacePins(TetMesh& mesh);
  ~RegionInterfacePins();
  RegionInterfacePins(const RegionInterfacePins&) = delete;
  RegionInterfacePins& operator=(const RegionInterfacePins&) = delete;

  // Interface nodes that the file had not pinned already.
  std::size_t added() const { return added_; }

 private:
  TetMesh& mesh_;
  std::vector<std::uint8_t> file_pins_;
  std::size_t added_ = 0;
};

}  // namespace tetsmooth::cli
