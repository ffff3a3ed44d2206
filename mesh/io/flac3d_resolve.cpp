// FLAC3D grid records resolved into a mesh (flac3d_io.hpp): ids into node
// indices, groups into region tags and names, zones other than tets and
// faces into pass-through blocks, and pins.
#include <algorithm>
#include <array>
#include <string_view>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "mesh/errors.hpp"
#include "mesh/io/flac3d_grid_records.hpp"
#include "mesh/io/flac3d_group_names.hpp"
#include "mesh/io/id_index.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth::flac3d {
namespace {

class Resolver {
 public:
  explicit Resolver(GridRecords records) : r_(std::move(records)) {}
  TetMesh resolve();

 private:
  [[noreturn]] void fail(std::size_t place, const std::string& what) const { throw InputError(r_.where(place), what); }
  std::array<index_t, 8> nodes_of(const Elements& from, std::size_t e, const char* what) const;
  std::vector<int> tags_of(char record, const Elements& elements, const IdIndex& ids, int dimension,
                           RegionNames& names);
  void place(const Elements& from, const std::vector<int>& tags, const char* what);

  GridRecords r_;
  IdIndex node_ids_{{}};
  TetMesh mesh_;
  std::vector<std::uint8_t> pinned_;
  std::size_t cut_bricks_ = 0;
};

// Zone or face e's gridpoints as node indices, in FLAC3D's order.
std::array<index_t, 8> Resolver::nodes_of(const Elements& from, std::size_t e, const char* what) const {
  std::array<index_t, 8> nodes{};
  for (std::size_t k = 0; k < from.types[e]->nodes; ++k) {
    const long long gp = from.gridpoints[from.first[e] + k];
    const long long n = node_ids_.find(gp);
    if (n < 0)
      fail(from.places[e], std::string(what) + " " + std::to_string(from.ids[e]) + " names gridpoint " +
                               std::to_string(gp) + ", which no gridpoint defines");
    nodes[k] = static_cast<index_t>(n);
  }
  return nodes;
}

// Tags for `elements` (zones or faces) from the groups of `record`, and the
// names of the groups that hold each tag; none without such groups. As in
// FLAC3D, groups of one name (in any case) in one slot are one group, and
// an element is in one group a slot: the last that lists it.
std::vector<int> Resolver::tags_of(char record, const Elements& elements, const IdIndex& ids, int dimension,
                                   RegionNames& names) {
  const std::size_t count = elements.ids.size();
  std::vector<std::string> slot_keys;                         // in upper case, "DEFAULT" for the default slot
  std::vector<std::string> slot_names;                        // as first spelled
  std::vector<std::vector<std::int32_t>> group_in;            // per slot: each element's group, or -1
  std::vector<Membership> groups;                             // as first spelled
  std::unordered_map<std::string, std::size_t> group_of_key;  // slot key, '\n', name in upper case
  std::vector<std::uint8_t> relisted(count, 0);               // elements listed in a second group of a slot
  for (const Group& g : r_.groups) {
    if (g.record != record) continue;
    const std::string slot_key = is_default_slot(g.slot) ? "DEFAULT" : upper_case(g.slot);
    auto slot = static_cast<std::size_t>(std::find(slot_keys.begin(), slot_keys.end(), slot_key) - slot_keys.begin());
    if (slot == slot_keys.size()) {
      slot_keys.push_back(slot_key);
      slot_names.push_back(g.slot.empty() ? "Default" : g.slot);
      group_in.emplace_back(count, -1);
    }
    const auto [found, added] = group_of_key.try_emplace(slot_key + '\n' + upper_case(g.name), groups.size());
    const std::size_t group = found->second;
    if (added) groups.push_back(Membership{slot_names[slot], g.name});
    for (std::size_t i = 0; i < g.ids.size(); ++i) {
      const long long e = ids.find(g.ids[i]);
      if (e < 0)
        fail(g.places[i], std::string(record == 'Z' ? "zone " : "face ") + std::to_string(g.ids[i]) + " of group " +
                              quoted_token(g.name) + " is not defined");
      std::int32_t& in = group_in[slot][static_cast<std::size_t>(e)];
      if (in >= 0 && in != static_cast<std::int32_t>(group)) relisted[static_cast<std::size_t>(e)] = 1;
      in = static_cast<std::int32_t>(group);
    }
  }
  if (groups.empty()) return {};
  if (const auto n = static_cast<std::size_t>(std::count(relisted.begin(), relisted.end(), 1)); n > 0)
    r_.notes.push_back(std::to_string(n) + (record == 'Z' ? " zone" : " face") + (n == 1 ? " is" : "s are") +
                       " listed in two groups of one slot: each is taken to be in the last, as FLAC3D does");
  RegionSplitter regions(count);
  std::vector<std::vector<std::size_t>> members(groups.size());
  for (const std::vector<std::int32_t>& in : group_in)
    for (std::size_t e = 0; e < count; ++e)
      if (in[e] >= 0) members[static_cast<std::size_t>(in[e])].push_back(e);
  for (const std::vector<std::size_t>& m : members) regions.split(m);
  std::vector<int> tags = regions.tags();
  // Each tag is named by the groups that hold its first element.
  std::vector<std::uint8_t> named(count + 1, 0);
  for (std::size_t e = 0; e < count; ++e) {
    const auto tag = static_cast<std::size_t>(tags[e]);
    if (named[tag]) continue;
    named[tag] = 1;
    std::vector<Membership> held;
    for (const std::vector<std::int32_t>& in : group_in)
      if (in[e] >= 0) held.push_back(groups[static_cast<std::size_t>(in[e])]);
    if (!held.empty()) names.add(dimension, tags[e], region_name(held));
  }
  return tags;
}

// The tets, blocks and pins of zones or faces.
void Resolver::place(const Elements& from, const std::vector<int>& tags, const char* what) {
  FileExtras& e = mesh_.extras;
  for (std::size_t z = 0; z < from.ids.size(); ++z) {
    const ZoneType& type = *from.types[z];
    const std::array<index_t, 8> nodes = nodes_of(from, z, what);
    if (type.kind == std::string_view("tetra")) {
      mesh_.tets.insert(mesh_.tets.end(), nodes.begin(), nodes.begin() + 4);
      e.tet_element_tags.push_back(from.ids[z]);
      if (!tags.empty()) e.tet_tags.push_back(tags[z]);
      continue;
    }
    for (std::size_t k = 0; k < type.nodes; ++k) pinned_[static_cast<std::size_t>(nodes[k])] = 1;
    if (*type.kind == '\0') {
      ++cut_bricks_;
      continue;
    }
    auto block =
        std::find_if(e.blocks.begin(), e.blocks.end(), [&](const PassThroughBlock& b) { return b.kind == type.kind; });
    if (block == e.blocks.end()) {
      block = e.blocks.insert(e.blocks.end(), PassThroughBlock{});
      block->kind = type.kind;
      block->nodes_per_element = static_cast<int>(type.nodes);
    }
    for (std::size_t k = 0; k < type.nodes; ++k)
      block->connectivity.push_back(nodes[static_cast<std::size_t>(type.from_file[k])]);
    block->element_tags.push_back(from.ids[z]);
    if (!tags.empty()) block->tags.push_back(tags[z]);
  }
}

TetMesh Resolver::resolve() {
  FileExtras& e = mesh_.extras;
  node_ids_ = IdIndex(r_.node_ids);
  if (const auto twice = node_ids_.repeated())
    fail(r_.node_places[*twice], "gridpoint " + std::to_string(r_.node_ids[*twice]) + " is defined a second time");
  const IdIndex zone_ids(r_.zones.ids), face_ids(r_.faces.ids);
  for (const auto& [ids, elements, what] :
       {std::tuple{&zone_ids, &r_.zones, "zone "}, std::tuple{&face_ids, &r_.faces, "face "}})
    if (const auto twice = ids->repeated())
      fail(elements->places[*twice], what + std::to_string(elements->ids[*twice]) + " is defined a second time");
  mesh_.xyz = std::move(r_.xyz);
  e.node_tags = std::move(r_.node_ids);

  RegionNames names;
  const std::vector<int> zone_tags = tags_of('Z', r_.zones, zone_ids, 3, names);
  const std::vector<int> face_tags = tags_of('F', r_.faces, face_ids, 2, names);
  pinned_.assign(mesh_.num_nodes(), 0);
  place(r_.zones, zone_tags, "zone");
  place(r_.faces, face_tags, "face");
  if (mesh_.tets.empty()) throw InputError(r_.source, "no T4 zones: tetsmooth smooths tetrahedral grids");
  for (const auto& [gp, at] : r_.pins) {
    const long long n = node_ids_.find(gp);
    if (n < 0) fail(at, "pinned gridpoint " + std::to_string(gp) + " is not defined");
    pinned_[static_cast<std::size_t>(n)] = 1;
  }
  if (std::find(pinned_.begin(), pinned_.end(), 1) != pinned_.end()) mesh_.fixed = std::move(pinned_);
  if (!names.empty()) e.raw_sections.emplace_back("$PhysicalNames", names.msh_body());
  if (cut_bricks_ > 0) e.raw_sections.emplace_back("flac3d:cut-bricks", std::to_string(cut_bricks_));
  e.read_notes = std::move(r_.notes);
  validate_mesh(mesh_, r_.source);
  return std::move(mesh_);
}

}  // namespace

TetMesh resolve_grid(GridRecords records) { return Resolver(std::move(records)).resolve(); }

}  // namespace tetsmooth::flac3d
