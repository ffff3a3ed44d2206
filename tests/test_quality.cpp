// Quality metrics: the radius ratio, mean ratio and minimum dihedral angle
// on planted shapes, their invariances, and the mesh summary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "mesh/quality_summary.hpp"
#include "mesh/tet_quality.hpp"
#include "test_meshes.hpp"

namespace tetsmooth {
namespace {

using V = Vec3<double>;
const V kA{0, 0, 0}, kB{1, 0, 0}, kC{0.5, 0.8660254037844386, 0}, kD{0.5, 0.2886751345948129, 0.816496580927726};

TEST(RadiusRatio, RegularTetIsOne) {
  EXPECT_NEAR(radius_ratio(kA, kB, kC, kD), 1.0, 1e-12);
  EXPECT_NEAR(mean_ratio(kA, kB, kC, kD), 1.0, 1e-12);
  EXPECT_NEAR(min_dihedral_deg(kA, kB, kC, kD), std::acos(1.0 / 3.0) * 180 / M_PI, 1e-9);
}

TEST(RadiusRatio, RightCornerTetMatchesClosedForm) {
  // Corner tet of the unit cube: r_in = 1/(3+sqrt 3), R = sqrt(3)/2.
  const double expected = 3.0 * (1.0 / (3.0 + std::sqrt(3.0))) / (std::sqrt(3.0) / 2.0);
  EXPECT_NEAR(radius_ratio(V{0, 0, 0}, V{1, 0, 0}, V{0, 1, 0}, V{0, 0, 1}), expected, 1e-12);
}

TEST(RadiusRatio, PoorShapesAreNearZero) {
  const V flat_d{0.5, 0.2886751345948129, 1e-6};            // flat: apex almost in the base plane
  const V needle_d{0.5, 0.2886751345948129, 1e4};           // needle: very tall apex
  const V sliver[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 1e-5}, {1, 1, 0}};  // four nearly coplanar corners of a square
  EXPECT_LT(radius_ratio(kA, kB, kC, flat_d), 1e-4);
  EXPECT_LT(radius_ratio(kA, kB, kC, needle_d), 1e-3);
  EXPECT_LT(std::abs(radius_ratio(sliver[0], sliver[1], sliver[2], sliver[3])), 1e-4);
  EXPECT_LT(min_dihedral_deg(sliver[0], sliver[1], sliver[2], sliver[3]), 0.01);
  EXPECT_EQ(radius_ratio(kA, kB, V{2, 0, 0}, kD), 0.0) << "a tet with three collinear corners is degenerate";
  EXPECT_EQ(radius_ratio(kA, kA, kC, kD), 0.0) << "a repeated corner is degenerate";
}

// An independent route to 3 r_in / R: face areas from edge lengths
// (Heron), the circumcentre by Gaussian elimination on 2 e_k·x = |e_k|²,
// r_in = 3V/S.
double radius_ratio_by_elimination(const V p[4]) {
  auto len = [](V x) { return std::sqrt(norm2(x)); };
  auto heron = [&](V x, V y, V z) {
    const double a = len(y - x), b = len(z - y), c = len(x - z), s = (a + b + c) / 2;
    return std::sqrt(std::max(0.0, s * (s - a) * (s - b) * (s - c)));
  };
  const double S = heron(p[0], p[1], p[2]) + heron(p[0], p[1], p[3]) + heron(p[0], p[2], p[3]) +
                   heron(p[1], p[2], p[3]);
  const double vol = signed_volume6(p[0], p[1], p[2], p[3]) / 6;
  double m[3][4];
  for (int r = 0; r < 3; ++r) {
    const V e = p[r + 1] - p[0];
    m[r][0] = 2 * e.x, m[r][1] = 2 * e.y, m[r][2] = 2 * e.z, m[r][3] = norm2(e);
  }
  for (int col = 0; col < 3; ++col) {
    int piv = col;
    for (int r = col + 1; r < 3; ++r)
      if (std::abs(m[r][col]) > std::abs(m[piv][col])) piv = r;
    std::swap(m[col], m[piv]);
    for (int r = 0; r < 3; ++r)
      if (r != col) {
        const double f = m[r][col] / m[col][col];
        for (int k = col; k < 4; ++k) m[r][k] -= f * m[col][k];
      }
  }
  const double R = std::sqrt(norm2(V{m[0][3] / m[0][0], m[1][3] / m[1][1], m[2][3] / m[2][2]}));
  return 3 * (3 * vol / S) / R;
}

TEST(RadiusRatio, AgreesWithAnIndependentConstruction) {
  std::uint64_t state = 12345;
  auto uniform = [&] {  // xorshift: the same draws on every platform
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  int checked = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    V p[4];
    for (V& x : p) x = V{uniform(), uniform(), uniform()};
    const double expected = radius_ratio_by_elimination(p);
    if (std::abs(expected) < 1e-3) continue;  // near-flat draws: both routes lose digits there
    EXPECT_NEAR(radius_ratio(p[0], p[1], p[2], p[3]), expected, 1e-9 * std::abs(expected)) << "draw " << trial;
    ++checked;
  }
  EXPECT_GT(checked, 1900);
}

// Four corners on one line in a random direction, exactly (up to the
// rounding of the coordinates) and nudged off it by far less than a float's
// resolution: every cross product is rounding noise, and a quotient of
// noises must not pass for quality.
template <class Real>
void expect_needles_degenerate(double nudge) {
  std::uint64_t state = 777;
  auto uniform = [&] {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  using R = Vec3<Real>;
  for (int trial = 0; trial < 20000; ++trial) {
    const V dir{uniform() - 0.5, uniform() - 0.5, uniform() - 0.5}, base{uniform(), uniform(), uniform()};
    R p[4];
    for (R& x : p) {
      const V at = base + (uniform() - 0.5) * dir + nudge * V{uniform(), uniform(), uniform()};
      x = R{static_cast<Real>(at.x), static_cast<Real>(at.y), static_cast<Real>(at.z)};
    }
    ASSERT_LT(std::abs(static_cast<double>(radius_ratio(p[0], p[1], p[2], p[3]))), 1e-3) << "draw " << trial;
  }
}

TEST(RadiusRatio, CollinearNeedlesAreDegenerate) {
  expect_needles_degenerate<double>(0.0);
  expect_needles_degenerate<float>(0.0);
  expect_needles_degenerate<float>(1e-9);
}

// Float keeps its range for small tets (a float run works in the unit box,
// where a graded mesh's smallest tets are far below 1).
TEST(RadiusRatio, FloatKeepsSmallTets) {
  using F = Vec3<float>;
  for (float h : {1e-2f, 1e-3f, 1e-4f, 1e-5f, 1e-6f}) {
    const float q = radius_ratio(F{0, 0, 0}, F{h, 0, 0}, F{0, h, 0}, F{0, 0, h});
    EXPECT_NEAR(q, radius_ratio(V{0, 0, 0}, V{1, 0, 0}, V{0, 1, 0}, V{0, 0, 1}), 1e-5) << "edge " << h;
  }
}

// Double forms N unscaled (tet_quality.hpp): its range still spans any
// unit a mesh comes in, the regular tet and a skewed one alike.
TEST(RadiusRatio, DoubleKeepsItsRangeUnscaled) {
  const double regular = radius_ratio(kA, kB, kC, kD);
  const double skewed = radius_ratio(V{0, 0, 0}, V{1, 0, 0}, V{0.3, 0.2, 0}, V{0.1, 0.4, 0.05});
  for (double h : {1e-35, 1e-20, 1e-8, 1e8, 1e20, 1e35}) {
    const auto at = [h](V v) { return V{h * v.x, h * v.y, h * v.z}; };
    EXPECT_NEAR(radius_ratio(at(kA), at(kB), at(kC), at(kD)), regular, 1e-12) << "scale " << h;
    EXPECT_NEAR(radius_ratio(at(V{0, 0, 0}), at(V{1, 0, 0}), at(V{0.3, 0.2, 0}), at(V{0.1, 0.4, 0.05})), skewed, 1e-12)
        << "scale " << h;
  }
}

TEST(RadiusRatio, InvertedIsNegative) {
  EXPECT_NEAR(radius_ratio(kB, kA, kC, kD), -1.0, 1e-12);
  EXPECT_NEAR(mean_ratio(kB, kA, kC, kD), -1.0, 1e-12);
  EXPECT_LT(signed_volume6(kB, kA, kC, kD), 0);
}

class Invariance : public ::testing::TestWithParam<double> {};

TEST_P(Invariance, TranslationRotationScale) {
  const double s = GetParam();
  const V tet[4] = {{0.1, 0.2, 0.05}, {1.3, 0.1, 0.2}, {0.4, 0.9, 0.1}, {0.5, 0.4, 0.7}};
  const double q0 = radius_ratio(tet[0], tet[1], tet[2], tet[3]);
  const double m0 = mean_ratio(tet[0], tet[1], tet[2], tet[3]);
  const double d0 = min_dihedral_deg(tet[0], tet[1], tet[2], tet[3]);
  // Rotation about an oblique axis (Rodrigues), then scale, then translate.
  const double th = 0.7, c = std::cos(th), sn = std::sin(th);
  const V k{1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  V moved[4];
  for (int i = 0; i < 4; ++i) {
    const V p = tet[i];
    const V r = c * p + sn * cross(k, p) + ((1 - c) * dot(k, p)) * k;
    moved[i] = s * r + V{123.0 * s, -45.0 * s, 7.0 * s};
  }
  EXPECT_NEAR(radius_ratio(moved[0], moved[1], moved[2], moved[3]), q0, 1e-9);
  EXPECT_NEAR(mean_ratio(moved[0], moved[1], moved[2], moved[3]), m0, 1e-9);
  EXPECT_NEAR(min_dihedral_deg(moved[0], moved[1], moved[2], moved[3]), d0, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Scales, Invariance, ::testing::Values(1e-6, 1e-3, 1.0, 1e3, 1e6));

TEST(RadiusRatio, FloatAgreesWithDoubleOnUnitScale) {
  using F = Vec3<float>;
  const float q = radius_ratio(F{0, 0, 0}, F{1, 0, 0}, F{0, 1, 0}, F{0, 0, 1});
  EXPECT_NEAR(q, radius_ratio(V{0, 0, 0}, V{1, 0, 0}, V{0, 1, 0}, V{0, 0, 1}), 1e-6);
}

// The dihedral angle at edge pq, found in the plane through p normal to
// the edge: the angle there between the projections of r - p and s - p
// (each face's in-plane perpendicular to the edge), by atan2 so that no
// angle loses digits near 0 or 180. Independent of the face normals that
// min_dihedral_deg uses.
double dihedral_at_edge_deg(V p, V q, V r, V s) {
  const V e = q - p;
  const auto across = [&](V x) { return (x - p) - (dot(x - p, e) / norm2(e)) * e; };
  const V u = across(r), w = across(s);
  return std::atan2(std::sqrt(norm2(cross(u, w))), dot(u, w)) * 180 / M_PI;
}

double smallest_dihedral_by_edges_deg(const V (&t)[4]) {
  constexpr int kEdges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  double smallest = 180;
  for (const auto& e : kEdges) smallest = std::min(smallest, dihedral_at_edge_deg(t[e[0]], t[e[1]], t[e[2]], t[e[3]]));
  return smallest;
}

// Irregular tets (no two dihedral angles alike, the smallest well below 180
// minus the largest), given to min_dihedral_deg in all 24 corner orders:
// each face takes each of the four normal slots, in both orientations, so a
// wrong normal or sign shows in some order.
TEST(MinDihedral, MatchesAnglesMeasuredAtTheEdgesInEveryCornerOrder) {
  const V tets[][4] = {{{0, 0, 0}, {2.3, 0.1, -0.2}, {0.4, 1.7, 0.3}, {0.9, 0.6, 1.4}},
                       {{0.2, -0.1, 0}, {1.1, 0.05, 0.02}, {0.3, 0.9, 0.1}, {0.6, 0.35, 0.25}}};
  for (const auto& tet : tets) {
    const double expected = smallest_dihedral_by_edges_deg(tet);
    ASSERT_GT(expected, 1.0);
    int order[4] = {0, 1, 2, 3};
    int orders = 0;
    do {
      EXPECT_NEAR(min_dihedral_deg(tet[order[0]], tet[order[1]], tet[order[2]], tet[order[3]]), expected, 1e-9)
          << "corner order " << order[0] << order[1] << order[2] << order[3];
      ++orders;
    } while (std::next_permutation(order, order + 4));
    EXPECT_EQ(orders, 24);
  }
}

// A face of zero area has no normal: the tet is degenerate, 0 degrees, in
// every corner order. Four corners on one line leave every face without a
// normal, so there is no pair of faces to fall back on.
TEST(MinDihedral, ZeroAreaFaceGivesZero) {
  const V flat_face[4] = {{0, 0, 0}, {1, 2, 3}, {2, 4, 6}, {0.5, -1, 2}};  // three corners on a line
  const V needle[4] = {{0, 0, 0}, {1, 2, 3}, {3, 6, 9}, {-2, -4, -6}};     // all four on a line
  const V repeated[4] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0.2, 0.3, 0.9}};
  const std::pair<const char*, const V*> tets[] = {
      {"flat face", flat_face}, {"needle", needle}, {"repeated", repeated}};
  for (const auto& [name, tet] : tets) {
    int order[4] = {0, 1, 2, 3};
    do {
      EXPECT_EQ(min_dihedral_deg(tet[order[0]], tet[order[1]], tet[order[2]], tet[order[3]]), 0.0)
          << name << ", corner order " << order[0] << order[1] << order[2] << order[3];
    } while (std::next_permutation(order, order + 4));
  }
}

TEST(QualitySummary, CountsAndHistogram) {
  TetMesh m = testing::cube_with_centre(0.5, 0.5, 0.05);
  const QualitySummary good = summarize_quality(testing::cube_with_centre());
  const QualitySummary skewed = summarize_quality(m);
  EXPECT_EQ(good.tets, 12u);
  std::size_t total = 0;
  for (auto h : skewed.histogram) total += h;
  EXPECT_EQ(total, 12u);
  EXPECT_GT(good.min, skewed.min);
  EXPECT_GT(skewed.below_0_1, 0u);
  EXPECT_EQ(skewed.inverted, 0u);
  // Push the centre through the bottom face: the two bottom tets invert.
  m.xyz[3 * 8 + 2] = -0.1;
  const QualitySummary inverted = summarize_quality(m);
  EXPECT_EQ(inverted.inverted, 2u);
  EXPECT_LT(inverted.min, 0);
  EXPECT_EQ(inverted.histogram[0], inverted.below_0_1);
}

TEST(QualitySummary, MinOverMovableIgnoresFrozenTets) {
  TetMesh m = testing::cube_with_centre();
  std::vector<std::uint8_t> movable(9, 0);
  const QualitySummary none = summarize_quality(m, movable);
  EXPECT_EQ(none.min_movable, 1.0);
  EXPECT_EQ(none.movable_tets, 0u);
  movable[8] = 1;
  const QualitySummary all = summarize_quality(m, movable);
  EXPECT_DOUBLE_EQ(all.min_movable, all.min);
  EXPECT_EQ(all.movable_tets, 12u);
  movable.assign(9, 0);
  movable[0] = 1;  // a corner: only the tets that touch it
  const QualitySummary corner = summarize_quality(m, movable);
  EXPECT_GT(corner.movable_tets, 0u);
  EXPECT_LT(corner.movable_tets, 12u);
}

// Two tets on a shared face, (0,1,2,3) and (0,2,1,4): the nodes 3 and 4
// are each the last corner of one tet only, so the count must look at all
// four corners of a tet, not just the first three.
TEST(QualitySummary, MovableTetsCountsATetByItsLastCorner) {
  TetMesh m;
  m.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.2, 0.3, 1, 0.3, 0.2, -0.8};
  m.tets = {0, 1, 2, 3, 0, 2, 1, 4};
  const std::vector<double> q = tet_qualities(m);
  ASSERT_NE(q[0], q[1]);
  for (int last : {3, 4}) {
    std::vector<std::uint8_t> movable(5, 0);
    movable[static_cast<std::size_t>(last)] = 1;
    const QualitySummary s = summarize_quality(m, movable);
    EXPECT_EQ(s.movable_tets, 1u) << "node " << last;
    EXPECT_EQ(s.min_movable, q[last == 3 ? 0 : 1]) << "node " << last;
  }
}

// An inverted tet has a volume, just a negative one: it is inverted and not
// degenerate. Only a tet of zero volume (here four corners in z = 0, whose
// volume is exactly 0 in floating point) is degenerate.
TEST(QualitySummary, InvertedTetsAreNotDegenerate) {
  TetMesh inverted;
  inverted.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  inverted.tets = {0, 2, 1, 3};
  const QualitySummary i = summarize_quality(inverted);
  EXPECT_EQ(i.inverted, 1u);
  EXPECT_EQ(i.degenerate, 0u);

  TetMesh flat = inverted;
  flat.xyz[11] = 0;
  flat.xyz[9] = flat.xyz[10] = 0.3;
  const QualitySummary f = summarize_quality(flat);
  EXPECT_EQ(f.inverted, 0u);
  EXPECT_EQ(f.degenerate, 1u);
}

TEST(TetQualities, PerTetMatchesSummary) {
  const TetMesh m = testing::cube_with_centre(0.3, 0.6, 0.4);
  const auto q = tet_qualities(m);
  ASSERT_EQ(q.size(), 12u);
  double sum = 0;
  for (double v : q) sum += v;
  EXPECT_NEAR(sum / 12, summarize_quality(m).mean, 1e-12);
}

TEST(MinMeanQuality, MatchesTheSummaryForAnyThreadCount) {
  TetMesh m = testing::random_delaunay(800, 5);
  m.xyz[3 * 10 + 2] += 0.3;  // something poor, perhaps inverted, to find
  const QualitySummary s = summarize_quality(m);
  for (int threads : {1, 2, 0}) {
    const MinMeanQuality q = min_mean_quality(m, threads);
    EXPECT_EQ(q.min, s.min) << threads << " threads";
    EXPECT_NEAR(q.mean, s.mean, 1e-14) << threads << " threads";
  }
  const MinMeanQuality none = min_mean_quality(TetMesh{});
  EXPECT_EQ(none.min, 0.0);
  EXPECT_EQ(none.mean, 0.0);
}

// Tet by tet, against the summary's count: the centre outside the cube past
// x = 1 inverts the 2 tets on that face; moved back, those are put right
// and none is made.
TEST(InvertedTets, FlagsAndTheirChange) {
  const TetMesh outside = testing::cube_with_centre(1.5, 0.5, 0.5);
  const std::vector<std::uint8_t> before = inverted_tets(outside);
  ASSERT_EQ(before.size(), outside.num_tets());
  EXPECT_EQ(static_cast<std::size_t>(std::count(before.begin(), before.end(), 1)), summarize_quality(outside).inverted);
  EXPECT_EQ(summarize_quality(outside).inverted, 2u);
  const std::vector<std::uint8_t> after = inverted_tets(testing::cube_with_centre());
  const InversionChange mended = inversion_change(before, after);
  EXPECT_EQ(mended.made, 0u);
  EXPECT_EQ(mended.mended, 2u);
  const InversionChange made = inversion_change(after, before);
  EXPECT_EQ(made.made, 2u);
  EXPECT_EQ(made.mended, 0u);
}

}  // namespace
}  // namespace tetsmooth
