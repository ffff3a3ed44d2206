#pragma once
// A *NODE data line as tetsmooth writes every one: "number, x, y, z", each
// coordinate the shortest text that reads back to the same double (not a
// public API).
#include <ostream>

#include "mesh/io/number_text.hpp"

namespace tetsmooth::abaqus {

inline void write_node_line(std::ostream& out, long long number, const double* xyz) {
  put_integer(out, number);
  for (int c = 0; c < 3; ++c) {
    out << ", ";
    put_real(out, xyz[c]);
  }
  out << '\n';
}

}  // namespace tetsmooth::abaqus
