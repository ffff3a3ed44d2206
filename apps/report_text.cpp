#include "apps/report_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace tetsmooth::cli {
namespace {

constexpr int kLabelWidth = 28;
constexpr int kValueWidth = 12;

template <class Value>
void row(std::ostream& os, const std::string& label, const std::vector<SummaryColumn>& columns, Value value) {
  os << "  " << std::left << std::setw(kLabelWidth) << label << std::right;
  for (const SummaryColumn& c : columns) os << std::setw(kValueWidth) << value(*c.summary);
  os << '\n';
}

}  // namespace

std::string fixed_digits(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::string quality_text(double q) {
  if (q == 0 || std::abs(q) >= 5e-5) return fixed_digits(q, 4);
  char text[16];
  std::snprintf(text, sizeof text, "%.2e", q);
  return text;
}

std::string with_thousands(std::size_t n) {
  std::string digits = std::to_string(n);
  for (int pos = static_cast<int>(digits.size()) - 3; pos > 0; pos -= 3)
    digits.insert(static_cast<std::size_t>(pos), ",");
  return digits;
}

std::string counted(std::size_t n, const std::string& one, const std::string& many) {
  return with_thousands(n) + " " + (n == 1 ? one : many);
}

void write_quality_table(std::ostream& os, const std::vector<SummaryColumn>& columns) {
  if (columns.size() > 1 || !columns.front().title.empty()) {
    os << "  " << std::setw(kLabelWidth) << "";
    for (const SummaryColumn& c : columns) os << std::setw(kValueWidth) << c.title;
    os << '\n';
  }
  using S = QualitySummary;
  row(os, "radius ratio  min", columns, [](const S& s) { return quality_text(s.min); });
  row(os, "              mean", columns, [](const S& s) { return quality_text(s.mean); });
  row(os, "              max", columns, [](const S& s) { return quality_text(s.max); });
  row(os, "min over movable tets", columns,
      [](const S& s) { return s.movable_tets > 0 ? quality_text(s.min_movable) : std::string("-"); });
  row(os, "tets with q < 0.1", columns, [](const S& s) { return with_thousands(s.below_0_1); });
  row(os, "inverted tets", columns, [](const S& s) { return with_thousands(s.inverted); });
  row(os, "degenerate tets", columns, [](const S& s) { return with_thousands(s.degenerate); });
  row(os, "min dihedral angle (deg)", columns, [](const S& s) { return fixed_digits(s.min_dihedral_deg, 2); });
  row(os, "mean ratio, mean", columns, [](const S& s) { return quality_text(s.mean_ratio_mean); });
}

void write_histogram(std::ostream& os, const std::vector<SummaryColumn>& columns) {
  const std::size_t bar_width = columns.size() > 1 ? 22 : 44;
  constexpr int kCountWidth = 10;
  std::size_t largest = 0;
  for (const SummaryColumn& c : columns)
    for (std::size_t n : c.summary->histogram) largest = std::max(largest, n);

  // Lines are built whole so that trailing padding can be cut off.
  const auto emit = [&os](std::string line) {
    line.erase(line.find_last_not_of(' ') + 1);
    os << line << '\n';
  };
  const auto cell = [&](const std::string& count, std::size_t marks) {
    std::ostringstream s;
    s << std::setw(kCountWidth) << count << ' ' << std::string(marks, '#') << std::string(bar_width - marks, ' ');
    return s.str();
  };

  os << "  radius ratio histogram (tets per bin; inverted tets count in 0.0-0.1)\n";
  if (columns.size() > 1) {
    std::string line(11, ' ');
    for (const SummaryColumn& c : columns) line += cell(c.title, 0);
    emit(line);
  }
  for (int bin = 0; bin < 10; ++bin) {
    char range[16];
    std::snprintf(range, sizeof range, "  %.1f-%.1f  ", bin / 10.0, (bin + 1) / 10.0);
    std::string line = range;
    for (const SummaryColumn& c : columns) {
      const std::size_t n = c.summary->histogram[static_cast<std::size_t>(bin)];
      // A non-empty bin always shows at least one mark: a handful of slivers
      // among millions of tets is exactly what the reader is looking for.
      const std::size_t marks = largest == 0 ? 0 : (n * bar_width + largest - 1) / largest;
      line += cell(with_thousands(n), marks);
    }
    emit(line);
  }
}

void write_worst_tets(std::ostream& os, const std::vector<RankedTet>& worst) {
  if (worst.empty()) return;
  os << "  " << worst.size() << (worst.size() == 1 ? " worst tet" : " worst tets")
     << " (0-based tet and node indices)\n";
  os << "  " << std::setw(12) << "tet" << std::setw(12) << "quality"
     << "   nodes\n";
  for (const RankedTet& t : worst) {
    os << "  " << std::setw(12) << t.tet << std::setw(12) << quality_text(t.quality) << "  ";
    for (index_t n : t.nodes) os << ' ' << n;
    // The file's own numbers, by which its users know the element.
    if (t.element != 0 || t.node_numbers[0] != 0) {
      os << "   (in the file:";
      if (t.element != 0) os << " element " << t.element;
      if (t.node_numbers[0] != 0) {
        os << " nodes";
        for (long long n : t.node_numbers) os << ' ' << n;
      }
      os << ')';
    }
    os << '\n';
  }
}

}  // namespace tetsmooth::cli
