#pragma once
// A tiny 3-vector for the shared host/device math. Real is float or double.
#include "mesh/hd.hpp"

namespace tetsmooth {

template <class Real>
struct Vec3 {
  Real x, y, z;
};

template <class Real>
TS_HD Vec3<Real> operator+(Vec3<Real> a, Vec3<Real> b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class Real>
TS_HD Vec3<Real> operator-(Vec3<Real> a, Vec3<Real> b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class Real>
TS_HD Vec3<Real> operator*(Real s, Vec3<Real> a) { return {s * a.x, s * a.y, s * a.z}; }
template <class Real>
TS_HD Real dot(Vec3<Real> a, Vec3<Real> b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class Real>
TS_HD Vec3<Real> cross(Vec3<Real> a, Vec3<Real> b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class Real>
TS_HD Real norm2(Vec3<Real> a) { return dot(a, a); }

}  // namespace tetsmooth
