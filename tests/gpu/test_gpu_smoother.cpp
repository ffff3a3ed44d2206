// The CUDA smoothers against the CPU reference. Every test skips with the
// reason when no CUDA device is usable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "generators/models.hpp"
#include "kernels/cuda/gpu_pipeline.hpp"
#include "kernels/cuda/star_test_check.hpp"
#include "kernels/smoother.hpp"
#include "kernels/sweep_log.hpp"
#include "mesh/errors.hpp"
#include "mesh/quality_summary.hpp"
#include "mesh/tet_quality.hpp"
#include "mesh/topology.hpp"
#include "test_meshes.hpp"

namespace tetsmooth {
namespace {

#define SKIP_WITHOUT_GPU()                              \
  do {                                                  \
    std::string why_;                                   \
    if (!cuda_available(&why_)) GTEST_SKIP() << why_;   \
  } while (0)

const TetMesh& model_5k() {
  static const TetMesh m = generate_model("5k");
  return m;
}

SmoothOptions gpu_options(Form form, Layout layout, Strategy strategy, Method method, Precision precision) {
  SmoothOptions o;
  o.form = form;
  o.layout = layout;
  o.strategy = strategy;
  o.method = method;
  o.precision = precision;
  return o;
}

// Race-free variants keep every adaptive guarantee; the paper's in-place
// MultiBlock/SingleBlock variants read neighbours while they move.
bool race_free(Form form, Strategy strategy) { return form == Form::A || strategy == Strategy::Coloured; }

// How far a device run lands from the CPU's run of the same scheme: nodes
// that end elsewhere (more than 1e-9 mean edge lengths apart), and accept
// decisions that flipped, counted per sweep as the difference in accepted
// moves (a flip on a move shorter than that tolerance shows here only).
struct Agreement {
  std::size_t differing = 0;
  long long flips = 0, accepted = 0;
};

Agreement agreement(const TetMesh& cpu, const TetMesh& gpu, const SmoothResult& rc, const SmoothResult& rg) {
  Agreement a;
  const double tol = 1e-9 * rc.mean_edge_length;
  for (std::size_t i = 0; i < cpu.num_nodes(); ++i) {
    const double d = std::hypot(cpu.xyz[3 * i] - gpu.xyz[3 * i], cpu.xyz[3 * i + 1] - gpu.xyz[3 * i + 1],
                                cpu.xyz[3 * i + 2] - gpu.xyz[3 * i + 2]);
    a.differing += d > tol;
  }
  a.flips = std::abs(static_cast<long long>(rg.accepted_per_sweep.size()) -
                     static_cast<long long>(rc.accepted_per_sweep.size()));
  for (std::size_t s = 0; s < std::min(rg.accepted_per_sweep.size(), rc.accepted_per_sweep.size()); ++s) {
    a.flips += std::abs(rg.accepted_per_sweep[s] - rc.accepted_per_sweep[s]);
    a.accepted += rc.accepted_per_sweep[s];
  }
  return a;
}

// Prints the agreement of a double run with the CPU's and allows at most
// 0.5% of the movable nodes to differ and 0.5% of the decisions to flip:
// the lanes sharing a node add its neighbours in another order, and nvcc
// may fuse a*b+c into one rounding (FMA), so a centroid or a quality can
// differ in its last bits; an accept decision can then flip only where the
// new and old minimum agree to ~1e-15.
void expect_same_decisions(const char* what, const TetMesh& cpu, const TetMesh& gpu, const SmoothResult& rc,
                           const SmoothResult& rg) {
  const Agreement a = agreement(cpu, gpu, rc, rg);
  std::printf("%s: %zu of %zu movable nodes differ from the CPU; %lld of %lld accept decisions flipped; sweeps cpu "
              "%d gpu %d\n",
              what, a.differing, rc.movable_nodes, a.flips, a.accepted, rc.sweeps, rg.sweeps);
  EXPECT_LE(a.differing, rc.movable_nodes / 200) << what;
  EXPECT_LE(a.flips, a.accepted / 200) << what;
  EXPECT_NEAR(rg.after.mean, rc.after.mean, 1e-6) << what;
  EXPECT_EQ(rg.after.inverted, 0u) << what;
}

// Given the CPU's colouring, the coloured Form B in double visits nodes in
// the CPU's order, so it makes the CPU's decisions up to rounding.
TEST(GpuSmoother, ColouredFormBDoubleMatchesCpuGivenSameColouring) {
  SKIP_WITHOUT_GPU();
  TetMesh cpu = model_5k();
  TetMesh gpu = cpu;
  const Topology topo = build_topology(cpu);
  const Colouring colouring = colour_nodes(topo.neighbours, topo.movable);
  SmoothOptions o = gpu_options(Form::B, Layout::AoS, Strategy::Coloured, Method::Adaptive, Precision::Double);
  o.ordering = Ordering::Coloured;
  const SmoothResult rc = smooth_cpu(cpu, o, &colouring);
  const SmoothResult rg = smooth_cuda(gpu, o, &colouring);
  expect_same_decisions("coloured Form B double", cpu, gpu, rc, rg);
}

// A colouring that does not fit is refused before any work, as on the CPU:
// the coloured loop moves every node its classes list, so a coloured
// boundary node would move.
TEST(GpuSmoother, ColouringThatDoesNotFitIsRefused) {
  SKIP_WITHOUT_GPU();
  const Topology topo = build_topology(model_5k());
  Colouring bad = colour_nodes(topo.neighbours, topo.movable);
  const auto boundary = std::find(topo.movable.begin(), topo.movable.end(), 0) - topo.movable.begin();
  bad.colour[static_cast<std::size_t>(boundary)] = 0;
  bad.classes = colour_classes(bad.colour, bad.num_colours);
  const SmoothOptions o = gpu_options(Form::B, Layout::AoS, Strategy::Coloured, Method::Adaptive, Precision::Double);
  TetMesh m = model_5k();
  EXPECT_THROW(smooth_cuda(m, o, &bad), UsageError);
  EXPECT_EQ(m.xyz, model_5k().xyz);
  bad = colour_nodes(topo.neighbours, topo.movable);
  bad.num_colours += 3;
  EXPECT_THROW(smooth_cuda(m, o, &bad), UsageError);
}

// Jacobi (Form A) reads only the previous sweep's positions, so the order in
// which the device takes the nodes does not matter, and MultiBlock in double
// makes the CPU's decisions up to rounding, repair included. Its old
// qualities come from the pass that opens each sweep (tet_quality_kernel),
// which must be what the CPU computes afresh.
TEST(GpuSmoother, JacobiMultiBlockDoubleMatchesCpu) {
  SKIP_WITHOUT_GPU();
  TetMesh cpu = model_5k();
  TetMesh gpu = cpu;
  const SmoothOptions o = gpu_options(Form::A, Layout::SoA, Strategy::MultiBlock, Method::Adaptive, Precision::Double);
  const SmoothResult rc = smooth_cpu(cpu, o);
  const SmoothResult rg = smooth_cuda(gpu, o);
  expect_same_decisions("MultiBlock Form A double", cpu, gpu, rc, rg);
  std::printf("reverted by the repair: cpu %lld gpu %lld\n", static_cast<long long>(rc.reverted_moves),
              static_cast<long long>(rg.reverted_moves));
  EXPECT_LE(std::llabs(rg.reverted_moves - rc.reverted_moves), rc.reverted_moves / 200 + 1);
}

// MultiBlock's warp-shared test (warp_star_test.cuh) against the one-thread
// test the CPU runs, on the same device and the same inputs: they must
// agree on every node, whatever tet the deal starts with. Targets are the
// centroids, moved by up to a third of the mean edge length on two nodes in
// three so that both verdicts are common and objections turn up at every
// place in a star. The 5k model has stars of up to 74 tets, so a node's
// tets also span rounds.
TEST(GpuSmoother, WarpSharedStarTestMatchesOneThread) {
  SKIP_WITHOUT_GPU();
  const TetMesh& mesh = model_5k();
  const Topology topo = build_topology(mesh);
  index_t largest_star = 0;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) largest_star = std::max(largest_star, topo.node_tets.row_size(i));
  EXPECT_GT(largest_star, 32);
  const double h = mean_edge_length(mesh.xyz, topo.neighbours);
  std::vector<double> targets(3 * mesh.num_nodes(), 0.0);
  std::uint32_t state = 12345;
  const auto jitter = [&] {
    state = state * 1664525u + 1013904223u;  // a fixed sequence: the same targets on every run
    return (static_cast<double>(state >> 8) / 16777216.0 - 0.5) * (2.0 / 3.0) * h;
  };
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    const index_t degree = topo.neighbours.row_size(i);
    for (const index_t* j = topo.neighbours.row_begin(i); j != topo.neighbours.row_end(i); ++j)
      for (int k = 0; k < 3; ++k) targets[3 * i + k] += mesh.xyz[3 * static_cast<std::size_t>(*j) + k] / degree;
    if (i % 3 != 0)
      for (int k = 0; k < 3; ++k) targets[3 * i + k] += jitter();
  }
  for (const cuda::LeadRule rule : {cuda::LeadRule::OldMinimum, cuda::LeadRule::Rotating}) {
    const cuda::StarTestAgreement a = cuda::compare_warp_star_test(mesh, targets, rule);
    std::printf("warp-shared star test, lead %s: %zu of %zu movable nodes accepted, %zu disagree\n",
                rule == cuda::LeadRule::OldMinimum ? "old minimum" : "rotating", a.accepted, a.judged,
                a.disagreements);
    EXPECT_EQ(a.disagreements, 0u);
    EXPECT_GT(a.accepted, a.judged / 20);
    EXPECT_LT(a.accepted, a.judged - a.judged / 10);
  }
}

