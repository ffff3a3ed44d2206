#include "kernels/second_order_smoothing.hpp"

#include <cstdint>
#include <vector>

#include "mesh/second_order.hpp"

namespace tetsmooth {
namespace {

// Gives mesh.fixed back as it was, however the run ends.
class FixedNodesRestorer {
 public:
  explicit FixedNodesRestorer(TetMesh& mesh) : mesh_(mesh), saved_(mesh.fixed) {}
  ~FixedNodesRestorer() { mesh_.fixed = std::move(saved_); }
  FixedNodesRestorer(const FixedNodesRestorer&) = delete;
  FixedNodesRestorer& operator=(const FixedNodesRestorer&) = delete;
  const std::vector<std::uint8_t>& saved() const { return saved_; }

 private:
  TetMesh& mesh_;
  std::vector<std::uint8_t> saved_;
};

void pin_corners(const TetMesh& mesh, std::size_t t, std::vector<std::uint8_t>& pins) {
  for (int k = 0; k < 4; ++k) pins[static_cast<std::size_t>(mesh.tets[4 * t + static_cast<std::size_t>(k)])] = 1;
}

// The corners of every tet with a midside node off its edge's midpoint.
void pin_every_offset_tet(const TetMesh& mesh, const std::vector<double>& input, std::vector<std::uint8_t>& pins) {
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    if (!exactly_straight(mesh, input, t)) pin_corners(mesh, t, pins);
}

}  // namespace

SmoothResult smooth_second_order(TetMesh& mesh, const std::function<SmoothResult()>& run) {
  const std::vector<double> input = mesh.xyz;
  const FixedNodesRestorer restorer(mesh);
  std::vector<std::uint8_t> pins = curved_tet_pins(mesh).corners;
  std::size_t folded_total = 0;
  for (int restarts = 0;; ++restarts) {
    mesh.fixed = restorer.saved();
    mesh.fixed.resize(mesh.num_nodes(), 0);
    for (std::size_t i = 0; i < pins.size(); ++i) mesh.fixed[i] |= pins[i];
    SmoothResult result = run();
    carry_midside_nodes(mesh, input);
    const std::vector<std::size_t> folded = folded_tets(mesh, input);
    if (folded.empty()) {
      result.second_order_restarts = restarts;
      result.folded_tets = folded_total;
      return result;
    }
    folded_total += folded.size();
    for (std::size_t t : folded) pin_corners(mesh, t, pins);
    if (restarts + 1 == kMaxRestarts) pin_every_offset_tet(mesh, input, pins);
    mesh.xyz = input;
  }
}

}  // namespace tetsmooth
