#include "apps/progress_line.hpp"

#include <cstdio>
#include <string>

#include "apps/report_text.hpp"

namespace tetsmooth::cli {

ProgressLine::ProgressLine(std::ostream& os, bool enabled, int max_sweeps, Clock::duration delay,
                           Clock::duration interval)
    : os_(os), enabled_(enabled), max_sweeps_(max_sweeps), start_(Clock::now()), delay_(delay), interval_(interval) {}

void ProgressLine::update(const SweepProgress& progress) {
  if (!enabled_) return;
  const Clock::time_point now = Clock::now();
  if (now - start_ < delay_ || (drawn_width_ > 0 && now - last_draw_ < interval_)) return;
  last_draw_ = now;
  char displacement[32];
  std::snprintf(displacement, sizeof displacement, "%.3g", progress.max_displacement);
  const std::string line = "  sweep " + std::to_string(progress.sweep) + "/" + std::to_string(max_sweeps_) +
                           "  accepted moves " + with_thousands(static_cast<std::size_t>(progress.accepted)) +
                           "  max displacement " + displacement;
  // Pad over the previous, possibly longer, line instead of relying on
  // terminal escape codes.
  const std::size_t pad = drawn_width_ > line.size() ? drawn_width_ - line.size() : 0;
  os_ << '\r' << line << std::string(pad, ' ') << std::flush;
  drawn_width_ = line.size();
}

void ProgressLine::finish() {
  if (drawn_width_ == 0) return;
  os_ << '\r' << std::string(drawn_width_, ' ') << '\r' << std::flush;
  drawn_width_ = 0;
}

}  // namespace tetsmooth::cli
