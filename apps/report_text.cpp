#include "apps/report_text.hpp"

#include <algorithm>
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

std::string with_thousands(std::size_t n) {
  std::string digits = std::to_string(n);
  for (int pos = static_cast<int>(digits.size()) - 3; pos > 0; pos -= 3) digits.insert(static_cast<std::size_t>(pos), ",");
  return digits;
}

void write_quality_table(std::ostream& os, const std::vector<SummaryColumn>& columns) {
  if (columns.size() > 1 || !columns.front().title.empty()) {
    os << "  " << std::setw(kLabelWidth) << "";
    for (const SummaryColumn& c : columns) os << std::setw(kValueWidth) << c.title;
    os << '\n';
  }
  using S = QualitySummary;
  row(os, "radius ratio  min", columns, [](const S& s) { return fixed_digits(s.min, 4); });
  row(os, "              mean", columns, [](const S& s) { return fixed_digits(s.mean, 4); });
  row(os, "              max", columns, [](const S& s) { return fixed_digits(s.max, 4); });
  row(os, "min over movable tets", columns, [](const S& s) { return fixed_digits(s.min_movable, 4); });
  row(os, "tets with q < 0.1", columns, [](const S& s) { return with_thousands(s.below_0_1); });
  row(os, "inverted tets", columns, [](const S& s) { return with_thousands(s.inverted); });
  row(os, "degenerate tets", columns, [](const S& s) { return with_thousands(s.degenerate); });
  row(os, "min dihedral angle (deg)", columns, [](const S& s) { return fixed_digits(s.min_dihedral_deg, 2); });
  row(os, "mean ratio, mean", columns, [](const S& s) { return fixed_digits(s.mean_ratio_mean, 4); });
}

void write_histogram(std::ostream& os, const std::vector<SummaryColumn>& columns) {
  const int bar_width = columns.size() > 1 ? 22 : 44;
  constexpr int kCountWidth = 10;
  std::size_t largest = 0;
  for (const SummaryColumn& c : columns)
    for (std::size_t n : c.summary->histogram) largest = std::max(largest, n);

  os << "  radius ratio histogram (tets per bin; inverted tets count in 0.0-0.1)\n";
  if (columns.size() > 1) {
    os << "  " << std::setw(9) << "";
    for (const SummaryColumn& c : columns)
      os << std::setw(kCountWidth) << c.title << ' ' << std::left << std::setw(bar_width) << "" << std::right;
    os << '\n';
  }
  for (int bin = 0; bin < 10; ++bin) {
    char range[16];
    std::snprintf(range, sizeof range, "%.1f-%.1f", bin / 10.0, (bin + 1) / 10.0);
    os << "  " << std::left << std::setw(9) << range << std::right;
    for (const SummaryColumn& c : columns) {
      const std::size_t n = c.summary->histogram[static_cast<std::size_t>(bin)];
      // A non-empty bin always shows at least one mark: a handful of slivers
      // among millions of tets is exactly what the reader is looking for.
      std::size_t marks = largest == 0 ? 0 : (n * static_cast<std::size_t>(bar_width) + largest - 1) / largest;
      os << std::setw(kCountWidth) << with_thousands(n) << ' ' << std::left << std::setw(bar_width)
         << std::string(marks, '#') << std::right;
    }
    os << '\n';
  }
}

void write_worst_tets(std::ostream& os, const std::vector<RankedTet>& worst) {
  if (worst.empty()) return;
  os << "  " << worst.size() << " worst tets (0-based tet and node indices)\n";
  os << "  " << std::setw(12) << "tet" << std::setw(12) << "quality" << "   nodes\n";
  for (const RankedTet& t : worst) {
    os << "  " << std::setw(12) << t.tet << std::setw(12) << fixed_digits(t.quality, 6) << "  ";
    for (index_t n : t.nodes) os << ' ' << n;
    os << '\n';
  }
}

}  // namespace tetsmooth::cli
