// The jittered Kuhn lattice: sizes, numbering, conformity, orientation and
// the jitter's bounds.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "generators/models.hpp"
#include "mesh/errors.hpp"
#include "mesh/tet_quality.hpp"

namespace tetsmooth {
namespace {

Vec3<double> node(const TetMesh& m, index_t i) {
  const double* p = &m.xyz[3 * static_cast<std::size_t>(i)];
  return {p[0], p[1], p[2]};
}

double volume6(const TetMesh& m, std::size_t t) {
  const index_t* v = &m.tets[4 * t];
  return signed_volume6(node(m, v[0]), node(m, v[1]), node(m, v[2]), node(m, v[3]));
}

// How the tets' faces pair up. In a conforming mesh of positive tets every
// face is either on the boundary (used once) or interior (used twice, in
// opposite orientations); anything else is a non-conforming or folded face.
struct FaceCensus {
  std::size_t interior = 0;
  std::vector<std::array<index_t, 3>> boundary;
  std::size_t bad = 0;
};

FaceCensus count_faces(const TetMesh& m) {
  struct Use {
    std::array<index_t, 3> key;  // sorted node indices
    bool even;                   // orientation: is the tet's order an even permutation of key?
  };
  std::vector<Use> uses;
  uses.reserve(4 * m.num_tets());
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (const auto& f : kTetFaces) {
      std::array<index_t, 3> v{m.tets[4 * t + f[0]], m.tets[4 * t + f[1]], m.tets[4 * t + f[2]]};
      bool even = true;
      for (int pass = 0; pass < 2; ++pass)
        for (int i = 0; i + 1 < 3 - pass; ++i)
          if (v[i] > v[i + 1]) {
            std::swap(v[i], v[i + 1]);
            even = !even;
          }
      uses.push_back({v, even});
    }
  std::sort(uses.begin(), uses.end(), [](const Use& a, const Use& b) { return a.key < b.key; });

  FaceCensus census;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i == 1)
      census.boundary.push_back(uses[i].key);
    else if (j - i == 2 && uses[i].even != uses[i + 1].even)
      ++census.interior;
    else
      ++census.bad;
    i = j;
  }
  return census;
}

TEST(Lattice, SizesAreCubesCubed) {
  for (int n = 1; n <= 6; ++n) {
    const TetMesh m = generate_lattice(n, 0.0, 1);
    EXPECT_EQ(m.num_nodes(), static_cast<std::size_t>((n + 1) * (n + 1) * (n + 1))) << "n=" << n;
    EXPECT_EQ(m.num_tets(), static_cast<std::size_t>(6 * n * n * n)) << "n=" << n;
  }
}

TEST(Lattice, NumbersNodesAndTetsByCube) {
  const int n = 4, m1 = n + 1;
  const TetMesh m = generate_lattice(n, 0.0, 1);
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const Vec3<double> p = node(m, i + m1 * (j + m1 * k));
        EXPECT_EQ(p.x, i);
        EXPECT_EQ(p.y, j);
        EXPECT_EQ(p.z, k);
      }
  // Cube (i,j,k) owns tets 6c..6c+5, whose nodes are that cube's corners.
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::size_t c = static_cast<std::size_t>(i + n * (j + n * k));
        for (std::size_t t = 6 * c; t < 6 * c + 6; ++t)
          for (int v = 0; v < 4; ++v) {
            const Vec3<double> p = node(m, m.tets[4 * t + v]);
            EXPECT_TRUE(p.x - i >= 0 && p.x - i <= 1 && p.y - j >= 0 && p.y - j <= 1 && p.z - k >= 0 && p.z - k <= 1)
                << "tet " << t << " leaves cube " << c;
          }
      }
}

TEST(Lattice, UnjitteredTetsAreSixthsOfACube) {
  const TetMesh m = generate_lattice(3, 0.0, 1);
  for (std::size_t t = 0; t < m.num_tets(); ++t) EXPECT_EQ(volume6(m, t), 1.0) << "tet " << t;
}

