// FLAC3D grid records resolved into a mesh (flac3d_io.hpp): ids into node
// indices, groups into region tags and names, zones other than tets and
// faces into pass-through blocks, and pins.
#include <algorithm>
#include <string_view>
#include <utility>

#include "mesh/errors.hpp"
#include "mesh/io/flac3d_grid_records.hpp"
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
  [[noreturn]] void fail(std::size_t place, const std::string& what) const {
    throw InputError(r_.where(place), what);
  }
  std::vector<index_t> nodes_of(const Elements& from, std::size_t e, const char* what) const;
  std::vector<int> tags_of(char record, const Elements& elements, int dimension, RegionNames& names) const;
  void place(const Elements& from, const std::vector<int>& tags, const char* what);

  GridRecords r_;
  IdIndex node_ids_{{}};
  TetMesh mesh_;
  std::vector<std::uint8_t> pinned_;
  std::size_t cut_bricks_ = 0;
};

// Zone or face e's gridpoints as node indices, in FLAC3D's order.
std::vector<index_t> Resolver::nodes_of(const Elements& from, std::size_t e, const char* what) const {
  std::vector<index_t> nodes;
  for (std::size_t k = 0; k < from.types[e]->nodes; ++k) {
    const long long gp = from.gridpoints[from.first[e] + k];
    const long long n = node_ids_.find(gp);
    if (n < 0)
      fail(from.places[e], std::string(what) + " " + std::to_string(from.ids[e]) + " names gridpoint " +
                               std::to_string(gp) + ", which no gridpoint defines");
    nodes.push_back(static_cast<index_t>(n));
  }
  return nodes;
}

// Tags for `elements` (zones or faces) from the groups of `record`, and the
// names of the groups that hold each tag; none without such groups.
std::vector<int> Resolver::tags_of(char record, const Elements& elements, int dimension, RegionNames& names) const {
  const IdIndex ids(elements.ids);
  RegionSplitter regions(elements.ids.size());
  bool any = false;
  for (const Group& g : r_.groups) {
    if (g.record != record) continue;
    any = true;
    std::vector<std::size_t> members;
    for (std::size_t i = 0; i < g.ids.size(); ++i) {
      const long long e = ids.find(g.ids[i]);
      if (e < 0)
        fail(g.places[i], std::string(record == 'Z' ? "zone " : "face ") + std::to_string(g.ids[i]) + " of group " +
                              quoted_token(g.name) + " is not defined");
      members.push_back(static_cast<std::size_t>(e));
    }
    regions.split(members);
  }
  if (!any) return {};
  std::vector<int> tags = regions.tags();
  // Each tag is named by the groups that hold its first element.
  std::vector<std::size_t> first_of(elements.ids.size() + 1, elements.ids.size());
  for (std::size_t e = elements.ids.size(); e-- > 0;) first_of[static_cast<std::size_t>(tags[e])] = e;
  std::vector<std::string> named(elements.ids.size() + 1);
  for (const Group& g : r_.groups) {
    if (g.record != record) continue;
    const std::string* last = nullptr;  // a group that lists an element twice names its tag once
    for (long long gid : g.ids) {
      const auto e = static_cast<std::size_t>(ids.find(gid));
      std::string& name = named[static_cast<std::size_t>(tags[e])];
      if (first_of[static_cast<std::size_t>(tags[e])] != e || last == &name) continue;
      name += (name.empty() ? "" : " + ") + g.name;
      last = &name;
    }
  }
  for (std::size_t t = 1; t < named.size(); ++t)
    if (!named[t].empty()) names.add(dimension, static_cast<int>(t), named[t]);
  return tags;
}

// The tets, blocks and pins of zones or faces.
void Resolver::place(const Elements& from, const std::vector<int>& tags, const char* what) {
  FileExtras& e = mesh_.extras;
  for (std::size_t z = 0; z < from.ids.size(); ++z) {
    const ZoneType& type = *from.types[z];
    const std::vector<index_t> nodes = nodes_of(from, z, what);
    if (type.kind == std::string_view("tetra")) {
      mesh_.tets.insert(mesh_.tets.end(), nodes.begin(), nodes.end());
      e.tet_element_tags.push_back(from.ids[z]);
      if (!tags.empty()) e.tet_tags.push_back(tags[z]);
      continue;
    }
    for (index_t n : nodes) pinned_[static_cast<std::size_t>(n)] = 1;
    if (*type.kind == '\0') {
      ++cut_bricks_;
      continue;
    }
    auto block = std::find_if(e.blocks.begin(), e.blocks.end(), [&](const PassThroughBlock& b) { return b.kind == type.kind; });
    if (block == e.blocks.end()) {
      block = e.blocks.insert(e.blocks.end(), PassThroughBlock{});
      block->kind = type.kind;
      block->nodes_per_element = static_cast<int>(type.nodes);
    }
    for (std::size_t k = 0; k < type.nodes; ++k) block->connectivity.push_back(nodes[static_cast<std::size_t>(type.from_file[k])]);
    block->element_tags.push_back(from.ids[z]);
    if (!tags.empty()) block->tags.push_back(tags[z]);
  }
}

TetMesh Resolver::resolve() {
  FileExtras& e = mesh_.extras;
  node_ids_ = IdIndex(r_.node_ids);
  if (const auto twice = node_ids_.repeated())
    fail(r_.node_places[*twice], "gridpoint " + std::to_string(r_.node_ids[*twice]) + " is defined a second time");
  for (const auto& [elements, what] : {std::pair{&r_.zones, "zone "}, std::pair{&r_.faces, "face "}})
    if (const auto twice = IdIndex(elements->ids).repeated())
      fail(elements->places[*twice], what + std::to_string(elements->ids[*twice]) + " is defined a second time");
  mesh_.xyz = std::move(r_.xyz);
  e.node_tags = std::move(r_.node_ids);

  RegionNames names;
  const std::vector<int> zone_tags = tags_of('Z', r_.zones, 3, names);
  const std::vector<int> face_tags = tags_of('F', r_.faces, 2, names);
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
