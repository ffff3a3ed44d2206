#include "mesh/io/file_numbers.hpp"

#include <algorithm>
#include <cstdint>
#include <set>
#include <utility>

namespace tetsmooth {
namespace {

bool in_set(const ElementSet& set, const PassThroughBlock& b) { return !set.block || set.block(b); }

}  // namespace

std::pair<std::vector<long long>, std::size_t> file_element_numbers(const TetMesh& mesh, const ElementSet& set) {
  std::vector<long long> ids;
  std::size_t count = 0;
  bool complete = true;
  if (set.tets) {
    ids = mesh.extras.tet_element_tags;
    count = mesh.num_tets();
    complete = ids.size() == count;
  }
  for (const PassThroughBlock& b : mesh.extras.blocks) {
    if (!in_set(set, b)) continue;
    count += elements_in(b);
    complete = complete && b.element_tags.size() == elements_in(b);
    ids.insert(ids.end(), b.element_tags.begin(), b.element_tags.end());
  }
  return {complete ? ids : std::vector<long long>{}, count};
}

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

std::vector<long long> element_numbers(const TetMesh& mesh, long long largest, const ElementSet& set) {
  const auto [ids, count] = file_element_numbers(mesh, set);
  return numbers_or_positions(ids, count, largest);
}

std::vector<long long> pins_to_list(const TetMesh& mesh, const std::vector<long long>& node_numbers,
                                    const std::function<bool(const PassThroughBlock&)>& written) {
  // Pinned: the file's pins, and the nodes of blocks not written; kept: the
  // nodes of the written blocks, which pin them themselves.
  std::vector<std::uint8_t> pinned(mesh.num_nodes(), 0), kept(mesh.num_nodes(), 0);
  for (std::size_t i = 0; i < std::min(mesh.fixed.size(), mesh.num_nodes()); ++i) pinned[i] = mesh.fixed[i];
  for (const PassThroughBlock& b : mesh.extras.blocks)
    for (std::int32_t n : b.connectivity) (!written || written(b) ? kept : pinned)[static_cast<std::size_t>(n)] = 1;
  std::vector<long long> listed;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i)
    if (pinned[i] && !kept[i]) listed.push_back(node_numbers[i]);
  return listed;
}

std::map<int, int> new_positive_ids(const TetMesh& mesh, long long largest,
                                    const std::function<bool(const PassThroughBlock&)>& block) {
  std::set<int> kept;       // tags that are ids as they are
  std::vector<int> others;  // tags that are not; 0 for elements without one
  const auto visit = [&](const std::vector<int>& tags, std::size_t elements) {
    if (elements > 0 && tags.size() != elements) others.push_back(0);
    for (int tag : tags)
      if (tag > 0 && tag <= largest)
        kept.insert(tag);
      else
        others.push_back(tag);
  };
  visit(mesh.extras.tet_tags, mesh.num_tets());
  for (const PassThroughBlock& b : mesh.extras.blocks)
    if (!block || block(b)) visit(b.tags, elements_in(b));
  // 0 first, then -1, -2, ..., then the tags past the largest id, each the
  // next id that no tag holds: above the largest kept, then from 1 up.
  std::sort(others.begin(), others.end(), [](int a, int b) { return a <= 0 && b <= 0 ? a > b : a < b; });
  others.erase(std::unique(others.begin(), others.end()), others.end());
  std::map<int, int> renumbered;
  long long next = kept.empty() ? 1 : *kept.rbegin() + 1;
  for (int tag : others) {
    if (next > largest) next = 1;
    while (kept.count(static_cast<int>(next)) != 0) ++next;
    renumbered[tag] = static_cast<int>(next);
    kept.insert(static_cast<int>(next++));
  }
  return renumbered;
}

RegionIds::RegionIds(const TetMesh& mesh, long long largest, const std::function<bool(const PassThroughBlock&)>& block)
    : renumbered_(new_positive_ids(mesh, largest, block)) {
  std::set<std::pair<int, int>> present;  // (dimension, tag)
  const auto visit = [&](int dimension, const std::vector<int>& tags, std::size_t elements) {
    if (elements > 0 && tags.size() != elements) present.insert({dimension, 0});
    for (int tag : tags) present.insert({dimension, tag});
  };
  visit(3, mesh.extras.tet_tags, mesh.num_tets());
  for (const PassThroughBlock& b : mesh.extras.blocks)
    if (!block || block(b)) visit(kind_dimension(b.kind), b.tags, elements_in(b));
  std::map<long long, int> owner;  // id → the highest dimension that holds it
  for (const auto& [dimension, tag] : present) {
    int& d = owner.emplace(of(dimension, tag), dimension).first->second;
    d = std::max(d, dimension);
  }
  long long next = owner.empty() ? 1 : owner.rbegin()->first + 1;
  for (auto it = present.rbegin(); it != present.rend(); ++it) {  // higher dimensions first
    const auto [dimension, tag] = *it;
    if (owner.at(of(dimension, tag)) == dimension) continue;
    if (next > largest) next = 1;
    while (owner.count(next) != 0) ++next;
    split_[*it] = next;
    owner[next++] = dimension;
  }
}

long long RegionIds::of(int dimension, int tag) const {
  if (const auto it = split_.find({dimension, tag}); it != split_.end()) return it->second;
  const auto it = renumbered_.find(tag);
  return it == renumbered_.end() ? tag : it->second;
}

std::string numbers_lost(const TetMesh& mesh, long long largest, const std::vector<ElementSet>& sets) {
  const FileExtras& e = mesh.extras;
  const bool nodes = !e.node_tags.empty() && !usable_numbers(e.node_tags, mesh.num_nodes(), largest);
  bool elements = false;
  for (const ElementSet& set : sets) {
    bool any = set.tets && !e.tet_element_tags.empty();
    for (const PassThroughBlock& b : e.blocks) any = any || (in_set(set, b) && !b.element_tags.empty());
    const auto [ids, count] = file_element_numbers(mesh, set);
    elements = elements || (any && !usable_numbers(ids, count, largest));
  }
  return nodes && elements ? "node and element" : nodes ? "node" : elements ? "element" : "";
}

}  // namespace tetsmooth
