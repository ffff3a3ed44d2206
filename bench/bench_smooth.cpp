// bench_smooth: the study of the paper's Tables 3-6 and Figures 9-13.
// Own flags (before Google Benchmark's): --models=5k,10k,59k,77k,109k
// --scaling=lattice-215 --precision=double|float --coloured-lanes=0|8|16|32
// --no-cpu --no-gpu.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <unistd.h>

#include "bench/bench_registry.hpp"
#include "mesh/errors.hpp"

namespace {

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// Takes our flags out of argv so Google Benchmark sees only its own.
tetsmooth::bench::BenchConfig take_own_flags(int& argc, char** argv) {
  tetsmooth::bench::BenchConfig c;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* prefix) { return a.substr(std::strlen(prefix)); };
    if (a.rfind("--models=", 0) == 0) {
      c.models = split_list(value("--models="));
    } else if (a.rfind("--scaling=", 0) == 0) {
      c.scaling = split_list(value("--scaling="));
    } else if (a == "--precision=float") {
      c.precision = tetsmooth::Precision::Float;
    } else if (a == "--precision=double") {
      c.precision = tetsmooth::Precision::Double;
    } else if (a.rfind("--coloured-lanes=", 0) == 0) {
      c.coloured_lanes = std::stoi(value("--coloured-lanes="));
    } else if (a == "--no-cpu") {
      c.cpu = false;
    } else if (a == "--no-gpu") {
      c.gpu = false;
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const tetsmooth::bench::BenchConfig config = take_own_flags(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    const char* sha = std::getenv("TETSMOOTH_GIT_SHA");
    benchmark::AddCustomContext("git_sha", sha && *sha ? sha : TETSMOOTH_GIT_SHA);
    char host[256] = {0};
    if (gethostname(host, sizeof host - 1) == 0) benchmark::AddCustomContext("host_name", host);
    for (const auto& [key, value] : tetsmooth::bench::register_benchmarks(config))
      benchmark::AddCustomContext(key, value);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_smooth: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
