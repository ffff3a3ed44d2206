// The counters bench_smooth writes into its JSON: the memory floor's byte
// count and the per-run values, checked on numbers worked out by hand.
#include <gtest/gtest.h>

#include "bench/bench_counters.hpp"
#include "run_counters.hpp"

namespace tetsmooth::bench {
namespace {

// 10 nodes, 8 of them movable, 4 tets; the movable nodes' rows hold 30
// neighbour and 16 incidence entries; double.
SweepFootprint tiny() {
  SweepFootprint f;
  f.nodes = 10;
  f.movable_nodes = 8;
  f.tets = 4;
  f.neighbour_entries = 30;
  f.incidence_entries = 16;
  f.real_bytes = 8;
  return f;
}

TEST(BenchCounters, BytesPerSweepCountsEachArrayOnce) {
  SweepFootprint f = tiny();
  // coordinates read and written 2*3*10*8 = 480, flags 10, the movable
  // nodes' neighbour rows 4*9 + 4*30 = 156 and stars 4*9 + 4*16 + 16*4 = 164.
  EXPECT_DOUBLE_EQ(bytes_per_sweep(f), 480 + 10 + 156 + 164);
  // Skipped nodes read neither their neighbour row nor their star.
  f.evaluated_share = 0.5;
  EXPECT_DOUBLE_EQ(bytes_per_sweep(f), 480 + 10 + 0.5 * (156 + 164));
  f.real_bytes = 4;
  EXPECT_DOUBLE_EQ(bytes_per_sweep(f), 240 + 10 + 0.5 * (156 + 164));
  // Ordinary Laplacian smoothing reads rows but no star.
  f.stars = false;
  EXPECT_DOUBLE_EQ(bytes_per_sweep(f), 240 + 10 + 0.5 * 156);
  // In place, only the nodes that move are written: 3*10*4 read, a quarter
  // of that written.
  f.written_share = 0.25;
  EXPECT_DOUBLE_EQ(bytes_per_sweep(f), 120 + 30 + 10 + 0.5 * 156);
}

// 4 sweeps in 2 ms, 10 moves, 8 movable nodes, each evaluated every sweep.
SmoothResult four_sweeps() {
  SmoothResult r;
  r.sweeps = 4;
  r.accepted_per_sweep = {5, 3, 2, 0};
  r.smoothing_ms = 2;
  r.movable_nodes = 8;
  r.evaluations = 32;
  return r;
}

TEST(BenchCounters, RunValuesOfAColouredRun) {
  SmoothResult r = four_sweeps();
  r.topology_ms = 0.25;
  r.evaluations = 16;  // half of 8 nodes x 4 sweeps
  r.num_colours = 2;
  r.colour_sizes = {5, 3};
  r.colour_ms = {1.5, 0.5};
  const auto c = run_counter_values(r, tiny());
  EXPECT_DOUBLE_EQ(c.at("accepted"), 10);
  EXPECT_DOUBLE_EQ(c.at("topology_ms"), 0.25);
  EXPECT_DOUBLE_EQ(c.at("colours"), 2);
  EXPECT_DOUBLE_EQ(c.at("colour_nodes_0"), 5);
  EXPECT_DOUBLE_EQ(c.at("colour_nodes_1"), 3);
  EXPECT_DOUBLE_EQ(c.at("colour_ms_0"), 1.5);
  EXPECT_DOUBLE_EQ(c.at("colour_ms_1"), 0.5);
  EXPECT_EQ(c.count("colour_ms_2"), 0u);
  EXPECT_DOUBLE_EQ(c.at("ms_per_sweep"), 0.5);
  EXPECT_DOUBLE_EQ(c.at("node_updates_per_s"), 16 / 0.002);
  // The evaluated share comes from the run: 16 of 32.
  EXPECT_DOUBLE_EQ(c.at("bytes_per_s"), (480 + 10 + 0.5 * (156 + 164)) * 4 / 0.002);
}

// An in-place (Form B) run writes the nodes it moves: 10 moves over 4
// sweeps of 10 nodes, a quarter of the writes a Jacobi sweep makes. A
// Jacobi (Form A) run of the same moves writes every node.
TEST(BenchCounters, InPlaceRunsCountOnlyTheirMovesWritten) {
  const SmoothResult r = four_sweeps();
  SweepFootprint f = tiny();
  f.in_place = true;
  EXPECT_DOUBLE_EQ(run_counter_values(r, f).at("bytes_per_s"), (240 + 60 + 10 + 156 + 164) * 4 / 0.002);
  f.in_place = false;
  EXPECT_DOUBLE_EQ(run_counter_values(r, f).at("bytes_per_s"), (480 + 10 + 156 + 164) * 4 / 0.002);
}

TEST(BenchCounters, NoRatesWithoutASweepAndNoColourTimesOffTheGpuLoop) {
  SmoothResult r;
  r.num_colours = 2;
  r.colour_sizes = {4, 4};  // a CPU coloured run: sizes, no times
  auto c = run_counter_values(r, tiny());
  EXPECT_DOUBLE_EQ(c.at("sweeps"), 0);
  EXPECT_EQ(c.count("ms_per_sweep"), 0u);
  EXPECT_EQ(c.count("bytes_per_s"), 0u);
  EXPECT_DOUBLE_EQ(c.at("colour_nodes_1"), 4);
  EXPECT_EQ(c.count("colour_ms_0"), 0u);
}

TEST(BenchCounters, PhaseTimesPerSweepOfTheTimedPhaseRun) {
  SmoothResult r = four_sweeps();
  r.phase_ms = {{"tet_quality", 0.4}, {"node_update", 1.2}, {"stopping_rule", 0.04}};
  const auto c = phase_counter_values(r);
  EXPECT_EQ(c.size(), 6u);
  EXPECT_DOUBLE_EQ(c.at("phase_run_sweeps"), 4);
  EXPECT_DOUBLE_EQ(c.at("phase_run_ms_per_sweep"), 0.5);
  EXPECT_DOUBLE_EQ(c.at("phase_ms_per_sweep_tet_quality"), 0.1);
  EXPECT_DOUBLE_EQ(c.at("phase_ms_per_sweep_node_update"), 0.3);
  EXPECT_DOUBLE_EQ(c.at("phase_ms_per_sweep_stopping_rule"), 0.01);
  EXPECT_NEAR(c.at("phase_run_rest_ms_per_sweep"), (2 - 1.64) / 4, 1e-12);
  // A run that timed nothing (not MultiBlock, or the CPU) adds no counter.
  EXPECT_TRUE(phase_counter_values(four_sweeps()).empty());
  r.sweeps = 0;
  EXPECT_TRUE(phase_counter_values(r).empty());
}

// Two summaries no value of which appears in the other, so that a counter
// filled from the wrong summary, or the wrong field, shows.
QualitySummary summary_with(double min, double mean, std::size_t low, std::size_t inverted, std::size_t first_bin) {
  QualitySummary s;
  s.min = min;
  s.mean = mean;
  s.below_0_1 = low;
  s.inverted = inverted;
  for (std::size_t k = 0; k < 10; ++k) s.histogram[k] = first_bin + k;
  return s;
}

// The quality counters are the figures' before/after comparison (Figure 13,
// quality.csv): before must come from the input, after from the result.
// State cannot be built in a test, so a registered benchmark fills one.
TEST(BenchCounters, QualityCountersKeepBeforeAndAfterApart) {
  const QualitySummary before = summary_with(-0.25, 0.5, 70, 3, 100);
  const QualitySummary after = summary_with(0.125, 0.625, 40, 0, 200);
  benchmark::RegisterBenchmark("QualityCountersOnly", [&](benchmark::State& state) {
    for (auto _ : state) {
    }
    set_quality_counters(state, before, after);
  })->Iterations(1);
  const testing::CounterCapture run = testing::run_benchmarks("^QualityCountersOnly");
  ASSERT_EQ(run.by_name.size(), 1u);
  const testing::Counters& c = run.by_name.begin()->second;
  EXPECT_DOUBLE_EQ(c.at("q_min_before"), -0.25);
  EXPECT_DOUBLE_EQ(c.at("q_min_after"), 0.125);
  EXPECT_DOUBLE_EQ(c.at("q_mean_before"), 0.5);
  EXPECT_DOUBLE_EQ(c.at("q_mean_after"), 0.625);
  EXPECT_DOUBLE_EQ(c.at("low_q_before"), 70);
  EXPECT_DOUBLE_EQ(c.at("low_q_after"), 40);
  EXPECT_DOUBLE_EQ(c.at("inverted_before"), 3);
  EXPECT_DOUBLE_EQ(c.at("inverted_after"), 0);
  for (int k = 0; k < 10; ++k) {
    EXPECT_DOUBLE_EQ(c.at("hist_before_" + std::to_string(k)), 100 + k) << k;
    EXPECT_DOUBLE_EQ(c.at("hist_after_" + std::to_string(k)), 200 + k) << k;
  }
  EXPECT_EQ(c.size(), 8u + 20u);
}

}  // namespace
}  // namespace tetsmooth::bench
