#include "mesh/io/file_numbers.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace tetsmooth {
namespace {

// The file's element numbers over the tets, then each block's elements, and
// how many elements there are; the numbers are empty unless every element
// has one.
std::pair<std::vector<long long>, std::size_t> file_element_numbers(const TetMesh& mesh) {
  std::vector<long long> ids = mesh.extras.tet_element_tags;
  std::size_t count = mesh.num_tets();
  bool complete = ids.size() == count;
  for (const PassThroughBlock& b : mesh.extras.blocks) {
    count += elements_in(b);
    complete = complete && b.element_tags.size() == elements_in(b);
    ids.insert(ids.end(), b.element_tags.begin(), b.element_tags.end());
  }
  return {complete ? ids : std::vector<long long>{}, count};
}

}  // namespace

bool usable_numbers(const std::vector<long long>& ids, std::size_t count, long long largest) {
  std::vector<long long> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  return ids.size() == count && (sorted.empty() || (sorted.front() > 0 && sorted.back() <= largest)) &&
         std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

std::vector<long long> numbers_or_positions(const std::vector<long long>& ids, std::size_t count, long long largest) {
  if (usable_numbers(ids, count, largest)) return ids;
  std::vector<long long> positions(count);
  for (std::size_t i = 0; i < count; ++i) positions[i] = static_cast<long long>(i) + 1;
  return positions;
}

std::size_t elements_in(const PassThroughBlock& b) {
  return b.nodes_per_element > 0 ? b.connectivity.size() / static_cast<std::size_t>(b.nodes_per_element) : 0;
}

std::vector<long long> element_numbers(const TetMesh& mesh, long long largest) {
  const auto [ids, count] = file_element_numbers(mesh);
  return numbers_or_positions(ids, count, largest);
}

std::vector<long long> pins_to_list(const TetMesh& mesh, const std::vector<long long>& node_numbers) {
  std::vector<std::uint8_t> by_element(mesh.num_nodes(), 0);
  mark_element_nodes(mesh.extras.blocks, by_element);
  std::vector<long long> listed;
  for (std::size_t i = 0; i < std::min(mesh.fixed.size(), mesh.num_nodes()); ++i)
    if (mesh.fixed[i] && !by_element[i]) listed.push_back(node_numbers[i]);
  return listed;
}

std::string numbers_lost(const TetMesh& mesh, long long largest) {
  const FileExtras& e = mesh.extras;
  const bool nodes = !e.node_tags.empty() && !usable_numbers(e.node_tags, mesh.num_nodes(), largest);
  const auto [ids, count] = file_element_numbers(mesh);
  bool any_element_ids = !e.tet_element_tags.empty();
  for (const PassThroughBlock& b : e.blocks) any_element_ids = any_element_ids || !b.element_tags.empty();
  const bool elements = any_element_ids && !usable_numbers(ids, count, largest);
  return nodes && elements ? "node and element" : nodes ? "node" : elements ? "element" : "";
}

}  // namespace tetsmooth
