#include "mesh/io/input_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "mesh/errors.hpp"

namespace tetsmooth {

std::ifstream open_input(const std::string& path) {
  // An ifstream opens a directory on Linux and fails only at the first read,
  // which would be reported as a read error at line 1.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) throw InputError(path, "is a directory, not a mesh file");
  errno = 0;
  std::ifstream in(path, std::ios::binary);  // binary: bytes as they are, offsets exact
  if (!in) throw InputError(path, std::string("cannot open: ") + (errno != 0 ? std::strerror(errno) : "unknown error"));
  return in;
}

std::string read_all(std::istream& in, const std::string& source) {
  std::string text;
  constexpr std::size_t kChunk = 1 << 20;
  for (;;) {
    const std::size_t size = text.size();
    text.resize(size + kChunk);
    in.read(text.data() + size, static_cast<std::streamsize>(kChunk));
    text.resize(size + static_cast<std::size_t>(in.gcount()));
    if (!in) break;
  }
  if (in.bad()) throw InputError(source, "read error");
  return text;
}

}  // namespace tetsmooth
