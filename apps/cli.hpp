#pragma once
// The whole command-line tool behind main(): parse, run, and turn every
// failure into one line on `err` and a documented exit code (exit_codes.hpp).
#include <ostream>
#include <string>
#include <vector>

namespace tetsmooth::cli {

// `args` excludes the program name. Never throws.
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, bool err_is_terminal);

}  // namespace tetsmooth::cli
