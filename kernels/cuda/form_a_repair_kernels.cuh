#pragma once
// The Form A (Jacobi) conflict repair (tet_rejects_movers in
// node_update.hpp): after a sweep, each tet with two or more movers whose
// result breaks the accept rule sends its movers back; the check repeats up
// to kMaxRepairPasses times, and a conflict left after the last pass undoes
// the whole sweep. The steps are shared by the multi-launch kernels here
// and by single_block_kernel.
#include <cuda_runtime.h>

#include <cstdint>

#include "kernels/cuda/lane_groups.cuh"
#include "kernels/cuda/sweep_state.cuh"
#include "kernels/node_update.hpp"

namespace tetsmooth::cuda {

// Flags the movers of tet t when it objects to the sweep's result.
template <class Real, class Coords>
__device__ __forceinline__ bool flag_objecting_tet(const index_t* tets, index_t t, const Coords& before,
                                                   const Coords& after, const std::uint8_t* moved, const Real* old_min,
                                                   std::uint8_t* revert) {
  const index_t* tet = tets + 4 * t;
  if (!tet_rejects_movers(tet, before, after, moved, old_min)) return false;
  for (int k = 0; k < 4; ++k)
    if (moved[tet[k]]) revert[tet[k]] = 1;  // every writer stores the same value
  return true;
}

// Form A conflict repair, pass `pass` (see node_update.hpp): flag the movers
// of objecting tets. Skipped when the previous pass found nothing.
template <class Real, class Coords>
__global__ void repair_check_kernel(const index_t* tets, index_t num_tets, Coords before, Coords after,
                                    const std::uint8_t* moved, const Real* old_min, std::uint8_t* revert,
                                    SweepState* st, SweepCounters c, int pass) {
  if (st->done || (pass > 0 && !c.repair_found[pass - 1])) return;
  const index_t t = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  if (t < num_tets && flag_objecting_tet(tets, t, before, after, moved, old_min, revert)) c.repair_found[pass] = 1;
}

template <class Coords>
__global__ void repair_apply_kernel(index_t n, Coords before, Coords after, std::uint8_t* moved, std::uint8_t* revert,
                                    SweepState* st, SweepCounters c, int pass) {
  if (st->done || !c.repair_found[pass]) return;
  const bool undo_all = repair_undoes_sweep(pass);
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  unsigned reverted = i < n && revert_if_flagged(i, before, after, moved, revert, undo_all);
  warp_atomic_add(&st->reverted, reverted);
}

// Form A: count the moves that survived the repair.
template <class Coords>
__global__ void count_moves_kernel(index_t n, Coords before, Coords after, const std::uint8_t* moved, SweepState* st,
                                   SweepCounters c) {
  if (st->done) return;
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  const bool live = i < n && moved[i];
  add_sweep_stats_block(c, st->sweep, live, live ? surviving_disp2(i, before, after, moved) : 0.0);
}

}  // namespace tetsmooth::cuda