TEST(GpuSmoother, DealGivesEachNodeItsSlots) {
  SKIP_WITHOUT_GPU();
  const cuda::DealCheck c = cuda::check_deal();
  EXPECT_GT(c.nodes, 100000u);
  EXPECT_EQ(c.broken, 0u);
}

// MultiBlock's lanes read their incidence rows a 16-byte quad at a time
// from the quad that holds the row's first entry (RowWalk in
// node_update.hpp): the old minima and their entries must be those of the
// walk entry by entry, and the neighbour sums those of the step sizes the
// sweeps use. The 5k model's neighbour rows start (and so end) at every
// place in a quad, its incidence rows only at places 0 and 2 (every star of
// it has an even number of tets), and each array's last row ends at its end.
TEST(GpuSmoother, QuadRowWalksMatchEntryByEntry) {
  SKIP_WITHOUT_GPU();
  const TetMesh& mesh = model_5k();
  const Topology topo = build_topology(mesh);
  int inc_starts[4] = {0, 0, 0, 0}, nbr_starts[4] = {0, 0, 0, 0};  // rows by where in a quad they start
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    ++inc_starts[topo.node_tets.offsets[i] % 4];
    ++nbr_starts[topo.neighbours.offsets[i] % 4];
  }
  for (int r = 0; r < 4; ++r) EXPECT_GT(nbr_starts[r], 0) << "no neighbour row starts at place " << r << " of a quad";
  EXPECT_GT(inc_starts[1] + inc_starts[2] + inc_starts[3], 0) << "every incidence row starts a quad";
  const cuda::RowWalkCheck c = cuda::check_row_walks(mesh);
  EXPECT_EQ(c.nodes, mesh.num_nodes());
  EXPECT_EQ(c.mismatches, 0u);
}

