// bench_smooth: the study of the paper's Tables 3-6 and Figures 9-13.
// Our own flags (bench/bench_flags.hpp, listed by --help) come out of argv
// first; Google Benchmark parses the rest.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "bench/bench_flags.hpp"
#include "bench/bench_registry.hpp"
#include "bench/command_line.hpp"
#include "bench/git_sha.hpp"
#include "mesh/errors.hpp"

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--help") == 0) std::fputs(tetsmooth::bench::own_flags_help(), stdout);
  // Taken before either parser removes the flags it knows.
  const std::string command = tetsmooth::bench::command_line(argc, argv);
  try {
    const tetsmooth::bench::BenchConfig config = tetsmooth::bench::take_own_flags(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    const char* sha = std::getenv("TETSMOOTH_GIT_SHA");
    benchmark::AddCustomContext("git_sha", sha && *sha ? sha : TETSMOOTH_GIT_SHA);
    benchmark::AddCustomContext("command_line", command);
    char host[256] = {0};
    if (gethostname(host, sizeof host - 1) == 0) benchmark::AddCustomContext("host_name", host);
    for (const auto& [key, value] : tetsmooth::bench::register_benchmarks(config))
      benchmark::AddCustomContext(key, value);
    // A filter that matches nothing, or is no regex, is a bad flag, not a
    // run: Google Benchmark says which above and writes an empty --benchmark_out.
    if (benchmark::RunSpecifiedBenchmarks() == 0)
      throw tetsmooth::UsageError("--benchmark_filter: no benchmark selected (--benchmark_list_tests=true lists them)");
    benchmark::Shutdown();
  } catch (const tetsmooth::UsageError& e) {
    std::fprintf(stderr, "bench_smooth: error: %s (see --help)\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_smooth: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
