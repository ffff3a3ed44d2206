// Binary FLAC3D grids (flac3d_io.hpp): the records of a grid that FLAC3D's
// zone export ... binary writes, little-endian and packed, in meshio 5's
// reading of the layout (meshio writes them so too):
//   uint32 1375135718 (the format's mark), uint32 version (3)
//   uint32 gridpoints, then each: uint32 id, float64 x, y, z
//   uint32 zones, then each: uint32 id, uint32 n, n x uint32 gridpoint id
//   uint32 zone groups, then each: uint16 length + the name, uint16 length
//     + the slot, uint32 n, n x uint32 zone id
//   faces and face groups as zones and zone groups.
// A zone's type is told by its gridpoint count (4 T4, 5 P5, 6 W6, 7 B7,
// 8 B8; a face's 3 T3, 4 Q4).
#include <cmath>
#include <cstdint>

#include "mesh/errors.hpp"
#include "mesh/io/flac3d_grid_records.hpp"
#include "mesh/io/little_endian.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::flac3d {
namespace {

constexpr std::uint32_t kMark = 1375135718;
constexpr std::uint32_t kVersion = 3;

class BinaryGridParser {
 public:
  BinaryGridParser(const std::string& bytes, const std::string& source) : bytes_(bytes) {
    r_.source = source;
    r_.binary = true;
  }
  GridRecords parse();

 private:
  [[noreturn]] void fail(std::size_t at, const std::string& what) const { throw InputError(r_.where(at), what); }
  const unsigned char* take(std::size_t n, const std::string& what) {
    if (bytes_.size() - pos_ < n) fail(pos_, "the file ends inside " + what);
    const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data()) + pos_;
    pos_ += n;
    return p;
  }
  std::uint32_t u32(const std::string& what) { return load_le<std::uint32_t>(take(4, "the " + what)); }
  long long id(const char* what) {
    const std::size_t at = pos_;
    const std::uint32_t v = u32(what);
    if (v == 0) fail(at, std::string(what) + " 0 is not positive");
    return v;
  }
  // A count of items of at least `each` bytes: no more than the rest of the
  // file holds, so that a corrupt count cannot allocate.
  std::size_t count(const char* what, std::size_t each) {
    const std::size_t at = pos_;
    const std::uint32_t n = u32(what);
    if (n > (bytes_.size() - pos_) / each)
      fail(at, std::string(what) + " " + std::to_string(n) + " is more than the rest of the file holds");
    return n;
  }
  // A name: control bytes are refused, as a text grid cannot hold them
  // either (a line break, a zero byte), so that every format can write it.
  std::string text(const char* what) {
    const std::size_t n = load_le<std::uint16_t>(take(2, what));
    const std::size_t at = pos_;
    const unsigned char* p = take(n, what);
    for (std::size_t i = 0; i < n; ++i)
      if (p[i] < 0x20 || p[i] == 0x7f)
        fail(at + i,
             std::string(what) + " holds the control byte " + text_excerpt(std::string(1, static_cast<char>(p[i]))));
    return std::string(reinterpret_cast<const char*>(p), n);
  }
  void elements(Elements& into, char record);
  void groups(char record);

  const std::string& bytes_;
  std::size_t pos_ = 0;
  GridRecords r_;
};

void BinaryGridParser::elements(Elements& into, char record) {
  const char* what = record == 'Z' ? "zone" : "face";
  const std::size_t n = count(record == 'Z' ? "zone count" : "face count", 8);
  for (std::size_t e = 0; e < n; ++e) {
    const std::size_t at = pos_;
    into.ids.push_back(id(record == 'Z' ? "zone id" : "face id"));
    const std::uint32_t nodes = u32(std::string("gridpoint count of a ") + what);
    const ZoneType* type = zone_type_with(nodes, record);
    if (type == nullptr)
      fail(at, std::string("a ") + what + " of " + std::to_string(nodes) + " gridpoints, which no " + what +
                   " type has (" + zone_codes(record) + ")");
    into.types.push_back(type);
    into.first.push_back(into.gridpoints.size());
    for (std::size_t k = 0; k < nodes; ++k) into.gridpoints.push_back(id("gridpoint id"));
    into.places.push_back(at);
  }
}

void BinaryGridParser::groups(char record) {
  const std::size_t n = count(record == 'Z' ? "zone group count" : "face group count", 8);
  for (std::size_t g = 0; g < n; ++g) {
    Group group{record, text("a group name"), text("a group's slot"), {}, {}};
    const std::size_t members = count("group size", 4);
    for (std::size_t i = 0; i < members; ++i) {
      group.places.push_back(pos_);
      group.ids.push_back(id(record == 'Z' ? "zone id" : "face id"));
    }
    r_.groups.push_back(std::move(group));
  }
}

GridRecords BinaryGridParser::parse() {
  if (bytes_.size() < 4 || load_le<std::uint32_t>(reinterpret_cast<const unsigned char*>(bytes_.data())) != kMark)
    fail(0, "not a FLAC3D grid: a binary file that does not start with the binary grid's mark (1375135718)");
  pos_ = 4;
  if (const std::uint32_t version = u32("header"); version != kVersion)
    r_.notes.push_back("the binary grid's version is " + std::to_string(version) + ", not " + std::to_string(kVersion) +
                       " as the grids this reader knows have it; its records read in "
                       "their layout");
  const std::size_t n = count("gridpoint count", 28);
  for (std::size_t k = 0; k < n; ++k) {
    r_.node_places.push_back(pos_);
    r_.node_ids.push_back(id("gridpoint id"));
    for (const char axis : {'x', 'y', 'z'}) {
      const std::size_t at = pos_;
      const double v = load_le<double>(take(8, "a coordinate"));
      if (!std::isfinite(v)) fail(at, std::string("coordinate ") + axis + " is not a finite number");
      r_.xyz.push_back(v);
    }
  }
  elements(r_.zones, 'Z');
  groups('Z');
  elements(r_.faces, 'F');
  groups('F');
  if (pos_ < bytes_.size())
    r_.notes.push_back(std::to_string(bytes_.size() - pos_) + " bytes after the face groups (from byte " +
                       std::to_string(pos_) + ") were not read; the FLAC3D output keeps them");
  return std::move(r_);
}

}  // namespace

GridRecords parse_binary_grid(const std::string& bytes, const std::string& source) {
  return BinaryGridParser(bytes, source).parse();
}

}  // namespace tetsmooth::flac3d
