// Second-order (10-node) tets: which corners stay (curved edges, pinned
// midside nodes), how midside nodes follow their corners, what validation
// refuses, boundary midside nodes, and smooth() on a second-order mesh
// against the same mesh smoothed as first-order tets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "input_error.hpp"
#include "kernels/second_order_smoothing.hpp"
#include "kernels/smoother.hpp"
#include "mesh/second_order.hpp"
#include "mesh/tet_quality.hpp"
#include "mesh/topology.hpp"
#include "mesh/validate.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

// The first tet edge with both corners movable (interior), as (tet, edge).
std::pair<std::size_t, int> interior_edge(const TetMesh& mesh) {
  const std::vector<std::uint8_t> boundary = find_boundary_nodes(mesh.tets, mesh.num_nodes());
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (int e = 0; e < 6; ++e)
      if (!boundary[static_cast<std::size_t>(mesh.tets[4 * t + kTetEdges[e][0]])] &&
          !boundary[static_cast<std::size_t>(mesh.tets[4 * t + kTetEdges[e][1]])])
        return {t, e};
  ADD_FAILURE() << "no interior edge";
  return {0, 0};
}

index_t midside_of(const TetMesh& mesh, std::pair<std::size_t, int> at) {
  return mesh.midsides[6 * at.first + static_cast<std::size_t>(at.second)];
}

// Moves node n by d along x.
void shift_x(TetMesh& mesh, index_t n, double d) { mesh.xyz[3 * static_cast<std::size_t>(n)] += d; }

// The tets that have node n as a midside node.
std::set<std::size_t> tets_with_midside(const TetMesh& mesh, index_t n) {
  std::set<std::size_t> tets;
  for (std::size_t k = 0; k < mesh.midsides.size(); ++k)
    if (mesh.midsides[k] == n) tets.insert(k / 6);
  return tets;
}

double edge_length(const TetMesh& mesh, std::pair<std::size_t, int> at) {
  const index_t a = mesh.tets[4 * at.first + kTetEdges[at.second][0]];
  const index_t b = mesh.tets[4 * at.first + kTetEdges[at.second][1]];
  double s = 0;
  for (int c = 0; c < 3; ++c) {
    const double d = mesh.xyz[3 * static_cast<std::size_t>(a) + c] - mesh.xyz[3 * static_cast<std::size_t>(b) + c];
    s += d * d;
  }
  return std::sqrt(s);
}

TEST(CurvedTetPins, FirstOrderAndStraightMeshesPinNothing) {
  EXPECT_TRUE(curved_tet_pins(testing::cube_grid(3, 0.2)).corners.empty());
  const CurvedTetPins pins = curved_tet_pins(testing::with_midsides(testing::cube_grid(3, 0.2)));
  EXPECT_EQ(pins.tets, 0u);
  EXPECT_EQ(std::count(pins.corners.begin(), pins.corners.end(), 1), 0);
}

TEST(CurvedTetPins, ACurvedEdgePinsTheCornersOfEveryTetOnIt) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(3, 0.2));
  const auto at = interior_edge(mesh);
  const index_t m = midside_of(mesh, at);
  shift_x(mesh, m, 0.01 * edge_length(mesh, at));
  const CurvedTetPins pins = curved_tet_pins(mesh);
  const std::set<std::size_t> bent = tets_with_midside(mesh, m);
  ASSERT_GE(bent.size(), 3u);  // an interior edge has a ring of tets
  EXPECT_EQ(pins.tets, bent.size());
  std::set<index_t> corners;
  for (std::size_t t : bent) corners.insert(&mesh.tets[4 * t], &mesh.tets[4 * t] + 4);
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i)
    EXPECT_EQ(pins.corners[i], corners.count(static_cast<index_t>(i))) << "node " << i;
}

TEST(CurvedTetPins, TheToleranceIsRelativeToTheEdge) {
  for (const double scale : {1e-3, 1.0, 1e3}) {
    TetMesh mesh = testing::with_midsides(testing::cube_grid(3, 0.2));
    for (double& x : mesh.xyz) x *= scale;
    const auto at = interior_edge(mesh);
    const index_t m = midside_of(mesh, at);
    const double step = kStraightEdgeTolerance * edge_length(mesh, at);
    shift_x(mesh, m, 0.5 * step);
    EXPECT_EQ(curved_tet_pins(mesh).tets, 0u) << scale;
    shift_x(mesh, m, step);
    EXPECT_GT(curved_tet_pins(mesh).tets, 0u) << scale;
  }
}

