#pragma once
// The mesh's coordinates into and out of the working precision and layout.
// Float works in the mesh's bounding box mapped onto [-1, 1] (the caller
// passes its centre and half-extent), so that a mesh far from the origin
// does not spend float's digits on its offset; double passes centre 0 and
// scale 1, and keeps the input's values.
#include <cuda_runtime.h>

#include <cstdint>

#include "kernels/node_update.hpp"

namespace tetsmooth::cuda {

// Input (double AoS, mesh units) -> working coordinates: (x - centre) * inv_scale.
template <class Real, class Coords>
__global__ void load_coords_kernel(const double* in, Coords out, index_t n, double cx, double cy, double cz,
                                   double inv_scale) {
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i >= n) return;
  out.set(i, Vec3<Real>{static_cast<Real>((in[3 * i] - cx) * inv_scale), static_cast<Real>((in[3 * i + 1] - cy) * inv_scale),
                        static_cast<Real>((in[3 * i + 2] - cz) * inv_scale)});
}

// Only movable nodes are written back, so the others keep their input bits
// even when the working precision is float.
template <class Real, class Coords>
__global__ void store_coords_kernel(Coords in, double* out, const std::uint8_t* movable, index_t n, double cx,
                                    double cy, double cz, double scale) {
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i >= n || !movable[i]) return;
  const Vec3<Real> v = in.get(i);
  out[3 * i] = static_cast<double>(v.x) * scale + cx;
  out[3 * i + 1] = static_cast<double>(v.y) * scale + cy;
  out[3 * i + 2] = static_cast<double>(v.z) * scale + cz;
}

// Counts the nodes that never move whose working coordinates differ from
// `loaded`, the input converted afresh the way the run's were: the sweeps
// must leave such nodes as they were loaded, and store_coords_kernel, which
// writes back only movable nodes, would hide it if they did not.
template <class Real, class Coords>
__global__ void count_moved_fixed_kernel(Coords working, Coords loaded, const std::uint8_t* movable, index_t n,
                                         unsigned long long* count) {
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i >= n || movable[i]) return;
  const Vec3<Real> a = working.get(i), b = loaded.get(i);
  if (a.x != b.x || a.y != b.y || a.z != b.z) atomicAdd(count, 1ull);
}

}  // namespace tetsmooth::cuda
