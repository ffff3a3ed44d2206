// Form A's conflict repair on the CPU (kernels/cpu/jacobi_repair.hpp): at
// the production pass limit it is the smoother's own repair, and a conflict
// still found by the last pass undoes the whole sweep. The meshes a test can
// build settle their conflicts in a few passes, far from kMaxRepairPasses,
// so the undo is reached by a shorter limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "kernels/cpu/jacobi_repair.hpp"
#include "kernels/node_update.hpp"
#include "kernels/smoother.hpp"
#include "mesh/topology.hpp"
#include "test_meshes.hpp"

namespace tetsmooth {
namespace {

// A Jacobi sweep before its repair: every movable node's adaptive move,
// judged from `before`, made in `after`.
struct JacobiSweep {
  std::vector<double> before, after, old_min;
  std::vector<std::uint8_t> moved, revert;
  std::int64_t movers = 0;
};

JacobiSweep unrepaired_sweep(const TetMesh& mesh, const Topology& topo) {
  JacobiSweep s;
  s.before = s.after = mesh.xyz;
  s.old_min.assign(mesh.num_nodes(), 0);
  s.moved.assign(mesh.num_nodes(), 0);
  s.revert.assign(mesh.num_nodes(), 0);
  const MeshView view = host_view(mesh, topo);
  const AosCoords<double> from{s.before.data()}, to{s.after.data()};
  for (index_t i = 0; i < static_cast<index_t>(mesh.num_nodes()); ++i) {
    if (!topo.movable[i]) continue;
    const NodeMove<double> mv = evaluate_node<double, true>(view, from, i);
    if (!takes_move(mv)) continue;
    to.set(i, mv.target);
    s.moved[i] = 1;
    s.old_min[i] = mv.old_min;
    ++s.movers;
  }
  return s;
}

std::int64_t repair(const TetMesh& mesh, const Topology& topo, JacobiSweep& s, int threads, int max_passes) {
  return repair_jacobi_conflicts(host_view(mesh, topo), mesh.num_tets(), static_cast<index_t>(mesh.num_nodes()),
                                 AosCoords<double>{s.before.data()}, AosCoords<double>{s.after.data()},
                                 s.moved.data(), s.revert.data(), s.old_min.data(), threads, max_passes);
}

std::int64_t tets_in_conflict(const TetMesh& mesh, const JacobiSweep& s) {
  std::int64_t n = 0;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    n += tet_rejects_movers(mesh.tets.data() + 4 * t, AosCoords<double>{const_cast<double*>(s.before.data())},
                            AosCoords<double>{const_cast<double*>(s.after.data())}, s.moved.data(),
                            s.old_min.data());
  return n;
}

// Every other node pushed through its neighbours: the first sweep's
// conflicts take 6 repair passes to settle, within kMaxRepairPasses.
const TetMesh& conflicted_mesh() {
  static const TetMesh mesh = testing::pushed_cube_grid(7, 0.2, 3, 2, 1.5);
  return mesh;
}

// At the production limit the repair leaves what a smoothing sweep leaves:
// it is the smoother's repair, and it settles this mesh without undoing.
TEST(JacobiRepair, ProductionLimitIsTheSmoothersSweep) {
  const TetMesh& mesh = conflicted_mesh();
  const Topology topo = build_topology(mesh);
  for (int threads : {1, 2}) {
    JacobiSweep s = unrepaired_sweep(mesh, topo);
    ASSERT_GT(tets_in_conflict(mesh, s), 0);
    const std::int64_t reverted = repair(mesh, topo, s, threads, kMaxRepairPasses);
    TetMesh swept = mesh;
    SmoothOptions o;
    o.form = Form::A;
    o.threads = threads;
    o.max_iterations = 1;
    const SmoothResult r = smooth_cpu(swept, o);
    EXPECT_EQ(s.after, swept.xyz) << threads << " threads";
    EXPECT_EQ(reverted, r.reverted_moves);
    EXPECT_GT(reverted, 0);
    EXPECT_LT(reverted, s.movers);
    EXPECT_EQ(tets_in_conflict(mesh, s), 0);
    EXPECT_EQ(std::count(s.revert.begin(), s.revert.end(), 1), 0) << "flags left set";
  }
}

// With a limit of m passes, a sweep whose conflicts take k passes to settle
// (the k-th reverts the last movers; pass k finds none) is undone whole when
// m <= k, and is the production result when m > k. Each mover is put back
// once, and no flag is left set.
TEST(JacobiRepair, ConflictFoundByTheLastPassUndoesTheSweep) {
  const TetMesh& mesh = conflicted_mesh();
  const Topology topo = build_topology(mesh);
  for (int threads : {1, 2}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    JacobiSweep settled = unrepaired_sweep(mesh, topo);
    repair(mesh, topo, settled, threads, kMaxRepairPasses);
    int undone_limits = 0;
    bool settled_before = false;
    for (int max_passes = 1; max_passes <= kMaxRepairPasses; ++max_passes) {
      JacobiSweep s = unrepaired_sweep(mesh, topo);
      const std::int64_t reverted = repair(mesh, topo, s, threads, max_passes);
      EXPECT_EQ(std::count(s.revert.begin(), s.revert.end(), 1), 0) << "flags left set, limit " << max_passes;
      if (s.after == s.before) {
        EXPECT_FALSE(settled_before) << "undone at limit " << max_passes << " after settling at a lower one";
        EXPECT_EQ(reverted, s.movers) << "limit " << max_passes;
        EXPECT_EQ(std::count(s.moved.begin(), s.moved.end(), 1), 0);
        ++undone_limits;
      } else {
        EXPECT_EQ(s.after, settled.after) << "limit " << max_passes;
        EXPECT_EQ(s.moved, settled.moved) << "limit " << max_passes;
        settled_before = true;
      }
    }
    // Undone at limits past 1: the last pass undoes a sweep that earlier
    // passes had partly reverted by their flags.
    EXPECT_GE(undone_limits, 2);
    EXPECT_TRUE(settled_before) << "the production limit must settle this mesh";
    std::printf("%d threads: undone at limits 1 to %d of %d\n", threads, undone_limits, kMaxRepairPasses);
  }
}

}  // namespace
}  // namespace tetsmooth