TEST(CoordinateResolution, TellsRoundedAndFloatCoordinatesFromFullDoubles) {
  const TetMesh mesh = testing::cube_grid(3, 0.2);
  const CoordinateResolution full = coordinate_resolution(mesh.xyz);
  EXPECT_EQ(full.step, 0);
  EXPECT_EQ(full.relative, 0);
  std::vector<double> mm = mesh.xyz, singles = mesh.xyz, six_digits = mesh.xyz;
  for (double& v : mm) v = std::round((v + 5400123) * 1000) / 1000;
  for (double& v : singles) v = static_cast<float>(v + 4321);
  for (double& v : six_digits) {  // as C's %g prints them
    char text[32];
    std::snprintf(text, sizeof text, "%g", (v + 0.37) * 1000);
    v = std::strtod(text, nullptr);
  }
  EXPECT_DOUBLE_EQ(coordinate_resolution(mm).step, 1e-3);
  EXPECT_DOUBLE_EQ(coordinate_resolution(mm).relative, 0.5e-9);  // 10 significant digits
  EXPECT_EQ(coordinate_resolution(singles).relative, 0x1p-24);
  EXPECT_DOUBLE_EQ(coordinate_resolution(six_digits).relative, 0.5e-5);
  EXPECT_EQ(coordinate_resolution(testing::cube_grid(3).xyz).step, 1);  // a lattice of whole numbers
}

// Midside nodes that are off their midpoints by the rounding of the file's
// coordinates alone (stored to the millimetre far from the origin, or as
// float32) are straight; a real bend is still curved.
TEST(CurvedTetPins, RoundedCoordinatesAreNotCurves) {
  const TetMesh exact = testing::with_midsides(testing::cube_grid(3, 0.2));
  const auto rounded = [&](auto round) {
    TetMesh mesh = exact;
    for (double& v : mesh.xyz) v = round(v);
    return mesh;
  };
  const TetMesh mm = rounded([](double v) { return std::round((v + 5400123) * 1000) / 1000; });
  const TetMesh singles = rounded([](double v) { return static_cast<double>(static_cast<float>(v + 4321)); });
  const TetMesh six_digits = rounded([](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", (v + 0.37) * 1000);
    return std::strtod(text, nullptr);
  });
  for (const TetMesh* mesh : {&mm, &singles, &six_digits}) {
    // The rounding does move the midside nodes off the midpoints.
    ASSERT_GT(testing::largest_midside_offset(*mesh), 1e-4);
    EXPECT_EQ(curved_tet_pins(*mesh).tets, 0u);
    TetMesh bent = *mesh;
    const auto at = interior_edge(bent);
    shift_x(bent, midside_of(bent, at), 0.05 * edge_length(bent, at));
    EXPECT_GT(curved_tet_pins(bent).tets, 0u);
  }
}

// A lattice of whole numbers has midside nodes on multiples of 0.1, which
// coordinate_resolution cannot tell from rounding; at most 1% of an edge is
// put down to it, so a 2% bend still counts and a 0.5% one does not.
TEST(CurvedTetPins, RoundingExplainsAtMostAHundredthOfAnEdge) {
  for (const double bend : {0.02, 0.005}) {
    TetMesh mesh = testing::with_midsides(testing::cube_grid(3));
    ASSERT_GT(coordinate_resolution(mesh.xyz).step, 0.01);
    const auto at = interior_edge(mesh);
    shift_x(mesh, midside_of(mesh, at), bend * edge_length(mesh, at));
    EXPECT_EQ(curved_tet_pins(mesh).tets > 0, bend > 0.01) << bend;
  }
}

TEST(CurvedTetPins, APinnedMidsideNodePinsItsEdgeOnly) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(3, 0.2));
  const auto at = interior_edge(mesh);
  mesh.fixed.assign(mesh.num_nodes(), 0);
  mesh.fixed[static_cast<std::size_t>(midside_of(mesh, at))] = 1;
  const CurvedTetPins pins = curved_tet_pins(mesh);
  EXPECT_EQ(pins.tets, 0u);
  const index_t a = mesh.tets[4 * at.first + kTetEdges[at.second][0]];
  const index_t b = mesh.tets[4 * at.first + kTetEdges[at.second][1]];
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i)
    EXPECT_EQ(pins.corners[i], i == static_cast<std::size_t>(a) || i == static_cast<std::size_t>(b)) << i;
}

