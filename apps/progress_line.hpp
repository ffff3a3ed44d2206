#pragma once
// A one-line progress display for long smoothing runs, redrawn in place with
// '\r' on a terminal: the sweep, its accepted moves and largest move, and
// the mesh's smallest and mean radius ratio after it. It stays silent for
// short runs and when stderr is not a terminal (logs and pipes would fill up
// with redraws).
#include <chrono>
#include <functional>
#include <ostream>

#include "kernels/smooth_options.hpp"

namespace tetsmooth::cli {

class ProgressLine {
 public:
  using Clock = std::chrono::steady_clock;
  using Now = std::function<Clock::time_point()>;

  // Draws only when `enabled`, not before `delay` has passed since
  // construction, and at most every `interval`, or every kPacing times as
  // long as the last quality pass took where that is longer: the pass reads
  // every tet, so on a large mesh it would otherwise slow the run it reports
  // on (this way by at most about 1 / kPacing). `now` is the clock (tests
  // give their own).
  static constexpr int kPacing = 20;
  // The longest line drawn: one column short of a classic terminal's 80.
  static constexpr std::size_t kWidth = 79;
  ProgressLine(std::ostream& os, bool enabled, int max_sweeps, Clock::duration delay = std::chrono::milliseconds(500),
               Clock::duration interval = std::chrono::milliseconds(100), Now now = Clock::now);

  // Draws reports that carry their quality (SweepProgress::quality) and
  // skips the others, which a later one of the same check supersedes.
  void update(const SweepProgress& progress);
  // Erases the line if one was drawn, so the report starts on a clean line.
  void finish();

 private:
  std::ostream& os_;
  bool enabled_;
  int max_sweeps_;
  Now now_;
  Clock::time_point start_, last_draw_;
  Clock::duration delay_, interval_;
  Clock::duration quality_cost_{};
  std::size_t drawn_width_ = 0;
};

}  // namespace tetsmooth::cli
