#pragma once
// SingleBlock: one block of 1024 threads runs every sweep in one launch,
// __syncthreads() between sweeps (the paper's single-block strategy).
#include <cuda_runtime.h>

#include <cstdint>

#include "kernels/cuda/form_a_repair_kernels.cuh"
#include "kernels/cuda/node_steps.cuh"
#include "kernels/cuda/sweep_state.cuh"
#include "kernels/node_update.hpp"
#include "kernels/smooth_options.hpp"

namespace tetsmooth::cuda {

inline constexpr int kSingleBlockThreads = 1024;

// The whole sweep loop in one block (SingleBlock). The per-node body and the
// repair are the same functions the other strategies use; only the loops
// and barriers differ.
template <class Real, bool kAdaptive, Form F, class Coords>
__global__ void __launch_bounds__(kSingleBlockThreads)
    single_block_kernel(MeshView m, Coords buf0, Coords buf1, index_t n, index_t num_tets,
                        const std::uint8_t* movable, Real* old_min, std::uint8_t* moved, std::uint8_t* revert,
                        SweepState* st, SweepCounters c, int max_iterations) {
  __shared__ unsigned long long s_accepted;
  __shared__ double s_disp2;
  __shared__ int s_flag;
  for (int s = 0; s < max_iterations; ++s) {
    const Coords read = (F == Form::A && (s & 1)) ? buf1 : buf0;
    const Coords write = (F == Form::A && (s & 1)) ? buf0 : buf1;
    if (threadIdx.x == 0) {
      s_accepted = 0;
      s_disp2 = 0;
    }
    __syncthreads();
    unsigned accepted = 0;
    double disp2 = 0;
    for (index_t i = threadIdx.x; i < n; i += blockDim.x) {
      if (!movable[i]) continue;
      double d2 = 0;
      if (smooth_node<Real, kAdaptive, F>(m, read, write, i, old_min, moved, d2)) {
        ++accepted;
        disp2 = fmax(disp2, d2);
      }
    }
    if (F == Form::A) {
      __syncthreads();
      for (int pass = 0; kAdaptive && pass < kMaxRepairPasses; ++pass) {
        if (threadIdx.x == 0) s_flag = 0;
        __syncthreads();
        for (index_t t = threadIdx.x; t < num_tets; t += blockDim.x)
          if (flag_objecting_tet(m.tets, t, read, write, moved, old_min, revert)) atomicOr(&s_flag, 1);
        __syncthreads();
        const int found = s_flag;
        if (!found) break;
        const bool undo_all = repair_undoes_sweep(pass);
        unsigned reverted = 0;
        for (index_t i = threadIdx.x; i < n; i += blockDim.x)
          reverted += revert_if_flagged(i, read, write, moved, revert, undo_all);
        if (reverted) atomicAdd(&st->reverted, static_cast<unsigned long long>(reverted));
        __syncthreads();
      }
      accepted = 0;
      disp2 = 0;
      for (index_t i = threadIdx.x; i < n; i += blockDim.x) {
        accepted += moved[i];
        disp2 = fmax(disp2, surviving_disp2(i, read, write, moved));
      }
    }
    if (accepted) {
      atomicAdd(&s_accepted, static_cast<unsigned long long>(accepted));
      atomicMax(reinterpret_cast<unsigned long long*>(&s_disp2), static_cast<unsigned long long>(__double_as_longlong(disp2)));
    }
    __syncthreads();
    if (threadIdx.x == 0) {
      c.accepted[s] = s_accepted;
      c.max_disp2_bits[s] = static_cast<unsigned long long>(__double_as_longlong(s_disp2));
      const SweepVerdict v = sweep_verdict(s + 1, static_cast<long long>(s_accepted), sqrt(s_disp2), st->tol_abs,
                                           max_iterations);
      record_verdict(st, s, v);
      s_flag = st->done;
    }
    __syncthreads();
    if (s_flag) break;
    __syncthreads();
  }
}

}  // namespace tetsmooth::cuda