TEST(CarryMidsideNodes, MidsidesMoveByTheMeanOfTheirCornersMoves) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(3, 0.2));
  const auto at = interior_edge(mesh);
  const index_t moved = mesh.tets[4 * at.first + kTetEdges[at.second][0]];
  const std::vector<double> before = mesh.xyz;
  mesh.xyz[3 * static_cast<std::size_t>(moved) + 1] += 0.1;
  carry_midside_nodes(mesh, before);
  std::size_t followed = 0;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (int e = 0; e < 6; ++e) {
      const auto m = static_cast<std::size_t>(mesh.midsides[6 * t + static_cast<std::size_t>(e)]);
      const bool on_moved = mesh.tets[4 * t + kTetEdges[e][0]] == moved || mesh.tets[4 * t + kTetEdges[e][1]] == moved;
      EXPECT_EQ(mesh.xyz[3 * m], before[3 * m]);
      EXPECT_EQ(mesh.xyz[3 * m + 2], before[3 * m + 2]);
      if (on_moved) {
        EXPECT_DOUBLE_EQ(mesh.xyz[3 * m + 1], before[3 * m + 1] + 0.05) << "midside " << m;
        ++followed;
      } else {
        EXPECT_EQ(mesh.xyz[3 * m + 1], before[3 * m + 1]) << "midside " << m;  // bit for bit
      }
    }
  EXPECT_GT(followed, 0u);
}

TEST(CarryMidsideNodes, ACurvedEdgeKeepsItsOffset) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(3, 0.0));
  const auto at = interior_edge(mesh);
  const index_t m = midside_of(mesh, at);
  shift_x(mesh, m, 0.125);
  const std::vector<double> before = mesh.xyz;
  const index_t a = mesh.tets[4 * at.first + kTetEdges[at.second][0]];
  const index_t b = mesh.tets[4 * at.first + kTetEdges[at.second][1]];
  shift_x(mesh, a, 0.25);
  shift_x(mesh, b, 0.5);
  carry_midside_nodes(mesh, before);
  const auto x = [&](index_t n) { return mesh.xyz[3 * static_cast<std::size_t>(n)]; };
  EXPECT_DOUBLE_EQ(x(m) - 0.5 * (x(a) + x(b)), 0.125);
}

TEST(ValidateSecondOrder, MidsideNodesCountAsUsed) {
  const TetMesh mesh = testing::with_midsides(testing::cube_grid(2, 0.2));
  EXPECT_EQ(validate_mesh(mesh).unreferenced, 0u);
  TetMesh loose = mesh;
  loose.midsides.clear();
  EXPECT_GT(validate_mesh(loose).unreferenced, 0u);
}

TEST(ValidateSecondOrder, RefusesMalformedMidsides) {
  const TetMesh good = testing::with_midsides(testing::cube_grid(2, 0.2));
  const auto message = [](const TetMesh& mesh) {
    return testing::input_error_message([&] { validate_mesh(mesh, "m.msh"); }, "the midsides");
  };
  TetMesh short_list = good;
  short_list.midsides.pop_back();
  EXPECT_NE(message(short_list).find("6 a tet"), std::string::npos) << message(short_list);

  TetMesh corner = good;
  corner.midsides[3] = corner.tets[5];
  EXPECT_NE(message(corner).find("is also a corner of tet"), std::string::npos) << message(corner);

  TetMesh shared = good;
  shared.midsides[1] = shared.midsides[0];  // edges (0,1) and (1,2) of tet 0
  const std::string msg = message(shared);
  EXPECT_NE(msg.find("m.msh"), std::string::npos) << msg;
  EXPECT_NE(msg.find("is also the midside node of edge"), std::string::npos) << msg;

  TetMesh outside = good;
  outside.midsides[7] = static_cast<index_t>(outside.num_nodes());
  EXPECT_NE(message(outside).find("midside nodes of tet 1"), std::string::npos) << message(outside);
}

