#pragma once
// Form A's conflict repair on the CPU: the passes described in
// node_update.hpp (tet_rejects_movers, revert_if_flagged, kMaxRepairPasses)
// over a Jacobi sweep's two buffers.
#include <cstddef>
#include <cstdint>

#include "kernels/coords.hpp"
#include "kernels/node_update.hpp"

namespace tetsmooth {

// After a Jacobi sweep from `before` to `after` over nodes [0, num_nodes)
// (moved[i] = 1 for the nodes that moved, old_min[i] their star's old
// minimum): puts back the movers of every tet that objects, pass after
// pass, until a pass finds no conflict; a conflict found by pass
// `max_passes` - 1 undoes every move of the sweep. Leaves moved[i] = 1 for
// the moves that stand and every revert flag clear. Returns the number of
// moves put back. Smoothing runs always take kMaxRepairPasses.
std::int64_t repair_jacobi_conflicts(const MeshView& view, std::size_t num_tets, index_t num_nodes,
                                     AosCoords<double> before, AosCoords<double> after, std::uint8_t* moved,
                                     std::uint8_t* revert, const double* old_min, int threads,
                                     int max_passes = kMaxRepairPasses);

}  // namespace tetsmooth
