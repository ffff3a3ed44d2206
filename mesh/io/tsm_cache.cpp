#include "mesh/io/tsm_cache.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <vector>

#include "mesh/errors.hpp"
#include "mesh/second_order.hpp"
#include "mesh/io/atomic_file.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/little_endian.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace {

constexpr unsigned char kMagic[8] = {0x89, 'T', 'S', 'M', 0x0D, 0x0A, 0x1A, 0x0A};
constexpr std::size_t kHeaderBytes = 32;
constexpr std::size_t kChunk = 1 << 16;  // values converted per batch

constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ULL;
constexpr std::uint64_t kFnvPrime = 0x100000001b3ULL;

std::uint64_t fnv1a(std::uint64_t hash, const unsigned char* p, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) hash = (hash ^ p[i]) * kFnvPrime;
  return hash;
}

// Writes bytes and hashes them on the way out.
class HashingWriter {
 public:
  explicit HashingWriter(std::ostream& out) : out_(out) {}
  void write(const unsigned char* p, std::size_t n) {
    hash_ = fnv1a(hash_, p, n);
    out_.write(reinterpret_cast<const char*>(p), static_cast<std::streamsize>(n));
  }
  std::uint64_t hash() const { return hash_; }

 private:
  std::ostream& out_;
  std::uint64_t hash_ = kFnvOffset;
};

// Reads bytes, hashes them and knows its byte offset for error messages.
class HashingReader {
 public:
  HashingReader(std::istream& in, const std::string& source) : in_(in), source_(source) {}

  void read(unsigned char* p, std::size_t n, const char* what) {
    in_.read(reinterpret_cast<char*>(p), static_cast<std::streamsize>(n));
    const auto got = static_cast<std::size_t>(in_.gcount());
    if (got != n) {
      offset_ += got;
      fail(std::string("truncated: the file ends inside ") + what);
    }
    hash_ = fnv1a(hash_, p, n);
    offset_ += n;
  }
  bool at_eof() { return in_.peek() == std::char_traits<char>::eof(); }
  std::uint64_t hash() const { return hash_; }
  std::uint64_t offset() const { return offset_; }

  [[noreturn]] void fail(const std::string& what, std::uint64_t at) const {
    throw InputError(source_ + ", byte " + std::to_string(at), what);
  }
  [[noreturn]] void fail(const std::string& what) const { fail(what, offset_); }

 private:
  std::istream& in_;
  const std::string& source_;
  std::uint64_t offset_ = 0;
  std::uint64_t hash_ = kFnvOffset;
};

}  // namespace

void write_cache(const TetMesh& mesh, std::ostream& out) {
  check_first_order_output(mesh, ".tsm");
  HashingWriter w(out);
  unsigned char header[kHeaderBytes];
  std::memcpy(header, kMagic, sizeof kMagic);
  store_le<std::uint32_t>(header + 8, kTsmVersion);
  store_le<std::uint32_t>(header + 12, 0);
  store_le<std::uint64_t>(header + 16, mesh.num_nodes());
  store_le<std::uint64_t>(header + 24, mesh.num_tets());
  w.write(header, sizeof header);

  std::vector<unsigned char> buf(8 * kChunk);
  for (std::size_t i = 0; i < mesh.xyz.size(); i += kChunk) {
    const std::size_t n = std::min(kChunk, mesh.xyz.size() - i);
    for (std::size_t k = 0; k < n; ++k) store_le(&buf[8 * k], mesh.xyz[i + k]);
    w.write(buf.data(), 8 * n);
  }
  for (std::size_t i = 0; i < mesh.tets.size(); i += kChunk) {
    const std::size_t n = std::min(kChunk, mesh.tets.size() - i);
    for (std::size_t k = 0; k < n; ++k) store_le(&buf[4 * k], mesh.tets[i + k]);
    w.write(buf.data(), 4 * n);
  }
  unsigned char trailer[8];
  store_le(trailer, w.hash());
  out.write(reinterpret_cast<const char*>(trailer), sizeof trailer);
}

void write_cache_file(const TetMesh& mesh, const std::string& path) {
  write_atomically(
      path, [&](std::ostream& out) { write_cache(mesh, out); }, true);
}

TetMesh read_cache(std::istream& in, const std::string& source) {
  HashingReader r(in, source);
  unsigned char header[kHeaderBytes];
  r.read(header, sizeof kMagic, "the magic number");
  if (std::memcmp(header, kMagic, sizeof kMagic) != 0) r.fail("not a tetsmooth cache (.tsm): wrong magic number", 0);
  r.read(header + 8, kHeaderBytes - 8, "the header");
  const std::uint64_t version = load_le<std::uint32_t>(header + 8);
  if (version != kTsmVersion)
    r.fail("unsupported cache version " + std::to_string(version) + ", this build reads version " +
               std::to_string(kTsmVersion) + " (regenerate the cache)",
           8);
  if (load_le<std::uint32_t>(header + 12) != 0)
    r.fail("unknown flags " + std::to_string(load_le<std::uint32_t>(header + 12)), 12);
  const std::uint64_t nodes = load_le<std::uint64_t>(header + 16);
  const std::uint64_t tets = load_le<std::uint64_t>(header + 24);
  constexpr auto kMaxIndex = static_cast<std::uint64_t>(std::numeric_limits<index_t>::max());
  if (nodes > kMaxIndex) r.fail("node count " + std::to_string(nodes) + " exceeds the 32-bit index range", 16);
  if (tets > max_tets())
    r.fail("tet count " + std::to_string(tets) + " exceeds the " + std::to_string(max_tets()) +
               " that 32-bit offsets of the node-to-tet table (4 entries a tet) allow",
           24);

  TetMesh mesh;
  std::vector<unsigned char> buf(8 * kChunk);
  // Grown chunk by chunk, so a header claiming more than the file holds ends
  // in a truncation error rather than a huge allocation.
  for (std::uint64_t left = 3 * nodes; left > 0;) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, left));
    r.read(buf.data(), 8 * n, "the node coordinates");
    const std::size_t at = mesh.xyz.size();
    mesh.xyz.resize(at + n);
    for (std::size_t k = 0; k < n; ++k) mesh.xyz[at + k] = load_le<double>(&buf[8 * k]);
    left -= n;
  }
  for (std::uint64_t left = 4 * tets; left > 0;) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, left));
    r.read(buf.data(), 4 * n, "the tets");
    const std::size_t at = mesh.tets.size();
    mesh.tets.resize(at + n);
    for (std::size_t k = 0; k < n; ++k) mesh.tets[at + k] = load_le<index_t>(&buf[4 * k]);
    left -= n;
  }
  const std::uint64_t expected = r.hash();
  const std::uint64_t at = r.offset();
  unsigned char trailer[8];
  r.read(trailer, sizeof trailer, "the checksum");
  if (load_le<std::uint64_t>(trailer) != expected) r.fail("checksum mismatch: the file is corrupt", at);
  if (!r.at_eof()) r.fail("unexpected bytes after the checksum");
  validate_mesh(mesh, source);
  return mesh;
}

TetMesh read_cache_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_cache(in, path);
}

}  // namespace tetsmooth
