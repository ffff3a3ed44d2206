#pragma once
// The square roots and quotients of radius_ratio (tet_quality.hpp).
//
// Everywhere they are the language's own, except in device code built with
// TETSMOOTH_FTZ_FLOAT_ROOTS (the CUDA float sweeps, which are also built
// with approximate square roots and division; kernels/cuda/CMakeLists.txt):
// there float takes the hardware's approximate forms that treat a subnormal
// operand as zero. Without that, each of the radius ratio's five square
// roots, its reciprocal and its division carries a test for subnormal
// operands and a rescaling around the hardware instruction (100 float
// MultiBlock sweeps of lattice-215 on an H100: 255.5 and 252.6 ms with
// these, 267.0 and 269.9 without). Nothing a supported tet feeds them is
// subnormal: they take squared face norms, |N s|² (both of the order of
// edge^4) and the largest squared edge, so edges down to ~1e-9 of the unit
// box keep their values, below the ~1e-6 to which float keeps the volume
// (whose products are plain multiplications, untouched here). The GPU test
// FloatRadiusRatioKeepsSmallTets checks tets down to 1e-6.
#include <cmath>

#include "mesh/hd.hpp"

namespace tetsmooth {

TS_HD double quality_sqrt(double x) { return std::sqrt(x); }
TS_HD double quality_div(double a, double b) { return a / b; }

TS_HD float quality_sqrt(float x) {
#if defined(__CUDA_ARCH__) && defined(TETSMOOTH_FTZ_FLOAT_ROOTS)
  float r;
  asm("sqrt.approx.ftz.f32 %0, %1;" : "=f"(r) : "f"(x));
  return r;
#else
  return std::sqrt(x);
#endif
}

TS_HD float quality_div(float a, float b) {
#if defined(__CUDA_ARCH__) && defined(TETSMOOTH_FTZ_FLOAT_ROOTS)
  float r;
  asm("div.approx.ftz.f32 %0, %1, %2;" : "=f"(r) : "f"(a), "f"(b));
  return r;
#else
  return a / b;
#endif
}

}  // namespace tetsmooth
