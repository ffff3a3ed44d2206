#pragma once
// Checks of warp_star_improves (warp_star_test.cuh) on the device, for
// tests: against star_improves, the one-thread form the CPU runs, on the
// same inputs; of the quotient its deal computes; and of radius_ratio in
// the float sweeps' arithmetic. Plain C++: callers need no CUDA headers.
#include <cstddef>
#include <vector>

#include "kernels/smooth_options.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::cuda {

// Which star entry the warp form deals first.
enum class LeadRule {
  OldMinimum,  // the star's old minimum, as MultiBlock sweeps do
  Rotating,    // entry (i mod star size) of node i: every place in the deal gets exercised
};

struct StarTestAgreement {
  std::size_t judged = 0;         // movable nodes
  std::size_t accepted = 0;       // by star_improves
  std::size_t disagreements = 0;  // nodes where the two forms decide differently
};

// Judges a move of every movable node of `mesh` (double AoS coordinates, old
// qualities computed afresh) to targets[3 i .. 3 i + 2], both ways, in one
// kernel with a thread per node.
StarTestAgreement compare_warp_star_test(const TetMesh& mesh, const std::vector<double>& targets, LeadRule lead);

// The pairs (n, d), 0 <= n <= 32 and 1 <= d <= 33, for which the deal's
// small_quotient(n, d) differs from n / d on the device (every pair the deal
// can ask for, so 0 means it is exact).
std::size_t small_quotient_errors();

// radius_ratio of each tet (corners[12 t .. 12 t + 11]: x, y, z of its four
// corners) on the device in `precision`, built as the sweeps are built
// (in float: approximate square roots and division, subnormal operands of
// both taken as zero; mesh/quality_roots.hpp).
std::vector<double> device_radius_ratios(const std::vector<double>& corners, Precision precision);

}  // namespace tetsmooth::cuda