// The float sweeps' radius ratio (approximate square roots and division,
// subnormal operands taken as zero) keeps small tets, down to the size
// below which float loses their volume, as the CPU's double does.
TEST(GpuSmoother, FloatRadiusRatioKeepsSmallTets) {
  SKIP_WITHOUT_GPU();
  const Vec3<double> shapes[2][4] = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                     {{0.1, 0.2, 0.05}, {1.3, 0.1, 0.2}, {0.4, 0.9, 0.1}, {0.5, 0.4, 0.7}}};
  std::vector<double> corners, expected;
  for (double h : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6})
    for (const auto& shape : shapes) {
      Vec3<double> v[4];
      for (int k = 0; k < 4; ++k) {
        v[k] = h * shape[k];
        corners.insert(corners.end(), {v[k].x, v[k].y, v[k].z});
      }
      expected.push_back(radius_ratio(v[0], v[1], v[2], v[3]));
    }
  for (Precision p : {Precision::Float, Precision::Double}) {
    const std::vector<double> q = cuda::device_radius_ratios(corners, p);
    ASSERT_EQ(q.size(), expected.size());
    for (std::size_t t = 0; t < q.size(); ++t)
      EXPECT_NEAR(q[t], expected[t], p == Precision::Float ? 1e-5 : 1e-12) << to_string(p) << " tet " << t;
  }
}

TEST(GpuSmoother, ColouredIsBitIdenticalAcrossRuns) {
  SKIP_WITHOUT_GPU();
  for (Precision p : {Precision::Double, Precision::Float}) {
    TetMesh a = model_5k(), b = model_5k();
    const SmoothOptions o = gpu_options(Form::B, Layout::SoA, Strategy::Coloured, Method::Adaptive, p);
    smooth_cuda(a, o);
    smooth_cuda(b, o);
    EXPECT_EQ(a.xyz, b.xyz) << to_string(p);
  }
}

// smooth() on CUDA with second-order tets: the midside nodes ride along on
// the device as nodes of no tet, so the corners end exactly where the same
// mesh's first-order run puts them, and each midside node at its edge's
// midpoint (mesh/second_order.hpp; the carrying itself is host code).
TEST(GpuSmoother, SecondOrderCornersMatchTheFirstOrderRun) {
  SKIP_WITHOUT_GPU();
  for (Precision p : {Precision::Double, Precision::Float}) {
    TetMesh first = model_5k();
    TetMesh second = testing::with_midsides(first);
    const SmoothOptions o = gpu_options(Form::B, Layout::AoS, Strategy::Coloured, Method::Adaptive, p);
    smooth(first, o, Device::Cuda);
    smooth(second, o, Device::Cuda);
    EXPECT_TRUE(std::equal(first.xyz.begin(), first.xyz.end(), second.xyz.begin())) << to_string(p);
    EXPECT_LT(testing::largest_midside_offset(second), 1e-9) << to_string(p);
  }
}

// Skipping settled nodes changes no decision: the coloured loop with and
// without it gives the same coordinates and per-sweep counts, bit for bit,
// while evaluating fewer nodes once the mesh settles.
TEST(GpuSmoother, SkippingSettledNodesChangesNothing) {
  SKIP_WITHOUT_GPU();
  for (Precision p : {Precision::Double, Precision::Float})
    for (Method method : {Method::Adaptive, Method::Ordinary}) {
      TetMesh skipped = model_5k(), full = model_5k();
      SmoothOptions o = gpu_options(Form::B, Layout::AoS, Strategy::Coloured, method, p);
      o.max_iterations = 30;
      const SmoothResult rs = smooth_cuda(skipped, o);
      o.skip_settled = false;
      const SmoothResult rf = smooth_cuda(full, o);
      EXPECT_EQ(skipped.xyz, full.xyz) << to_string(p) << " " << to_string(method);
      EXPECT_EQ(rs.accepted_per_sweep, rf.accepted_per_sweep);
      EXPECT_EQ(rs.max_displacement_per_sweep, rf.max_displacement_per_sweep);
      EXPECT_EQ(rf.evaluations, static_cast<std::int64_t>(rf.movable_nodes) * rf.sweeps);
      // Ordinary smoothing moves nearly every node in every sweep, so only
      // the adaptive method is sure to leave nodes settled.
      if (method == Method::Adaptive) {
        EXPECT_LT(rs.evaluations, rf.evaluations);
      }
      EXPECT_LE(rs.evaluations, rf.evaluations);
      std::printf("%s %s: %lld of %lld node evaluations with skipping, %d sweeps\n", to_string(p), to_string(method),
                  static_cast<long long>(rs.evaluations), static_cast<long long>(rf.evaluations), rs.sweeps);
    }
}

