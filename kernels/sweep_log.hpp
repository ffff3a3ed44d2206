#pragma once
// Bookkeeping shared by every backend's sweep loop: records each sweep,
// applies the one stopping rule (node_update.hpp: sweep_verdict) and calls
// the progress callback.
#include <functional>

#include "kernels/node_update.hpp"
#include "kernels/smooth_options.hpp"

namespace tetsmooth {

// Throws UsageError for options no backend accepts.
void check_smooth_options(const SmoothOptions& opt);

// The CUDA backend keeps two 8-byte counters on the device for every sweep
// a run may take (the loops that run on the device write one a sweep, and
// the host reads them at the end), allocated before the run: so a GPU run
// takes at most this many sweeps (16 MB), whatever the mesh.
inline constexpr int kMaxGpuSweeps = 1000000;

// UsageError when opt asks the GPU for more sweeps than kMaxGpuSweeps.
void check_gpu_sweeps(const SmoothOptions& opt);

// UsageError for the Coloured strategy in Form A: colouring makes in-place
// updates race-free, and Form A, which writes another buffer, has no race
// to remove. (The CPU has no strategies; it colours Form B by --threads.)
void check_gpu_strategy(const SmoothOptions& opt);

StopReason to_stop_reason(SweepVerdict v);

class SweepLog {
 public:
  SweepLog(SmoothResult& result, const SmoothOptions& opt, double tol_abs);
  bool wants_another_sweep() const { return result_.stop == StopReason::NotStarted; }
  // `quality` is SweepProgress::quality for this sweep.
  void record(std::int64_t accepted, double max_displacement, std::function<MinMeanQuality()> quality);

 private:
  SmoothResult& result_;
  const SmoothOptions& opt_;
  double tol_abs_;
};

}  // namespace tetsmooth
