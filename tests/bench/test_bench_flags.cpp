// bench_smooth's own flags: taken out of argv, checked, the rest left for
// Google Benchmark.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bench/bench_flags.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth::bench {
namespace {

// Holds the strings so argv can point into them.
struct Args {
  std::vector<std::string> text;
  std::vector<char*> argv;
  int argc = 0;
  explicit Args(std::vector<std::string> a) : text(std::move(a)) {
    text.insert(text.begin(), "bench_smooth");
    for (std::string& s : text) argv.push_back(s.data());
    argc = static_cast<int>(argv.size());
  }
  BenchConfig take() { return take_own_flags(argc, argv.data()); }
  std::vector<std::string> left() const { return {argv.begin() + 1, argv.begin() + argc}; }
};

TEST(BenchFlags, OwnFlagsAreTakenAndTheRestKeptInOrder) {
  Args a({"--benchmark_filter=Serial", "--models=5k,slope-77k", "--precision=float", "--no-cpu",
          "--scaling=lattice-20", "--coloured-lanes=16", "--benchmark_min_time=0.01"});
  const BenchConfig c = a.take();
  EXPECT_EQ(c.models, (std::vector<std::string>{"5k", "77k"}));
  EXPECT_EQ(c.scaling, (std::vector<std::string>{"lattice-20"}));
  EXPECT_EQ(c.precision, Precision::Float);
  EXPECT_EQ(c.coloured_lanes, 16);
  EXPECT_FALSE(c.cpu);
  EXPECT_TRUE(c.gpu);
  EXPECT_EQ(a.left(), (std::vector<std::string>{"--benchmark_filter=Serial", "--benchmark_min_time=0.01"}));
}

TEST(BenchFlags, DefaultsAreThePaperModelsInDoubleWithoutScaling) {
  Args a({});
  const BenchConfig c = a.take();
  EXPECT_EQ(c.models, (std::vector<std::string>{"5k", "10k", "59k", "77k", "109k"}));
  EXPECT_TRUE(c.scaling.empty());
  EXPECT_EQ(c.precision, Precision::Double);
  EXPECT_EQ(c.coloured_lanes, 0);
}

TEST(BenchFlags, ALaterFlagReplacesAnEarlierOne) {
  // run_study.sh puts its defaults first and the user's flags after them.
  Args a({"--scaling=lattice-215", "--scaling=lattice-30", "--precision=float", "--precision=double"});
  const BenchConfig c = a.take();
  EXPECT_EQ(c.scaling, (std::vector<std::string>{"lattice-30"}));
  EXPECT_EQ(c.precision, Precision::Double);
}

TEST(BenchFlags, ScalingNoneDropsTheLatticeAndRepeatsCountOnce) {
  Args off({"--scaling=lattice-215", "--scaling=none"});
  EXPECT_TRUE(off.take().scaling.empty());
  Args empty({"--scaling=lattice-215", "--scaling="});
  EXPECT_TRUE(empty.take().scaling.empty());
  // A model named twice, under either name, would register its benchmarks twice.
  Args twice({"--models=77k,slope-77k,5k,5k", "--scaling=lattice-20,lattice-20"});
  const BenchConfig c = twice.take();
  EXPECT_EQ(c.models, (std::vector<std::string>{"77k", "5k"}));
  EXPECT_EQ(c.scaling, (std::vector<std::string>{"lattice-20"}));
}

TEST(BenchFlags, TheLargestLatticeIsAccepted) {
  Args a({"--scaling=lattice-447"});
  EXPECT_EQ(a.take().scaling, (std::vector<std::string>{"lattice-447"}));
}

TEST(BenchFlags, BadValuesNameTheFlag) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--models=5k,12k", "--models: unknown model '12k'; expected some of 5k, 10k, 59k, 77k (or slope-77k), 109k;"},
      {"--models=lattice-20", "--models: unknown model 'lattice-20'"},
      {"--models=", "--models: empty list"},
      {"--scaling=lattice-", "--scaling: 'lattice-'"},
      {"--scaling=lattice-0", "--scaling: 'lattice-0'"},
      {"--scaling=109k", "--scaling: '109k'"},
      {"--scaling=lattice-9x", "--scaling: 'lattice-9x'"},
      {"--scaling=lattice-448", "--scaling: 'lattice-448' is too large: the largest lattice is lattice-447"},
      {"--scaling=lattice-99999999999", "--scaling: 'lattice-99999999999'"},
      {"--precision=half", "--precision: 'half'"},
      {"--coloured-lanes=abc", "--coloured-lanes: 'abc'"},
      {"--coloured-lanes=12", "--coloured-lanes: '12'"},
      {"--coloured-lanes=8x", "--coloured-lanes: '8x'"},
      {"--models", "--models: the value follows '=', as in --models=5k,10k"},
      {"--scaling", "--scaling: the value follows '='"},
      {"--precision", "--precision: the value follows '='"},
      {"--coloured-lanes", "--coloured-lanes: the value follows '='"},
  };
  for (const auto& [flag, message] : cases) {
    Args a({flag});
    try {
      a.take();
      ADD_FAILURE() << flag << " was accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << flag << ": " << e.what();
    }
  }
}

TEST(BenchFlags, HelpIsLeftForGoogleBenchmarkAndListsEveryOwnFlag) {
  Args a({"--help"});
  a.take();
  EXPECT_EQ(a.left(), (std::vector<std::string>{"--help"}));
  const std::string help = own_flags_help();
  for (const char* flag : {"--models=", "--scaling=", "--precision=", "--coloured-lanes=", "--no-cpu", "--no-gpu"})
    EXPECT_NE(help.find(flag), std::string::npos) << flag;
}

}  // namespace
}  // namespace tetsmooth::bench