// Runs the coloured loop with each lane count in `lanes` on `mesh`, given
// the CPU's colouring, against the CPU's coloured smoothing: the sums over
// a node's neighbours are added in another order, so only near-tie
// decisions may differ.
void expect_lane_counts_match_cpu(const TetMesh& mesh, Layout layout, int max_iterations,
                                  std::initializer_list<int> lanes, const char* name, int blocks = 0) {
  TetMesh cpu = mesh;
  const Topology topo = build_topology(cpu);
  const Colouring colouring = colour_nodes(topo.neighbours, topo.movable);
  SmoothOptions o = gpu_options(Form::B, layout, Strategy::Coloured, Method::Adaptive, Precision::Double);
  o.ordering = Ordering::Coloured;
  o.max_iterations = max_iterations;
  o.coloured_blocks = blocks;
  const SmoothResult rc = smooth_cpu(cpu, o, &colouring);
  index_t largest = 0;
  for (std::size_t c = 0; c + 1 < colouring.classes.offsets.size(); ++c)
    largest = std::max(largest, colouring.classes.offsets[c + 1] - colouring.classes.offsets[c]);
  for (int n : lanes) {
    TetMesh gpu = mesh;
    o.coloured_lanes = n;
    const SmoothResult rg = smooth_cuda(gpu, o, &colouring);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < gpu.xyz.size(); ++i) differing += std::abs(gpu.xyz[i] - cpu.xyz[i]) > 1e-9 * rc.mean_edge_length;
    const std::string grid = blocks > 0 ? ", " + std::to_string(blocks) + " blocks" : "";
    std::printf("coloured %s (largest class %d nodes), %d lanes per node%s: %zu coordinates differ from the CPU, "
                "sweeps %d (cpu %d)\n",
                name, static_cast<int>(largest), n, grid.c_str(), differing, rg.sweeps, rc.sweeps);
    EXPECT_LE(differing, 3 * rc.movable_nodes / 200) << n;
    EXPECT_NEAR(rg.after.mean, rc.after.mean, 1e-6) << n;
    EXPECT_EQ(rg.after.inverted, 0u) << n;
  }
}

// The coloured loop gives a node a warp on small classes and 8 lanes on
// large ones (the 5k model takes the warp when left to choose); 16 can be
// asked for. Each must do the CPU's coloured smoothing.
TEST(GpuSmoother, ColouredLaneCountsAgree) {
  SKIP_WITHOUT_GPU();
  expect_lane_counts_match_cpu(model_5k(), Layout::SoA, SmoothOptions{}.max_iterations, {8, 16, 32}, "5k");
}

// A class of the 5k model fits in one share per warp. On a lattice of
// 118k nodes, whose classes are several times the warps a device holds at
// once, each warp takes several shares of a class in turn from its block's
// counter (coloured_loop_kernel.cuh); that too must be the CPU's order of
// decisions.
TEST(GpuSmoother, ColouredLargeClassesAgree) {
  SKIP_WITHOUT_GPU();
  expect_lane_counts_match_cpu(generate_model("lattice-48"), Layout::AoS, 4, {8, 32}, "lattice-48");
}

// With a warp per node, a block stages the openings of its nodes of a class
// at most one per thread at a time (staged_openings.cuh). On 6 blocks, each
// gets ~2,400 nodes of lattice-48's largest class: four chunks in double.
TEST(GpuSmoother, ColouredStagesLargeSharesInChunks) {
  SKIP_WITHOUT_GPU();
  expect_lane_counts_match_cpu(generate_model("lattice-48"), Layout::AoS, 4, {32}, "lattice-48", 6);
}

// Every variant on the 5k model: boundary nodes untouched bit for bit in
// the device's working coordinates,
// quality close to the CPU's for the same form, and for race-free adaptive
// variants no inverted tet and no lower minimum. The racy variants report
// how many tets they invert.
class AllGpuVariants
    : public ::testing::TestWithParam<std::tuple<Form, Layout, Strategy, Method, Precision>> {};

