// ANSYS file reading (ansys_io.hpp): the file's numbers into the mesh, its
// regions and its pins, once every line is read.
#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "mesh/errors.hpp"
#include "mesh/io/ansys_element_types.hpp"
#include "mesh/io/ansys_reader.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/second_order.hpp"

namespace tetsmooth::ansys {
namespace {

// The kinds of pass-through elements that solids give.
const char* kind_of(Shape shape) {
  switch (shape) {
    case Shape::Hexahedron:
      return "hexahedron";
    case Shape::Wedge:
      return "wedge";
    case Shape::Pyramid:
      return "pyramid";
    default:
      return nullptr;
  }
}

// The places of a 10-node tet's midside nodes in the list append_file_tet
// takes (its corners then kTetEdges' midside nodes).
constexpr MidsidePlaces kInOrder = {4, 5, 6, 7, 8, 9};

// `ranges` (first, last) sorted, those that overlap or touch made one.
std::vector<std::pair<long long, long long>> merged(std::vector<std::pair<long long, long long>> ranges) {
  std::sort(ranges.begin(), ranges.end());
  std::vector<std::pair<long long, long long>> out;
  for (const auto& r : ranges)
    if (!out.empty() && r.first - 1 <= out.back().second)
      out.back().second = std::max(out.back().second, r.second);
    else
      out.push_back(r);
  return out;
}

}  // namespace

void FileReader::resolve_elements(const IdIndex& nodes) {
  FileExtras& e = mesh_.extras;
  std::map<const char*, std::size_t> block_of;  // pass-through kind -> its block in e.blocks
  std::vector<std::uint8_t>& fixed = mesh_.fixed;
  int tet_nodes = 0;
  std::vector<index_t> index;  // an element's nodes, -1 where it lists none
  std::set<std::string> uncarried;
  tet_of_element_.assign(elements_.size(), -1);
  block_element_.assign(elements_.size(), kNotPassed);
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const Element& el = elements_[i];
    const long long* listed_nodes = element_nodes_.data() + el.first;
    index.assign(el.count, -1);
    for (std::size_t k = 0; k < el.count; ++k) {
      if (listed_nodes[k] == 0) continue;
      const long long n = nodes.find(listed_nodes[k]);
      if (n < 0)
        fail_at(el.line, "element " + std::to_string(el.number) + " lists node " + std::to_string(listed_nodes[k]) +
                             ", which no NBLOCK defines");
      index[k] = static_cast<index_t>(n);
    }
    const auto type = types_.find(el.type);
    if (type == types_.end())
      fail_at(el.line, "element " + std::to_string(el.number) + " is of type " + std::to_string(el.type) +
                           ", which no ET command defines");
    const Family family = el.solid ? family_of(type->second.number) : Family::Other;
    const SolidShape shape = solid_shape(family, listed_nodes, static_cast<int>(el.count));
    if (shape.shape == Shape::Tet4 || shape.shape == Shape::Tet10) {
      const int count = shape.count;
      if (tet_nodes != 0 && tet_nodes != count) fail_at(el.line, mixed_tet_kinds(count));
      tet_nodes = count;
      index_t tet[10];
      for (int k = 0; k < count; ++k) tet[k] = index[shape.places[k]];
      tet_of_element_[i] = static_cast<long long>(mesh_.num_tets());
      append_file_tet(mesh_, tet, count == 10, kInOrder);
      e.tet_tags.push_back(el.mat);
      e.tet_element_tags.push_back(el.number);
      continue;
    }
    // Every other element pins its nodes.
    for (std::size_t k = 0; k < el.count; ++k)
      if (index[k] >= 0) fixed[static_cast<std::size_t>(index[k])] = 1;
    if (const char* kind = kind_of(shape.shape); kind != nullptr) {
      const auto [at, added] = block_of.emplace(kind, e.blocks.size());
      if (added) {
        PassThroughBlock& b = e.blocks.emplace_back();
        b.kind = kind;
        b.nodes_per_element = shape.count;
      }
      PassThroughBlock& b = e.blocks[at->second];
      for (int k = 0; k < shape.count; ++k) b.connectivity.push_back(index[shape.places[k]]);
      block_element_[i] = {at->second, b.tags.size()};
      b.tags.push_back(el.mat);
      b.element_tags.push_back(el.number);
      continue;
    }
    const std::string& name = type->second.name;
    if (uncarried.insert(name).second) uncarried_.push_back(name);
  }
  if (mesh_.tets.empty())
    throw InputError(source_,
                     "no tets among the EBLOCK elements: a volume mesh of tets is needed (SOLID285, "
                     "SOLID187, or a SOLID185/186 with the nodes of a tet)");
}

