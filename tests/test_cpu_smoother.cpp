// The CPU smoothers: the paper's Figure 2 case, the adaptive guarantees,
// boundary nodes, determinism across thread counts, and the stopping rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "generators/models.hpp"
#include "kernels/node_update.hpp"
#include "kernels/smoother.hpp"
#include "kernels/sweep_log.hpp"
#include "mesh/errors.hpp"
#include "mesh/quality_summary.hpp"
#include "mesh/topology.hpp"
#include "test_meshes.hpp"

namespace tetsmooth {
namespace {

SmoothOptions options(Method method, Form form, int threads = 1) {
  SmoothOptions o;
  o.method = method;
  o.form = form;
  o.threads = threads;
  return o;
}

TEST(CpuSmoother, Figure2OrdinaryInvertsAdaptiveDoesNot) {
  TetMesh ordinary = testing::concave_star();
  TetMesh adaptive = ordinary;
  ASSERT_EQ(summarize_quality(ordinary).inverted, 0u);
  const SmoothResult r_ord = smooth_cpu(ordinary, options(Method::Ordinary, Form::B));
  const SmoothResult r_ada = smooth_cpu(adaptive, options(Method::Adaptive, Form::B));
  EXPECT_GT(r_ord.after.inverted, 0u) << "ordinary Laplacian should move the node out of its concave star";
  EXPECT_EQ(r_ada.after.inverted, 0u);
  EXPECT_GE(r_ada.after.min, r_ada.before.min);
}

// Every variant: boundary nodes bit for bit, and for adaptive no new
// inverted tet and a minimum quality that never drops.
class AllVariants : public ::testing::TestWithParam<std::tuple<Method, Form, int>> {};

TEST_P(AllVariants, BoundaryFixedAndAdaptiveGuarantees) {
  const auto [method, form, threads] = GetParam();
  TetMesh m = testing::random_delaunay(1200, 11);
  const TetMesh input = m;
  const Topology topo = build_topology(input);
  SmoothOptions o = options(method, form, threads);
  o.max_iterations = 30;
  const SmoothResult r = smooth_cpu(m, o);
  EXPECT_GT(r.sweeps, 0);
  EXPECT_GT(r.accepted_per_sweep.front(), 0);
  for (std::size_t i = 0; i < m.num_nodes(); ++i) {
    if (topo.movable[i]) continue;
    for (int k = 0; k < 3; ++k) ASSERT_EQ(m.xyz[3 * i + k], input.xyz[3 * i + k]) << "node " << i << " moved";
  }
  if (method == Method::Adaptive) {
    EXPECT_EQ(r.after.inverted, 0u);
    EXPECT_GE(r.after.min, r.before.min);
    EXPECT_GT(r.after.mean, r.before.mean);
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, AllVariants,
                         ::testing::Combine(::testing::Values(Method::Adaptive, Method::Ordinary),
                                            ::testing::Values(Form::A, Form::B), ::testing::Values(1, 2)));

// One sweep at a time: after each, the minimum quality over movable tets
// must not drop and no tet may invert (adaptive, both forms).
TEST(CpuSmoother, AdaptiveNeverLowersMinimumSweepBySweep) {
  for (Form form : {Form::A, Form::B}) {
    TetMesh m = testing::random_delaunay(1500, 4);
    const Topology topo = build_topology(m);
    SmoothOptions o = options(Method::Adaptive, form, 2);
    o.max_iterations = 1;
    double last = summarize_quality(m, topo.movable).min_movable;
    for (int sweep = 0; sweep < 8; ++sweep) {
      const SmoothResult r = smooth_cpu(m, o);
      EXPECT_EQ(r.after.inverted, 0u);
      EXPECT_GE(r.after.min_movable, last) << "form " << to_string(form) << " sweep " << sweep;
      last = r.after.min_movable;
    }
  }
}

// The rule node by node and tet by tet, one sweep at a time, on meshes with
// inverted tets (nodes pushed through their neighbours): no valid tet
// becomes invalid and no invalid one gets worse (both forms); and in Form A,
// whose movers are judged together and repaired where they share a tet,
// every node that moved ends the sweep with a higher minimum over its tets
// than it started with. (In Form B a later neighbour's move may lower a
// node's minimum again; that neighbour's own minimum rises.)
TEST(CpuSmoother, EachSweepKeepsTheRuleNodeByNodeAndTetByTet) {
  long long movers = 0, reverted = 0, inverted_seen = 0;
  for (Form form : {Form::A, Form::B})
    for (int threads : {1, 2}) {
      TetMesh m = testing::cube_grid(7, 0.3, 5);
      const Topology topo = build_topology(m);
      for (std::size_t n = 0; n < m.num_nodes(); n += 5)
        if (topo.movable[n]) m.xyz[3 * n] += 1.5;  // the spacing is 1: inverts tets
      SmoothOptions o = options(Method::Adaptive, form, threads);
      o.max_iterations = 1;
      for (int sweep = 0; sweep < 6; ++sweep) {
        SCOPED_TRACE(std::string("form ") + to_string(form) + ", threads " + std::to_string(threads) + ", sweep " +
                     std::to_string(sweep));
        const std::vector<double> xyz = m.xyz;
        const std::vector<double> q0 = tet_qualities(m);
        const SmoothResult r = smooth_cpu(m, o);
        reverted += r.reverted_moves;
        const std::vector<double> q1 = tet_qualities(m);
        for (std::size_t t = 0; t < q0.size(); ++t) {
          inverted_seen += q0[t] <= 0;
          if (q0[t] > 0) {
            EXPECT_GT(q1[t], 0) << "tet " << t;
          } else {
            EXPECT_GE(q1[t], q0[t]) << "tet " << t;
          }
        }
        if (form != Form::A) continue;
        for (std::size_t i = 0; i < m.num_nodes(); ++i) {
          if (std::equal(xyz.begin() + 3 * i, xyz.begin() + 3 * i + 3, m.xyz.begin() + 3 * i)) continue;
          double min0 = 2, min1 = 2;
          for (const index_t* t = topo.node_tets.row_begin(i); t != topo.node_tets.row_end(i); ++t) {
            min0 = std::min(min0, q0[*t]);
            min1 = std::min(min1, q1[*t]);
          }
          EXPECT_GT(min1, min0) << "node " << i;
          ++movers;
        }
      }
    }
  // The meshes reach the clauses under test: inverted tets, Form A movers,
  // and conflicts that the repair resolved.
  EXPECT_GT(inverted_seen, 0);
  EXPECT_GT(movers, 0);
  EXPECT_GT(reverted, 0);
}

TEST(CpuSmoother, ColouredFormBIsIdenticalForAnyThreadCount) {
  const TetMesh input = testing::random_delaunay(2000, 21);
  TetMesh serial = input;
  TetMesh threaded = input;
  SmoothOptions o = options(Method::Adaptive, Form::B, 1);
  o.ordering = Ordering::Coloured;
  const SmoothResult a = smooth_cpu(serial, o);
  o.threads = 2;
  const SmoothResult b = smooth_cpu(threaded, o);
  EXPECT_EQ(serial.xyz, threaded.xyz);
  EXPECT_EQ(a.sweeps, b.sweeps);
  EXPECT_EQ(a.accepted_per_sweep, b.accepted_per_sweep);
  // The largest move is a max over threads' shares: exact whatever the split.
  EXPECT_EQ(a.max_displacement_per_sweep, b.max_displacement_per_sweep);
  EXPECT_GT(a.num_colours, 1);
  // Threads colour Form B without being asked (smoother.hpp): the natural
  // order in parallel is the coloured one.
  TetMesh natural = input;
  o.ordering = Ordering::Natural;
  const SmoothResult c = smooth_cpu(natural, o);
  EXPECT_EQ(serial.xyz, natural.xyz);
  EXPECT_EQ(a.accepted_per_sweep, c.accepted_per_sweep);
  EXPECT_EQ(a.max_displacement_per_sweep, c.max_displacement_per_sweep);
}

TEST(CpuSmoother, FormAIsIdenticalForAnyThreadCount) {
  TetMesh serial = testing::random_delaunay(2000, 22);
  TetMesh threaded = serial;
  const SmoothResult a = smooth_cpu(serial, options(Method::Adaptive, Form::A, 1));
  const SmoothResult b = smooth_cpu(threaded, options(Method::Adaptive, Form::A, 2));
  EXPECT_EQ(serial.xyz, threaded.xyz);
  EXPECT_EQ(a.reverted_moves, b.reverted_moves);
  EXPECT_EQ(a.accepted_per_sweep, b.accepted_per_sweep);
  EXPECT_EQ(a.max_displacement_per_sweep, b.max_displacement_per_sweep);
}

TEST(CpuSmoother, GivenColouringIsUsedAndChecked) {
  TetMesh m = testing::random_delaunay(600, 2);
  const Topology topo = build_topology(m);
  Colouring c = colour_nodes(topo.neighbours, topo.movable);
  SmoothOptions o = options(Method::Adaptive, Form::B, 1);
  o.ordering = Ordering::Coloured;
  TetMesh copy = m;
  const SmoothResult r = smooth_cpu(copy, o, &c);
  EXPECT_EQ(r.num_colours, c.num_colours);
  ASSERT_EQ(r.colour_sizes.size(), static_cast<std::size_t>(c.num_colours));
  for (int k = 0; k < c.num_colours; ++k) EXPECT_EQ(r.colour_sizes[k], c.classes.row_size(k)) << "colour " << k;
  EXPECT_TRUE(r.colour_ms.empty());  // timed per colour by the GPU loop only
  // Refused, and the mesh untouched: every colour the same; classes that
  // disagree with the colours (the sweeps walk the classes); a coloured
  // boundary node.
  const auto refused = [&](const Colouring& bad) {
    TetMesh untouched = m;
    EXPECT_THROW(smooth_cpu(untouched, o, &bad), UsageError);
    EXPECT_EQ(untouched.xyz, m.xyz);
  };
  Colouring bad = c;
  std::fill(bad.colour.begin(), bad.colour.end(), 0);
  refused(bad);
  bad = c;
  bad.classes = Csr{};
  bad.num_colours = 0;
  refused(bad);
  bad = c;
  bad.num_colours += 3;
  refused(bad);
  bad = c;
  const auto boundary = std::find(topo.movable.begin(), topo.movable.end(), 0) - topo.movable.begin();
  bad.colour[static_cast<std::size_t>(boundary)] = 0;
  bad.classes = colour_classes(bad.colour, bad.num_colours);
  refused(bad);
}

TEST(CpuSmoother, InvertedInputTetIsNeverMadeWorse) {
  TetMesh m = testing::cube_with_centre(0.5, 0.5, 0.5);
  m.xyz[3 * 8 + 2] = -0.05;  // the centre pokes through the bottom: two tets invert
  const auto before = tet_qualities(m);
  const SmoothResult r = smooth_cpu(m, options(Method::Adaptive, Form::B));
  const auto after = tet_qualities(m);
  EXPECT_EQ(r.before.inverted, 2u);
  for (std::size_t t = 0; t < before.size(); ++t) {
    if (before[t] <= 0) {
      EXPECT_GE(after[t], before[t]) << "tet " << t;
    } else {
      EXPECT_GT(after[t], 0) << "tet " << t;
    }
  }
  EXPECT_LT(r.after.inverted, 2u) << "the move to the centroid fixes them";
}

TEST(CpuSmoother, StoppingRule) {
  TetMesh m = testing::random_delaunay(800, 6);
  const std::vector<double> input = m.xyz;
  SmoothOptions o = options(Method::Adaptive, Form::B);
  o.max_iterations = 0;
  SmoothResult r = smooth_cpu(m, o);
  EXPECT_EQ(r.sweeps, 0);
  EXPECT_EQ(r.stop, StopReason::MaxIterations);
  EXPECT_EQ(m.xyz, input);
  o.max_iterations = 2;
  r = smooth_cpu(m, o);
  EXPECT_EQ(r.sweeps, 2);
  EXPECT_EQ(r.stop, StopReason::MaxIterations);
  o.max_iterations = 100;
  o.tolerance = 1e6;  // any move is below a million edge lengths
  r = smooth_cpu(m, o);
  EXPECT_EQ(r.sweeps, 1);
  EXPECT_EQ(r.stop, StopReason::Tolerance);
  o.max_iterations = 1;  // the cap and the tolerance in the same sweep: the tolerance is the reason
  r = smooth_cpu(m, o);
  EXPECT_EQ(r.sweeps, 1);
  EXPECT_EQ(r.stop, StopReason::Tolerance);
  o.max_iterations = 100;
  o.tolerance = 0;    // only "no moves" or the cap can stop it now
  r = smooth_cpu(m, o);
  if (r.stop == StopReason::NoMoves) {
    EXPECT_EQ(r.accepted_per_sweep.back(), 0);
  } else {
    EXPECT_EQ(r.stop, StopReason::MaxIterations);
    EXPECT_EQ(r.sweeps, 100);
  }
  // A centre node already at its neighbours' centroid: its move changes no
  // quality, so the minimum cannot rise and the first sweep moves nothing.
  TetMesh settled = testing::cube_with_centre();
  const std::vector<double> settled_input = settled.xyz;
  r = smooth_cpu(settled, o);
  EXPECT_EQ(r.stop, StopReason::NoMoves);
  EXPECT_EQ(r.sweeps, 1);
  EXPECT_EQ(r.accepted_per_sweep, std::vector<std::int64_t>{0});
  EXPECT_EQ(settled.xyz, settled_input);
  int calls = 0;
  o.max_iterations = 3;
  o.progress = [&](const SweepProgress& p) { EXPECT_EQ(p.sweep, ++calls); };
  r = smooth_cpu(m, o);
  EXPECT_EQ(calls, r.sweeps);
}

// Each sweep's progress report gives the quality of the mesh as that sweep
// left it: the summary of a run stopped there, for both forms (Form A swaps
// its buffers before reporting) and with threads.
TEST(CpuSmoother, ProgressQualityIsThatOfTheSweepReported) {
  const TetMesh input = testing::random_delaunay(900, 6);
  for (Form form : {Form::A, Form::B})
    for (int threads : {1, 2}) {
      SmoothOptions o = options(Method::Adaptive, form, threads);
      o.max_iterations = 4;
      o.tolerance = 0;
      std::vector<MinMeanQuality> reported;
      o.progress = [&](const SweepProgress& p) {
        ASSERT_TRUE(p.quality);
        reported.push_back(p.quality());
      };
      TetMesh m = input;
      const SmoothResult r = smooth_cpu(m, o);
      ASSERT_EQ(static_cast<int>(reported.size()), r.sweeps);
      ASSERT_GE(r.sweeps, 2);
      EXPECT_GT(reported.back().mean, r.before.mean);
      o.progress = nullptr;
      for (int k : {1, r.sweeps}) {
        TetMesh stopped = input;
        o.max_iterations = k;
        const SmoothResult rk = smooth_cpu(stopped, o);
        const MinMeanQuality& q = reported[static_cast<std::size_t>(k - 1)];
        EXPECT_EQ(q.min, rk.after.min) << "form " << to_string(form) << ", " << threads << " threads, sweep " << k;
        EXPECT_NEAR(q.mean, rk.after.mean, 1e-14) << "form " << to_string(form) << ", sweep " << k;
      }
    }
}

// The GPU's cap on sweeps (kernels/sweep_log.hpp): the CPU has none.
TEST(CpuSmoother, GpuSweepCapIsChecked) {
  SmoothOptions o;
  o.max_iterations = kMaxGpuSweeps;
  EXPECT_NO_THROW(check_gpu_sweeps(o));
  o.max_iterations = kMaxGpuSweeps + 1;
  EXPECT_THROW(check_gpu_sweeps(o), UsageError);
}

// The names are an interface, not decoration: bench family names
// (Form/Layout/Strategy/size) are matched by users' --benchmark_filter
// regular expressions, `stop_reason` is a documented report field, and the
// method and precision names are the README's option values.
TEST(CpuSmoother, OptionAndStopReasonNamesAreTheDocumentedOnes) {
  EXPECT_STREQ(to_string(Method::Adaptive), "adaptive");
  EXPECT_STREQ(to_string(Method::Ordinary), "ordinary");
  EXPECT_STREQ(to_string(Form::A), "A");
  EXPECT_STREQ(to_string(Form::B), "B");
  EXPECT_STREQ(to_string(Layout::AoS), "AoS");
  EXPECT_STREQ(to_string(Layout::SoA), "SoA");
  EXPECT_STREQ(to_string(Strategy::SingleBlock), "SingleBlock");
  EXPECT_STREQ(to_string(Strategy::MultiBlock), "MultiBlock");
  EXPECT_STREQ(to_string(Strategy::Coloured), "Coloured");
  EXPECT_STREQ(to_string(Precision::Float), "float");
  EXPECT_STREQ(to_string(Precision::Double), "double");
  EXPECT_STREQ(to_string(StopReason::NoMoves), "no-moves");
  EXPECT_STREQ(to_string(StopReason::Tolerance), "tolerance");
  EXPECT_STREQ(to_string(StopReason::MaxIterations), "max-iterations");
  EXPECT_STREQ(to_string(StopReason::NotStarted), "not-started");
}

TEST(CpuSmoother, RejectsBadOptions) {
  TetMesh m = testing::regular_tet();
  SmoothOptions o;
  o.max_iterations = -1;
  EXPECT_THROW(smooth_cpu(m, o), UsageError);
  o = SmoothOptions{};
  o.tolerance = -1;
  EXPECT_THROW(smooth_cpu(m, o), UsageError);
  o = SmoothOptions{};
  o.coloured_lanes = 12;
  EXPECT_THROW(smooth_cpu(m, o), UsageError);
  o = SmoothOptions{};
  o.coloured_blocks = -1;
  EXPECT_THROW(smooth_cpu(m, o), UsageError);
}

// An infinite tolerance passes "tolerance >= 0" but would stop every run
// after one sweep whatever it moved: the library rejects it itself, not only
// the command line's parser.
TEST(CpuSmoother, RejectsAnInfiniteTolerance) {
  TetMesh m = testing::regular_tet();
  SmoothOptions o;
  o.tolerance = std::numeric_limits<double>::infinity();
  EXPECT_THROW(smooth_cpu(m, o), UsageError);
}

// Every lane count the coloured GPU strategy documents (0 = automatic) is
// accepted; the check runs on every backend, so a CPU run must not refuse one.
TEST(CpuSmoother, AcceptsEveryDocumentedColouredLaneCount) {
  for (int lanes : {0, 8, 16, 32}) {
    SmoothOptions o;
    o.coloured_lanes = lanes;
    EXPECT_NO_THROW(check_smooth_options(o)) << lanes;
  }
}

// The CUDA MultiBlock loop advances check_every sweeps between host checks:
// zero would never advance, so it is refused up front like the other options.
TEST(CpuSmoother, RejectsACheckIntervalOfZero) {
  SmoothOptions o;
  o.check_every = 0;
  EXPECT_THROW(check_smooth_options(o), UsageError);
  o.check_every = 1;
  EXPECT_NO_THROW(check_smooth_options(o));
}

TEST(CpuSmoother, PaperModel5kLosesPoorTets) {
  TetMesh m = generate_model("5k");
  const SmoothResult r = smooth_cpu(m, options(Method::Adaptive, Form::B));
  EXPECT_LT(r.after.below_0_1, r.before.below_0_1);
  EXPECT_GT(r.after.mean, r.before.mean);
  EXPECT_EQ(r.after.inverted, 0u);
  std::printf("5k adaptive Form B serial: q<0.1 %zu -> %zu (%.1f%% fewer), mean q %.4f -> %.4f, min q %.4f -> %.4f, %d sweeps\n",
              r.before.below_0_1, r.after.below_0_1,
              100.0 * (1.0 - double(r.after.below_0_1) / double(r.before.below_0_1)), r.before.mean, r.after.mean,
              r.before.min, r.after.min, r.sweeps);
}

// Nodes whose position differs between two coordinate arrays, and the
// largest distance one went.
std::int64_t nodes_moved(const std::vector<double>& a, const std::vector<double>& b) {
  std::int64_t n = 0;
  for (std::size_t i = 0; i < a.size(); i += 3) n += !std::equal(a.begin() + i, a.begin() + i + 3, b.begin() + i);
  return n;
}

double move_length(const std::vector<double>& a, const std::vector<double>& b, std::size_t i) {
  const double dx = b[3 * i] - a[3 * i], dy = b[3 * i + 1] - a[3 * i + 1], dz = b[3 * i + 2] - a[3 * i + 2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

double largest_move(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size() / 3; ++i) d = std::max(d, move_length(a, b, i));
  return d;
}

// The same over nodes [first, last).
double largest_move_of(const std::vector<double>& a, const std::vector<double>& b, const index_t* first,
                       const index_t* last) {
  double d = 0;
  for (const index_t* i = first; i != last; ++i) d = std::max(d, move_length(a, b, static_cast<std::size_t>(*i)));
  return d;
}

// A grid with inverted tets, where Form A's movers conflict and the repair
// puts some back (EachSweepKeepsTheRuleNodeByNodeAndTetByTet shows it).
TetMesh grid_with_conflicts() { return testing::pushed_cube_grid(7, 0.3, 5, 5, 1.5); }

// A sweep's reported largest move is the largest distance a node went in
// it, and its accepted moves are the nodes that went anywhere, for every
// way the CPU sweeps: Form A counts only the moves that survived the
// repair, Form B in place, in natural order or colour by colour.
TEST(CpuSmoother, ReportedLargestMoveIsTheLargestDistanceMoved) {
  const TetMesh input = grid_with_conflicts();
  std::int64_t reverted = 0;
  for (Method method : {Method::Adaptive, Method::Ordinary})
    for (Form form : {Form::A, Form::B})
      for (int threads : {1, 2})
        for (Ordering ordering : {Ordering::Natural, Ordering::Coloured}) {
          if (form == Form::A && ordering == Ordering::Coloured) continue;  // Form A takes no order
          SCOPED_TRACE(std::string(to_string(method)) + ", form " + to_string(form) + ", " + std::to_string(threads) +
                       " threads, " + (ordering == Ordering::Coloured ? "coloured" : "natural"));
          TetMesh m = input;
          SmoothOptions o = options(method, form, threads);
          o.ordering = ordering;
          o.max_iterations = 1;
          const SmoothResult r = smooth_cpu(m, o);
          ASSERT_EQ(r.max_displacement_per_sweep.size(), 1u);
          EXPECT_GT(r.accepted_per_sweep[0], 0);
          EXPECT_EQ(r.accepted_per_sweep[0], nodes_moved(input.xyz, m.xyz));
          EXPECT_DOUBLE_EQ(r.max_displacement_per_sweep[0], largest_move(input.xyz, m.xyz));
          reverted += r.reverted_moves;
        }
  EXPECT_GT(reverted, 0) << "the repair must have put moves back, or Form A's count of survivors is untested";
}

// A tolerance no move reaches stops Form A, as Form B, after its first
// sweep, and for that reason rather than the cap.
TEST(CpuSmoother, HugeToleranceStopsAfterOneSweep) {
  const TetMesh input = testing::cube_grid(5, 0.3, 2);
  for (Form form : {Form::A, Form::B})
    for (int threads : {1, 2}) {
      TetMesh m = input;
      SmoothOptions o = options(Method::Adaptive, form, threads);
      o.tolerance = 1e6;
      const SmoothResult r = smooth_cpu(m, o);
      EXPECT_EQ(r.sweeps, 1) << "form " << to_string(form) << ", " << threads << " threads";
      EXPECT_EQ(r.stop, StopReason::Tolerance) << "form " << to_string(form) << ", " << threads << " threads";
      EXPECT_GT(r.accepted_per_sweep.at(0), 0);
    }
}

// Coloured Form B sweeps one colour class after another: its largest move
// is the largest over every class, not that of the last class swept.
TEST(CpuSmoother, ColouredLargestMoveIsOverEveryColour) {
  const TetMesh input = testing::cube_grid(6, 0.3, 3);
  const Topology topo = build_topology(input);
  const Colouring c = colour_nodes(topo.neighbours, topo.movable);
  ASSERT_GT(c.num_colours, 1);
  for (int threads : {1, 2}) {
    TetMesh m = input;
    SmoothOptions o = options(Method::Adaptive, Form::B, threads);
    o.ordering = Ordering::Coloured;
    o.max_iterations = 1;
    const SmoothResult r = smooth_cpu(m, o, &c);
    const int last = c.num_colours - 1;
    const double in_last = largest_move_of(input.xyz, m.xyz, c.classes.row_begin(last), c.classes.row_end(last));
    const double overall = largest_move(input.xyz, m.xyz);
    ASSERT_LT(in_last, overall) << "the largest move must lie outside the last class for this to test anything";
    EXPECT_DOUBLE_EQ(r.max_displacement_per_sweep.at(0), overall) << threads << " threads";
  }
}

// Form B colours its nodes when it runs in parallel (natural order cannot
// be) or when asked to; Form A and serial natural Form B do not, and report
// no colours.
TEST(CpuSmoother, ColoursWhereFormBRunsInParallelOrAsks) {
  const TetMesh input = testing::cube_grid(4, 0.2, 1);
  const auto run = [&](Form form, int threads, Ordering ordering) {
    TetMesh m = input;
    SmoothOptions o = options(Method::Adaptive, form, threads);
    o.ordering = ordering;
    o.max_iterations = 1;
    return smooth_cpu(m, o);
  };
  for (const auto& [threads, ordering] : {std::pair{2, Ordering::Natural}, std::pair{2, Ordering::Coloured},
                                          std::pair{1, Ordering::Coloured}}) {
    const SmoothResult r = run(Form::B, threads, ordering);
    EXPECT_GT(r.num_colours, 1) << threads << " threads";
    ASSERT_EQ(r.colour_sizes.size(), static_cast<std::size_t>(r.num_colours));
    std::int64_t coloured = 0;
    for (std::int64_t k : r.colour_sizes) coloured += k;
    EXPECT_EQ(coloured, static_cast<std::int64_t>(r.movable_nodes)) << "every movable node has a colour";
  }
  EXPECT_EQ(run(Form::B, 2, Ordering::Natural).backend, "cpu-threads");
  for (const auto& [form, threads] : {std::pair{Form::B, 1}, std::pair{Form::A, 2}, std::pair{Form::A, 1}}) {
    const SmoothResult r = run(form, threads, Ordering::Natural);
    EXPECT_EQ(r.num_colours, 0) << "form " << to_string(form) << ", " << threads << " threads";
    EXPECT_TRUE(r.colour_sizes.empty());
  }
  EXPECT_EQ(run(Form::B, 1, Ordering::Natural).backend, "cpu-serial");
}

// The CPU evaluates every movable node once a sweep and skips none, so its
// count of evaluations is movable nodes x sweeps, however the run stopped.
TEST(CpuSmoother, EvaluationsAreMovableNodesTimesSweeps) {
  const TetMesh input = testing::cube_grid(5, 0.3, 4);
  const Topology topo = build_topology(input);
  const auto movable = static_cast<std::size_t>(std::count(topo.movable.begin(), topo.movable.end(), 1));
  ASSERT_GT(movable, 0u);
  for (Form form : {Form::A, Form::B})
    for (int threads : {1, 2})
      for (int max_iterations : {0, 1, 3}) {
        TetMesh m = input;
        SmoothOptions o = options(Method::Adaptive, form, threads);
        o.max_iterations = max_iterations;
        o.tolerance = 0;
        const SmoothResult r = smooth_cpu(m, o);
        EXPECT_EQ(r.movable_nodes, movable);
        EXPECT_EQ(r.sweeps, max_iterations);
        EXPECT_EQ(r.evaluations, static_cast<std::int64_t>(movable) * max_iterations)
            << "form " << to_string(form) << ", " << threads << " threads, " << max_iterations << " sweeps";
      }
  // Stopped by "no moves": its one sweep still evaluated the one movable node.
  TetMesh settled = testing::cube_with_centre();
  const SmoothResult r = smooth_cpu(settled, options(Method::Adaptive, Form::B));
  EXPECT_EQ(r.stop, StopReason::NoMoves);
  EXPECT_EQ(r.evaluations, 1);
}

// Form A carries nothing from one sweep to the next but the positions: a
// run of several sweeps is those sweeps run one at a time. A revert flag or
// mover mark left from one sweep would put back, or count, a move of the
// next. Each sweep also accounts for every candidate move exactly once:
// those that stand are the nodes that moved, the rest were reverted.
TEST(CpuSmoother, FormASweepsCarryNothingButPositions) {
  constexpr int kSweeps = 4;
  for (int threads : {1, 2}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    TetMesh chained = grid_with_conflicts();
    TetMesh stepped = chained;
    const Topology topo = build_topology(chained);
    SmoothOptions o = options(Method::Adaptive, Form::A, threads);
    o.tolerance = 0;
    o.max_iterations = kSweeps;
    const SmoothResult r = smooth_cpu(chained, o);
    ASSERT_EQ(r.sweeps, kSweeps);
    o.max_iterations = 1;
    std::int64_t reverted = 0;
    int sweeps_with_reverts = 0;
    for (int k = 0; k < kSweeps; ++k) {
      // The candidates: movable nodes whose own test takes their move from
      // this sweep's positions.
      const MeshView view = host_view(stepped, topo);
      const AosCoords<double> xyz{stepped.xyz.data()};
      std::int64_t candidates = 0;
      for (index_t i = 0; i < static_cast<index_t>(stepped.num_nodes()); ++i)
        candidates += topo.movable[i] && takes_move(evaluate_node<double, true>(view, xyz, i));
      const std::vector<double> before = stepped.xyz;
      const SmoothResult rk = smooth_cpu(stepped, o);
      EXPECT_EQ(rk.accepted_per_sweep.at(0), nodes_moved(before, stepped.xyz)) << "sweep " << k;
      EXPECT_EQ(rk.accepted_per_sweep.at(0) + rk.reverted_moves, candidates) << "sweep " << k;
      EXPECT_EQ(rk.accepted_per_sweep.at(0), r.accepted_per_sweep[k]) << "sweep " << k;
      EXPECT_EQ(rk.max_displacement_per_sweep.at(0), r.max_displacement_per_sweep[k]) << "sweep " << k;
      reverted += rk.reverted_moves;
      sweeps_with_reverts += rk.reverted_moves > 0;
    }
    EXPECT_EQ(chained.xyz, stepped.xyz);
    EXPECT_EQ(r.reverted_moves, reverted);
    ASSERT_GE(sweeps_with_reverts, 2) << "flags must be set in a sweep that another sweep with conflicts follows";
  }
}

}  // namespace
}  // namespace tetsmooth