TEST_P(AllGpuVariants, AgainstCpuReference) {
  SKIP_WITHOUT_GPU();
  const auto [form, layout, strategy, method, precision] = GetParam();
  if (strategy == Strategy::Coloured && form == Form::A) GTEST_SKIP() << "Coloured is a Form B scheme";
  TetMesh gpu = model_5k();
  TetMesh cpu = gpu;
  const Topology topo = build_topology(cpu);
  SmoothOptions o = gpu_options(form, layout, strategy, method, precision);
  const SmoothResult rc = smooth_cpu(cpu, o);
  // smooth_cuda's steps, with a look at the working coordinates before the
  // download, which writes back movable nodes only.
  cuda::GpuPipeline pipeline(gpu);
  pipeline.restore_coordinates(o);
  SmoothResult rg = pipeline.run(o);
  EXPECT_EQ(pipeline.fixed_nodes_moved(), 0u) << "boundary nodes moved on the device";
  gpu.xyz = pipeline.download_xyz();
  rg.before = summarize_quality(model_5k(), topo.movable);
  rg.after = summarize_quality(gpu, topo.movable);
  EXPECT_GT(rg.sweeps, 0);
  EXPECT_GT(rg.after.mean, rg.before.mean);
  // The mean quality over 33k tets moves by ~0.025 when smoothing; node
  // orders and precisions differ, so race-free results must stay within a
  // tenth of that. The racy in-place variants accept moves judged on
  // half-updated neighbours and land further off (within 0.01, measured
  // about 0.005 on an H200).
  EXPECT_NEAR(rg.after.mean, rc.after.mean, race_free(form, strategy) ? 0.0025 : 0.01);
  std::printf("%s/%s/%s/%s/%s: sweeps %d (cpu %d), mean q %.5f (cpu %.5f), inverted %zu (cpu %zu), reverted %lld\n",
              to_string(form), to_string(layout), to_string(strategy), to_string(method), to_string(precision),
              rg.sweeps, rc.sweeps, rg.after.mean, rc.after.mean, rg.after.inverted, rc.after.inverted,
              static_cast<long long>(rg.reverted_moves));
  if (method == Method::Adaptive && race_free(form, strategy)) {
    EXPECT_EQ(rg.after.inverted, 0u);
    EXPECT_GE(rg.after.min, rg.before.min);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Variants, AllGpuVariants,
    ::testing::Combine(::testing::Values(Form::A, Form::B), ::testing::Values(Layout::AoS, Layout::SoA),
                       ::testing::Values(Strategy::SingleBlock, Strategy::MultiBlock, Strategy::Coloured),
                       ::testing::Values(Method::Adaptive, Method::Ordinary),
                       ::testing::Values(Precision::Double, Precision::Float)));

TEST(GpuSmoother, Figure2OnTheDevice) {
  SKIP_WITHOUT_GPU();
  TetMesh ordinary = testing::concave_star(), adaptive = ordinary;
  smooth_cuda(ordinary, gpu_options(Form::B, Layout::AoS, Strategy::Coloured, Method::Ordinary, Precision::Double));
  const SmoothResult r =
      smooth_cuda(adaptive, gpu_options(Form::B, Layout::AoS, Strategy::Coloured, Method::Adaptive, Precision::Double));
  EXPECT_GT(summarize_quality(ordinary).inverted, 0u);
  EXPECT_EQ(r.after.inverted, 0u);
}

// The 5k model under `o` stops at a cap of 3 sweeps, checked every 2 (not
// a divisor of 3: sweeps past the cap must not run), and after one sweep
// when the tolerance is huge.
void expect_stops_of_the_cpu(SmoothOptions o) {
  SCOPED_TRACE(to_string(o.strategy));
  TetMesh m = model_5k();
  o.max_iterations = 3;
  o.check_every = 2;
  SmoothResult r = smooth_cuda(m, o);
  EXPECT_EQ(r.sweeps, 3);
  EXPECT_EQ(r.stop, StopReason::MaxIterations);
  EXPECT_EQ(r.accepted_per_sweep.size(), 3u);
  o.max_iterations = 100;
  o.tolerance = 1e6;
  m = model_5k();
  r = smooth_cuda(m, o);
  EXPECT_EQ(r.sweeps, 1);
  EXPECT_EQ(r.stop, StopReason::Tolerance);
  o.max_iterations = 1;  // the cap and the tolerance in one sweep: the tolerance is the reason, as on the CPU
  m = model_5k();
  r = smooth_cuda(m, o);
  EXPECT_EQ(r.sweeps, 1);
  EXPECT_EQ(r.stop, StopReason::Tolerance);
  // A centre node already at its neighbours' centroid cannot raise its
  // minimum: the first sweep moves nothing.
  o.max_iterations = 100;
  o.tolerance = 0;
  m = testing::cube_with_centre();
  r = smooth_cuda(m, o);
  EXPECT_EQ(r.stop, StopReason::NoMoves);
  EXPECT_EQ(r.sweeps, 1);
  EXPECT_EQ(r.accepted_per_sweep, std::vector<std::int64_t>{0});
  EXPECT_EQ(m.xyz, testing::cube_with_centre().xyz);
  o.max_iterations = 0;
  m = model_5k();
  r = smooth_cuda(m, o);
  EXPECT_EQ(r.sweeps, 0);
  EXPECT_EQ(r.stop, StopReason::MaxIterations);
  EXPECT_EQ(m.xyz, model_5k().xyz);
}

TEST(GpuSmoother, StoppingRuleMatchesCpu) {
  SKIP_WITHOUT_GPU();
  for (Strategy strategy : {Strategy::Coloured, Strategy::MultiBlock, Strategy::SingleBlock})
    expect_stops_of_the_cpu(gpu_options(Form::B, Layout::AoS, strategy, Method::Adaptive, Precision::Double));
  expect_stops_of_the_cpu(gpu_options(Form::A, Layout::SoA, Strategy::MultiBlock, Method::Adaptive, Precision::Float));
  // Each allowed sweep takes device memory for its counters: past the cap,
  // a usage error before any work, not an allocation of gigabytes.
  SmoothOptions o = gpu_options(Form::B, Layout::AoS, Strategy::MultiBlock, Method::Adaptive, Precision::Double);
  o.max_iterations = kMaxGpuSweeps + 1;
  TetMesh m = model_5k();
  EXPECT_THROW(smooth_cuda(m, o), UsageError);
  EXPECT_EQ(m.xyz, model_5k().xyz);
}

// MultiBlock reads the stop flag back every check_every sweeps. However
// often it looks, a Jacobi run (deterministic) makes the same sweeps, moves
// and coordinates; every sweep is reported once, in order; and no sweep
// runs past the cap or the tolerance.
TEST(GpuSmoother, MultiBlockHostChecksDoNotChangeTheRun) {
  SKIP_WITHOUT_GPU();
  SmoothOptions o = gpu_options(Form::A, Layout::AoS, Strategy::MultiBlock, Method::Adaptive, Precision::Double);
  TetMesh reference = model_5k();
  o.check_every = 4;
  const SmoothResult ref = smooth_cuda(reference, o);
  ASSERT_GT(ref.sweeps, 4);
  for (int every : {1, 2, 3, 100}) {
    TetMesh m = model_5k();
    o.check_every = every;
    std::vector<int> reported;
    o.progress = [&](const SweepProgress& p) { reported.push_back(p.sweep); };
    const SmoothResult r = smooth_cuda(m, o);
    EXPECT_EQ(r.sweeps, ref.sweeps) << "check_every " << every;
    EXPECT_EQ(r.stop, ref.stop) << "check_every " << every;
    EXPECT_EQ(r.accepted_per_sweep, ref.accepted_per_sweep) << "check_every " << every;
    EXPECT_EQ(m.xyz, reference.xyz) << "check_every " << every;
    std::vector<int> each(static_cast<std::size_t>(r.sweeps));
    for (int s = 0; s < r.sweeps; ++s) each[s] = s + 1;
    EXPECT_EQ(reported, each) << "check_every " << every;
  }
  o.progress = nullptr;
  expect_stops_of_the_cpu(o);
}

// The progress reports (what the CLI's progress line shows). Each sweep is
// reported once with the run's own counts, its largest move in mesh units
// (float works in the unit box, so the model is scaled away from it); the
// last report of each host check carries a quality, the others none, and it
// is that of the mesh as the reported sweep left it: the run's own `after`
// at the end, a run stopped there in between. Form A's positions after 3
// sweeps are in its second buffer, after 8 in its first. Ordinary smoothing
// of the concave star leaves an inverted tet, a negative minimum.
struct Reported {
  std::vector<int> sweeps;
  std::vector<std::int64_t> accepted;
  std::vector<double> max_displacement;
  std::vector<int> quality_sweeps;  // of the reports that carried a quality
  std::vector<MinMeanQuality> quality;
};

SmoothResult run_with_progress(TetMesh& m, SmoothOptions o, Reported& seen) {
  o.progress = [&seen](const SweepProgress& p) {
    seen.sweeps.push_back(p.sweep);
    seen.accepted.push_back(p.accepted);
    seen.max_displacement.push_back(p.max_displacement);
    if (!p.quality) return;
    seen.quality_sweeps.push_back(p.sweep);
    seen.quality.push_back(p.quality());
  };
  return smooth_cuda(m, o);
}

TEST(GpuSmoother, ProgressReportsTheSweepsAndTheirQuality) {
  SKIP_WITHOUT_GPU();
  TetMesh scaled = model_5k();
  for (double& x : scaled.xyz) x = 37.0 * x + 5.0;
  struct Case {
    Form form;
    Layout layout;
    Strategy strategy;
    Method method;
  };
  const Case cases[] = {{Form::A, Layout::SoA, Strategy::MultiBlock, Method::Adaptive},
                        {Form::B, Layout::AoS, Strategy::MultiBlock, Method::Adaptive},
                        {Form::A, Layout::AoS, Strategy::SingleBlock, Method::Adaptive},
                        {Form::B, Layout::AoS, Strategy::SingleBlock, Method::Ordinary},
                        {Form::B, Layout::AoS, Strategy::Coloured, Method::Adaptive}};
  for (Precision precision : {Precision::Double, Precision::Float})
    for (const Case& c : cases) {
      SmoothOptions o = gpu_options(c.form, c.layout, c.strategy, c.method, precision);
      SCOPED_TRACE(std::string(to_string(c.form)) + "/" + to_string(c.layout) + "/" + to_string(c.strategy) + "/" +
                   to_string(c.method) + "/" + to_string(precision));
      o.max_iterations = 8;
      o.tolerance = 0;
      o.check_every = 3;
      TetMesh m = scaled;
      Reported seen;
      const SmoothResult r = run_with_progress(m, o, seen);
      ASSERT_EQ(r.sweeps, 8);
      EXPECT_EQ(seen.sweeps, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}));
      EXPECT_EQ(seen.accepted, r.accepted_per_sweep);
      EXPECT_EQ(seen.max_displacement, r.max_displacement_per_sweep);
      EXPECT_GT(r.max_displacement_per_sweep.front(), 0.01 * r.mean_edge_length) << "moves in mesh units";
      const std::vector<int> checks =
          c.strategy == Strategy::MultiBlock ? std::vector<int>{3, 6, 8} : std::vector<int>{8};
      EXPECT_EQ(seen.quality_sweeps, checks);
      // Float's ratios come from float positions, the summary's from them
      // in double: a few float ulps of a ratio apart.
      const double tol = precision == Precision::Double ? 1e-12 : 2e-5;
      ASSERT_FALSE(seen.quality.empty());
      EXPECT_NEAR(seen.quality.back().min, r.after.min, tol);
      EXPECT_NEAR(seen.quality.back().mean, r.after.mean, tol);
      if (c.strategy == Strategy::MultiBlock && c.form == Form::A && precision == Precision::Double) {
        TetMesh stopped = scaled;  // Jacobi is deterministic: the same 3 sweeps
        o.max_iterations = 3;
        const SmoothResult r3 = smooth_cuda(stopped, o);
        EXPECT_NEAR(seen.quality.front().min, r3.after.min, tol);
        EXPECT_NEAR(seen.quality.front().mean, r3.after.mean, tol);
        EXPECT_NE(seen.quality.front().mean, seen.quality.back().mean);
      }
    }
  TetMesh star = testing::concave_star();
  Reported seen;
  const SmoothResult r = run_with_progress(
      star, gpu_options(Form::B, Layout::AoS, Strategy::Coloured, Method::Ordinary, Precision::Double), seen);
  ASSERT_EQ(seen.quality.size(), 1u);
  EXPECT_LT(seen.quality.back().min, 0.0);
  EXPECT_NEAR(seen.quality.back().min, r.after.min, 1e-12);
  EXPECT_NEAR(seen.quality.back().mean, r.after.mean, 1e-12);
}

