#pragma once
// Starts the fetches of a node's star (its incident tets' corner indices and
// their qualities in a per-tet cache) into the SM's L1 before the centroid
// is summed, so that the adaptive test finds them there instead of waiting
// on each in turn.
//
// Why: with a few lanes per node (coloured_loop_kernel.cuh), a lane walks
// its share of a ~24-tet star in rounds, and every round waited on the
// incidence entry, then on the tet's corner indices, then on the corner
// coordinates, one after another: with the neighbour row and the cached
// qualities, about a dozen memory latencies in a row per node on meshes far
// larger than L2. Here the lane's incidence entries are read beside the
// neighbour row, and the lines they point to are requested while the
// centroid's coordinates are on their way. A prefetch holds no register and
// no thread waits on it; the loads that follow read the same addresses, so
// nothing the test computes changes.
#include <cuda_runtime.h>

#include "kernels/node_update.hpp"

namespace tetsmooth::cuda {

template <class T>
__device__ __forceinline__ void prefetch_l1(const T* p) {
  asm volatile("prefetch.global.L1 [%0];" ::"l"(p));
}

// The lane's first R incidence entries of a star, entries begin + lane,
// begin + lane + stride, ... below end (R rounds of `stride` lanes).
template <int R>
struct StarPrefetch {
  index_t tet[R > 0 ? R : 1];

  // Reads the entries (none for an inactive node: a settled node's star is
  // not read).
  __device__ __forceinline__ void read_entries(const MeshView& m, index_t begin, index_t end, int lane, int stride,
                                               bool active) {
#pragma unroll
    for (int r = 0; r < R; ++r) {
      const index_t e = begin + lane + r * stride;
      tet[r] = active && e < end ? m.inc[e] : index_t(-1);
    }
  }

  // Requests each entry's corner indices and its quality in the per-tet
  // cache `tet_q`.
  template <class Real>
  __device__ __forceinline__ void fetch(const MeshView& m, const Real* tet_q) const {
#pragma unroll
    for (int r = 0; r < R; ++r)
      if (tet[r] >= 0) {
        prefetch_l1(m.tets + 4 * static_cast<long long>(tet[r]));
        prefetch_l1(tet_q + tet[r]);
      }
  }
};

}  // namespace tetsmooth::cuda
