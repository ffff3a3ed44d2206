#pragma once
// A colour step's node openings staged in shared memory (the coloured loop
// with a warp per node, coloured_loop_kernel.cuh).
//
// A node's work opens with two dependent reads: its index in the colour
// class, then its flag and the bounds of its neighbour and incidence rows.
// Where a warp takes the block's nodes one after another, each node waited on
// both before its rows could be requested. Here the whole block first reads
// the openings of a chunk of its nodes at once, one node a thread, and keeps
// those of the nodes to evaluate (flagged, or all of them without
// skip_settled), packed, in shared memory; the warps then take them from
// there. A step pays the two reads once instead of once a node, and settled
// nodes cost a warp nothing.
//
// Reading a flag at the step's start instead of at the node's turn reads the
// same value: only the node itself and movers among its neighbours write it,
// and no neighbour shares its colour.
#include <cuda_runtime.h>

#include <cstdint>

#include "kernels/cuda/lane_groups.cuh"
#include "mesh/csr.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::cuda {

// Where a node's work starts: its index and row bounds (the star's only
// where it is read), whether it is in the class at all (a group past the
// class's end still takes part in its warp's shuffles), and its flag.
struct NodeOpening {
  index_t i = 0, row_begin = 0, row_end = 0, star_begin = 0, star_end = 0;
  bool in_class = false, flagged = false;
};

// Reads node i's opening (in_class: whether there is a node at all).
template <bool kWithStar>
__device__ __forceinline__ NodeOpening read_opening(const MeshView& m, const std::uint8_t* changed, index_t i,
                                                    bool in_class) {
  NodeOpening o;
  if (!in_class) return o;
  o.i = i;
  o.in_class = true;
  o.flagged = changed[i] != 0;
  o.row_begin = m.nbr_off[i];
  o.row_end = m.nbr_off[i + 1];
  if (kWithStar) {
    o.star_begin = m.inc_off[i];
    o.star_end = m.inc_off[i + 1];
  }
  return o;
}

// The shared-memory side: kCap openings (a chunk of at most one node per
// thread of the block: blockDim.x <= kCap), and per parity a count of those
// staged and of those taken. Chunks alternate parities, so that a chunk can clear the other
// parity's counters while the block's warps may still read its own.
template <int kCap>
struct StagedOpenings {
  int4 head[kCap];  // i | flagged << 31 (node indices stay below 2^31), row_begin, row_end, star_begin
  index_t star_end[kCap];
  unsigned staged[2], taken[2];

  __device__ __forceinline__ void clear() {
    if (threadIdx.x < 2) staged[threadIdx.x] = taken[threadIdx.x] = 0;
  }

  // The block's nodes j = chunk + threadIdx.x (j < count) of a class, node j
  // at position first + stride * j of `nodes`: their openings, those to
  // evaluate kept. Every thread of the block calls it; returns how many
  // were kept, once the whole block's are.
  template <bool kWithStar>
  __device__ __forceinline__ unsigned stage(const MeshView& m, const std::uint8_t* changed, const index_t* nodes,
                                            long long first, long long stride, long long chunk, long long count,
                                            bool skip_settled, unsigned parity) {
    __syncthreads();  // the last chunk's openings are all read
    if (threadIdx.x == 0) staged[parity ^ 1u] = taken[parity ^ 1u] = 0;
    const long long j = chunk + threadIdx.x;
    const bool in = j < count;
    const NodeOpening o = read_opening<kWithStar>(m, changed, in ? nodes[first + stride * j] : 0, in);
    const bool keep = in && (o.flagged || !skip_settled);
    const unsigned kept = __ballot_sync(0xffffffffu, keep);
    unsigned slot = 0;
    if ((threadIdx.x & 31) == 0 && kept != 0) slot = atomicAdd(&staged[parity], static_cast<unsigned>(__popc(kept)));
    slot = __shfl_sync(0xffffffffu, slot, 0) + __popc(kept & ((1u << (threadIdx.x & 31)) - 1u));
    if (keep) {
      head[slot] = int4{o.i | (o.flagged ? static_cast<int>(0x80000000u) : 0), o.row_begin, o.row_end, o.star_begin};
      star_end[slot] = o.star_end;
    }
    __syncthreads();
    return staged[parity];
  }

  // The calling warp's next `per_warp` openings: the first one's place (the
  // same for every lane; none left once it reaches the count staged).
  __device__ __forceinline__ unsigned claim(unsigned per_warp, unsigned parity) {
    return warp_claim(&taken[parity], per_warp);
  }

  // Opening r (in_class false where r is past the `count` staged).
  __device__ __forceinline__ NodeOpening opening(unsigned r, unsigned count) const {
    NodeOpening o;
    if (r >= count) return o;
    const int4 h = head[r];
    o.i = h.x & 0x7fffffff;
    o.flagged = h.x < 0;
    o.row_begin = h.y;
    o.row_end = h.z;
    o.star_begin = h.w;
    o.star_end = star_end[r];
    o.in_class = true;
    return o;
  }
};

}  // namespace tetsmooth::cuda
