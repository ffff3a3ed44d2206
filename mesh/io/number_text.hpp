#pragma once
// Numbers as text for the ASCII writers: the shortest decimal form that reads
// back to the same double (std::to_chars), so ASCII round trips are exact and
// the files no longer than they need to be.
#include <charconv>
#include <cstddef>
#include <ostream>
#include <string>

namespace tetsmooth {

inline void put_real(std::ostream& out, double value) {
  char buf[32];  // the longest shortest form, "-2.2250738585072014e-308", is 24
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  out.write(buf, result.ptr - buf);
}

inline void put_integer(std::ostream& out, long long value) {
  char buf[24];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  out.write(buf, result.ptr - buf);
}

// "1 node set", "3 node sets": a count and a noun made plural with an s.
inline std::string count_of(std::size_t n, const std::string& what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

}  // namespace tetsmooth