// Float runs work in a frame around the tets' corners: a node no tet uses,
// far away, must not stretch it (at 1e6 it squeezed the cube into a few
// float steps, and the centre landed 0.06 from the centroid).
TEST(GpuSmoother, FloatFrameIgnoresNodesInNoTet) {
  SKIP_WITHOUT_GPU();
  const TetMesh base = testing::cube_with_centre(0.3, 0.6, 0.45);
  TetMesh stray = base;
  stray.xyz.insert(stray.xyz.end(), {1e6, -1e6, 1e6});
  for (Strategy strategy : {Strategy::MultiBlock, Strategy::Coloured, Strategy::SingleBlock}) {
    SCOPED_TRACE(to_string(strategy));
    SmoothOptions o = gpu_options(Form::B, Layout::AoS, strategy, Method::Ordinary, Precision::Float);
    o.max_iterations = 1;
    TetMesh gpu = stray;
    smooth_cuda(gpu, o);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(gpu.xyz[3 * 8 + k], 0.5, 1e-6) << k;  // the corners' centroid
    EXPECT_EQ(std::vector<double>(gpu.xyz.begin() + 27, gpu.xyz.end()), (std::vector<double>{1e6, -1e6, 1e6}));
  }
}

// smooth_cuda checks on the host what the device would trust: a mesh
// without tets, an index out of range, a fixed array of another length.
TEST(GpuSmoother, MeshesTheDeviceCannotTrustAreRefused) {
  SKIP_WITHOUT_GPU();
  const SmoothOptions o = gpu_options(Form::B, Layout::AoS, Strategy::MultiBlock, Method::Adaptive, Precision::Double);
  TetMesh none = testing::cube_with_centre();
  none.tets.clear();
  EXPECT_THROW(smooth_cuda(none, o), InputError);
  TetMesh out_of_range = testing::cube_with_centre();
  out_of_range.tets[5] = 9;
  EXPECT_THROW(smooth_cuda(out_of_range, o), InputError);
  TetMesh short_fixed = testing::cube_with_centre();
  short_fixed.fixed.assign(3, 0);
  EXPECT_THROW(smooth_cuda(short_fixed, o), InputError);
}

