// The CPU smoother: the serial reference (threads == 1) and its OpenMP
// version, around the shared per-node math of kernels/node_update.hpp.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

#include "kernels/cpu/jacobi_repair.hpp"
#include "kernels/node_update.hpp"
#include "kernels/smoother.hpp"
#include "kernels/sweep_log.hpp"
#include "mesh/errors.hpp"
#include "mesh/team_size.hpp"
#include "mesh/topology.hpp"

namespace tetsmooth {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

struct SweepStats {
  std::int64_t accepted = 0;
  double max_disp2 = 0;
};

// Form B in place over `nodes` (one colour class, or all nodes in natural
// order when threads == 1). Nodes of one colour share no tet, so running
// them in parallel reads and writes nothing another thread touches.
template <bool kAdaptive>
SweepStats sweep_in_place(const MeshView& view, AosCoords<double> xyz, const index_t* nodes, std::size_t count,
                          const std::vector<std::uint8_t>& movable, int threads) {
  std::int64_t accepted = 0;
  double max_disp2 = 0;
#pragma omp parallel for num_threads(threads) if (threads > 1) schedule(static) reduction(+ : accepted) \
    reduction(max : max_disp2)
  for (std::size_t k = 0; k < count; ++k) {
    const index_t i = nodes[k];
    if (!movable[i]) continue;
    const NodeMove<double> mv = evaluate_node<double, kAdaptive>(view, xyz, i);
    if (takes_move(mv)) {
      xyz.set(i, mv.target);
      ++accepted;
      max_disp2 = std::max(max_disp2, mv.displacement2);
    }
  }
  return {accepted, max_disp2};
}

// Form A (Jacobi): every candidate is computed from `prev`; moves land in
// `next`. Adaptive moves then go through the conflict repair (jacobi_repair.hpp).
template <bool kAdaptive>
SweepStats sweep_jacobi(const MeshView& view, const std::vector<double>& prev, std::vector<double>& next,
                        std::size_t num_tets, const std::vector<std::uint8_t>& movable, std::vector<std::uint8_t>& moved,
                        std::vector<std::uint8_t>& revert, std::vector<double>& old_min, std::int64_t& reverted_total,
                        int threads) {
  const AosCoords<double> from{const_cast<double*>(prev.data())};
  const AosCoords<double> to{next.data()};
  const index_t n = static_cast<index_t>(movable.size());
  std::memcpy(next.data(), prev.data(), prev.size() * sizeof(double));
#pragma omp parallel for num_threads(threads) if (threads > 1) schedule(static)
  for (index_t i = 0; i < n; ++i) {
    moved[i] = 0;
    if (!movable[i]) continue;
    const NodeMove<double> mv = evaluate_node<double, kAdaptive>(view, from, i);
    if (takes_move(mv)) {
      to.set(i, mv.target);
      moved[i] = 1;
      old_min[i] = mv.old_min;
    }
  }
  if (kAdaptive)
    reverted_total += repair_jacobi_conflicts(view, num_tets, n, from, to, moved.data(), revert.data(), old_min.data(),
                                              threads);
  std::int64_t accepted = 0;
  double max_disp2 = 0;
#pragma omp parallel for num_threads(threads) if (threads > 1) schedule(static) reduction(+ : accepted) \
    reduction(max : max_disp2)
  for (index_t i = 0; i < n; ++i) {
    if (!moved[i]) continue;
    ++accepted;
    max_disp2 = std::max(max_disp2, surviving_disp2(i, from, to, moved.data()));
  }
  return {accepted, max_disp2};
}

template <bool kAdaptive>
void run_sweeps(TetMesh& mesh, const Topology& topo, const Colouring* colouring, const SmoothOptions& opt,
                int threads, double tol_abs, SmoothResult& result) {
  const MeshView view = host_view(mesh, topo);
  std::vector<index_t> natural;
  std::vector<double> other, old_min;
  std::vector<std::uint8_t> moved, revert;  // Form A: this sweep's movers, and those to put back
  if (opt.form == Form::A) {
    other.resize(mesh.xyz.size());
    old_min.resize(mesh.num_nodes());
    moved.resize(mesh.num_nodes());
    revert.assign(mesh.num_nodes(), 0);
  } else if (!colouring) {
    natural.resize(mesh.num_nodes());
    for (std::size_t i = 0; i < natural.size(); ++i) natural[i] = static_cast<index_t>(i);
  }
  SweepLog log(result, opt, tol_abs);
  while (log.wants_another_sweep()) {
    SweepStats s;
    if (opt.form == Form::A) {
      s = sweep_jacobi<kAdaptive>(view, mesh.xyz, other, mesh.num_tets(), topo.movable, moved, revert, old_min,
                                  result.reverted_moves, threads);
      mesh.xyz.swap(other);
    } else if (colouring) {
      for (int c = 0; c < colouring->num_colours; ++c) {
        const SweepStats sc =
            sweep_in_place<kAdaptive>(view, AosCoords<double>{mesh.xyz.data()}, colouring->classes.row_begin(c),
                                      colouring->classes.row_size(c), topo.movable, threads);
        s.accepted += sc.accepted;
        s.max_disp2 = std::max(s.max_disp2, sc.max_disp2);
      }
    } else {
      s = sweep_in_place<kAdaptive>(view, AosCoords<double>{mesh.xyz.data()}, natural.data(), natural.size(),
                                    topo.movable, 1);
    }
    log.record(s.accepted, std::sqrt(s.max_disp2), [&mesh, threads] { return min_mean_quality(mesh, threads); });
  }
}

}  // namespace

