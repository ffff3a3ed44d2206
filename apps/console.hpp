#pragma once
// Where a command speaks: results to `out`, everything else (notes,
// warnings, reports, progress) to `err`, so `out` stays parseable.
#include <ostream>
#include <string>

namespace tetsmooth::cli {

struct Console {
  std::ostream& out;
  std::ostream& err;
  bool err_is_terminal = false;  // enables the overwritten progress line
  bool quiet = false;            // -q: nothing on err but errors

  // "tetsmooth: warning: <text>" on err, unless quiet.
  void warn(const std::string& text) const;
  // A plain line on err, unless quiet.
  void note(const std::string& text) const;
};

}  // namespace tetsmooth::cli