TEST(BoundaryMidsides, AreThoseOnTheEdgesOfBoundaryFaces) {
  const TetMesh mesh = testing::with_midsides(testing::cube_grid(3, 0.2));
  // Boundary faces counted afresh: a face of one tet.
  std::map<std::set<index_t>, int> uses;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (const auto& f : kTetFaces) ++uses[{mesh.tets[4 * t + f[0]], mesh.tets[4 * t + f[1]], mesh.tets[4 * t + f[2]]}];
  std::vector<std::uint8_t> expected(mesh.num_nodes(), 0);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (int e = 0; e < 6; ++e) {
      const index_t a = mesh.tets[4 * t + kTetEdges[e][0]], b = mesh.tets[4 * t + kTetEdges[e][1]];
      for (int k = 0; k < 4; ++k) {
        const index_t c = mesh.tets[4 * t + k];
        if (c == a || c == b) continue;
        if (uses[{a, b, c}] == 1) {
          expected[static_cast<std::size_t>(a)] = expected[static_cast<std::size_t>(b)] =
              expected[static_cast<std::size_t>(c)] = 1;
          expected[static_cast<std::size_t>(mesh.midsides[6 * t + static_cast<std::size_t>(e)])] = 1;
        }
      }
    }
  EXPECT_EQ(find_boundary_nodes(mesh.tets, mesh.num_nodes(), 2, mesh.midsides), expected);
  // Without the midsides, none of them is a boundary node.
  const std::vector<std::uint8_t> corners_only = find_boundary_nodes(mesh.tets, mesh.num_nodes());
  for (index_t m : mesh.midsides) EXPECT_EQ(corners_only[static_cast<std::size_t>(m)], 0);
}

SmoothOptions serial() {
  SmoothOptions o;
  o.threads = 1;
  o.max_iterations = 20;
  return o;
}

TEST(SmoothSecondOrder, CornersMoveAsTheFirstOrderMeshAndMidsidesFollow) {
  TetMesh first = testing::cube_grid(4, 0.3, 11);
  TetMesh second = testing::with_midsides(first);
  const SmoothResult r1 = smooth(first, serial(), Device::Cpu);
  const SmoothResult r2 = smooth(second, serial(), Device::Cpu);
  EXPECT_EQ(r2.sweeps, r1.sweeps);
  ASSERT_GT(r1.accepted_per_sweep.at(0), 0);
  EXPECT_TRUE(std::equal(first.xyz.begin(), first.xyz.end(), second.xyz.begin()));  // the corners, bit for bit
  EXPECT_TRUE(second.fixed.empty());  // the run's pins are gone again
  EXPECT_LT(testing::largest_midside_offset(second), 1e-12);
}

// A midside node the mesh pins stays, with its edge's corners, even where
// no tet is curved.
TEST(SmoothSecondOrder, APinnedMidsideNodeStays) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(4, 0.3, 11));
  const auto at = interior_edge(mesh);
  const auto m = static_cast<std::size_t>(midside_of(mesh, at));
  const auto a = static_cast<std::size_t>(mesh.tets[4 * at.first + kTetEdges[at.second][0]]);
  mesh.fixed.assign(mesh.num_nodes(), 0);
  mesh.fixed[m] = 1;
  ASSERT_EQ(curved_tet_pins(mesh).tets, 0u);
  // Unpinned, the edge's first corner moves in this run.
  TetMesh free_run = mesh;
  free_run.fixed.assign(mesh.num_nodes(), 0);
  smooth(free_run, serial(), Device::Cpu);
  ASSERT_NE(free_run.xyz[3 * a], mesh.xyz[3 * a]);
  const TetMesh before = mesh;
  const SmoothResult r = smooth(mesh, serial(), Device::Cpu);
  ASSERT_GT(r.accepted_per_sweep.at(0), 0);
  for (const std::size_t n : {m, a})
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(mesh.xyz[3 * n + c], before.xyz[3 * n + c]) << "node " << n;
  EXPECT_EQ(mesh.fixed, before.fixed);
}