TEST(Lattice, NeighbouringCubesShareFaces) {
  for (const double jitter : {0.0, kLatticeDefaultJitter}) {
    const int n = 5;
    const TetMesh m = generate_lattice(n, jitter, 3);
    const FaceCensus census = count_faces(m);
    EXPECT_EQ(census.bad, 0u);
    // Every tet face is interior or boundary: 4T = 2 interior + boundary.
    EXPECT_EQ(2 * census.interior + census.boundary.size(), 4 * m.num_tets());
    // Six box faces of n^2 squares, two triangles each.
    ASSERT_EQ(census.boundary.size(), static_cast<std::size_t>(12 * n * n));
    for (const auto& f : census.boundary) {
      const Vec3<double> a = node(m, f[0]), b = node(m, f[1]), c = node(m, f[2]);
      const bool on_box = (a.x == b.x && b.x == c.x && (a.x == 0 || a.x == n)) ||
                          (a.y == b.y && b.y == c.y && (a.y == 0 || a.y == n)) ||
                          (a.z == b.z && b.z == c.z && (a.z == 0 || a.z == n));
      EXPECT_TRUE(on_box) << "boundary face " << f[0] << " " << f[1] << " " << f[2] << " is not on the box";
    }
  }
}

TEST(Lattice, JitteredTetsFillTheBoxWithoutInverting) {
  const int n = 16;
  for (const double jitter : {kLatticeDefaultJitter, 0.99 * kLatticeSafeJitter})
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const TetMesh m = generate_lattice(n, jitter, seed);
      double total = 0, smallest = std::numeric_limits<double>::infinity();
      for (std::size_t t = 0; t < m.num_tets(); ++t) {
        const double v6 = volume6(m, t);
        total += v6;
        smallest = std::min(smallest, v6);
      }
      EXPECT_GT(smallest, 0.0) << "jitter " << jitter << " seed " << seed;
      // Boundary nodes stay put, so positive tets of a conforming mesh add
      // up to the box.
      EXPECT_NEAR(total / 6.0, n * n * n, 1e-9 * n * n * n) << "jitter " << jitter << " seed " << seed;
    }
}

TEST(Lattice, JitterMovesInteriorNodesOnlyAndWithinItsBall) {
  const int n = 6, m1 = n + 1;
  const double jitter = 0.2;
  const TetMesh m = generate_lattice(n, jitter, 11);
  double largest = 0;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const Vec3<double> p = node(m, i + m1 * (j + m1 * k));
        const double moved = std::sqrt(norm2(p - Vec3<double>{double(i), double(j), double(k)}));
        const bool interior = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        if (interior) {
          EXPECT_LE(moved, jitter * (1 + 1e-12));
          largest = std::max(largest, moved);
        } else {
          EXPECT_EQ(moved, 0.0) << "boundary node " << i << "," << j << "," << k << " moved";
        }
      }
  // 125 interior nodes uniform in the ball: some land in its outer half.
  EXPECT_GT(largest, 0.5 * jitter);
}

TEST(Lattice, SameSeedSameMeshWhateverTheThreadCount) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const TetMesh serial = generate_lattice(9, kLatticeDefaultJitter, 5);
  omp_set_num_threads(3);
  const TetMesh parallel = generate_lattice(9, kLatticeDefaultJitter, 5);
  omp_set_num_threads(threads);
  EXPECT_EQ(serial.xyz, parallel.xyz);
  EXPECT_EQ(serial.tets, parallel.tets);

  const TetMesh other_seed = generate_lattice(9, kLatticeDefaultJitter, 6);
  EXPECT_NE(serial.xyz, other_seed.xyz);
  EXPECT_EQ(serial.tets, other_seed.tets);
}

TEST(Lattice, ByNameUsesTheDefaultJitter) {
  const TetMesh named = generate_model("lattice-4", 9);
  const TetMesh direct = generate_lattice(4, kLatticeDefaultJitter, 9);
  EXPECT_EQ(named.xyz, direct.xyz);
  EXPECT_EQ(named.tets, direct.tets);
  EXPECT_LT(kLatticeDefaultJitter, kLatticeSafeJitter);
}

TEST(Lattice, RejectsBadSizesAndJitter) {
  EXPECT_THROW(generate_lattice(0, 0.0, 1), UsageError);
  EXPECT_THROW(generate_lattice(-3, 0.0, 1), UsageError);
  // 24 * 448^3 node-to-tet entries no longer fit 32-bit offsets; refused
  // before allocating.
  EXPECT_THROW(generate_lattice(448, 0.0, 1), UsageError);
  EXPECT_THROW(generate_lattice(std::numeric_limits<int>::max(), 0.0, 1), UsageError);
  EXPECT_THROW(generate_lattice(2, -0.1, 1), UsageError);
  EXPECT_THROW(generate_lattice(2, 0.5, 1), UsageError);
  EXPECT_THROW(generate_lattice(2, std::numeric_limits<double>::quiet_NaN(), 1), UsageError);
  EXPECT_THROW(generate_model("lattice-448"), UsageError);
}

}  // namespace
}  // namespace tetsmooth
