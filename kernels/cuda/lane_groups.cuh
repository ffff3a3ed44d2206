#pragma once
// Reductions over a group of G consecutive lanes of a warp (G a power of two
// up to 32), for kernels that give one item (a node) to several threads; a
// warp's broadcast, for kernels whose lanes share out work.
// Every lane named in `mask` must call them: the whole warp by default (also
// lanes whose group is idle), or just the group (group_mask) where groups of
// one warp run apart. All lanes of a group get the same result: the same bits
// for sums; for min and max, values that compare equal (a zero may keep its
// sign).
#include <cuda_runtime.h>

#include "mesh/vec3.hpp"

namespace tetsmooth::cuda {

// The lanes of this thread's group of G.
template <int G>
__device__ __forceinline__ unsigned group_mask() {
  if constexpr (G == 32) {
    return 0xffffffffu;
  } else {
    const unsigned first = (threadIdx.x & 31u) & ~static_cast<unsigned>(G - 1);
    return ((1u << G) - 1u) << first;
  }
}

// Sum with the total taken from the group's first lane, so every lane holds
// the same bits whatever the order of additions.
template <int G, class T>
__device__ __forceinline__ T group_sum(T v, unsigned mask = 0xffffffffu) {
  for (int offset = G / 2; offset > 0; offset >>= 1) v += __shfl_down_sync(mask, v, offset, G);
  return __shfl_sync(mask, v, 0, G);
}

template <int G, class T>
__device__ __forceinline__ T group_min(T v, unsigned mask = 0xffffffffu) {
  for (int offset = G / 2; offset > 0; offset >>= 1) {
    const T w = __shfl_xor_sync(mask, v, offset, G);
    v = w < v ? w : v;
  }
  return v;
}

template <int G, class T>
__device__ __forceinline__ T group_max(T v, unsigned mask = 0xffffffffu) {
  for (int offset = G / 2; offset > 0; offset >>= 1) {
    const T w = __shfl_xor_sync(mask, v, offset, G);
    v = w > v ? w : v;
  }
  return v;
}

template <int G, class T>
__device__ __forceinline__ T group_or(T v, unsigned mask = 0xffffffffu) {
  for (int offset = G / 2; offset > 0; offset >>= 1) v |= __shfl_xor_sync(mask, v, offset, G);
  return v;
}

// Whether any lane of this thread's group has b set; only the group's lanes
// take part, so groups of one warp may call it apart.
template <int G>
__device__ __forceinline__ bool group_any(bool b) {
  return __any_sync(group_mask<G>(), b) != 0;
}

inline constexpr unsigned kFullWarp = 0xffffffffu;

// The value of lane `src`, for the types the hardware shuffles and Vec3.
template <class T>
__device__ __forceinline__ T lane_value(T v, int src) {
  return __shfl_sync(kFullWarp, v, src);
}
template <class Real>
__device__ __forceinline__ Vec3<Real> lane_value(Vec3<Real> v, int src) {
  return {lane_value(v.x, src), lane_value(v.y, src), lane_value(v.z, src)};
}

// Adds every lane's v to *target with one atomic per warp (none when the
// warp's total is zero). Every lane of the warp must call it.
template <class Target, class T>
__device__ __forceinline__ void warp_atomic_add(Target* target, T v) {
  v = group_sum<32>(v);
  if ((threadIdx.x & 31) == 0 && v != T(0)) atomicAdd(target, static_cast<Target>(v));
}

// Takes n items for the warp from a counter (shared or global): the old
// count, the warp's first item, handed to every lane. One atomic a warp
// instead of one a lane. Every lane of the warp must call it.
__device__ __forceinline__ unsigned warp_claim(unsigned* counter, unsigned n) {
  unsigned first = 0;
  if ((threadIdx.x & 31) == 0) first = atomicAdd(counter, n);
  return __shfl_sync(0xffffffffu, first, 0);
}

// Lane (this + offset)'s v, as __shfl_down_sync over the whole warp, for the
// types the hardware shuffles; a struct reduced below brings its own
// overload beside it (found by argument-dependent lookup).
template <class T>
__device__ __forceinline__ T shfl_down(T v, int offset) {
  return __shfl_down_sync(0xffffffffu, v, offset);
}

// Reduces every lane's v with `op` into lane 0, combining in the order
// group_sum adds, so a sum has the same bits. Every lane of the warp must
// call it.
template <class T, class Op>
__device__ __forceinline__ T warp_reduce_to_lane0(T v, Op op) {
  for (int offset = 16; offset > 0; offset >>= 1) v = op(v, shfl_down(v, offset));
  return v;
}

// The same over the block, into thread 0; `identity` fills the slots of
// warps the block lacks. Every thread of the block must call it; blockDim.x
// is a multiple of 32. A second call with the same T in the same block
// needs a __syncthreads() before it (the warp totals' slots are reused).
template <class T, class Op>
__device__ __forceinline__ T block_reduce_to_thread0(T v, Op op, T identity) {
  __shared__ T warp_totals[32];
  const unsigned warp = threadIdx.x / 32, warps = blockDim.x / 32;
  v = warp_reduce_to_lane0(v, op);
  if ((threadIdx.x & 31) == 0) warp_totals[warp] = v;
  __syncthreads();
  if (warp == 0) v = warp_reduce_to_lane0(threadIdx.x < warps ? warp_totals[threadIdx.x] : identity, op);
  return v;
}

// Adds every thread's v to *target with one atomic per block (none when the
// block's total is zero): for sums over many blocks, where one atomic per
// warp would queue on the one address. Every thread of the block must call
// it; blockDim.x is a multiple of 32.
template <class Target, class T>
__device__ __forceinline__ void block_atomic_add(Target* target, T v) {
  v = block_reduce_to_thread0(v, [](T a, T b) { return a + b; }, T(0));
  if (threadIdx.x == 0 && v != T(0)) atomicAdd(target, static_cast<Target>(v));
  __syncthreads();  // the next call may reduce the same T
}

}  // namespace tetsmooth::cuda