// run() needs coordinates loaded, and a run stopped part way (a progress
// callback that cancels) keeps the sweeps it made: Form A's result lies in
// the other buffer after an odd count, which download_xyz must take.
TEST(GpuPipeline, RunNeedsCoordinatesAndAStoppedRunKeepsItsSweeps) {
  SKIP_WITHOUT_GPU();
  const TetMesh& mesh = model_5k();
  SmoothOptions o = gpu_options(Form::A, Layout::AoS, Strategy::MultiBlock, Method::Adaptive, Precision::Double);
  o.tolerance = 0;
  o.max_iterations = 20;
  o.check_every = 1;
  cuda::GpuPipeline stopped(mesh);
  EXPECT_THROW(stopped.run(o), UsageError);
  int reported = 0;
  SmoothOptions cancelling = o;
  cancelling.progress = [&](const SweepProgress& s) {
    reported = s.sweep;
    throw std::runtime_error("cancelled");
  };
  stopped.restore_coordinates(cancelling);
  EXPECT_THROW(stopped.run(cancelling), std::runtime_error);
  ASSERT_EQ(reported, 1);
  cuda::GpuPipeline one(mesh);
  o.max_iterations = 1;
  one.restore_coordinates(o);
  one.run(o);
  const std::vector<double> after_one = one.download_xyz();
  EXPECT_NE(after_one, mesh.xyz);
  EXPECT_EQ(stopped.download_xyz(), after_one);
}

TEST(GpuPipeline, RestoreGivesTheSameRunAgain) {
  SKIP_WITHOUT_GPU();
  cuda::GpuPipeline p(model_5k());
  const SmoothOptions o = gpu_options(Form::B, Layout::AoS, Strategy::Coloured, Method::Adaptive, Precision::Float);
  p.restore_coordinates(o);
  const SmoothResult a = p.run(o);
  const std::vector<double> xa = p.download_xyz();
  p.restore_coordinates(o);
  const SmoothResult b = p.run(o);
  EXPECT_EQ(a.accepted_per_sweep, b.accepted_per_sweep);
  EXPECT_EQ(xa, p.download_xyz());
  EXPECT_GT(cuda::measure_copy_bandwidth(std::size_t(64) << 20, 3), 1e9);
}

