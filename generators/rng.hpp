#pragma once
// The generators' own random numbers.
//
// std::uniform_real_distribution and friends are implementation-defined, so a
// mesh drawn with them would change between standard libraries. SplitMix64
// (Steele, Lea and Flood, 2014) with an explicit bits-to-double mapping gives
// the same stream everywhere, which is what "same seed, same mesh" needs.
#include <cstdint>

namespace tetsmooth {

// SplitMix64's output function: a bijective 64-bit mix with full avalanche.
inline std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

  // An independent stream per (seed, index), so that parallel loops can give
  // every item its own numbers and stay independent of the thread count.
  static SplitMix64 stream(std::uint64_t seed, std::uint64_t index) {
    return SplitMix64(mix64(seed ^ mix64(index + 0x632BE59BD9B4E019ull)));
  }

  std::uint64_t next() { return mix64(state_ += 0x9E3779B97F4A7C15ull); }

  // Uniform in the open interval (0, 1): an odd multiple of 2^-53, exact in a
  // double (52 random bits plus the half), so never 0 or 1. Random nodes then
  // never land on a box face.
  double open01() { return (static_cast<double>(next() >> 12) + 0.5) * 0x1.0p-52; }

  // Uniform in (lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * open01(); }

 private:
  std::uint64_t state_;
};

}  // namespace tetsmooth
