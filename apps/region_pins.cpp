#include "apps/region_pins.hpp"

#include "mesh/region_interfaces.hpp"

namespace tetsmooth::cli {

RegionInterfacePins::RegionInterfacePins(TetMesh& mesh) : mesh_(mesh), file_pins_(mesh.fixed) {
  const std::vector<std::uint8_t> interface = region_interface_nodes(mesh);
  for (std::size_t i = 0; i < interface.size(); ++i) {
    if (!interface[i] || (!mesh.fixed.empty() && mesh.fixed[i])) continue;
    if (mesh.fixed.empty()) mesh.fixed.assign(mesh.num_nodes(), 0);
    mesh.fixed[i] = 1;
    ++added_;
  }
}

RegionInterfacePins::~RegionInterfacePins() { mesh_.fixed = std::move(file_pins_); }

}  // namespace tetsmooth::cli
