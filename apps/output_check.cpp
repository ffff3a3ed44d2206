#include "apps/output_check.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "mesh/errors.hpp"
#include "mesh/io/atomic_file.hpp"
#include "mesh/io/tetgen_io.hpp"

namespace tetsmooth::cli {

namespace {

// The files a mesh path stands for in its format.
std::vector<std::string> mesh_files(const std::string& path, MeshFormat format) {
  if (format != MeshFormat::TetGen) return {path};
  const std::string base = tetgen_base(path);
  return {base + ".node", base + ".ele"};
}

// One file under two names: the same inode where both exist, else the same
// path once "." / ".." and links are resolved.
bool same_file(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  const fs::path ca = fs::weakly_canonical(a, ec), cb = fs::weakly_canonical(b, ec);
  return !ec && ca == cb;
}

}  // namespace

void check_output_location(const std::string& path) {
  namespace fs = std::filesystem;
  const auto fail = [&](const std::string& why) { throw OutputError("cannot write '" + path + "': " + why); };
  std::error_code ec;
  if (fs::is_directory(path, ec)) fail("it is a directory");
  // The write lands where the target's links end: that directory must exist.
  const LinkEnd end = follow_links(path);
  if (end.endless) fail(std::strerror(ELOOP));
  const fs::path parent = fs::path(end.path).parent_path();
  const std::string dir = parent.empty() ? "." : parent.string();
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) fail("directory '" + dir + "' does not exist");
  if (!fs::is_directory(status)) fail("'" + dir + "' is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0) fail("directory '" + dir + "': " + std::strerror(errno));
  if (fs::exists(end.path, ec) && ::access(end.path.c_str(), W_OK) != 0)
    fail("the file is not writable: " + std::string(std::strerror(errno)));
}

void check_mesh_output_location(const std::string& path, MeshFormat format) {
  for (const std::string& file : mesh_files(path, format_from_path(path, format))) check_output_location(file);
}

bool writes_over_input(const std::string& input, MeshFormat input_format, const std::string& output,
                       MeshFormat output_format) {
  for (const std::string& in : mesh_files(input, input_format))
    for (const std::string& out : mesh_files(output, output_format))
      if (same_file(in, out)) return true;
  return false;
}

void check_report_path(const std::string& report, const std::string& input, MeshFormat input_format,
                       const std::string& output, MeshFormat output_format) {
  for (const std::string& f : mesh_files(input, input_format))
    if (same_file(report, f)) throw UsageError("--report '" + report + "' is the input mesh '" + f + "'");
  for (const std::string& f : mesh_files(output, output_format))
    if (same_file(report, f)) throw UsageError("--report '" + report + "' is the output mesh '" + f + "'");
}

}  // namespace tetsmooth::cli
