// Node and element tags as MSH can write them back: Gmsh requires them to
// be positive and distinct (within nodes, and within all elements of every
// dimension together), and field data names them by 32-bit ints.
#include <algorithm>
#include <climits>
#include <functional>

#include "mesh/file_extras.hpp"
#include "mesh/io/gmsh_detail.hpp"

namespace tetsmooth::gmsh {

std::optional<long long> unusable_tag(std::vector<long long> tags, long long largest) {
  std::sort(tags.begin(), tags.end());
  if (!tags.empty() && tags.front() <= 0) return tags.front();
  if (!tags.empty() && tags.back() > largest) return tags.back();
  const auto repeated = std::adjacent_find(tags.begin(), tags.end());
  if (repeated != tags.end()) return *repeated;
  return std::nullopt;
}

std::map<int, int> negative_tag_renumbering(const FileExtras& extras) {
  long long largest = 0;
  std::vector<int> negative;
  const auto visit = [&](const std::vector<int>& tags) {
    for (int tag : tags) {
      largest = std::max<long long>(largest, tag);
      if (tag < 0) negative.push_back(tag);
    }
  };
  visit(extras.tet_tags);
  for (const PassThroughBlock& block : extras.blocks) visit(block.tags);
  std::sort(negative.begin(), negative.end(), std::greater<int>());
  negative.erase(std::unique(negative.begin(), negative.end()), negative.end());
  std::map<int, int> renumbered;
  for (int tag : negative)
    renumbered[tag] = ++largest <= INT_MAX ? static_cast<int>(largest) : 0;  // 0: past int, "none"
  return renumbered;
}

bool node_tags_fit_int(const std::vector<long long>& node_tags) {
  return std::all_of(node_tags.begin(), node_tags.end(), [](long long tag) { return tag <= kLargestIntTag; });
}

std::vector<long long> file_element_tags(const FileExtras& extras, std::size_t tets) {
  if (extras.tet_element_tags.size() != tets) return {};
  std::vector<long long> all = extras.tet_element_tags;
  for (const PassThroughBlock& block : extras.blocks) {
    const std::size_t count = block.nodes_per_element > 0 ? block.connectivity.size() / block.nodes_per_element : 0;
    if (block.element_tags.size() != count) return {};
    all.insert(all.end(), block.element_tags.begin(), block.element_tags.end());
  }
  return all;
}

}  // namespace tetsmooth::gmsh
