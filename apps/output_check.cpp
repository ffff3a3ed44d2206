#include "apps/output_check.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "mesh/errors.hpp"

namespace tetsmooth::cli {

void check_output_location(const std::string& path) {
  namespace fs = std::filesystem;
  const auto fail = [&](const std::string& why) { throw OutputError("cannot write '" + path + "': " + why); };
  std::error_code ec;
  if (fs::is_directory(path, ec)) fail("it is a directory");
  const fs::path parent = fs::path(path).parent_path();
  const std::string dir = parent.empty() ? "." : parent.string();
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) fail("directory '" + dir + "' does not exist");
  if (!fs::is_directory(status)) fail("'" + dir + "' is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0) fail("directory '" + dir + "': " + std::strerror(errno));
}

}  // namespace tetsmooth::cli
