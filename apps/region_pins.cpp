#include "apps/region_pins.hpp"

#include "mesh/region_interfaces.hpp"

namespace tetsmooth::cli {

RegionInterfacePins::RegionInterfacePins(TetMesh& mesh, int threads) : mesh_(mesh), file_pins_(mesh.fixed) {
  const std::vector<std::uint8_t> pinned = region_interface_nodes(mesh, {}, threads);
  for (std::size_t i = 0; i < pinned.size(); ++i) {
    if (pinned[i] == kNotPinned || (!mesh.fixed.empty() && mesh.fixed[i])) continue;
    if (mesh.fixed.empty()) mesh.fixed.assign(mesh.num_nodes(), 0);
    mesh.fixed[i] = 1;
    ++(pinned[i] == kOnInterface ? added_interface_ : added_features_);
  }
}

RegionInterfacePins::~RegionInterfacePins() { mesh_.fixed = std::move(file_pins_); }

}  // namespace tetsmooth::cli
