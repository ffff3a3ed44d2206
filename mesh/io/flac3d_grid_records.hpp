#pragma once
// A FLAC3D grid's records as its text or binary reader parsed them, before
// ids are resolved into node indices (flac3d_io.hpp; not a public API).
// Each item keeps where it was read: a line number in a text grid, a byte
// offset in a binary one.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "mesh/io/flac3d_zone_types.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::flac3d {

// Zones or faces: their types, ids, gridpoint ids and places.
struct Elements {
  std::vector<const ZoneType*> types;
  std::vector<long long> ids;
  std::vector<std::size_t> first;  // into gridpoints
  std::vector<long long> gridpoints;
  std::vector<std::size_t> places;
};

// A ZGROUP or FGROUP with its ids, each with its place.
struct Group {
  char record;  // 'Z' or 'F'
  std::string name, slot;
  std::vector<long long> ids;
  std::vector<std::size_t> places;
};

struct GridRecords {
  std::string source;
  bool binary = false;  // places are byte offsets, else line numbers
  std::vector<long long> node_ids;
  std::vector<double> xyz;
  std::vector<std::size_t> node_places;
  Elements zones, faces;
  std::vector<Group> groups;
  std::vector<std::pair<long long, std::size_t>> pins;  // (gridpoint id, place) of pin comments
  std::vector<std::string> notes;                       // for FileExtras::read_notes

  // "source:line" or "source, byte N".
  std::string where(std::size_t place) const {
    return binary ? source + ", byte " + std::to_string(place) : source + ":" + std::to_string(place);
  }
};

// The mesh the records describe, with its region tags, names, blocks and
// pins (flac3d_io.hpp), validated; InputError at the place of the first
// record at fault. The caller keeps the file in the mesh's raw sections.
TetMesh resolve_grid(GridRecords records);

// The records of a binary grid (`bytes`: the whole file), in the layout
// flac3d_io.hpp gives; InputError naming the byte offset at fault.
GridRecords parse_binary_grid(const std::string& bytes, const std::string& source);

// Where a binary grid holds gridpoint `k`'s x (then y, z): the records of
// id and coordinates follow the header and the count, 28 bytes each.
inline std::size_t binary_coordinates_at(std::size_t k) { return 12 + 28 * k + 4; }

}  // namespace tetsmooth::flac3d
