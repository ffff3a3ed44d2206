#pragma once
// Counters that carry the physics of a run into the benchmark JSON.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "kernels/smooth_options.hpp"
#include "mesh/csr.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::bench {

// Sizes a sweep's memory traffic is counted from.
struct SweepFootprint {
  std::size_t nodes = 0, tets = 0;
  // The movable nodes and their rows (movable_rows in mesh/topology.hpp):
  // a sweep evaluates no other node, so reads no other row.
  std::size_t movable_nodes = 0, neighbour_entries = 0, incidence_entries = 0;
  std::size_t real_bytes = 8;  // sizeof(Real) of the coordinates
  double evaluated_share = 1;  // nodes evaluated / (movable nodes x sweeps)
  bool in_place = false;       // Form B: a sweep writes only the nodes it moves
  double written_share = 1;    // nodes written / nodes (in place: moves / (nodes x sweeps))
  bool stars = true;           // false for ordinary Laplacian, which reads no star
};

// The fewest bytes one sweep must move through device memory: every
// coordinate read once; written once where the sweep writes every node (Form
// A fills the other buffer), and only for the nodes it moves where it works
// in place (Form B: written_share); a flag byte per node (which nodes may
// move); and for the share of movable nodes evaluated their neighbour rows
// and stars (neighbour and incidence CSR rows with their offsets, the tets)
// read once: a sweep
// that skips settled nodes (CUDA Coloured) reads neither the row nor the
// star of a skipped node, and ordinary Laplacian smoothing reads no star at
// all.
// Re-reads of neighbour coordinates are not counted: an ideal cache would
// serve them. Nor are a variant's own helpers (the tet quality cache of
// MultiBlock and Coloured, the colour classes): the floor is the smoothing's.
double bytes_per_sweep(const SweepFootprint& f);

// A run's counters by name: sweeps, accepted, evaluations, phase times,
// colour_nodes_k and colour_ms_k per colour class, and once a sweep has run
// ms per sweep, node updates (evaluations) per second and bytes/s (the
// footprint of bytes_per_sweep, its evaluated share and, in place, its
// written share taken from the run).
std::map<std::string, double> run_counter_values(const SmoothResult& r, const SweepFootprint& f);

// The counters of a run taken with SmoothOptions::time_phases, beside the
// timed ones: phase_run_sweeps, phase_run_ms_per_sweep (that run's
// smoothing phase, events included), phase_ms_per_sweep_<kernel> for each
// of its SmoothResult::phase_ms, and phase_run_rest_ms_per_sweep, what the
// kernels leave of that run's smoothing phase (host checks, set-up), taken
// within the run so that its median over repetitions is a run's. Empty when
// it timed no phase or ran no sweep.
std::map<std::string, double> phase_counter_values(const SmoothResult& phased);

// Puts run_counter_values into the benchmark's counters.
void set_run_counters(benchmark::State& state, const SmoothResult& r, const SweepFootprint& f);

// Quality before and after: min, mean, q < 0.1, inverted, 10-bin histograms.
void set_quality_counters(benchmark::State& state, const QualitySummary& before, const QualitySummary& after);

}  // namespace tetsmooth::bench
