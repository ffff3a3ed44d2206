#include "apps/worst_tets.hpp"

#include <algorithm>
#include <numeric>

namespace tetsmooth::cli {
namespace {

// The file's numbers, or empty where they are missing, just positions, or
// name no item alone (the parts of an Abaqus deck each number theirs 1, 2,
// ...; the indices then say which item is meant).
std::vector<long long> own_numbers(const std::vector<long long>& numbers, std::size_t count) {
  if (numbers.size() != count || numbered_by_position(numbers)) return {};
  std::vector<long long> sorted = numbers;
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end() ? numbers : std::vector<long long>{};
}

}  // namespace

std::vector<RankedTet> worst_tets(const TetMesh& mesh, const std::vector<double>& qualities, std::size_t k) {
  std::vector<index_t> order(qualities.size());
  std::iota(order.begin(), order.end(), index_t{0});
  k = std::min(k, order.size());
  // Partial sort: only k of possibly millions of tets are wanted.
  std::partial_sort(
      order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(),
      [&](index_t a, index_t b) { return qualities[a] < qualities[b] || (qualities[a] == qualities[b] && a < b); });
  const std::vector<long long> elements = own_numbers(mesh.extras.tet_element_tags, mesh.num_tets());
  const std::vector<long long> nodes = own_numbers(mesh.extras.node_tags, mesh.num_nodes());
  std::vector<RankedTet> ranked(k);
  for (std::size_t r = 0; r < k; ++r) {
    const index_t t = order[r];
    ranked[r].tet = t;
    ranked[r].quality = qualities[t];
    if (!elements.empty()) ranked[r].element = elements[static_cast<std::size_t>(t)];
    for (int c = 0; c < 4; ++c) {
      ranked[r].nodes[c] = mesh.tets[4 * static_cast<std::size_t>(t) + c];
      if (!nodes.empty()) ranked[r].node_numbers[c] = nodes[static_cast<std::size_t>(ranked[r].nodes[c])];
    }
  }
  return ranked;
}

}  // namespace tetsmooth::cli
