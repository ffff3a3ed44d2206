#pragma once
// The mesh's coordinates into and out of the working precision and layout.
// Float works in the mesh's bounding box mapped onto [-1, 1] (the caller
// passes its centre and half-extent), so that a mesh far from the origin
// does not spend float's digits on its offset; double passes centre 0 and
// scale 1, and keeps the input's values.
#include <cuda_runtime.h>

#include <cstddef>
#include <cstdint>

#include "kernels/node_update.hpp"

namespace tetsmooth::cuda {

// The working frame: x_working = (x - centre) * inv_scale, and back
// x = x_working * scale + centre. Double passes centre 0 and scale 1.
struct WorkingFrame {
  double cx, cy, cz, scale, inv_scale;
};

inline WorkingFrame working_frame(const double centre[3], double scale) {
  return WorkingFrame{centre[0], centre[1], centre[2], scale, 1.0 / scale};
}

// Node i of the input (double AoS, mesh units) in working coordinates: the
// one conversion, for loading and for telling a node the run left alone.
template <class Real>
__device__ __forceinline__ Vec3<Real> working_position(const double* in, index_t i, const WorkingFrame& f) {
  const double* p = in + 3 * static_cast<std::size_t>(i);  // 3 * i wraps in index_t past 715 M nodes
  return Vec3<Real>{static_cast<Real>((p[0] - f.cx) * f.inv_scale), static_cast<Real>((p[1] - f.cy) * f.inv_scale),
                    static_cast<Real>((p[2] - f.cz) * f.inv_scale)};
}

template <class Real, class Coords>
__global__ void load_coords_kernel(const double* in, Coords out, index_t n, WorkingFrame f) {
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i >= n) return;
  out.set(i, working_position<Real>(in, i, f));
}

// Writes back the movable nodes that the run moved, into `out`, which holds
// the input already: a node whose working position is still the one it was
// loaded at keeps its input bits, so that float, whose working position is
// the input rounded, returns unmoved nodes exactly as they came (a run of no
// sweeps returns the input), and nodes that never move are never written.
template <class Real, class Coords>
__global__ void store_coords_kernel(Coords working, const double* input, double* out, const std::uint8_t* movable,
                                    index_t n, WorkingFrame f) {
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i >= n || !movable[i]) return;
  const Vec3<Real> v = working.get(i), loaded = working_position<Real>(input, i, f);
  if (v.x == loaded.x && v.y == loaded.y && v.z == loaded.z) return;
  double* const p = out + 3 * static_cast<std::size_t>(i);
  p[0] = static_cast<double>(v.x) * f.scale + f.cx;
  p[1] = static_cast<double>(v.y) * f.scale + f.cy;
  p[2] = static_cast<double>(v.z) * f.scale + f.cz;
}

// Counts the nodes that never move whose working coordinates are not those
// they were loaded at: the sweeps must leave such nodes alone, and
// store_coords_kernel, which writes back movable nodes only, would hide it
// if they did not.
template <class Real, class Coords>
__global__ void count_moved_fixed_kernel(Coords working, const double* input, const std::uint8_t* movable, index_t n,
                                         WorkingFrame f, unsigned long long* count) {
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i >= n || movable[i]) return;
  const Vec3<Real> v = working.get(i), loaded = working_position<Real>(input, i, f);
  if (v.x != loaded.x || v.y != loaded.y || v.z != loaded.z) atomicAdd(count, 1ull);
}

}  // namespace tetsmooth::cuda