TEST(SmoothSecondOrder, CurvedTetsComeBackUnchanged) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(4, 0.3, 11));
  mesh.fixed.assign(mesh.num_nodes(), 0);
  const std::vector<std::uint8_t> file_pins = mesh.fixed;
  const auto at = interior_edge(mesh);
  const index_t m = midside_of(mesh, at);
  shift_x(mesh, m, 0.05 * edge_length(mesh, at));
  const TetMesh before = mesh;
  const SmoothResult r = smooth(mesh, serial(), Device::Cpu);
  ASSERT_GT(r.accepted_per_sweep.at(0), 0);
  EXPECT_EQ(mesh.fixed, file_pins);
  const auto same_node = [&](index_t n) {
    const auto i = 3 * static_cast<std::size_t>(n);
    return std::equal(&mesh.xyz[i], &mesh.xyz[i] + 3, &before.xyz[i]);
  };
  for (std::size_t t : tets_with_midside(mesh, m)) {
    for (int k = 0; k < 4; ++k) EXPECT_TRUE(same_node(mesh.tets[4 * t + k])) << "tet " << t;
    for (int e = 0; e < 6; ++e) EXPECT_TRUE(same_node(mesh.midsides[6 * t + static_cast<std::size_t>(e)])) << t;
  }
}

// --- the Jacobian guard -----------------------------------------------------

TEST(SmallestJacobian, IsSixTimesTheVolumeForAStraightTet) {
  const TetMesh mesh = testing::with_midsides(testing::cube_grid(2, 0.2));
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    const auto p = [&](int k) {
      const double* x = &mesh.xyz[3 * static_cast<std::size_t>(mesh.tets[4 * t + static_cast<std::size_t>(k)])];
      return Vec3<double>{x[0], x[1], x[2]};
    };
    const double v6 = signed_volume6(p(0), p(1), p(2), p(3));
    EXPECT_NEAR(smallest_jacobian(mesh, mesh.xyz, t), v6, 1e-12 * std::abs(v6)) << t;
  }
}

TEST(SmallestJacobian, TurnsNegativeWhenAMidsideNodeFoldsTheTet) {
  TetMesh mesh = testing::with_midsides(testing::regular_tet());
  const double before = smallest_jacobian(mesh, mesh.xyz, 0);
  ASSERT_GT(before, 0);
  // Edge (0,1)'s midside node pushed past the opposite edge's midpoint.
  const auto m = static_cast<std::size_t>(mesh.midsides[0]), c = static_cast<std::size_t>(mesh.midsides[5]);
  for (std::size_t k = 0; k < 3; ++k) mesh.xyz[3 * m + k] += 1.2 * (mesh.xyz[3 * c + k] - mesh.xyz[3 * m + k]);
  EXPECT_LT(smallest_jacobian(mesh, mesh.xyz, 0), 0);
}

// A second-order grid whose interior edge (a, b) has its midside node off
// the midpoint by half the straight-edge tolerance: straight for the pins,
// but no longer exactly.
struct SlightlyBent {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(3, 0.2));
  std::pair<std::size_t, int> at = interior_edge(mesh);
  index_t a = mesh.tets[4 * at.first + kTetEdges[at.second][0]];
  index_t b = mesh.tets[4 * at.first + kTetEdges[at.second][1]];
  SlightlyBent() { shift_x(mesh, midside_of(mesh, at), 0.5 * kStraightEdgeTolerance * edge_length(mesh, at)); }
};

// A stand-in smoother that moves node n, unless it is pinned, twice its
// distance to node `to` along that line (past `to`): the tets on edge
// (n, to) fold. Counts its runs.
struct FoldingRun {
  TetMesh& mesh;
  index_t n, to;
  int runs = 0;
  SmoothResult operator()() {
    ++runs;
    const auto i = static_cast<std::size_t>(n), j = static_cast<std::size_t>(to);
    if (mesh.fixed.empty() || !mesh.fixed[i])
      for (std::size_t c = 0; c < 3; ++c) mesh.xyz[3 * i + c] += 2 * (mesh.xyz[3 * j + c] - mesh.xyz[3 * i + c]);
    return {};
  }
};

