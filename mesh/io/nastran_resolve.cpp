// The Nastran deck reader's second half (nastran_reader.hpp): once every
// entry is read, ids become indices, and the mesh gets its tets (turned
// right-handed), pass-through blocks, regions and pins, by the rules of
// nastran_io.hpp.
#include <algorithm>
#include <limits>

#include "mesh/errors.hpp"
#include "mesh/second_order.hpp"
#include "mesh/io/nastran_reader.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::nastran {
namespace {

bool blank_or_zero(const std::string& field) { return field.empty() || field == "0"; }

}  // namespace

index_t DeckReader::node_of(long long id, const IdIndex& nodes, std::uint32_t mark, long long element) const {
  const long long n = nodes.find(id);
  if (n < 0)
    throw InputError(cards_.where(mark), "element " + std::to_string(element) + " names grid point " +
                                             std::to_string(id) + ", which no GRID defines");
  return static_cast<index_t>(n);
}

bool DeckReader::scalar_point(long long id) const {
  // scalar_points_ is sorted and merged (resolve_pins).
  const auto after = std::upper_bound(scalar_points_.begin(), scalar_points_.end(), std::make_pair(id, std::numeric_limits<long long>::max()));
  return after != scalar_points_.begin() && id <= (after - 1)->second;
}

void DeckReader::resolve_pins(const IdIndex& nodes) {
  std::sort(scalar_points_.begin(), scalar_points_.end());
  std::vector<std::pair<long long, long long>> merged;
  for (const auto& range : scalar_points_)
    if (!merged.empty() && range.first <= merged.back().second)
      merged.back().second = std::max(merged.back().second, range.second);
    else
      merged.push_back(range);
  scalar_points_ = std::move(merged);
  // GRDSET's PS stands for a blank one.
  const bool grdset_pins = !blank_or_zero(grdset_ps_);
  std::vector<std::uint8_t> pinned(mesh_.num_nodes(), 0);
  for (std::size_t i = 0; i < pinned.size(); ++i)
    pinned[i] = (grid_bits_[i] & kPsGiven) != 0 || (grdset_pins && (grid_bits_[i] & kPsBlank) != 0);
  mark_element_nodes(mesh_.extras.blocks, pinned);
  std::vector<std::size_t> in_range;
  for (const PinRef& ref : pin_refs_) {
    if (ref.first == ref.last) {
      const long long n = nodes.find(ref.first);
      if (n >= 0)
        pinned[static_cast<std::size_t>(n)] = 1;
      else if (!scalar_point(ref.first))
        throw InputError(cards_.where(ref.mark), std::string(ref.entry) + " names grid point " +
                                                     std::to_string(ref.first) + ", which no GRID defines");
      continue;
    }
    in_range.clear();  // THRU: grid points the range holds, those defined
    nodes.append_range(ref.first, ref.last, 1, in_range);
    for (std::size_t n : in_range) pinned[n] = 1;
  }
  if (std::find(pinned.begin(), pinned.end(), 1) != pinned.end()) mesh_.fixed = std::move(pinned);
}

void DeckReader::resolve() {
  FileExtras& e = mesh_.extras;
  if (!blank_or_zero(grdset_cp_) &&
      std::any_of(grid_bits_.begin(), grid_bits_.end(), [](std::uint8_t b) { return (b & kCpBlank) != 0; }))
    throw InputError(cards_.where(grdset_mark_),
                     "GRDSET gives the GRIDs without a CP coordinate system " + text_excerpt(grdset_cp_) +
                         ": nodes in other coordinate systems than the basic one are not read");
  const IdIndex nodes(e.node_tags), elements(element_ids_);
  if (const auto twice = nodes.repeated())
    throw InputError(cards_.where(node_marks_[*twice]),
                     "grid point " + std::to_string(e.node_tags[*twice]) + " is defined a second time");
  if (const auto twice = elements.repeated())
    throw InputError(cards_.where(element_marks_[*twice]),
                     "element id " + std::to_string(element_ids_[*twice]) + " is used a second time");
  const auto each = static_cast<std::size_t>(tet_nodes_each_);
  index_t tet[10];
  for (std::size_t t = 0; t < tet_marks_.size(); ++t) {
    for (std::size_t k = 0; k < each; ++k)
      tet[k] = node_of(tet_grids_[each * t + k], nodes, tet_marks_[t], e.tet_element_tags[t]);
    append_file_tet(mesh_, tet, each == 10, kCtetraMidsides);
  }
  if (const std::size_t turned = turn_left_handed_tets(mesh_); turned > 0)
    e.read_notes.push_back(std::to_string(turned) + " of the " + std::to_string(mesh_.num_tets()) +
                           " CTETRA list their grid points left-handed, which Nastran takes: they are read turned "
                           "round (G2 and G3 swapped), and the deck keeps them as written");
  for (const Others& o : others_) {
    PassThroughBlock& block = e.blocks.emplace_back();
    block.kind = o.kind;
    block.nodes_per_element = o.nodes;
    block.element_tags = o.ids;
    if (o.tagged) block.tags = o.pids;
    const auto n = static_cast<std::size_t>(o.nodes);
    for (std::size_t i = 0; i < o.ids.size(); ++i)
      for (std::size_t k = 0; k < n; ++k)
        block.connectivity.push_back(node_of(o.grids[i * n + k], nodes, o.marks[i], o.ids[i]));
  }
  resolve_pins(nodes);
}

}  // namespace tetsmooth::nastran
