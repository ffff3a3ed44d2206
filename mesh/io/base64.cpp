#include "mesh/io/base64.hpp"

namespace tetsmooth {
namespace {

int sextet(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

}  // namespace

bool base64_decode(std::string_view text, std::vector<unsigned char>& out, std::size_t& bad_at) {
  out.reserve(out.size() + text.size() / 4 * 3);
  unsigned group = 0;
  int filled = 0;   // characters of the current group seen, padding included
  int padding = 0;  // '=' among them
  std::size_t group_start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (is_space(c)) continue;
    if (filled == 0) group_start = i;
    int v = 0;
    if (c == '=') {
      if (filled < 2) {
        bad_at = i;
        return false;
      }
      ++padding;
    } else {
      v = sextet(c);
      if (v < 0 || padding > 0) {
        bad_at = i;
        return false;
      }
    }
    group = (group << 6) | static_cast<unsigned>(v);
    if (++filled < 4) continue;
    const int bytes = 3 - padding;
    for (int b = 0; b < bytes; ++b) out.push_back(static_cast<unsigned char>(group >> (16 - 8 * b)));
    group = 0;
    filled = padding = 0;
  }
  if (filled != 0) {
    bad_at = group_start;
    return false;
  }
  return true;
}

}  // namespace tetsmooth
