// The Abaqus deck reader's second half (abaqus_reader.hpp): once every line
// is read, node and element numbers become indices, sets their members,
// and the mesh gets its tets, pass-through blocks, regions and pins, by the
// rules of abaqus_io.hpp.
#include <algorithm>
#include <array>
#include <sstream>
#include <unordered_set>

#include "mesh/errors.hpp"
#include "mesh/io/abaqus_reader.hpp"
#include "mesh/io/abaqus_regions.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/number_text.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/second_order.hpp"

namespace tetsmooth::abaqus {
namespace {

// The set of the node pins that the writer leaves (abaqus_io.hpp).
constexpr const char* kPinnedSet = "TETSMOOTH_PINNED";


}  // namespace

std::vector<std::size_t> DeckReader::tets_of(const std::vector<std::size_t>& elements) const {
  std::vector<std::size_t> tets;
  for (std::size_t g : elements)
    if (element_at_[g] >= 0) tets.push_back(static_cast<std::size_t>(element_at_[g]));
  return tets;
}

void DeckReader::resolve_regions(const IdIndex& element_ids, RegionNames& names) {
  FileExtras& e = mesh_.extras;
  if (!sections_.empty()) {
    // A tet in two sections (which Abaqus refuses) takes the first.
    e.tet_tags.assign(tet_ids_.size(), 0);
    for (std::size_t s = 0; s < sections_.size(); ++s) {
      const int tag = static_cast<int>(s) + 1;
      names.add(3, tag, sections_[s].written);
      for (std::size_t g : sets_.elements(sections_[s].elset, sections_[s].where, element_ids))
        if (element_at_[g] >= 0 && e.tet_tags[static_cast<std::size_t>(element_at_[g])] == 0)
          e.tet_tags[static_cast<std::size_t>(element_at_[g])] = tag;
    }
    return;
  }
  e.tet_tags = tags_from_element_sets(tet_elsets_, elset_names_);
  names.add(3, e.tet_tags, tet_elsets_, elset_written_);
  if (!e.tet_tags.empty() || elset_order_.empty()) return;
  // Regions are the tets that the same element sets hold (meshio writes
  // Gmsh's physical groups so).
  RegionSplitter regions(tet_ids_.size());
  std::vector<std::vector<std::size_t>> tets_of_sets;
  for (const std::string& name : elset_order_) {
    tets_of_sets.push_back(tets_of(sets_.elements(name, "", element_ids)));
    regions.split(tets_of_sets.back());
  }
  e.tet_tags = regions.tags();
  name_regions_by_lists(tets_of_sets, names);
}

void DeckReader::name_regions_by_lists(const std::vector<std::vector<std::size_t>>& tets_of_sets,
                                       RegionNames& names) const {
  // A region takes the name of the first set that holds its tets and no
  // others, as a region named by ELSET= on *ELEMENT would; a region that
  // only several sets together describe (or none) stays unnamed.
  const std::vector<int>& tags = mesh_.extras.tet_tags;
  std::vector<std::size_t> tets_in(tags.size() + 1, 0);  // by tag: 1, 2, ... up to one per tet
  for (int t : tags) ++tets_in[static_cast<std::size_t>(t)];
  std::vector<std::size_t> seen_in(tags.size(), 0);  // the last set (+ 1) that met each tet
  for (std::size_t s = 0; s < tets_of_sets.size(); ++s) {
    const std::vector<std::size_t>& tets = tets_of_sets[s];
    if (tets.empty()) continue;
    const int tag = tags[tets.front()];
    std::size_t distinct = 0;
    bool one_region = true;
    for (std::size_t t : tets) {
      one_region = one_region && tags[t] == tag;
      if (seen_in[t] != s + 1) ++distinct;
      seen_in[t] = s + 1;
    }
    if (one_region && distinct == tets_in[static_cast<std::size_t>(tag)]) names.add(3, tag, elset_order_written_[s]);
  }
}

void DeckReader::resolve_pins(const IdIndex& node_ids, const IdIndex& element_ids) {
  std::vector<std::uint8_t> pinned(mesh_.num_nodes(), 0);
  mark_element_nodes(mesh_.extras.blocks, pinned);
  const auto mark_element = [&](std::size_t g, std::vector<std::uint8_t>& flags) {
    const std::int64_t at = element_at_[g];
    if (at >= 0) {
      const auto t = static_cast<std::size_t>(at);
      for (std::size_t k = 0; k < 4; ++k) flags[static_cast<std::size_t>(mesh_.tets[4 * t + k])] = 1;
      if (!mesh_.midsides.empty())
        for (std::size_t k = 0; k < 6; ++k) flags[static_cast<std::size_t>(mesh_.midsides[6 * t + k])] = 1;
      return;
    }
    const auto [b, i] = others_at_[static_cast<std::size_t>(-1 - at)];
    const PassThroughBlock& block = mesh_.extras.blocks[b];
    const auto n = static_cast<std::size_t>(block.nodes_per_element);
    for (std::size_t k = 0; k < n; ++k) flags[static_cast<std::size_t>(block.connectivity[i * n + k])] = 1;
  };
  std::unordered_set<std::string> sets_done;  // a set named on many lines is resolved once
  for (const PinRef& pin : pin_refs_) {
    const std::string where = lines_.where_of(pin.mark);
    const Ref ref = reference(pin.name, pin.scope, where);
    if (ref.is_node) {
      const long long node = node_ids.find(ref.key);
      if (node < 0)
        throw InputError(where, "node " + text_excerpt(pin.name) + " is not defined" +
                                    (has_parts() && pin.scope == 0
                                         ? " (outside parts, a number names a node of the assembly; a part's node is "
                                           "named through its instance: Instance.number)"
                                         : ""));
      pinned[static_cast<std::size_t>(node)] = 1;
    } else if (sets_done.insert(ref.set).second) {
      sets_.mark_nodes(ref.set, where, node_ids, element_ids, mark_element, pinned);
    }
  }
  if (sets_.has_nset(kPinnedSet)) sets_.mark_nodes(kPinnedSet, "", node_ids, element_ids, mark_element, pinned);
  if (std::find(pinned.begin(), pinned.end(), 1) != pinned.end()) mesh_.fixed = std::move(pinned);
}

void DeckReader::resolve() {
  FileExtras& e = mesh_.extras;
  place_instances();
  const IdIndex node_ids(node_keys_), element_ids(element_keys_);
  if (const auto twice = node_ids.repeated())
    throw InputError(lines_.where_of(node_marks_[*twice]),
                     "node " + std::to_string(e.node_tags[*twice]) + " is defined a second time");
  if (const auto twice = element_ids.repeated())
    throw InputError(lines_.where_of(element_marks_[*twice]),
                     "element " + std::to_string(element_ids_[*twice]) + " is defined a second time");
  RegionNames names;
  resolve_regions(element_ids, names);
  for (const Others& o : others_) {
    PassThroughBlock& block = e.blocks.emplace_back();
    block.kind = o.type.kind;
    block.nodes_per_element = o.type.nodes;
    block.element_tags = o.ids;
    block.tags = tags_from_element_sets(o.elsets, elset_names_);
    names.add(o.type.dimension, block.tags, o.elsets, elset_written_);
  }
  // Gmsh's name for each region, so that MSH output keeps the deck's.
  if (!names.empty()) e.raw_sections.emplace_back("$PhysicalNames", names.msh_body());
  // Elements in read order, so that each block's come in its own order.
  const auto each = static_cast<std::size_t>(tet_nodes_each_);
  index_t tet[10];
  for (std::size_t g = 0; g < element_ids_.size(); ++g) {
    const auto node = [&](long long id) {
      const long long n = node_ids.find(id);
      if (n < 0)
        throw InputError(lines_.where_of(element_marks_[g]), "element " + std::to_string(element_ids_[g]) +
                                                                 " names node " + std::to_string(shown(id)) +
                                                                 ", which no *NODE line defines");
      return static_cast<index_t>(n);
    };
    if (element_at_[g] >= 0) {
      const auto t = static_cast<std::size_t>(element_at_[g]);
      for (std::size_t k = 0; k < each; ++k) tet[k] = node(tet_nodes_[each * t + k]);
      append_file_tet(mesh_, tet, each == 10, kMidsidePlaces);
      continue;
    }
    const auto [b, i] = others_at_[static_cast<std::size_t>(-1 - element_at_[g])];
    const auto n = static_cast<std::size_t>(others_[b].type.nodes);
    for (std::size_t k = 0; k < n; ++k) e.blocks[b].connectivity.push_back(node(others_[b].nodes[i * n + k]));
  }
  e.tet_element_tags = tet_ids_;
  resolve_pins(node_ids, element_ids);
}

void DeckReader::place_instances() {
  FileExtras& e = mesh_.extras;
  for (const auto& [section, run_first] : node_runs_) {
    // A copy: a lambda may not capture a structured binding in C++17.
    const std::size_t first = run_first;
    const auto part = std::find_if(parts_.begin(), parts_.end(),
                                   [&](const Part& p) { return p.node_first <= first && first < p.node_end; });
    if (part == parts_.end()) continue;
    const Placement& placement = instances_[part->instance - 1].placement;
    if (!placement.moves()) continue;
    // The part's coordinates as read stay with the deck: the writer writes
    // a node that did not move as it was (abaqus_io.hpp).
    auto& [name, body] = e.raw_sections[section];
    const std::size_t count = std::stoull(body);
    std::ostringstream kept;
    kept << count << '\n' << placement.to_text() << '\n';
    for (std::size_t i = first; i < first + count; ++i) {
      double* xyz = &mesh_.xyz[3 * i];
      for (int c = 0; c < 3; ++c) {
        put_real(kept, xyz[c]);
        kept << (c < 2 ? ' ' : '\n');
      }
      const std::array<double, 3> placed = placement.place(xyz);
      std::copy(placed.begin(), placed.end(), xyz);
    }
    name = "abaqus:placed";
    body = kept.str();
  }
}

void DeckReader::keep_deck_notes() {
  FileExtras& e = mesh_.extras;
  stamp_kept_deck(mesh_, "abaqus");
  if (!other_keywords_.empty()) e.raw_sections.emplace_back("abaqus:keywords", joined(other_keywords_));
  if (!lines_.included().empty()) e.raw_sections.emplace_back("abaqus:includes", joined(lines_.included()));
}

}  // namespace tetsmooth::abaqus
