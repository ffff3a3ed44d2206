#pragma once
// The host side of the sweep loop: launches sweeps per strategy and reads
// the device's stop flag every `check_every` sweeps; Coloured runs the whole
// loop in one cooperative launch (coloured_loop_kernel.cuh).
#include <cuda_runtime.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "kernels/cuda/sweep_state.cuh"
#include "kernels/node_update.hpp"
#include "kernels/smooth_options.hpp"

namespace tetsmooth::cuda {

struct SweepLoopArgs {
  MeshView view;
  index_t n = 0, num_tets = 0;
  const std::uint8_t* movable = nullptr;
  void* buf0 = nullptr;  // working coordinates (3 * n Real), both layouts
  void* buf1 = nullptr;  // Form A's second buffer
  void* old_min = nullptr;  // n Real
  std::uint8_t* moved = nullptr;
  std::uint8_t* revert = nullptr;
  SweepState* state = nullptr;
  SweepState* host_state = nullptr;  // pinned
  SweepCounters counters{};
  const index_t* class_nodes = nullptr;
  const index_t* class_off = nullptr;  // device, num_colours + 1
  int num_colours = 0;
  index_t largest_class = 0;
  void* tet_quality = nullptr;  // MultiBlock and Coloured: num_tets Real
  std::uint8_t* changed = nullptr;  // Coloured: n (coloured_loop_kernel.cuh)
  cudaStream_t stream = nullptr;
  double unit = 1;  // mesh units per working unit: float works in the unit box around the mesh
};

// Form A alternates its two buffers: after `sweeps` sweeps its latest
// positions are in buf1 when the count is odd. Form B works in buf0.
inline bool latest_in_buf1(Form form, int sweeps) { return form == Form::A && (sweeps & 1); }

// Sweeps [first, last) of the device's per-sweep counters: each one's
// accepted moves, and its largest move in mesh units (the working units'
// times `unit`). Synchronous; a host check reads only the sweeps it has not
// reported yet.
struct SweepCount {
  std::int64_t accepted = 0;
  double max_displacement = 0;
};
std::vector<SweepCount> read_sweep_counts(const SweepCounters& counters, int first, int last, double unit);

struct SweepLoopStats {
  int launches = 0;
  int host_checks = 0;
  int lanes_per_node = 0;  // threads per node of the sweep kernel
  std::vector<std::pair<std::string, double>> phase_ms;  // SmoothResult::phase_ms
};

// Runs sweeps until the device says stop; Real is float or double.
template <class Real>
SweepLoopStats run_sweep_loop(const SweepLoopArgs& args, const SmoothOptions& options);

// Loads the input (double AoS) into a working buffer, in the frame
// x_working = (x - centre) / scale (coords_transfer_kernels.cuh), and back:
// store_movable_coords writes into `out`, which holds the input, the
// movable nodes whose working position is not the one they were loaded at.
template <class Real>
void load_working_coords(const double* input, void* buf, index_t n, Layout layout, const double centre[3],
                         double scale, cudaStream_t stream);
template <class Real>
void store_movable_coords(const void* buf, const double* input, double* out, const std::uint8_t* movable, index_t n,
                          Layout layout, const double centre[3], double scale, cudaStream_t stream);
// How many nodes that never move are not where they were loaded; adds
// them to *count.
template <class Real>
void count_moved_fixed(const void* working, const double* input, const std::uint8_t* movable, index_t n, Layout layout,
                       const double centre[3], double scale, unsigned long long* count, cudaStream_t stream);
template <class Real>
void sum_edge_lengths(const MeshView& view, const void* buf, index_t n, Layout layout, SweepState* state,
                      cudaStream_t stream);

}  // namespace tetsmooth::cuda
