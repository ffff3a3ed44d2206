// The jittered Kuhn lattice: a structured mesh of any size in seconds, for
// scaling studies far beyond what TetGen builds quickly.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "generators/models.hpp"
#include "generators/rng.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth {
namespace {

// The six Kuhn tets of a cube, as cube-corner numbers (bit 0: +x, bit 1: +y,
// bit 2: +z). Each is a path 0 -> one axis -> two axes -> 7; for an odd axis
// permutation the last two corners are swapped so the volume is positive.
constexpr int kKuhnTets[6][4] = {
    {0, 1, 3, 7},  // x, y, z
    {0, 2, 6, 7},  // y, z, x
    {0, 4, 5, 7},  // z, x, y
    {0, 1, 7, 5},  // x, z, y
    {0, 2, 7, 3},  // y, x, z
    {0, 4, 7, 6},  // z, y, x
};

// kMaxLatticeN (models.hpp) is the largest n whose node-to-tet table fits.
constexpr std::int64_t kMaxIndex = std::numeric_limits<index_t>::max();
static_assert(24 * std::int64_t{kMaxLatticeN} * kMaxLatticeN * kMaxLatticeN <= kMaxIndex &&
              24 * std::int64_t{kMaxLatticeN + 1} * (kMaxLatticeN + 1) * (kMaxLatticeN + 1) > kMaxIndex);

struct Offset {
  double x, y, z;
};

// A point uniform in the unit ball by rejection from the cube. Each node has
// its own stream, so a parallel loop gives the same mesh for any thread count.
Offset ball_offset(std::uint64_t seed, std::uint64_t node) {
  SplitMix64 rng = SplitMix64::stream(seed, node);
  for (;;) {
    const Offset o{rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)};
    if (o.x * o.x + o.y * o.y + o.z * o.z <= 1.0) return o;
  }
}

}  // namespace

TetMesh generate_lattice(int n, double jitter, std::uint64_t seed) {
  if (n < 1) throw UsageError("lattice: n must be >= 1 cubes per axis, got " + std::to_string(n));
  if (!(jitter >= 0.0 && jitter < 0.5))
    throw UsageError("lattice: jitter must be in [0, 0.5) cell sizes, got " + std::to_string(jitter));
  if (n > kMaxLatticeN)
    throw UsageError("lattice-" + std::to_string(n) + ": its 6 n^3 tets need more than the 32-bit offsets of the "
                     "node-to-tet table hold (4 entries a tet); the largest is lattice-" +
                     std::to_string(kMaxLatticeN));
  const std::int64_t m = static_cast<std::int64_t>(n) + 1;  // nodes per axis
  const std::int64_t cubes = static_cast<std::int64_t>(n) * n * n;

  TetMesh mesh;
  mesh.xyz.resize(static_cast<std::size_t>(3 * m * m * m));
  mesh.tets.resize(static_cast<std::size_t>(24 * cubes));
  double* xyz = mesh.xyz.data();
  index_t* tets = mesh.tets.data();

#pragma omp parallel for schedule(static)
  for (std::int64_t k = 0; k < m; ++k)
    for (std::int64_t j = 0; j < m; ++j)
      for (std::int64_t i = 0; i < m; ++i) {
        const std::int64_t node = i + m * (j + m * k);
        double* p = xyz + 3 * node;
        p[0] = static_cast<double>(i);
        p[1] = static_cast<double>(j);
        p[2] = static_cast<double>(k);
        const bool interior = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        if (interior && jitter > 0.0) {
          const Offset o = ball_offset(seed, static_cast<std::uint64_t>(node));
          p[0] += jitter * o.x;
          p[1] += jitter * o.y;
          p[2] += jitter * o.z;
        }
      }

  const std::int64_t corner_step[8] = {0, 1, m, m + 1, m * m, m * m + 1, m * m + m, m * m + m + 1};
#pragma omp parallel for schedule(static)
  for (std::int64_t k = 0; k < n; ++k)
    for (std::int64_t j = 0; j < n; ++j)
      for (std::int64_t i = 0; i < n; ++i) {
        const std::int64_t origin = i + m * (j + m * k);
        index_t* t = tets + 24 * (i + n * (j + static_cast<std::int64_t>(n) * k));
        for (const auto& kuhn : kKuhnTets)
          for (int corner : kuhn) *t++ = static_cast<index_t>(origin + corner_step[corner]);
      }
  return mesh;
}

}  // namespace tetsmooth
