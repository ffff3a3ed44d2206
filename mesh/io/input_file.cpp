#include "mesh/io/input_file.hpp"

#include <cerrno>
#include <cstring>

#include "mesh/errors.hpp"

namespace tetsmooth {

std::ifstream open_input(const std::string& path) {
  errno = 0;
  std::ifstream in(path, std::ios::binary);  // binary: bytes as they are, offsets exact
  if (!in) throw InputError(path, std::string("cannot open: ") + (errno != 0 ? std::strerror(errno) : "unknown error"));
  return in;
}

}  // namespace tetsmooth