void FileReader::resolve_regions(const IdIndex& elements) {
  FileExtras& e = mesh_.extras;
  // Each element component's solids (tets and pass-through solids), as
  // places in elements_, in order, once each.
  std::vector<std::pair<const Component*, std::vector<std::size_t>>> solid_sets;
  for (const Component& c : components_) {
    if (c.nodes) continue;
    std::vector<std::size_t> places;
    for (const auto& [first, last] : merged(c.ranges)) {
      if (first == last && elements.find(first) < 0)
        fail_at(c.line, "component " + quoted_token(c.name) + " lists element " + std::to_string(first) +
                            ", which no EBLOCK defines");
      elements.append_range(first, last, 1, places);
    }
    places.erase(
        std::remove_if(places.begin(), places.end(),
                       [&](std::size_t p) { return tet_of_element_[p] < 0 && block_element_[p] == kNotPassed; }),
        places.end());
    std::sort(places.begin(), places.end());
    if (!places.empty()) solid_sets.emplace_back(&c, std::move(places));
  }
  if (solid_sets.empty()) return;
  // Regions: the materials, split further where a component holds some of a
  // material's solids and not the others. The solids are numbered tets
  // first, then the pass-through solids in element order, so that both get
  // regions of one numbering.
  std::vector<long long> solid_of(elements_.size(), -1);
  std::vector<int> mats = e.tet_tags;
  for (std::size_t p = 0; p < elements_.size(); ++p)
    if (tet_of_element_[p] >= 0) solid_of[p] = tet_of_element_[p];
  for (std::size_t p = 0; p < elements_.size(); ++p)
    if (const auto [b, i] = block_element_[p]; b != kNotPassed.first) {
      solid_of[p] = static_cast<long long>(mats.size());
      mats.push_back(e.blocks[b].tags[i]);
    }
  std::map<int, std::vector<std::size_t>> by_mat;
  for (std::size_t k = 0; k < mats.size(); ++k) by_mat[mats[k]].push_back(k);
  RegionSplitter splitter(mats.size());
  for (const auto& [mat, members] : by_mat) splitter.split(members);
  std::vector<std::size_t> members;
  for (const auto& [component, places] : solid_sets) {
    members.clear();
    for (std::size_t p : places) members.push_back(static_cast<std::size_t>(solid_of[p]));
    splitter.split(members);
  }
  std::vector<int> regions = splitter.tags();
  const int count = regions.empty() ? 0 : *std::max_element(regions.begin(), regions.end());
  if (static_cast<std::size_t>(count) != by_mat.size()) {
    e.read_notes.push_back("element components divide materials, so the " + std::to_string(count) +
                           " regions they make (the solids that share a material and their components) are "
                           "numbered 1, 2, ... in order of their first solids");
  } else {
    regions = mats;
  }
  // The regions into the tets and the pass-through solids' blocks.
  std::copy_n(regions.begin(), e.tet_tags.size(), e.tet_tags.begin());
  for (std::size_t p = 0; p < elements_.size(); ++p)
    if (const auto [b, i] = block_element_[p]; b != kNotPassed.first)
      e.blocks[b].tags[i] = regions[static_cast<std::size_t>(solid_of[p])];
  std::map<int, std::size_t> region_size;
  for (int tag : regions) ++region_size[tag];
  RegionNames names;
  for (const auto& [component, places] : solid_sets) {
    const int tag = regions[static_cast<std::size_t>(solid_of[places.front()])];
    const bool one = std::all_of(places.begin(), places.end(),
                                 [&](std::size_t p) { return regions[static_cast<std::size_t>(solid_of[p])] == tag; });
    if (one && region_size[tag] == places.size()) names.add(3, tag, component->name);
  }
  if (!names.empty()) e.raw_sections.emplace_back("$PhysicalNames", names.msh_body());
}

