#pragma once
// The progress display of long smoothing runs: the sweep, its accepted moves
// and largest move, and the mesh's smallest and mean radius ratio after it.
// On a terminal one line is redrawn in place with '\r'; for a log (a batch
// job's stderr, with --progress always) a line is written now and then. It
// stays silent for short runs.
#include <chrono>
#include <cstddef>
#include <functional>
#include <ostream>

#include "kernels/smooth_options.hpp"

namespace tetsmooth::cli {

// --progress: auto draws on a terminal only (redraws would fill a log),
// always writes log lines where stderr is not a terminal, never is silent.
enum class ProgressMode { Auto, Always, Never };

class ProgressLine {
 public:
  using Clock = std::chrono::steady_clock;
  using Now = std::function<Clock::time_point()>;
  // Off draws nothing; Redraw keeps one line overwritten in place; Lines
  // writes whole lines, for logs.
  enum class Style { Off, Redraw, Lines };

  // The style for `mode` with stderr a terminal or not; -q turns it off.
  static Style style_for(ProgressMode mode, bool terminal, bool quiet);

  // Nothing before this much of the run has passed: short runs stay quiet.
  static constexpr Clock::duration kDelay = std::chrono::milliseconds(500);
  // The least time between draws: a redraw is cheap to overwrite, a log
  // line is not.
  static Clock::duration interval_for(Style style) {
    return style == Style::Lines ? std::chrono::seconds(10) : std::chrono::milliseconds(100);
  }
  // A quality pass reads every tet, so on a large mesh it would slow the run
  // it reports on: draws are also kPacing times as far apart as the last
  // pass took, which keeps the passes to about 1 / kPacing of the run.
  static constexpr int kPacing = 20;
  // The longest line drawn: one column short of a classic terminal's 80,
  // past which a terminal wraps it and '\r' no longer returns to its start.
  static constexpr std::size_t kWidth = 79;

  // Draws in `style`, not before `delay` has passed since construction, and
  // at most every `interval` (or as kPacing asks). `now` is the clock (tests
  // give their own).
  ProgressLine(std::ostream& os, Style style, int max_sweeps, Clock::duration delay, Clock::duration interval,
               Now now = Clock::now);

  // Draws reports that carry their quality (SweepProgress::quality) and
  // skips the others, which a later one of the same check supersedes.
  void update(const SweepProgress& progress);
  // Erases a redrawn line if one was drawn, so the report starts on a clean
  // line.
  void finish();

 private:
  std::ostream& os_;
  Style style_;
  int max_sweeps_;
  Now now_;
  Clock::time_point start_, last_draw_;
  Clock::duration delay_, interval_;
  Clock::duration quality_cost_{};
  bool drawn_ = false;
  std::size_t drawn_width_ = 0;  // of the redrawn line on screen
};

}  // namespace tetsmooth::cli
