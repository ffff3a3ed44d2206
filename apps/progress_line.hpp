#pragma once
// A one-line progress display for long smoothing runs, redrawn in place with
// '\r' on a terminal. It stays silent for short runs and when stderr is not
// a terminal (logs and pipes would fill up with redraws).
#include <chrono>
#include <ostream>

#include "kernels/smooth_options.hpp"

namespace tetsmooth::cli {

class ProgressLine {
 public:
  using Clock = std::chrono::steady_clock;

  // Draws only when `enabled`, not before `delay` has passed since
  // construction, and at most every `interval`.
  ProgressLine(std::ostream& os, bool enabled, int max_sweeps, Clock::duration delay = std::chrono::milliseconds(500),
               Clock::duration interval = std::chrono::milliseconds(100));

  void update(const SweepProgress& progress);
  // Erases the line if one was drawn, so the report starts on a clean line.
  void finish();

 private:
  std::ostream& os_;
  bool enabled_;
  int max_sweeps_;
  Clock::time_point start_, last_draw_;
  Clock::duration delay_, interval_;
  std::size_t drawn_width_ = 0;
};

}  // namespace tetsmooth::cli
