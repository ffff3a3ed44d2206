#pragma once
// Checks of the MultiBlock node pass's pieces on the device, for tests:
// warp_star_improves (warp_star_test.cuh) against star_improves, the
// one-thread form the CPU runs, on the same inputs; its deal; the quad walks
// of the incidence rows; and radius_ratio in the float sweeps' arithmetic.
// Plain C++: callers need no CUDA headers.
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

// One round of the deal (deal_round) for 16,384 warps of pseudo-random
// pending counts, against its rule (warp_star_test.cuh) written out with
// integer division: how many slots each busy node gets, which ones, and
// that they serve its tets in order.
struct DealCheck {
  std::size_t nodes = 0;   // busy nodes dealt to
  std::size_t broken = 0;  // nodes dealt other than by the rule
};
DealCheck check_deal();

// row_sum and star_old_min as MultiBlock sweeps call them (a lane a node,
// with the incidence rows walked a 16-byte quad at a time: RowWalk in
// node_update.hpp) against the same walking the rows entry by entry, for
// every node of `mesh` (double AoS coordinates, old qualities computed
// afresh), both on the device: the neighbour sums, the old minima and the
// minima's entries must agree bit for bit.
struct RowWalkCheck {
  std::size_t nodes = 0;       // nodes compared
  std::size_t mismatches = 0;  // nodes where any of the three differ
};
RowWalkCheck check_row_walks(const TetMesh& mesh);

// radius_ratio of each tet (corners[12 t .. 12 t + 11]: x, y, z of its four
// corners) on the device in `precision`, built as the sweeps are built
// (in float: approximate square roots and division, subnormal operands of
// both taken as zero; mesh/quality_roots.hpp).
std::vector<double> device_radius_ratios(const std::vector<double>& corners, Precision precision);

}  // namespace tetsmooth::cuda