SmoothResult smooth_cpu(TetMesh& mesh, const SmoothOptions& opt, const Colouring* given) {
  check_smooth_options(opt);
  const int threads = team_size(opt.threads);
  SmoothResult result;
  result.backend = threads == 1 ? "cpu-serial" : "cpu-threads";

  auto t0 = Clock::now();
  const Topology topo = build_topology(mesh, threads);
  result.topology_ms = ms_since(t0);
  result.movable_nodes = static_cast<std::size_t>(std::count(topo.movable.begin(), topo.movable.end(), 1));
  result.before = summarize_quality(mesh, topo.movable);

  // Form B in parallel is only race-free colour by colour.
  const bool coloured = opt.form == Form::B && (threads > 1 || opt.ordering == Ordering::Coloured);
  Colouring computed;
  const Colouring* colouring = nullptr;
  if (coloured) {
    t0 = Clock::now();
    if (given) {
      const std::string flaw = colouring_flaw(topo.neighbours, topo.movable, *given);
      if (!flaw.empty()) throw UsageError("the colouring given to smooth_cpu does not fit this mesh: " + flaw);
      colouring = given;
    } else {
      computed = colour_nodes(topo.neighbours, topo.movable, threads);
      colouring = &computed;
    }
    result.num_colours = colouring->num_colours;
    for (int c = 0; c < colouring->num_colours; ++c) result.colour_sizes.push_back(colouring->classes.row_size(c));
    result.colouring_ms = ms_since(t0);
  }

  result.mean_edge_length = mean_edge_length(mesh.xyz, topo.neighbours);
  const double tol_abs = opt.tolerance * result.mean_edge_length;
  t0 = Clock::now();
  if (opt.method == Method::Adaptive)
    run_sweeps<true>(mesh, topo, colouring, opt, threads, tol_abs, result);
  else
    run_sweeps<false>(mesh, topo, colouring, opt, threads, tol_abs, result);
  result.smoothing_ms = ms_since(t0);
  result.evaluations = static_cast<std::int64_t>(result.movable_nodes) * result.sweeps;
  result.after = summarize_quality(mesh, topo.movable);
  return result;
}

}  // namespace tetsmooth