// The coloured loop's time, colour by colour: one entry per class, each
// class's size as the colouring has it, every entry positive, and together
// no more than the smoothing phase that contains them (the CUDA events
// bracket the loop; 1% and 10 us allow for the two clocks). A second run
// starts its sums from zero.
TEST(GpuPipeline, ColouredLoopTimesEachColour) {
  SKIP_WITHOUT_GPU();
  cuda::GpuPipeline p(model_5k());
  const Topology topo = build_topology(model_5k());
  const Colouring cpu_colouring = colour_nodes(topo.neighbours, topo.movable);
  const SmoothOptions o = gpu_options(Form::B, Layout::AoS, Strategy::Coloured, Method::Adaptive, Precision::Double);
  for (const Colouring* given : {static_cast<const Colouring*>(nullptr), &cpu_colouring, &cpu_colouring}) {
    p.restore_coordinates(o);
    const SmoothResult r = p.run(o, given);
    ASSERT_GT(r.num_colours, 1);
    ASSERT_EQ(r.colour_ms.size(), static_cast<std::size_t>(r.num_colours));
    ASSERT_EQ(r.colour_sizes.size(), static_cast<std::size_t>(r.num_colours));
    std::int64_t nodes = 0;
    double total = 0;
    for (int k = 0; k < r.num_colours; ++k) {
      if (given) {
        EXPECT_EQ(r.colour_sizes[k], given->classes.row_size(k)) << "colour " << k;
      }
      EXPECT_GT(r.colour_ms[k], 0.0) << "colour " << k;
      nodes += r.colour_sizes[k];
      total += r.colour_ms[k];
    }
    EXPECT_EQ(static_cast<std::size_t>(nodes), r.movable_nodes);
    EXPECT_LE(total, 1.01 * r.smoothing_ms + 0.01);
    std::printf("%s colouring: %d colours, %.3f of %.3f smoothing ms in the colour steps\n",
                given ? "CPU" : "device", r.num_colours, total, r.smoothing_ms);
  }
  const SmoothOptions multi = gpu_options(Form::B, Layout::AoS, Strategy::MultiBlock, Method::Adaptive,
                                          Precision::Double);
  p.restore_coordinates(multi);
  EXPECT_TRUE(p.run(multi).colour_ms.empty());
}

std::vector<std::string> phase_names(const SmoothResult& r) {
  std::vector<std::string> names;
  for (const auto& [name, ms] : r.phase_ms) names.push_back(name);
  return names;
}

// MultiBlock's time, kernel by kernel (SmoothOptions::time_phases): each
// kind of kernel its sweeps launch, in launch order, every time positive,
// and together no more than the smoothing phase (1% and 10 us for the
// events' resolution), the events of the first chunk of sweeps serving the
// others. The events only observe: Jacobi (Form A) gives the same moves and
// coordinates with and without them.
// Nothing is timed where the option is off, nor by the strategies that run
// their loop in one launch.
TEST(GpuPipeline, MultiBlockTimesEachKernel) {
  SKIP_WITHOUT_GPU();
  cuda::GpuPipeline p(model_5k());
  SmoothOptions o = gpu_options(Form::A, Layout::AoS, Strategy::MultiBlock, Method::Adaptive, Precision::Double);
  p.restore_coordinates(o);
  const SmoothResult plain = p.run(o);
  const std::vector<double> plain_xyz = p.download_xyz();
  EXPECT_TRUE(plain.phase_ms.empty());
  o.time_phases = true;
  p.restore_coordinates(o);
  const SmoothResult timed = p.run(o);
  EXPECT_EQ(timed.accepted_per_sweep, plain.accepted_per_sweep);
  EXPECT_EQ(p.download_xyz(), plain_xyz);
  EXPECT_EQ(phase_names(timed), (std::vector<std::string>{"tet_quality", "node_update", "repair", "stopping_rule"}));
  double total = 0;
  for (const auto& [name, ms] : timed.phase_ms) {
    EXPECT_GT(ms, 0.0) << name;
    total += ms;
  }
  EXPECT_LE(total, 1.01 * timed.smoothing_ms + 0.01);
  std::printf("Form A MultiBlock, %d sweeps: %.3f of %.3f smoothing ms in the kernels\n", timed.sweeps, total,
              timed.smoothing_ms);

  o = gpu_options(Form::B, Layout::SoA, Strategy::MultiBlock, Method::Ordinary, Precision::Float);
  o.time_phases = true;
  p.restore_coordinates(o);
  EXPECT_EQ(phase_names(p.run(o)), (std::vector<std::string>{"node_update", "stopping_rule"}));
  for (Strategy one_launch : {Strategy::SingleBlock, Strategy::Coloured}) {
    o = gpu_options(Form::B, Layout::AoS, one_launch, Method::Adaptive, Precision::Double);
    o.time_phases = true;
    p.restore_coordinates(o);
    EXPECT_TRUE(p.run(o).phase_ms.empty()) << to_string(one_launch);
  }
}

}  // namespace
}  // namespace tetsmooth
