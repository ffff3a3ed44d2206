// The adaptive test of node_update.hpp (two passes, stopping at the first
// objecting tet) against the accept rule written out tet by tet, on every
// movable node of meshes jittered hard enough to hold inverted and
// near-degenerate tets; row_sum's chunked fetches against the row added
// entry by entry; star_old_min's chunked scan against one entry at a time;
// the stopping rule (sweep_verdict) and the Form A repair steps on planted
// values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <vector>

#include "kernels/node_update.hpp"
#include "kernels/ordered_double.hpp"
#include "mesh/topology.hpp"
#include "test_meshes.hpp"

namespace tetsmooth {
namespace {

// The rule as node_update.hpp states it, written out here rather than
// through its helpers: the minimum quality over the incident tets strictly
// rises, no valid tet (q > 0) becomes invalid, and no invalid tet gets worse.
struct RuleParts {
  bool min_rises = false, valid_stay_valid = true, invalid_no_worse = true;
  bool accepted() const { return min_rises && valid_stay_valid && invalid_no_worse; }
};

RuleParts rule_tet_by_tet(const MeshView& m, const AosCoords<double>& xyz, index_t i, Vec3<double> target) {
  RuleParts r;
  double old_min = 2, new_min = 2;
  for (index_t k = m.inc_off[i]; k < m.inc_off[i + 1]; ++k) {
    const double q_old = tet_quality_with(m, xyz, m.inc[k], i, xyz.get(i));
    const double q_new = tet_quality_with(m, xyz, m.inc[k], i, target);
    old_min = std::min(old_min, q_old);
    new_min = std::min(new_min, q_new);
    if (q_old > 0 && !(q_new > 0)) r.valid_stay_valid = false;
    if (!(q_old > 0) && q_new < q_old) r.invalid_no_worse = false;
  }
  r.min_rises = new_min > old_min;
  return r;
}

TEST(AcceptRule, KeepsValidity) {
  EXPECT_TRUE(keeps_validity(0.5, 0.1));
  EXPECT_FALSE(keeps_validity(0.5, 0.0));
  EXPECT_FALSE(keeps_validity(0.5, -0.1));
  EXPECT_TRUE(keeps_validity(-0.2, -0.1));
  EXPECT_TRUE(keeps_validity(-0.2, -0.2));
  EXPECT_FALSE(keeps_validity(-0.2, -0.3));
  EXPECT_TRUE(keeps_validity(0.0, 0.0));
  EXPECT_FALSE(keeps_validity(0.0, -1e-9));
}

// Lattice jitter, and how far every fifth interior node is then pushed
// along x, in lattice spacings (far enough inverts tets of its star).
struct Shake {
  double jitter, push;
};

void PrintTo(const Shake& s, std::ostream* os) { *os << "jitter " << s.jitter << ", push " << s.push; }

class AdaptiveTest : public ::testing::TestWithParam<Shake> {};

TEST_P(AdaptiveTest, SameDecisionAsTheRuleTetByTet) {
  constexpr int kCells = 6;
  TetMesh mesh = testing::cube_grid(kCells, GetParam().jitter, 11);
  const Topology topo = build_topology(mesh);
  for (std::size_t n = 0; n < mesh.num_nodes(); n += 5)
    if (topo.movable[n]) mesh.xyz[3 * n] += GetParam().push;  // the lattice spacing is 1
  const MeshView view = host_view(mesh, topo);
  const AosCoords<double> xyz{mesh.xyz.data()};  // read only
  int accepted = 0, rejected = 0, inverted_stars = 0, decided_by_validity = 0;
  for (std::size_t n = 0; n < mesh.num_nodes(); ++n) {
    if (!topo.movable[n]) continue;
    const auto i = static_cast<index_t>(n);
    const NodeMove<double> mv = evaluate_node<double, true>(view, xyz, i);
    const RuleParts rule = rule_tet_by_tet(view, xyz, i, mv.target);
    EXPECT_EQ(mv.accept, rule.accepted()) << "node " << i;
    (mv.accept ? accepted : rejected)++;
    inverted_stars += mv.old_min <= 0;
    // Moves that raise the minimum and yet are refused for a tet's validity.
    decided_by_validity += rule.min_rises && !(rule.valid_stay_valid && rule.invalid_no_worse);
  }
  // The meshes exercise both outcomes; pushed nodes also give stars with
  // inverted tets, where the validity clauses alone decide some moves.
  EXPECT_GT(accepted, 0);
  EXPECT_GT(rejected, 0);
  if (GetParam().push > 1) {
    EXPECT_GT(inverted_stars, 0);
    EXPECT_GT(decided_by_validity, 0);
  }
  std::printf("accepted %d, rejected %d, stars with an inverted tet %d, decided by validity %d\n", accepted, rejected,
              inverted_stars, decided_by_validity);
}

INSTANTIATE_TEST_SUITE_P(Meshes, AdaptiveTest,
                         ::testing::Values(Shake{0.1, 0}, Shake{0.3, 0}, Shake{0.3, 0.6}, Shake{0.3, 1.5}));

// A lane's share of a row, added entry by entry in the row's order.
template <class Real>
Vec3<Real> share_entry_by_entry(const MeshView& m, const AosCoords<Real>& xyz, index_t i, int lane, int stride) {
  Vec3<Real> s{0, 0, 0};
  for (index_t k = m.nbr_off[i] + lane; k < m.nbr_off[i + 1]; k += stride) s = s + xyz.get(m.nbr[k]);
  return s;
}

// Every lane's share, for shares of 1 to 8 lanes and rows longer and
// shorter than a chunk: a chunk must neither skip nor reorder entries. In
// float, on jittered positions, a reordered sum rarely keeps its bits.
template <class Real, int kChunk>
void expect_chunked_row_sums_match(const TetMesh& mesh, const Topology& topo) {
  std::vector<Real> xyz_real(mesh.xyz.begin(), mesh.xyz.end());
  const AosCoords<Real> xyz{xyz_real.data()};
  const MeshView view = host_view(mesh, topo);
  int compared = 0;
  for (index_t i = 0; i < static_cast<index_t>(mesh.num_nodes()); ++i)
    for (int stride : {1, 2, 3, 8})
      for (int lane = 0; lane < stride; ++lane) {
        const Vec3<Real> want = share_entry_by_entry(view, xyz, i, lane, stride);
        const Vec3<Real> got =
            row_sum<Real, kChunk>(view, xyz, view.nbr_off[i], view.nbr_off[i + 1], lane, stride);
        ASSERT_TRUE(got.x == want.x && got.y == want.y && got.z == want.z)
            << "node " << i << ", lane " << lane << " of " << stride << ", chunk " << kChunk;
        ++compared;
      }
  EXPECT_EQ(compared, static_cast<int>(mesh.num_nodes()) * (1 + 2 + 3 + 8));
}

TEST(RowSum, ChunkedFetchesKeepTheSumsBits) {
  TetMesh mesh = testing::cube_grid(4, 0.3, 5);
  for (double& x : mesh.xyz) x = x * 1.37 + 0.011;  // fractions that round
  const Topology topo = build_topology(mesh);
  expect_chunked_row_sums_match<float, 1>(mesh, topo);
  expect_chunked_row_sums_match<float, 3>(mesh, topo);
  expect_chunked_row_sums_match<float, 8>(mesh, topo);
  expect_chunked_row_sums_match<double, 2>(mesh, topo);
  expect_chunked_row_sums_match<double, 8>(mesh, topo);
}

// The star's old minimum and where it sits, for every lane's share, chunked
// or not, against a scan entry by entry: the same minimum, and `at` naming
// the first entry that holds it (the entry the MultiBlock test deals first).
template <int kChunk>
void expect_star_minima_match(const TetMesh& mesh, const Topology& topo) {
  const MeshView view = host_view(mesh, topo);
  const AosCoords<double> xyz{const_cast<double*>(mesh.xyz.data())};  // read only
  for (index_t i = 0; i < static_cast<index_t>(mesh.num_nodes()); ++i)
    for (int stride : {1, 3}) {
      for (int lane = 0; lane < stride; ++lane) {
        double want = 2;
        index_t want_at = view.inc_off[i] + lane;
        for (index_t k = view.inc_off[i] + lane; k < view.inc_off[i + 1]; k += stride) {
          const double q = tet_quality_with(view, xyz, view.inc[k], i, xyz.get(i));
          if (q < want) {
            want = q;
            want_at = k;
          }
        }
        index_t at = -1;
        const double got = star_old_min<double, kChunk>(view, xyz, i, xyz.get(i), lane, stride, FreshOldQuality{}, &at);
        ASSERT_EQ(got, want) << "node " << i << ", lane " << lane << " of " << stride << ", chunk " << kChunk;
        ASSERT_EQ(at, want_at) << "node " << i << ", lane " << lane << " of " << stride << ", chunk " << kChunk;
      }
    }
}

TEST(StarOldMin, ChunkedScanFindsTheSameMinimumAndEntry) {
  // Pushed nodes give stars with inverted tets, so minima go below zero.
  TetMesh mesh = testing::cube_grid(4, 0.3, 9);
  const Topology topo = build_topology(mesh);
  for (std::size_t n = 0; n < mesh.num_nodes(); n += 4)
    if (topo.movable[n]) mesh.xyz[3 * n] += 1.2;
  expect_star_minima_match<1>(mesh, topo);
  expect_star_minima_match<4>(mesh, topo);
  expect_star_minima_match<5>(mesh, topo);
}

TEST(TetNodes, ReadsTheTetsFourNodesInOrder) {
  const std::vector<index_t> tets{0, 1, 2, 3, 7, 5, 9, 4};
  const TetNodes b = tet_nodes(tets.data(), 1);
  EXPECT_EQ(b.v[0], 7);
  EXPECT_EQ(b.v[1], 5);
  EXPECT_EQ(b.v[2], 9);
  EXPECT_EQ(b.v[3], 4);
}

// The keys order as the doubles do, across signs and magnitudes, and give
// each double back bit for bit (the CUDA progress quality's minimum).
TEST(OrderedDouble, KeysOrderAsTheDoublesAndRoundTrip) {
  const std::vector<double> sorted = {-HUGE_VAL, -1e300, -1.0, -0.5, -1e-300, -0.0, 0.0, 1e-310, 1e-300,
                                      0.25,       0.5,    1.0,  1e300, HUGE_VAL};
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    const double back = from_ordered_key(ordered_key(sorted[k]));
    EXPECT_EQ(std::signbit(back), std::signbit(sorted[k])) << sorted[k];
    EXPECT_EQ(back, sorted[k]);
    if (k > 0) {
      EXPECT_LT(ordered_key(sorted[k - 1]), ordered_key(sorted[k])) << sorted[k - 1] << " " << sorted[k];
    }
  }
  EXPECT_LT(ordered_key(HUGE_VAL), ~std::uint64_t{0}) << "all ones stands above every double";
}

// The stopping rule on planted values. A sweep that made no move stops for
// that reason even though its largest move (none: 0) is below any positive
// tolerance: "no node could improve" says more than "moves fell below".
TEST(SweepVerdict, NoMovesWhenNothingMovedWhateverTheTolerance) {
  EXPECT_EQ(sweep_verdict(1, 0, 0.0, 1e-3, 100), SweepVerdict::NoMoves);
  EXPECT_EQ(sweep_verdict(1, 0, 0.0, 0.0, 100), SweepVerdict::NoMoves);
  EXPECT_EQ(sweep_verdict(1, 0, 0.0f, 1e-3f, 100), SweepVerdict::NoMoves);
}

// README: stop when the largest move is *below* tol x mean edge length, so a
// move of exactly the tolerance goes on.
TEST(SweepVerdict, ToleranceIsStrictlyBelow) {
  EXPECT_EQ(sweep_verdict(3, 5, 0.25, 0.25, 100), SweepVerdict::Continue);
  EXPECT_EQ(sweep_verdict(3, 5, std::nextafter(0.25, 0.0), 0.25, 100), SweepVerdict::Tolerance);
  EXPECT_EQ(sweep_verdict(3, 5, 0.25f, 0.25f, 100), SweepVerdict::Continue);
  EXPECT_EQ(sweep_verdict(3, 5, std::nextafter(0.25f, 0.0f), 0.25f, 100), SweepVerdict::Tolerance);
  // A tolerance of 0 never stops a sweep that moved something.
  EXPECT_EQ(sweep_verdict(3, 5, 1e-300, 0.0, 100), SweepVerdict::Continue);
}

// `sweep` counts from 1: the cap stops the run after sweep max_iterations,
// not before it.
TEST(SweepVerdict, MaxIterationsStopsAtTheCap) {
  EXPECT_EQ(sweep_verdict(99, 5, 1.0, 1e-3, 100), SweepVerdict::Continue);
  EXPECT_EQ(sweep_verdict(100, 5, 1.0, 1e-3, 100), SweepVerdict::MaxIterations);
  EXPECT_EQ(sweep_verdict(1, 5, 1.0, 1e-3, 1), SweepVerdict::MaxIterations);
}

// When several reasons hold in one sweep, the one that says the most about
// the mesh wins: no moves, then the tolerance, then the cap (which only says
// that more sweeps might still help).
TEST(SweepVerdict, PrecedenceNoMovesThenToleranceThenCap) {
  EXPECT_EQ(sweep_verdict(100, 0, 0.0, 1e-3, 100), SweepVerdict::NoMoves);
  EXPECT_EQ(sweep_verdict(100, 5, 1e-4, 1e-3, 100), SweepVerdict::Tolerance);
  EXPECT_EQ(sweep_verdict(7, 0, 0.0, 1e-3, 1), SweepVerdict::NoMoves);
}

// A move is made only when accepted and of nonzero length (a zero move
// would keep a settled sweep counting moves and never stop on "no moves").
TEST(TakesMove, AcceptedAndGoingSomewhere) {
  NodeMove<double> mv{{0, 0, 0}, 0.5, 1e-30, true};
  EXPECT_TRUE(takes_move(mv));
  mv.displacement2 = 0;
  EXPECT_FALSE(takes_move(mv));
  mv.displacement2 = 1;
  mv.accept = false;
  EXPECT_FALSE(takes_move(mv));
}

// Only the last repair pass undoes the sweep; a test may shorten the limit.
TEST(RepairSteps, OnlyTheLastPassUndoesTheSweep) {
  for (int pass = 0; pass < kMaxRepairPasses - 1; ++pass) EXPECT_FALSE(repair_undoes_sweep(pass)) << pass;
  EXPECT_TRUE(repair_undoes_sweep(kMaxRepairPasses - 1));
  EXPECT_TRUE(repair_undoes_sweep(0, 1));
  EXPECT_FALSE(repair_undoes_sweep(0, 2));
  EXPECT_TRUE(repair_undoes_sweep(1, 2));
}

// Four nodes on a line, x = node index before, x = 10 + index after:
// node 0 moved and flagged, 1 moved, 2 flagged but did not move (cannot
// happen in a sweep, and must still not count), 3 neither.
struct RepairFixture {
  std::vector<double> before{0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0};
  std::vector<double> after{10, 0, 0, 11, 0, 0, 2, 0, 0, 3, 0, 0};
  std::vector<std::uint8_t> moved{1, 1, 0, 0};
  std::vector<std::uint8_t> revert{1, 0, 1, 0};
  AosCoords<double> b{before.data()}, a{after.data()};
  int pass(bool undo_all) {
    int n = 0;
    for (index_t i = 0; i < 4; ++i) n += revert_if_flagged(i, b, a, moved.data(), revert.data(), undo_all);
    return n;
  }
};

TEST(RepairSteps, FlaggedMoversGoBackAndEveryFlagIsCleared) {
  RepairFixture f;
  EXPECT_EQ(f.pass(false), 1);
  EXPECT_EQ(f.after, (std::vector<double>{0, 0, 0, 11, 0, 0, 2, 0, 0, 3, 0, 0}));
  EXPECT_EQ(f.moved, (std::vector<std::uint8_t>{0, 1, 0, 0}));
  // A flag left set would put back a move of the next sweep that no tet
  // objected to.
  EXPECT_EQ(f.revert, (std::vector<std::uint8_t>(4, 0)));
  EXPECT_EQ(surviving_disp2(0, f.b, f.a, f.moved.data()), 0.0);
  EXPECT_EQ(surviving_disp2(1, f.b, f.a, f.moved.data()), 100.0);
}

TEST(RepairSteps, UndoingTheSweepPutsBackEveryMoverOnce) {
  RepairFixture f;
  EXPECT_EQ(f.pass(true), 2);
  EXPECT_EQ(f.after, f.before);
  EXPECT_EQ(f.moved, (std::vector<std::uint8_t>(4, 0)));
  EXPECT_EQ(f.revert, (std::vector<std::uint8_t>(4, 0)));
  EXPECT_EQ(f.pass(true), 0) << "nothing left to put back";
  for (index_t i = 0; i < 4; ++i) EXPECT_EQ(surviving_disp2(i, f.b, f.a, f.moved.data()), 0.0);
}

}  // namespace
}  // namespace tetsmooth
