#include "apps/smoothing_pins.hpp"

#include "mesh/region_interfaces.hpp"
#include "mesh/second_order.hpp"
#include "mesh/topology.hpp"

namespace tetsmooth::cli {

SmoothingPins::SmoothingPins(TetMesh& mesh, int threads) : mesh_(mesh), file_pins_(mesh.fixed) {
  const auto pin = [&](std::size_t i) {
    if (mesh.fixed.empty()) mesh.fixed.assign(mesh.num_nodes(), 0);
    mesh.fixed[i] = 1;
  };
  const auto pinned = [&](std::size_t i) { return !mesh.fixed.empty() && mesh.fixed[i]; };
  const std::vector<std::uint8_t> interfaces = region_interface_nodes(mesh, {}, threads);
  for (std::size_t i = 0; i < interfaces.size(); ++i) {
    if (interfaces[i] == kNotPinned || pinned(i)) continue;
    pin(i);
    ++(interfaces[i] == kOnInterface ? added_interface_ : added_features_);
  }
  // Then the corners that second-order tets keep (curved_tet_pins).
  const CurvedTetPins curved = curved_tet_pins(mesh);
  curved_tets_ = curved.tets;
  std::vector<std::size_t> added;
  for (std::size_t i = 0; i < curved.corners.size(); ++i)
    if (curved.corners[i] && !pinned(i)) added.push_back(i);
  if (added.empty()) return;  // spares the face sort below
  const std::vector<std::uint8_t> boundary = find_boundary_nodes(mesh.tets, mesh.num_nodes(), threads);
  for (std::size_t i : added) {
    pin(i);
    added_curved_ += !boundary[i];
  }
}

SmoothingPins::~SmoothingPins() { mesh_.fixed = std::move(file_pins_); }

}  // namespace tetsmooth::cli
