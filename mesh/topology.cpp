#include "mesh/topology.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

namespace tetsmooth {
namespace {

// Local vertex pairs of a tet's six edges.
constexpr int kTetEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

// Rows from (row, item) pairs already sorted by row: counts, then an
// exclusive scan into offsets.
Csr csr_from_sorted_pairs(const std::vector<std::uint64_t>& keys, std::size_t rows) {
  Csr csr;
  csr.offsets.assign(rows + 1, 0);
  csr.items.resize(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) {
    ++csr.offsets[static_cast<std::size_t>(keys[k] >> 32) + 1];
    csr.items[k] = static_cast<index_t>(keys[k] & 0xffffffffu);
  }
  std::partial_sum(csr.offsets.begin(), csr.offsets.end(), csr.offsets.begin());
  return csr;
}

std::uint64_t pack(index_t hi, index_t lo) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(hi)) << 32) | static_cast<std::uint32_t>(lo);
}

}  // namespace

Csr build_neighbours(const std::vector<index_t>& tets, std::size_t num_nodes) {
  const std::size_t nt = tets.size() / 4;
  // Each edge in both directions, so every node's row is complete.
  std::vector<std::uint64_t> keys(nt * 12);
  for (std::size_t t = 0; t < nt; ++t)
    for (int e = 0; e < 6; ++e) {
      const index_t a = tets[4 * t + kTetEdges[e][0]], b = tets[4 * t + kTetEdges[e][1]];
      keys[12 * t + 2 * e] = pack(a, b);
      keys[12 * t + 2 * e + 1] = pack(b, a);
    }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  // A tet with a repeated node would give self loops; they are no neighbours.
  keys.erase(std::remove_if(keys.begin(), keys.end(), [](std::uint64_t k) { return (k >> 32) == (k & 0xffffffffu); }),
             keys.end());
  return csr_from_sorted_pairs(keys, num_nodes);
}

Csr build_node_tets(const std::vector<index_t>& tets, std::size_t num_nodes) {
  const std::size_t nt = tets.size() / 4;
  std::vector<std::uint64_t> keys(nt * 4);
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 4; ++k) keys[4 * t + k] = pack(tets[4 * t + k], static_cast<index_t>(t));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return csr_from_sorted_pairs(keys, num_nodes);
}

std::vector<FaceUse> sorted_face_uses(const std::vector<index_t>& tets) {
  const std::size_t nt = tets.size() / 4;
  std::vector<FaceUse> uses(nt * 4);
  for (std::size_t t = 0; t < nt; ++t)
    for (int f = 0; f < 4; ++f) {
      FaceUse& u = uses[4 * t + f];
      u.face = {tets[4 * t + kTetFaces[f][0]], tets[4 * t + kTetFaces[f][1]], tets[4 * t + kTetFaces[f][2]]};
      std::sort(u.face.begin(), u.face.end());
      u.opposite = tets[4 * t + f];
      u.tet = static_cast<index_t>(t);
    }
  std::sort(uses.begin(), uses.end(), [](const FaceUse& a, const FaceUse& b) {
    return std::tie(a.face, a.opposite, a.tet) < std::tie(b.face, b.opposite, b.tet);
  });
  return uses;
}

std::vector<std::uint8_t> find_boundary_nodes(const std::vector<index_t>& tets, std::size_t num_nodes) {
  const std::vector<FaceUse> uses = sorted_face_uses(tets);
  std::vector<std::uint8_t> boundary(num_nodes, 0);
  for (std::size_t first = 0, last; first < uses.size(); first = last) {
    for (last = first + 1; last < uses.size() && uses[last].face == uses[first].face; ++last) {
    }
    // Sorted by opposite node within the run: all uses agree on it exactly
    // when the first and the last do.
    if (uses[first].opposite == uses[last - 1].opposite)
      for (index_t n : uses[first].face) boundary[static_cast<std::size_t>(n)] = 1;
  }
  return boundary;
}

std::size_t count_repeated_tets(const std::vector<index_t>& tets) {
  std::vector<std::array<index_t, 4>> sorted(tets.size() / 4);
  for (std::size_t t = 0; t < sorted.size(); ++t) {
    std::copy(tets.begin() + 4 * t, tets.begin() + 4 * t + 4, sorted[t].begin());
    std::sort(sorted[t].begin(), sorted[t].end());
  }
  std::sort(sorted.begin(), sorted.end());
  std::size_t repeated = 0;
  for (std::size_t t = 1; t < sorted.size(); ++t) repeated += sorted[t] == sorted[t - 1];
  return repeated;
}

std::vector<std::uint8_t> movable_nodes(const TetMesh& mesh, const std::vector<std::uint8_t>& boundary,
                                        const Csr& neighbours) {
  const std::size_t n = mesh.num_nodes();
  std::vector<std::uint8_t> movable(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const bool pinned = !mesh.fixed.empty() && mesh.fixed[i];
    movable[i] = !boundary[i] && !pinned && neighbours.row_size(i) > 0;
  }
  return movable;
}

Topology build_topology(const TetMesh& mesh) {
  Topology topo;
  topo.neighbours = build_neighbours(mesh.tets, mesh.num_nodes());
  topo.node_tets = build_node_tets(mesh.tets, mesh.num_nodes());
  topo.boundary = find_boundary_nodes(mesh.tets, mesh.num_nodes());
  topo.movable = movable_nodes(mesh, topo.boundary, topo.neighbours);
  return topo;
}

double mean_edge_length(const std::vector<double>& xyz, const Csr& neighbours) {
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < neighbours.rows(); ++i)
    for (const index_t* j = neighbours.row_begin(i); j != neighbours.row_end(i); ++j) {
      if (static_cast<std::size_t>(*j) <= i) continue;
      const double dx = xyz[3 * i] - xyz[3 * *j], dy = xyz[3 * i + 1] - xyz[3 * *j + 1],
                   dz = xyz[3 * i + 2] - xyz[3 * *j + 2];
      sum += std::sqrt(dx * dx + dy * dy + dz * dz);
      ++count;
    }
  return count ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace tetsmooth
