#include "kernels/sweep_log.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "mesh/errors.hpp"

namespace tetsmooth {

void check_smooth_options(const SmoothOptions& opt) {
  if (opt.max_iterations < 0) throw UsageError("max iterations must be >= 0, got " + std::to_string(opt.max_iterations));
  if (!(opt.tolerance >= 0) || !std::isfinite(opt.tolerance))
    throw UsageError("tolerance must be a finite number >= 0, got " + std::to_string(opt.tolerance));
  if (opt.threads < 0) throw UsageError("threads must be >= 0 (0 = all cores), got " + std::to_string(opt.threads));
  if (opt.check_every < 1) throw UsageError("check_every must be >= 1");
  if (opt.coloured_lanes != 0 && opt.coloured_lanes != 8 && opt.coloured_lanes != 16 && opt.coloured_lanes != 32)
    throw UsageError("coloured_lanes must be 0 (automatic), 8, 16 or 32");
  if (opt.coloured_blocks < 0)
    throw UsageError("coloured_blocks must be >= 0 (0 = as many as fit), got " + std::to_string(opt.coloured_blocks));
}

void check_gpu_sweeps(const SmoothOptions& opt) {
  if (opt.max_iterations > kMaxGpuSweeps)
    throw UsageError("--max-iter " + std::to_string(opt.max_iterations) + ": a GPU run takes at most " +
                     std::to_string(kMaxGpuSweeps) + " sweeps (it keeps each sweep's counters on the device)");
}

void check_gpu_strategy(const SmoothOptions& opt) {
  if (opt.strategy == Strategy::Coloured && opt.form == Form::A)
    throw UsageError("the coloured strategy is an in-place (Form B) scheme; Form A is already race-free "
                     "(use the multiblock or singleblock strategy with Form A)");
}

StopReason to_stop_reason(SweepVerdict v) {
  switch (v) {
    case SweepVerdict::NoMoves: return StopReason::NoMoves;
    case SweepVerdict::Tolerance: return StopReason::Tolerance;
    case SweepVerdict::MaxIterations: return StopReason::MaxIterations;
    case SweepVerdict::Continue: break;
  }
  return StopReason::NotStarted;
}

SweepLog::SweepLog(SmoothResult& result, const SmoothOptions& opt, double tol_abs)
    : result_(result), opt_(opt), tol_abs_(tol_abs) {
  if (opt.max_iterations == 0) result_.stop = StopReason::MaxIterations;
}

void SweepLog::record(std::int64_t accepted, double max_displacement, std::function<MinMeanQuality()> quality) {
  ++result_.sweeps;
  result_.accepted_per_sweep.push_back(accepted);
  result_.max_displacement_per_sweep.push_back(max_displacement);
  result_.stop = to_stop_reason(sweep_verdict(result_.sweeps, accepted, max_displacement, tol_abs_, opt_.max_iterations));
  if (opt_.progress) opt_.progress(SweepProgress{result_.sweeps, accepted, max_displacement, std::move(quality)});
}

}  // namespace tetsmooth
