#pragma once
// The whole GPU pipeline on a mesh that stays on the device: topology,
// colouring and smoothing to convergence, timed with CUDA events. Used by
// smooth_cuda() and by bench_smooth, which restores the input coordinates
// before every timed run. Plain C++: callers need no CUDA headers.
#include <memory>
#include <string>
#include <vector>

#include "kernels/smooth_options.hpp"
#include "mesh/colouring.hpp"
#include "mesh/topology.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::cuda {

struct DeviceInfo {
  std::string name;
  int sm_count = 0;
  int cc_major = 0, cc_minor = 0;
  int runtime_version = 0, driver_version = 0;
  std::size_t memory_bytes = 0;
};

// Throws DeviceError when no device is usable.
DeviceInfo device_info();

struct GpuRunTimes {
  double topology_ms = 0, colouring_ms = 0, smoothing_ms = 0, total_ms = 0;
  int launches = 0;        // kernel launches issued by the smoothing phase
  int host_checks = 0;     // times the host read the stop flag back
  int lanes_per_node = 0;  // threads per node of the sweep kernel (0 for SingleBlock)
};

class GpuPipeline {
 public:
  // Uploads tets, fixed flags and the input coordinates (kept as the
  // restore point). Throws DeviceError on failure (out of memory included).
  explicit GpuPipeline(const TetMesh& mesh);
  ~GpuPipeline();
  GpuPipeline(const GpuPipeline&) = delete;
  GpuPipeline& operator=(const GpuPipeline&) = delete;

  // Converts the stored input into the working coordinates of `options`
  // (precision and layout). Not part of the timed pipeline.
  void restore_coordinates(const SmoothOptions& options);

  // Runs topology + colouring + smoothing on the working coordinates; the
  // result has sweeps, per-sweep counters, stop reason and phase times
  // (quality summaries are left for the caller). `colouring` replaces the
  // device colouring (tests use the CPU one); it must fit the mesh
  // (colouring_flaw, which smooth_cuda checks on the host topology), since
  // every node its classes list may move. Synchronises at the end. Throws
  // UsageError before any restore_coordinates(); a run that throws part way
  // keeps the sweeps it made for download_xyz() and the next run().
  SmoothResult run(const SmoothOptions& options, const Colouring* colouring = nullptr);

  const GpuRunTimes& last_times() const;

  // The working coordinates as double AoS (3 per node), in mesh units; a
  // node the run left where it was loaded keeps its input value exactly,
  // in float too (so a run of no sweeps gives the input back).
  std::vector<double> download_xyz() const;

  // After run(): how many nodes that never move (boundary, pinned, in no
  // tet) the run did not leave where restore_coordinates loaded them, in
  // the working coordinates themselves (download_xyz writes back movable nodes
  // only, so it cannot show this). 0 unless a kernel is wrong; for tests.
  std::size_t fixed_nodes_moved() const;

  // After run(): the movable nodes' rows of the device topology (for the
  // benchmarks' memory floor).
  MovableRows movable_rows() const;

  std::size_t num_nodes() const;
  std::size_t num_tets() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Device-to-device copy bandwidth in bytes/s (read + write counted) on a
// buffer of `bytes`, the memory ceiling the benchmarks compare against.
double measure_copy_bandwidth(std::size_t bytes, int repetitions = 20);

}  // namespace tetsmooth::cuda
