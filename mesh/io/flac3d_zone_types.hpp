#pragma once
// FLAC3D's zone and face types and their gridpoint orders (flac3d_io.hpp;
// not a public API).
//
// FLAC3D lists a brick's corners as origin, x, y, z, xy, yz, xz, xyz (its
// first four right-handed), and a wedge (W6) and a pyramid (P5) as the first
// six and five of those: a wedge is the triangle (origin, z, x) drawn out
// along y, a pyramid the quad (origin, x, xy, y) under the apex z. The other
// formats list a hexahedron's bottom quad and then the top, a wedge's two
// triangles one over the other (the first wound with its normal into the
// cell, as Gmsh's), and a pyramid's base and then its apex.
#include <cstddef>
#include <string>
#include <string_view>

namespace tetsmooth::flac3d {

struct ZoneType {
  const char* code;   // "B8"
  char record;        // 'Z' for zones, 'F' for faces
  const char* kind;   // the PassThroughBlock kind; "tetra" for T4, "" for B7 (not carried)
  std::size_t nodes;  // gridpoints a zone
  // from_file[k]: the place in FLAC3D's list of the other formats' k-th node.
  int from_file[8];
  // mirrored[k]: the place in FLAC3D's list of the k-th gridpoint of the same
  // zone mirrored (two of its axes swapped), for a zone whose FLAC3D list
  // would be left-handed (bricks, wedges and pyramids of other formats).
  int mirrored[8];
};

// The type with this code and record (the code compared in any case), or
// nullptr.
const ZoneType* zone_type(std::string_view code, char record);

// The type of `record` with `nodes` gridpoints (binary grids give no type
// code), or nullptr.
const ZoneType* zone_type_with(std::size_t nodes, char record);

// The type that writes blocks of `kind`, or nullptr.
const ZoneType* zone_type_of_kind(const std::string& kind);

// The codes of `record`'s types, "B8, B7, W6, P5 or T4", for messages.
std::string zone_codes(char record);

}  // namespace tetsmooth::flac3d
