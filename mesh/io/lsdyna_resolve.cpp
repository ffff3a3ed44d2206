// The LS-DYNA deck reader's second half (lsdyna_reader.hpp): once every card
// is read, ids become indices, and the mesh gets its tets, pass-through
// blocks, region names and pins, by the rules of
// lsdyna_io.hpp.
#include <algorithm>
#include <set>

#include "mesh/errors.hpp"
#include "mesh/io/lsdyna_reader.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/second_order.hpp"

namespace tetsmooth::lsdyna {
namespace {

// LS-DYNA lists a 10-node tet's midside nodes in kTetEdges order.
constexpr MidsidePlaces kMidsides = {4, 5, 6, 7, 8, 9};

}  // namespace

index_t DeckReader::node_of(long long id, const IdIndex& nodes, std::uint32_t mark, const std::string& item) const {
  const long long n = nodes.find(id);
  if (n < 0)
    throw InputError(lines_.where_of(mark), item + " names node " + std::to_string(id) + ", which no *NODE defines");
  return static_cast<index_t>(n);
}

void DeckReader::resolve_pins(const IdIndex& nodes) {
  std::vector<std::uint8_t> pinned(constrained_);
  mark_element_nodes(mesh_.extras.blocks, pinned);
  std::vector<std::size_t> in_range;
  for (const PinRef& ref : pin_refs_) {
    if (ref.first == ref.last) {
      pinned[static_cast<std::size_t>(node_of(ref.first, nodes, ref.mark, "*" + ref.keyword))] = 1;
      continue;
    }
    in_range.clear();  // a set's range: the nodes defined in it
    nodes.append_range(ref.first, ref.last, 1, in_range);
    for (std::size_t n : in_range) pinned[n] = 1;
  }
  if (std::find(pinned.begin(), pinned.end(), 1) != pinned.end()) mesh_.fixed = std::move(pinned);
}

void DeckReader::resolve() {
  FileExtras& e = mesh_.extras;
  const IdIndex nodes(e.node_tags), solids(solid_ids_);
  if (const auto twice = nodes.repeated())
    throw InputError(lines_.where_of(node_marks_[*twice]),
                     "node " + std::to_string(e.node_tags[*twice]) + " is defined a second time");
  if (const auto twice = solids.repeated())
    throw InputError(lines_.where_of(solid_marks_[*twice]),
                     "solid element " + std::to_string(solid_ids_[*twice]) + " is defined a second time");
  const auto each = static_cast<std::size_t>(tet_nodes_each_);
  index_t tet[10];
  for (std::size_t t = 0; t < tet_marks_.size(); ++t) {
    for (std::size_t k = 0; k < each; ++k)
      tet[k] = node_of(tet_nodes_[each * t + k], nodes, tet_marks_[t],
                       "solid element " + std::to_string(e.tet_element_tags[t]));
    append_file_tet(mesh_, tet, each == 10, kMidsides);
  }
  // A left-handed tet is inverted (LS-DYNA takes a solid's nodes in one
  // order), and smoothing may untangle it: it is not turned round.
  std::set<std::pair<int, int>> used;  // (dimension, PID) of the elements
  for (int pid : e.tet_tags) used.emplace(3, pid);
  for (const Others& o : others_) {
    PassThroughBlock& block = e.blocks.emplace_back();
    block.kind = o.kind;
    block.nodes_per_element = o.nodes;
    block.element_tags = o.ids;
    block.tags = o.pids;
    for (int pid : o.pids) used.emplace(kind_dimension(o.kind), pid);
    const auto n = static_cast<std::size_t>(o.nodes);
    for (std::size_t i = 0; i < o.ids.size(); ++i)
      for (std::size_t k = 0; k < n; ++k)
        block.connectivity.push_back(
            node_of(o.nodes_of[i * n + k], nodes, o.marks[i], "element " + std::to_string(o.ids[i])));
  }
  RegionNames names;
  for (const auto& [pid, heading] : part_names_)
    for (int dimension = 0; dimension <= 3; ++dimension)
      if (used.count({dimension, pid}) != 0) names.add(dimension, pid, heading);
  if (!names.empty()) e.raw_sections.emplace_back("$PhysicalNames", names.msh_body());
  resolve_pins(nodes);
}

}  // namespace tetsmooth::lsdyna
