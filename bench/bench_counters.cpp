#include "bench/bench_counters.hpp"

#include <algorithm>
#include <map>
#include <string>

namespace tetsmooth::bench {

double bytes_per_sweep(const SweepFootprint& f) {
  const double coords =
      (1.0 + f.written_share) * 3.0 * static_cast<double>(f.nodes) * static_cast<double>(f.real_bytes);
  const double neighbours =
      4.0 * static_cast<double>(f.movable_nodes + 1) + 4.0 * static_cast<double>(f.neighbour_entries);
  const double flags = static_cast<double>(f.nodes);
  const double star_bytes = 4.0 * static_cast<double>(f.movable_nodes + 1) + 4.0 * static_cast<double>(f.incidence_entries) +
                            16.0 * static_cast<double>(f.tets);
  const double stars = f.stars ? star_bytes : 0.0;
  return coords + flags + f.evaluated_share * (neighbours + stars);
}

std::map<std::string, double> run_counter_values(const SmoothResult& r, const SweepFootprint& f) {
  std::map<std::string, double> c;
  std::int64_t accepted = 0;
  for (auto a : r.accepted_per_sweep) accepted += a;
  const double smooth_s = r.smoothing_ms / 1000.0;
  c["sweeps"] = r.sweeps;
  c["accepted"] = static_cast<double>(accepted);
  c["topology_ms"] = r.topology_ms;
  c["colouring_ms"] = r.colouring_ms;
  c["smoothing_ms"] = r.smoothing_ms;
  c["colours"] = r.num_colours;
  c["movable"] = static_cast<double>(r.movable_nodes);
  c["nodes"] = static_cast<double>(f.nodes);
  c["tets"] = static_cast<double>(f.tets);
  c["reverted"] = static_cast<double>(r.reverted_moves);
  c["evaluations"] = static_cast<double>(r.evaluations);
  // Where a coloured run's time goes, class by class (plots/make_tables.py
  // turns these into colours.csv).
  for (std::size_t k = 0; k < r.colour_sizes.size(); ++k)
    c["colour_nodes_" + std::to_string(k)] = static_cast<double>(r.colour_sizes[k]);
  for (std::size_t k = 0; k < r.colour_ms.size(); ++k) c["colour_ms_" + std::to_string(k)] = r.colour_ms[k];
  if (r.sweeps > 0 && smooth_s > 0) {
    const double full = static_cast<double>(r.movable_nodes) * r.sweeps;
    SweepFootprint g = f;
    g.evaluated_share = full > 0 ? std::min(1.0, static_cast<double>(r.evaluations) / full) : 1.0;
    const double written = static_cast<double>(f.nodes) * r.sweeps;
    if (f.in_place) g.written_share = written > 0 ? std::min(1.0, static_cast<double>(accepted) / written) : 0.0;
    c["ms_per_sweep"] = r.smoothing_ms / r.sweeps;
    c["node_updates_per_s"] = static_cast<double>(r.evaluations) / smooth_s;
    c["bytes_per_s"] = bytes_per_sweep(g) * r.sweeps / smooth_s;
  }
  return c;
}

std::map<std::string, double> phase_counter_values(const SmoothResult& phased) {
  std::map<std::string, double> c;
  if (phased.sweeps <= 0 || phased.phase_ms.empty()) return c;
  c["phase_run_sweeps"] = phased.sweeps;
  c["phase_run_ms_per_sweep"] = phased.smoothing_ms / phased.sweeps;
  double kernels = 0;
  for (const auto& [kernel, ms] : phased.phase_ms) {
    c["phase_ms_per_sweep_" + kernel] = ms / phased.sweeps;
    kernels += ms;
  }
  c["phase_run_rest_ms_per_sweep"] = (phased.smoothing_ms - kernels) / phased.sweeps;
  return c;
}

void set_run_counters(benchmark::State& state, const SmoothResult& r, const SweepFootprint& f) {
  for (const auto& [name, value] : run_counter_values(r, f)) state.counters[name] = value;
}

void set_quality_counters(benchmark::State& state, const QualitySummary& before, const QualitySummary& after) {
  state.counters["q_min_before"] = before.min;
  state.counters["q_min_after"] = after.min;
  state.counters["q_mean_before"] = before.mean;
  state.counters["q_mean_after"] = after.mean;
  state.counters["low_q_before"] = static_cast<double>(before.below_0_1);
  state.counters["low_q_after"] = static_cast<double>(after.below_0_1);
  state.counters["inverted_before"] = static_cast<double>(before.inverted);
  state.counters["inverted_after"] = static_cast<double>(after.inverted);
  for (int k = 0; k < 10; ++k) {
    state.counters["hist_before_" + std::to_string(k)] = static_cast<double>(before.histogram[k]);
    state.counters["hist_after_" + std::to_string(k)] = static_cast<double>(after.histogram[k]);
  }
}

}  // namespace tetsmooth::bench