void FileReader::resolve_pins(const IdIndex& nodes) {
  std::vector<std::uint8_t>& fixed = mesh_.fixed;
  // Node components and single-step loads as one set of ranges, merged, so
  // that a node is marked once however many of them repeat it.
  std::vector<std::pair<long long, long long>> ranges;
  std::set<std::string> node_components;
  for (const Component& c : components_) {
    if (!c.nodes) continue;
    node_components.insert(upper_case(c.name));
    for (const auto& [first, last] : c.ranges) {
      if (first == last && nodes.find(first) < 0)
        fail_at(c.line, "component " + quoted_token(c.name) + " lists node " + std::to_string(first) +
                            ", which no NBLOCK defines");
      ranges.emplace_back(first, last);
    }
  }
  std::set<std::tuple<long long, long long, long long>> stepped;
  for (const PinnedRange& range : pinned_) {
    if (nodes.find(range.first) < 0)
      fail_at(range.line, "node " + std::to_string(range.first) + " is named here, and no NBLOCK defines it");
    if (range.step == 1)
      ranges.emplace_back(range.first, range.last);
    else
      stepped.emplace(range.first, range.last, range.step);
  }
  // Each range marked as it is expanded, so that memory stays that of the
  // largest.
  std::vector<std::size_t> places;
  const auto mark = [&](long long first, long long last, long long step) {
    places.clear();
    nodes.append_range(first, last, step, places);
    for (std::size_t p : places) fixed[p] = 1;
  };
  for (const auto& [first, last] : merged(ranges)) mark(first, last, 1);
  for (const auto& [first, last, step] : stepped) mark(first, last, step);
  std::vector<std::string> unknown;
  std::set<std::string> noted;
  for (const auto& [word, command] : named_components_)
    if (node_components.count(word) == 0 && noted.insert(word).second)
      unknown.push_back(command + " " + text_excerpt(word));
  if (!unknown.empty())
    mesh_.extras.read_notes.push_back(
        "the file names nodes by words that no node CMBLOCK defines (" + listed(unknown, 12) +
        "): a parameter tetsmooth cannot evaluate, or a component made by selection (CM); their nodes are pinned "
        "only where a node component or an element pins them");
}

void FileReader::resolve() {
  FileExtras& e = mesh_.extras;
  const IdIndex nodes(node_numbers_);
  if (const auto twice = nodes.repeated())
    fail_at(node_lines_[*twice], "node " + std::to_string(node_numbers_[*twice]) + " is defined a second time");
  std::vector<long long> numbers;
  for (const Element& el : elements_) numbers.push_back(el.number);
  const IdIndex elements(numbers);
  if (const auto twice = elements.repeated())
    fail_at(elements_[*twice].line, "element " + std::to_string(numbers[*twice]) + " is defined a second time");
  e.node_tags = node_numbers_;
  mesh_.fixed.assign(node_numbers_.size(), 0);
  resolve_elements(nodes);
  resolve_regions(elements);
  resolve_pins(nodes);
  if (std::find(mesh_.fixed.begin(), mesh_.fixed.end(), 1) == mesh_.fixed.end()) mesh_.fixed.clear();
}

void FileReader::keep_notes() {
  FileExtras& e = mesh_.extras;
  stamp_kept_deck(mesh_, "ansys");
  if (!commands_.empty()) e.raw_sections.emplace_back("ansys:commands", listed(commands_, 12));
  if (!uncarried_.empty()) e.raw_sections.emplace_back("ansys:uncarried", joined(uncarried_));
  if (!by_selection_.empty())
    e.read_notes.push_back("the file's " + joined(by_selection_) +
                           " commands name nodes through APDL's selection (ALL, P), which tetsmooth does not "
                           "follow: their nodes are pinned only where a node component or an element pins them");
  if (!generated_.empty())
    e.read_notes.push_back("the file's " + joined(generated_) +
                           " commands make coupled sets or constraint equations from others, which tetsmooth does not "
                           "follow: the nodes of those they make are pinned only where something else pins them");
  if (!cdwrite_forms_.empty())
    e.read_notes.push_back("the file's " + joined(cdwrite_forms_) +
                           " commands in CDWRITE's block form are not read: their nodes are pinned only where a node "
                           "component or an element pins them");
}

}  // namespace tetsmooth::ansys
