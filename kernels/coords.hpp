#pragma once
// Coordinate accessors: the data layout as a policy type, so one kernel body
// serves both layouts.
//  AosCoords: x0 y0 z0 x1 y1 z1 ... (one array, 3 * N)
//  SoaCoords: x[N], y[N], z[N]
#include <cstddef>

#include "mesh/hd.hpp"
#include "mesh/tet_mesh.hpp"
#include "mesh/vec3.hpp"

namespace tetsmooth {

// AosCoords forms a point's address in 64 bits (3 * i never wraps past 715 M
// nodes), which the GPU computes in one multiply-add where 3 * i in 32 bits
// took two (100 float MultiBlock sweeps of lattice-215 on an H200: 228.7 and
// 227.9 ms against 229.2, 461.3 and 460.8 against 464.0 in double).
template <class Real>
struct AosCoords {
  Real* p;
  TS_HD Vec3<Real> get(index_t i) const {
    const Real* q = p + 3 * static_cast<std::ptrdiff_t>(i);
    return {q[0], q[1], q[2]};
  }
  TS_HD void set(index_t i, Vec3<Real> v) const {
    Real* q = p + 3 * static_cast<std::ptrdiff_t>(i);
    q[0] = v.x;
    q[1] = v.y;
    q[2] = v.z;
  }
};

template <class Real>
struct SoaCoords {
  Real* x;
  Real* y;
  Real* z;
  TS_HD Vec3<Real> get(index_t i) const { return {x[i], y[i], z[i]}; }
  TS_HD void set(index_t i, Vec3<Real> v) const {
    x[i] = v.x;
    y[i] = v.y;
    z[i] = v.z;
  }
};

}  // namespace tetsmooth
