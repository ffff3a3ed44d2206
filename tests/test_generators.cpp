// The paper's models (Table 2) and the TetGen generators behind them: sizes,
// orientation, coverage, geometry, determinism and argument checking.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "generators/models.hpp"
#include "mesh/errors.hpp"
#include "mesh/tet_quality.hpp"
#include "mesh/topology.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace {

Vec3<double> node(const TetMesh& m, std::size_t i) {
  const double* p = &m.xyz[3 * i];
  return {p[0], p[1], p[2]};
}

// Total volume, and checks that every tet is positively oriented (the
// contract) and that validation finds nothing to warn about.
double checked_volume(const TetMesh& m) {
  const ValidationReport report = validate_mesh(m, "generated");
  EXPECT_EQ(report.inverted, 0u);
  EXPECT_EQ(report.degenerate, 0u);
  EXPECT_EQ(report.unreferenced, 0u);
  double total = 0;
  std::size_t non_positive = 0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    const index_t* v = &m.tets[4 * t];
    const double v6 = signed_volume6(node(m, v[0]), node(m, v[1]), node(m, v[2]), node(m, v[3]));
    non_positive += !(v6 > 0);
    total += v6 / 6;
  }
  EXPECT_EQ(non_positive, 0u);
  return total;
}

struct Bounds {
  Vec3<double> lo, hi;
};

Bounds bounds(const TetMesh& m) {
  const double inf = std::numeric_limits<double>::infinity();
  Bounds b{{inf, inf, inf}, {-inf, -inf, -inf}};
  for (std::size_t i = 0; i < m.num_nodes(); ++i) {
    const Vec3<double> p = node(m, i);
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

double relative_error(double got, double expected) { return std::abs(got - expected) / expected; }

TEST(Generators, PaperModelNamesInTableOrder) {
  const std::vector<std::string> expected{"5k", "10k", "59k", "slope-77k", "109k"};
  EXPECT_EQ(paper_model_names(), expected);
}

TEST(Generators, UnknownNamesAreUsageErrorsThatListTheModels) {
  for (const char* name : {"", "7k", "5K", "slope", "lattice", "lattice-", "lattice-0", "lattice--2", "lattice-+2",
                           "lattice-02", "lattice-2x", "lattice-2.5", "lattice-99999999999", "Lattice-2"}) {
    try {
      generate_model(name);
      ADD_FAILURE() << "'" << name << "' was accepted";
    } catch (const UsageError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("unknown model '" + std::string(name) + "'"), std::string::npos) << message;
      EXPECT_NE(message.find("slope-77k"), std::string::npos) << message;
      EXPECT_NE(message.find("lattice-N"), std::string::npos) << message;
    }
  }
}

// Table 2: exact node counts, tet counts within 3% (the Delaunay
// tetrahedralisation of random nodes varies with the draw).
struct BoxCase {
  const char* name;
  std::size_t nodes;
  std::size_t paper_tets;
};

class BoxModel : public ::testing::TestWithParam<BoxCase> {};

TEST_P(BoxModel, MatchesTable2AndFillsTheUnitBox) {
  const BoxCase c = GetParam();
  const TetMesh m = generate_model(c.name, 1);
  EXPECT_EQ(m.num_nodes(), c.nodes);
  EXPECT_LT(relative_error(double(m.num_tets()), double(c.paper_tets)), 0.03) << m.num_tets() << " tets";
  std::printf("%s: %zu nodes, %zu tets (Table 2: %zu)\n", c.name, m.num_nodes(), m.num_tets(), c.paper_tets);

  // Positive tets that add up to the box's volume, with every boundary node
  // on a box face: the box is covered once, with no gaps or overlaps.
  EXPECT_NEAR(checked_volume(m), 1.0, 1e-12);
  const Bounds b = bounds(m);
  EXPECT_EQ(b.lo.x, 0.0);
  EXPECT_EQ(b.lo.y, 0.0);
  EXPECT_EQ(b.lo.z, 0.0);
  EXPECT_EQ(b.hi.x, 1.0);
  EXPECT_EQ(b.hi.y, 1.0);
  EXPECT_EQ(b.hi.z, 1.0);
  const std::vector<std::uint8_t> boundary = find_boundary_nodes(m.tets, m.num_nodes());
  for (std::size_t i = 0; i < m.num_nodes(); ++i) {
    if (!boundary[i]) continue;
    const Vec3<double> p = node(m, i);
    EXPECT_TRUE(p.x == 0 || p.x == 1 || p.y == 0 || p.y == 1 || p.z == 0 || p.z == 1) << "node " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Table2, BoxModel,
                         ::testing::Values(BoxCase{"5k", 5'000, 32'978}, BoxCase{"10k", 10'000, 66'542},
                                           BoxCase{"59k", 59'261, 391'220}, BoxCase{"109k", 109'260, 727'088}),
                         [](const ::testing::TestParamInfo<BoxCase>& p) { return "m" + std::string(p.param.name); });

TEST(Generators, BoxLatticeNodesComeFirst) {
  const int n = 4;
  const TetMesh m = generate_box_delaunay(n, 100, 2);
  ASSERT_EQ(m.num_nodes(), static_cast<std::size_t>(n * n * n + 100));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3<double> p = node(m, static_cast<std::size_t>(i + n * (j + n * k)));
        EXPECT_DOUBLE_EQ(p.x, i / 3.0);
        EXPECT_DOUBLE_EQ(p.y, j / 3.0);
        EXPECT_DOUBLE_EQ(p.z, k / 3.0);
      }
  // The random nodes are strictly inside.
  for (std::size_t i = n * n * n; i < m.num_nodes(); ++i) {
    const Vec3<double> p = node(m, i);
    EXPECT_TRUE(p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1 && p.z > 0 && p.z < 1) << "node " << i;
  }
  EXPECT_NEAR(checked_volume(m), 1.0, 1e-12);
}

TEST(Generators, RandomNodesOnlyMeshTheirHull) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const TetMesh m = generate_box_delaunay(0, 500, seed);
    EXPECT_EQ(m.num_nodes(), 500u);
    const double volume = checked_volume(m);
    EXPECT_GT(volume, 0.5);  // the hull of 500 uniform points fills most of the box
    EXPECT_LT(volume, 1.0);
  }
}

