// The CPU families bench_smooth registers, run in-process on a small mesh:
// their byte counts must match the arrays each method reads, counted here
// from the tets without the library's topology.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "bench/bench_registry.hpp"
#include "mesh/io/tsm_cache.hpp"
#include "run_counters.hpp"
#include "scratch_dir.hpp"
#include "test_meshes.hpp"

namespace tetsmooth::bench {
namespace {

namespace fs = std::filesystem;

// What a sweep reads, counted from the tets alone: a node is movable when no
// boundary face (a face of one tet only) holds it; its neighbour row lists
// the other nodes of its tets once each, its incidence row its tets.
struct HandCount {
  double nodes = 0, tets = 0, movable = 0, neighbour_entries = 0, incidence_entries = 0;
};

HandCount count_by_hand(const TetMesh& m) {
  const std::size_t n = m.num_nodes();
  std::map<std::array<index_t, 3>, int> faces;
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<index_t, 3> f{};
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != skip) f[j++] = m.tets[4 * t + k];
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  std::vector<bool> boundary(n, false);
  for (const auto& [f, count] : faces)
    if (count == 1)
      for (index_t v : f) boundary[v] = true;
  std::vector<std::set<index_t>> neighbours(n);
  std::vector<int> incident(n, 0);
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (int a = 0; a < 4; ++a) {
      ++incident[m.tets[4 * t + a]];
      for (int b = 0; b < 4; ++b)
        if (b != a) neighbours[m.tets[4 * t + a]].insert(m.tets[4 * t + b]);
    }
  HandCount c;
  c.nodes = static_cast<double>(n);
  c.tets = static_cast<double>(m.num_tets());
  for (std::size_t i = 0; i < n; ++i)
    if (!boundary[i]) {
      ++c.movable;
      c.neighbour_entries += static_cast<double>(neighbours[i].size());
      c.incidence_entries += incident[i];
    }
  return c;
}

// The fewest bytes a sweep of this run moves (bench_counters.hpp): the
// coordinates read, and written (all of them, or in place only the moved
// ones), a flag byte a node, and for the evaluated share of the movable
// nodes their neighbour rows; with `stars`, their incidence rows and tets.
double floor_bytes(const HandCount& k, const testing::Counters& c, bool stars, bool in_place) {
  const double sweeps = c.at("sweeps");
  const double evaluated = std::min(1.0, c.at("evaluations") / (k.movable * sweeps));
  const double written = in_place ? std::min(1.0, c.at("accepted") / (k.nodes * sweeps)) : 1.0;
  const double rows = 4 * (k.movable + 1) + 4 * k.neighbour_entries;
  const double star = 4 * (k.movable + 1) + 4 * k.incidence_entries + 16 * k.tets;
  return (1 + written) * 3 * k.nodes * 8 + k.nodes + evaluated * (rows + (stars ? star : 0));
}

// The bytes a sweep was counted at: bytes_per_s is bytes per sweep x sweeps
// over the smoothing time, so this undoes that division (no timing is
// judged, the time only cancels).
double counted_bytes_per_sweep(const testing::Counters& c) {
  return c.at("bytes_per_s") * (c.at("smoothing_ms") / 1000.0) / c.at("sweeps");
}

// The cache folder holds a jittered 4^3 grid under the 5k model's file
// name, so the families load it instead of generating the model.
class BenchRegistry : public ::testing::Test {
 protected:
  void SetUp() override {
    mesh_ = tetsmooth::testing::cube_grid(4, 0.2);
    write_cache_file(mesh_, (dir_ / "5k-seed1.tsm").string());
    ::setenv("TETSMOOTH_MESH_CACHE", dir_.c_str(), 1);
  }
  void TearDown() override { ::unsetenv("TETSMOOTH_MESH_CACHE"); }

  tetsmooth::testing::ScratchDir scratch_{"bench_registry"};
  const fs::path dir_ = scratch_.path();
  TetMesh mesh_;
};

// Ordinary Laplacian smoothing moves a node to its neighbours' centroid
// without judging its star, so its floor has no incidence rows and no tets;
// the adaptive method reads both. Form A writes every node, Form B (the
// ordinary run too) only the ones it moves.
TEST_F(BenchRegistry, CpuFamiliesCountTheArraysTheirMethodReads) {
  // A millisecond of minimum time rather than half a second: the counters
  // come from the last iteration whatever their number, and no time is judged.
  int argc = 2;
  char name[] = "test_bench_registry", min_time[] = "--benchmark_min_time=0.001";
  char* argv[] = {name, min_time, nullptr};
  benchmark::Initialize(&argc, argv);

  BenchConfig config;
  config.models = {"5k"};
  config.gpu = false;
  register_benchmarks(config);
  const testing::CounterCapture run = testing::run_benchmarks("^Serial/(Ordinary|FormA|FormB)/5k");
  EXPECT_TRUE(run.errors.empty());
  ASSERT_EQ(run.by_name.size(), 3u);

  const HandCount k = count_by_hand(mesh_);
  ASSERT_EQ(k.movable, 27);  // the 3^3 interior nodes
  struct Expected {
    const char* family;
    bool stars, in_place;
  };
  for (const Expected& e : {Expected{"Serial/Ordinary/5k", false, true}, Expected{"Serial/FormB/5k", true, true},
                            Expected{"Serial/FormA/5k", true, false}}) {
    const auto found = std::find_if(run.by_name.begin(), run.by_name.end(),
                                     [&](const auto& r) { return r.first.rfind(e.family, 0) == 0; });
    ASSERT_NE(found, run.by_name.end()) << e.family;
    const testing::Counters& c = found->second;
    EXPECT_EQ(c.at("nodes"), k.nodes) << e.family;
    EXPECT_EQ(c.at("tets"), k.tets) << e.family;
    EXPECT_EQ(c.at("movable"), k.movable) << e.family;
    ASSERT_GT(c.at("sweeps"), 0) << e.family;
    ASSERT_GT(c.count("bytes_per_s"), 0u) << e.family << ": no rate (no smoothing time?)";
    const double expected = floor_bytes(k, c, e.stars, e.in_place);
    EXPECT_NEAR(counted_bytes_per_sweep(c), expected, 1e-9 * expected) << e.family;  // rounding of the division only
  }
}

}  // namespace
}  // namespace tetsmooth::bench
