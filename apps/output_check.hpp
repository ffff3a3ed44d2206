#pragma once
// A check of an output location before any work is done, so a typo in -o or
// --report fails at once rather than after a long smoothing run. The writers
// still report (and clean up) any failure that happens later.
#include <string>

#include "mesh/io/mesh_io.hpp"

namespace tetsmooth::cli {

// Throws OutputError when `path`'s directory does not exist, is not a
// directory or is not writable, when `path` itself is a directory, or when
// it is a file this user may not write (a read-only file is not replaced,
// though the rename that replaces a file would need only the directory).
void check_output_location(const std::string& path);

// The same for each file a mesh output stands for: both of TetGen's
// base.node and base.ele, one file in any other format.
void check_mesh_output_location(const std::string& path, MeshFormat format);

// Whether a file of the mesh output (`output` in `output_format`) is a file
// of the mesh read (`input` in `input_format`): the run then replaces its
// input, which is allowed (the file is replaced only by a whole result) but
// worth a warning.
bool writes_over_input(const std::string& input, MeshFormat input_format, const std::string& output,
                       MeshFormat output_format);

// Throws UsageError when the report at `report` would be written over the
// mesh that was read (`input` in `input_format`) or the one to be written
// (`output` in `output_format`): a file of the TetGen pair counts for both.
// The two meshes may be one file (smoothing in place).
void check_report_path(const std::string& report, const std::string& input, MeshFormat input_format,
                       const std::string& output, MeshFormat output_format);

}  // namespace tetsmooth::cli
