#pragma once
// Quality reports for people: aligned tables and histogram bars that read
// well in an 80-column terminal.
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "apps/worst_tets.hpp"
#include "mesh/quality_summary.hpp"

namespace tetsmooth::cli {

struct SummaryColumn {
  std::string title;  // "before", "after", or empty for a single summary
  const QualitySummary* summary;
};

// Radius ratio min/mean/max, min over movable tets, counts of poor, inverted
// and degenerate tets, min dihedral angle and mean of the mean ratio, one
// column per summary.
void write_quality_table(std::ostream& os, const std::vector<SummaryColumn>& columns);

// The 10-bin radius-ratio histogram, one count and bar per summary; bars of
// all columns share one scale so they compare at a glance.
void write_histogram(std::ostream& os, const std::vector<SummaryColumn>& columns);

void write_worst_tets(std::ostream& os, const std::vector<RankedTet>& worst);

// 0.123456 with 4 digits -> "0.1235".
std::string fixed_digits(double v, int digits);

// A quality value with 4 decimals, or in scientific notation when that would
// round a non-zero value to 0.0000: slivers of 1e-6 must not look like
// degenerate tets.
std::string quality_text(double q);

// 1234567 -> "1,234,567".
std::string with_thousands(std::size_t n);

// n, then `one` or `many` as n is 1 or not: "1 node", "1,234 nodes".
std::string counted(std::size_t n, const std::string& one, const std::string& many);

}  // namespace tetsmooth::cli
