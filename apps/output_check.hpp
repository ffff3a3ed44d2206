#pragma once
// A check of an output location before any work is done, so a typo in -o or
// --report fails at once rather than after a long smoothing run. The writers
// still report (and clean up) any failure that happens later.
#include <string>

#include "mesh/io/mesh_io.hpp"

namespace tetsmooth::cli {

// Throws OutputError when `path`'s directory does not exist, is not a
// directory or is not writable, or when `path` itself is a directory.
void check_output_location(const std::string& path);

// The same for each file a mesh output stands for: both of TetGen's
// base.node and base.ele, one file in any other format.
void check_mesh_output_location(const std::string& path, MeshFormat format);

// Throws UsageError when the report at `report` would be written over the
// mesh that was read (`input` in `input_format`) or the one to be written
// (`output` in `output_format`): a file of the TetGen pair counts for both.
// The two meshes may be one file (smoothing in place).
void check_report_path(const std::string& report, const std::string& input, MeshFormat input_format,
                       const std::string& output, MeshFormat output_format);

}  // namespace tetsmooth::cli
