#pragma once
// A check of an output location before any work is done, so a typo in -o or
// --report fails at once rather than after a long smoothing run. The writers
// still report (and clean up) any failure that happens later.
#include <string>

namespace tetsmooth::cli {

// Throws OutputError when `path`'s directory does not exist, is not a
// directory or is not writable, or when `path` itself is a directory.
void check_output_location(const std::string& path);

}  // namespace tetsmooth::cli
