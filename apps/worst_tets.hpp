#pragma once
// The tets an engineer should look at first.
#include <array>
#include <cstddef>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth::cli {

struct RankedTet {
  index_t tet = 0;                 // 0-based, in file order
  double quality = 0;              // radius ratio
  std::array<index_t, 4> nodes{};  // 0-based node indices
  // The file's own numbers (Gmsh tags, Abaqus element and node numbers),
  // where it has distinct numbers other than the positions 1, 2, ...; 0 where not
  // (the formats that keep numbers have them positive).
  long long element = 0;
  std::array<long long, 4> node_numbers{};
};

// The `k` tets of lowest quality, worst first (ties by index), from the
// per-tet qualities of mesh/quality_summary.hpp's tet_qualities, with the
// file's numbers for them where it has its own.
std::vector<RankedTet> worst_tets(const TetMesh& mesh, const std::vector<double>& qualities, std::size_t k);

}  // namespace tetsmooth::cli
