#include "kernels/smoother.hpp"

#include <algorithm>

#include "mesh/second_order.hpp"

namespace tetsmooth {

SmoothResult smooth(TetMesh& mesh, const SmoothOptions& options, Device device) {
  const auto run = [&] {
    if (device == Device::Cuda || (device == Device::Auto && cuda_available())) return smooth_cuda(mesh, options);
    return smooth_cpu(mesh, options);
  };
  if (mesh.midsides.empty()) return run();
  // Second-order tets: curved ones keep their corners, for the span of the
  // run only, and the midside nodes follow the corners that moved.
  const CurvedTetPins pins = curved_tet_pins(mesh);
  std::vector<std::uint8_t> file_pins = mesh.fixed;
  // Corners of curved tets, and of edges whose midside node is pinned.
  if (std::find(pins.corners.begin(), pins.corners.end(), 1) != pins.corners.end()) {
    mesh.fixed.resize(mesh.num_nodes(), 0);
    for (std::size_t i = 0; i < pins.corners.size(); ++i) mesh.fixed[i] |= pins.corners[i];
  }
  const std::vector<double> before = mesh.xyz;
  SmoothResult result;
  try {
    result = run();
  } catch (...) {
    mesh.fixed = std::move(file_pins);
    throw;
  }
  mesh.fixed = std::move(file_pins);
  carry_midside_nodes(mesh, before);
  return result;
}

}  // namespace tetsmooth
