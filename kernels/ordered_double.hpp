#pragma once
// Doubles as unsigned 64-bit keys in the doubles' own order, so that an
// integer atomicMin or atomicMax finds the smallest or largest double of any
// sign (CUDA has neither for doubles). Negative values have their bits
// reversed; -0 sorts just below +0, and NaNs (which no caller passes) beyond
// the infinities.
#include <cstdint>
#include <cstring>

#include "mesh/hd.hpp"

namespace tetsmooth {

TS_HD std::uint64_t ordered_key(double v) {
  std::uint64_t bits;
  static_assert(sizeof bits == sizeof v);
  memcpy(&bits, &v, sizeof bits);
  return (bits >> 63) ? ~bits : bits | (std::uint64_t{1} << 63);
}

TS_HD double from_ordered_key(std::uint64_t key) {
  const std::uint64_t bits = (key >> 63) ? key & ~(std::uint64_t{1} << 63) : ~key;
  double v;
  memcpy(&v, &bits, sizeof v);
  return v;
}

}  // namespace tetsmooth
