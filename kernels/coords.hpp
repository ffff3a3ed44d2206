#pragma once
// Coordinate accessors: the data layout as a policy type, so one kernel body
// serves both layouts.
//  AosCoords: x0 y0 z0 x1 y1 z1 ... (one array, 3 * N)
//  SoaCoords: x[N], y[N], z[N]
#include "mesh/hd.hpp"
#include "mesh/tet_mesh.hpp"
#include "mesh/vec3.hpp"

namespace tetsmooth {

template <class Real>
struct AosCoords {
  Real* p;
  TS_HD Vec3<Real> get(index_t i) const { return {p[3 * i], p[3 * i + 1], p[3 * i + 2]}; }
  TS_HD void set(index_t i, Vec3<Real> v) const {
    p[3 * i] = v.x;
    p[3 * i + 1] = v.y;
    p[3 * i + 2] = v.z;
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
