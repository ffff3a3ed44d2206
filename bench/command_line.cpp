#include "bench/command_line.hpp"

#include <cstring>

namespace tetsmooth::bench {

std::string shell_quoted(const std::string& arg) {
  static const char kPlain[] =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=/.,:@%";
  if (!arg.empty() && arg.find_first_not_of(kPlain) == std::string::npos) return arg;
  std::string quoted = "'";
  for (const char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string command_line(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    std::string arg = argv[i] ? argv[i] : "";
    if (i == 0) {
      const std::size_t slash = arg.rfind('/');
      if (slash != std::string::npos) arg.erase(0, slash + 1);
    }
    if (i > 0) line += ' ';
    line += shell_quoted(arg);
  }
  return line;
}

}  // namespace tetsmooth::bench