TEST(SmoothSecondOrderGuard, AFoldedTetKeepsItsCornersAndTheRunStartsAgain) {
  SlightlyBent bent;
  TetMesh& mesh = bent.mesh;
  ASSERT_EQ(curved_tet_pins(mesh).tets, 0u);
  const std::vector<double> input = mesh.xyz;
  FoldingRun run{mesh, bent.a, bent.b};
  const SmoothResult r = smooth_second_order(mesh, std::ref(run));
  EXPECT_EQ(run.runs, 2);
  EXPECT_EQ(r.second_order_restarts, 1);
  EXPECT_GT(r.folded_tets, 0u);
  EXPECT_EQ(mesh.xyz, input);  // node a was pinned, and nothing else moves
  EXPECT_TRUE(mesh.fixed.empty());
  EXPECT_TRUE(folded_tets(mesh, input).empty());
}

TEST(SmoothSecondOrderGuard, ExactlyStraightTetsAreLeftToTheSmoother) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(3, 0.2));
  const auto at = interior_edge(mesh);
  FoldingRun run{mesh, mesh.tets[4 * at.first + kTetEdges[at.second][0]],
                 mesh.tets[4 * at.first + kTetEdges[at.second][1]]};
  const SmoothResult r = smooth_second_order(mesh, std::ref(run));
  EXPECT_EQ(run.runs, 1);  // the corner tets fold, which is the smoother's to judge
  EXPECT_EQ(r.second_order_restarts, 0);
}

TEST(SmoothSecondOrderGuard, TheCallersPinsComeBackWhenTheRunThrows) {
  SlightlyBent bent;
  bent.mesh.fixed.assign(bent.mesh.num_nodes(), 0);
  bent.mesh.fixed[0] = 1;
  const std::vector<std::uint8_t> pins = bent.mesh.fixed;
  bent.mesh.xyz[3 * static_cast<std::size_t>(midside_of(bent.mesh, bent.at))] += 1;  // a curved tet: more pins
  EXPECT_THROW(smooth_second_order(bent.mesh, []() -> SmoothResult { throw std::runtime_error("device lost"); }),
               std::runtime_error);
  EXPECT_EQ(bent.mesh.fixed, pins);
}

// Every midside node a little off: a run that folds whatever it may move
// still ends, within kMaxRestarts restarts, with nothing folded.
TEST(SmoothSecondOrderGuard, EndsWhenEveryTetCouldFold) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(3, 0.2));
  for (index_t m : mesh.midsides) mesh.xyz[3 * static_cast<std::size_t>(m)] += 1e-6;
  const std::vector<double> input = mesh.xyz;
  // Moves every corner that may move past its neighbours.
  const auto fold_all = [&]() {
    const std::vector<std::uint8_t> boundary = find_boundary_nodes(mesh.tets, mesh.num_nodes());
    for (index_t corner : std::set<index_t>(mesh.tets.begin(), mesh.tets.end())) {
      const auto i = static_cast<std::size_t>(corner);
      if (!boundary[i] && !mesh.fixed[i]) mesh.xyz[3 * i] += 3.0;
    }
    return SmoothResult{};
  };
  const SmoothResult r = smooth_second_order(mesh, fold_all);
  EXPECT_LE(r.second_order_restarts, kMaxRestarts);
  EXPECT_GT(r.second_order_restarts, 0);
  EXPECT_TRUE(folded_tets(mesh, input).empty());
}

// A run that folds one more place each time reaches kMaxRestarts; then
// every tet with an offset keeps its corners, and the last run moves none.
TEST(SmoothSecondOrderGuard, AfterTheLastRestartEveryOffsetTetStays) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(6, 0.2));
  for (index_t m : mesh.midsides) mesh.xyz[3 * static_cast<std::size_t>(m)] += 1e-6;
  const std::vector<double> input = mesh.xyz;
  const std::vector<std::uint8_t> boundary = find_boundary_nodes(mesh.tets, mesh.num_nodes());
  const std::set<index_t> corners(mesh.tets.begin(), mesh.tets.end());
  const auto fold_one = [&]() {
    for (index_t corner : corners) {
      const auto i = static_cast<std::size_t>(corner);
      if (boundary[i] || mesh.fixed[i]) continue;
      mesh.xyz[3 * i] += 3.0;
      break;
    }
    return SmoothResult{};
  };
  const SmoothResult r = smooth_second_order(mesh, fold_one);
  EXPECT_EQ(r.second_order_restarts, kMaxRestarts);
  EXPECT_EQ(mesh.xyz, input);
}

}  // namespace
}  // namespace tetsmooth
