#pragma once
// Exceptions that carry what went wrong and where. The CLI maps each to a
// documented exit code (apps/exit_codes.hpp): usage 2, input 3, output 4,
// device 5.
#include <stdexcept>
#include <string>

namespace tetsmooth {

// Bad input data: a malformed file, or a mesh that fails validation.
// `where` names the file and the line or byte offset, e.g. "box.node:12".
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& where, const std::string& what)
      : std::runtime_error(where.empty() ? what : where + ": " + what) {}
};

// An output file that cannot be written.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A GPU that is missing, out of memory or failing, or a backend not built.
class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Options that make no sense together.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tetsmooth