TEST(Generators, BoxIsDeterministicForASeed) {
  const TetMesh a = generate_model("5k", 42);
  const TetMesh b = generate_model("5k", 42);
  EXPECT_EQ(a.xyz, b.xyz);
  EXPECT_EQ(a.tets, b.tets);

  // Another seed draws other random nodes around the same lattice.
  const TetMesh c = generate_model("5k", 43);
  ASSERT_EQ(c.num_nodes(), a.num_nodes());
  const std::size_t lattice = 3 * 27;
  EXPECT_TRUE(std::equal(a.xyz.begin(), a.xyz.begin() + lattice, c.xyz.begin()));
  std::size_t same = 0;
  for (std::size_t i = lattice; i < a.xyz.size(); ++i) same += a.xyz[i] == c.xyz[i];
  EXPECT_EQ(same, 0u);
}

TEST(Generators, BoxRejectsBadArguments) {
  EXPECT_THROW(generate_box_delaunay(1, 100, 1), UsageError);
  EXPECT_THROW(generate_box_delaunay(-2, 100, 1), UsageError);
  EXPECT_THROW(generate_box_delaunay(2, -1, 1), UsageError);
  EXPECT_THROW(generate_box_delaunay(0, 3, 1), UsageError);
  EXPECT_THROW(generate_box_delaunay(1291, 0, 1), UsageError);
  EXPECT_THROW(generate_box_delaunay(1000, std::numeric_limits<int>::max() - 10, 1), UsageError);
  // 2^22 per axis: its cube, 2^66, wraps to 0 in 64 bits and would pass the
  // node count check, so the per-axis bound must refuse it first.
  try {
    generate_box_delaunay(1 << 22, 10, 1);
    ADD_FAILURE() << "no UsageError for a 2^22 lattice";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("exceed 32-bit node indices"), std::string::npos) << e.what();
  }
}

