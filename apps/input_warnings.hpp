#pragma once
// Warnings about a mesh that was read successfully but deserves a second
// look: these never stop a command.
#include <string>
#include <vector>

#include "mesh/validate.hpp"

namespace tetsmooth::cli {

// validate_mesh, with the count of repeated tets filled in.
ValidationReport inspect_input(const TetMesh& mesh, const std::string& source);

// The reader's notes on what it skipped (FileExtras::read_notes), then one
// message per kind of problem (inverted, degenerate, unreferenced, repeated), each
// naming `source` and the count. `inverted_note` is appended to the
// inverted-tets message when not empty.
std::vector<std::string> input_warnings(const TetMesh& mesh, const ValidationReport& report, const std::string& source,
                                        const std::string& inverted_note = "");

}  // namespace tetsmooth::cli
