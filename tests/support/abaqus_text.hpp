#pragma once
// Abaqus decks to and from strings, for the tests of the reader and writer
// (test_io_abaqus.cpp, test_io_abaqus_parts.cpp).
#include <sstream>
#include <string>

#include "input_error.hpp"
#include "mesh/io/abaqus_io.hpp"

namespace tetsmooth::testing {

// The mesh of the deck `text`, read as if from the file `source` (which
// messages name).
inline TetMesh read_abaqus_text(const std::string& text, const std::string& source = "t.inp") {
  std::istringstream in(text);
  return read_abaqus(in, source);
}

inline std::string write_abaqus_text(const TetMesh& mesh) {
  std::ostringstream out;
  write_abaqus(mesh, out);
  return out.str();
}

// The message with which reading `text` is refused (a test failure if it is
// read).
inline std::string abaqus_read_error(const std::string& text) {
  return input_error_message([&] { read_abaqus_text(text); }, "read_abaqus:\n" + text);
}

}  // namespace tetsmooth::testing
