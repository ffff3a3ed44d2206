#include "apps/progress_line.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "apps/report_text.hpp"

namespace tetsmooth::cli {

ProgressLine::Style ProgressLine::style_for(ProgressMode mode, bool terminal, bool quiet) {
  if (quiet || mode == ProgressMode::Never) return Style::Off;
  if (terminal) return Style::Redraw;
  return mode == ProgressMode::Always ? Style::Lines : Style::Off;
}

ProgressLine::ProgressLine(std::ostream& os, Style style, int max_sweeps, Clock::duration delay,
                           Clock::duration interval, Now now)
    : os_(os),
      style_(style),
      max_sweeps_(max_sweeps),
      now_(std::move(now)),
      start_(now_()),
      delay_(delay),
      interval_(interval) {}

void ProgressLine::update(const SweepProgress& progress) {
  if (style_ == Style::Off || !progress.quality) return;
  const Clock::time_point now = now_();
  if (now - start_ < delay_) return;
  if (drawn_ && now - last_draw_ < std::max(interval_, kPacing * quality_cost_)) return;
  const MinMeanQuality q = progress.quality();
  last_draw_ = now_();
  quality_cost_ = last_draw_ - now;
  drawn_ = true;
  char numbers[96];
  std::snprintf(numbers, sizeof numbers, " up to %.3g  q min %.3g  mean %.3g", progress.max_displacement, q.min,
                q.mean);
  // "moved N up to d": N accepted moves, the farthest d (mesh units). Past
  // kWidth (sweep counts and moves in the hundreds of millions) the cap goes,
  // then the end of the line.
  const std::string moves = "  moved " + with_thousands(static_cast<std::size_t>(progress.accepted)) + numbers;
  std::string line = "  sweep " + std::to_string(progress.sweep) + "/" + std::to_string(max_sweeps_) + moves;
  if (line.size() > kWidth) line = "  sweep " + std::to_string(progress.sweep) + moves;
  if (line.size() > kWidth) line.resize(kWidth);
  if (style_ == Style::Lines) {
    os_ << line << '\n' << std::flush;
    return;
  }
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
