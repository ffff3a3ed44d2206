#pragma once
// bench_smooth's own command-line flags, taken out of argv before Google
// Benchmark parses the rest (its --benchmark_* flags and --help).
#include <string>

#include "bench/bench_registry.hpp"

namespace tetsmooth::bench {

// Removes our flags from argv (argc shrinks) and returns the configuration.
// Throws UsageError naming the flag for a bad value: an unknown model, a
// scaling mesh that is not lattice-N, a precision other than double/float,
// or --coloured-lanes other than 0, 8, 16 or 32. "--help" is left in argv
// for Google Benchmark, which prints its own flags and exits.
BenchConfig take_own_flags(int& argc, char** argv);

// A paper model's benchmark label: "slope-77k" (the generator's name) is
// "77k" (Table 2's label); the others are their own labels. Throws
// UsageError for a name that is not a paper model.
std::string model_label(const std::string& name);

// The help text of our flags, printed before Google Benchmark's on --help.
const char* own_flags_help();

}  // namespace tetsmooth::bench