// The embankment: its profile's top surface at x (see SlopeGeometry).
double slope_top(const SlopeGeometry& g, double x) {
  if (x <= g.toe_x) return g.base_height;
  if (x >= g.crest_x) return g.crest_height;
  return g.base_height + (x - g.toe_x) * (g.crest_height - g.base_height) / (g.crest_x - g.toe_x);
}

TEST(Generators, SlopeMatchesTable2) {
  const TetMesh m = generate_model("slope-77k", 1);
  EXPECT_LT(relative_error(double(m.num_nodes()), 76'928), 0.05) << m.num_nodes() << " nodes";
  EXPECT_LT(relative_error(double(m.num_tets()), 388'428), 0.05) << m.num_tets() << " tets";
  std::printf("slope-77k: %zu nodes, %zu tets (Table 2: 76928, 388428)\n", m.num_nodes(), m.num_tets());
}

TEST(Generators, SlopeHasTheEmbankmentsShape) {
  const SlopeGeometry& g = slope_geometry();
  const TetMesh m = generate_slope(20'000, 1);

  const Bounds b = bounds(m);
  EXPECT_EQ(b.lo.x, 0.0);
  EXPECT_EQ(b.lo.y, 0.0);
  EXPECT_EQ(b.lo.z, 0.0);
  EXPECT_EQ(b.hi.x, g.length);
  EXPECT_EQ(b.hi.y, g.width);
  EXPECT_EQ(b.hi.z, g.crest_height);

  // Filled exactly once: positive tets whose volume is the prism's.
  const double rise = g.crest_height - g.base_height;
  const double area = g.length * g.base_height + 0.5 * (g.crest_x - g.toe_x) * rise + (g.length - g.crest_x) * rise;
  EXPECT_NEAR(checked_volume(m), area * g.width, 1e-9 * area * g.width);

  // Every boundary node is on one of the PLC's facets, many on the inclined
  // face, and no node is above the ground surface.
  const double tol = 1e-9 * g.length;
  const std::vector<std::uint8_t> boundary = find_boundary_nodes(m.tets, m.num_nodes());
  std::size_t on_incline = 0;
  for (std::size_t i = 0; i < m.num_nodes(); ++i) {
    const Vec3<double> p = node(m, i);
    const double top = slope_top(g, p.x);
    EXPECT_LE(p.z, top + tol) << "node " << i << " is above the ground";
    if (!boundary[i]) continue;
    const bool on_top = std::abs(p.z - top) <= tol;
    on_incline += on_top && p.x > g.toe_x + tol && p.x < g.crest_x - tol;
    const bool on_side = p.x <= tol || p.x >= g.length - tol || p.y <= tol || p.y >= g.width - tol || p.z <= tol;
    EXPECT_TRUE(on_top || on_side) << "boundary node " << i << " is inside the embankment";
  }
  EXPECT_GT(on_incline, 300u);
}

TEST(Generators, SlopeSizeFollowsTheTarget) {
  for (const int target : {5'000, 20'000}) {
    const TetMesh m = generate_slope(target, 1);
    EXPECT_LT(relative_error(double(m.num_nodes()), target), 0.05) << m.num_nodes() << " nodes for " << target;
  }
  EXPECT_THROW(generate_slope(10, 1), UsageError);
}

// What `tetsmooth generate` says of the seed rests on this.
TEST(Generators, OnlyTheSlopeIgnoresTheSeed) {
  for (const std::string& name : paper_model_names()) EXPECT_EQ(model_uses_seed(name), name != "slope-77k") << name;
  EXPECT_TRUE(model_uses_seed("lattice-4"));
  EXPECT_NE(generate_model("lattice-4", 1).xyz, generate_model("lattice-4", 2).xyz);
}

TEST(Generators, SlopeIsDeterministicAndSeedIndependent) {
  const TetMesh a = generate_slope(10'000, 1);
  const TetMesh b = generate_slope(10'000, 1);
  const TetMesh c = generate_slope(10'000, 2);
  EXPECT_EQ(a.xyz, b.xyz);
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.xyz, c.xyz);
  EXPECT_EQ(a.tets, c.tets);
}

}  // namespace
}  // namespace tetsmooth
