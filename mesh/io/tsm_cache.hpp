#pragma once
// The tetsmooth binary cache (.tsm): node coordinates and tets only, for
// reloading generated meshes fast (bench_smooth). Not an exchange format:
// extras, fixed flags and fields are not stored, and second-order tets are
// refused on writing.
//
// Layout, all little-endian, no padding:
//   offset 0    8 bytes   magic 89 'T' 'S' 'M' 0D 0A 1A 0A (catches text-mode
//                         and 7-bit mangling, as PNG's signature does)
//          8    uint32    format version, kTsmVersion
//          12   uint32    flags, 0 (reserved)
//          16   uint64    #N nodes
//          24   uint64    #T tets
//          32   float64   x,y,z per node (24 #N bytes)
//               int32     4 node indices per tet, 0-based (16 #T bytes)
//               uint64    FNV-1a 64-bit hash of every preceding byte
// Nothing may follow the hash.
#include <cstdint>
#include <istream>
#include <ostream>
#include <string>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

inline constexpr std::uint32_t kTsmVersion = 1;

// Throws InputError naming the source and byte offset for a bad magic,
// version or flags, implausible counts, truncation, a hash mismatch or
// trailing bytes; validates the mesh.
TetMesh read_cache(std::istream& in, const std::string& source);
TetMesh read_cache_file(const std::string& path);

void write_cache(const TetMesh& mesh, std::ostream& out);
void write_cache_file(const TetMesh& mesh, const std::string& path);

}  // namespace tetsmooth
