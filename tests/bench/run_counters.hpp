#pragma once
// Runs registered benchmarks in-process and hands back the counters each
// wrote: the way to see what a function that fills a benchmark::State (which
// a test cannot build itself) puts into the result JSON.
#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace tetsmooth::bench::testing {

// Counter values of one benchmark run, by counter name.
using Counters = std::map<std::string, double>;

// Keeps each run's counters under its name (suffixes such as /manual_time
// included), and prints nothing.
class CounterCapture : public benchmark::BenchmarkReporter {
 public:
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      Counters& counters = by_name[run.benchmark_name()];
      for (const auto& [name, counter] : run.counters) counters[name] = counter.value;
      if (run.error_occurred) errors.push_back(run.benchmark_name());
    }
  }

  std::map<std::string, Counters> by_name;
  std::vector<std::string> errors;
};

// Runs the registered benchmarks whose names match `filter` (a regular
// expression, as --benchmark_filter takes it).
inline CounterCapture run_benchmarks(const std::string& filter) {
  CounterCapture capture;
  benchmark::RunSpecifiedBenchmarks(&capture, filter);
  return capture;
}

}  // namespace tetsmooth::bench::testing
