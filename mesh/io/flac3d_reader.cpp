// FLAC3D grid reading (flac3d_io.hpp): the records are read line by line
// and resolved once the whole grid is read, since a group may come before
// the zones it holds, and ids name items by the file's numbers.
#include <algorithm>
#include <cmath>
#include <istream>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/errors.hpp"
#include "mesh/io/flac3d_io.hpp"
#include "mesh/io/flac3d_records.hpp"
#include "mesh/io/flac3d_zone_types.hpp"
#include "mesh/io/id_index.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace {

using flac3d::ZoneType;

// Zones or faces as read: their types, ids, gridpoint ids and lines.
struct Elements {
  std::vector<const ZoneType*> types;
  std::vector<long long> ids;
  std::vector<std::size_t> first;  // into gridpoints
  std::vector<long long> gridpoints;
  std::vector<std::size_t> lines;
};

// A ZGROUP or FGROUP with its ids, each with the line it is on.
struct Group {
  char record;  // 'Z' or 'F'
  std::string name, slot;
  std::vector<long long> ids;
  std::vector<std::size_t> lines;
};

class GridReader {
 public:
  GridReader(std::string text, std::string source) : text_(std::move(text)), source_(std::move(source)) {}
  TetMesh read();

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw InputError(source_ + ":" + std::to_string(line), what);
  }
  long long id(std::string_view value, const char* what) const;
  void record(std::string_view line);
  void gridpoint();
  void element(Elements& into, char record);
  void group(char record);
  void resolve();
  // Zone or face e's gridpoints as node indices, in FLAC3D's order.
  std::vector<index_t> nodes_of(const Elements& from, std::size_t e, const IdIndex& node_ids, const char* what) const;
  void resolve_groups(char record, const Elements& elements, std::vector<int>& tags, int dimension,
                      RegionNames& names) const;

  std::string text_;
  std::string source_;
  std::size_t line_no_ = 0;
  std::vector<std::string_view> values_;
  TetMesh mesh_;
  std::vector<std::size_t> node_lines_;
  Elements zones_, faces_;
  std::vector<Group> groups_;
  // The group whose ids the next lines may list (an index in groups_).
  static constexpr std::size_t kNone = ~std::size_t{0};
  std::size_t open_group_ = kNone;
  std::vector<std::pair<long long, std::size_t>> pins_;  // (gridpoint id, line) of pin comments
};

long long GridReader::id(std::string_view value, const char* what) const {
  long long v = 0;
  if (!parse_integer(value, v)) fail(line_no_, std::string(what) + " " + quoted_token(value) + " is not a whole number");
  if (v <= 0) fail(line_no_, std::string(what) + " " + std::to_string(v) + " is not positive");
  return v;
}

void GridReader::gridpoint() {
  if (values_.size() != 5)
    fail(line_no_, "a gridpoint is 'G id x y z', and this line has " + std::to_string(values_.size()) + " values");
  mesh_.extras.node_tags.push_back(id(values_[1], "gridpoint id"));
  for (std::size_t c = 0; c < 3; ++c) {
    double v = 0;
    if (!parse_real(values_[2 + c], v) || !std::isfinite(v))
      fail(line_no_, std::string("coordinate ") + "xyz"[c] + " " + quoted_token(values_[2 + c]) +
                         " is not a finite number");
    mesh_.xyz.push_back(v);
  }
  node_lines_.push_back(line_no_);
}

void GridReader::element(Elements& into, char record) {
  const char* what = record == 'Z' ? "zone" : "face";
  if (values_.size() < 3) fail(line_no_, std::string("a ") + what + " is '" + record + " type id gridpoints...'");
  const ZoneType* type = flac3d::zone_type(values_[1], record);
  if (type == nullptr)
    fail(line_no_, std::string(what) + " type " + quoted_token(values_[1]) + " is not one of " +
                       flac3d::zone_codes(record));
  if (values_.size() != 3 + type->nodes)
    fail(line_no_, std::string("a ") + type->code + " " + what + " has " + std::to_string(type->nodes) +
                       " gridpoints, and this line lists " + std::to_string(values_.size() - 3));
  into.types.push_back(type);
  into.ids.push_back(id(values_[2], record == 'Z' ? "zone id" : "face id"));
  into.first.push_back(into.gridpoints.size());
  for (std::size_t k = 0; k < type->nodes; ++k) into.gridpoints.push_back(id(values_[3 + k], "gridpoint id"));
  into.lines.push_back(line_no_);
}

void GridReader::group(char record) {
  const bool slotted = values_.size() == 4 && upper_case(values_[2]) == "SLOT";
  if (values_.size() != 2 && !slotted)
    fail(line_no_, std::string("a group is '") + record + "GROUP name' or '" + record + "GROUP name SLOT slot'");
  groups_.push_back(Group{record, std::string(values_[1]), slotted ? std::string(values_[3]) : "", {}, {}});
  open_group_ = groups_.size() - 1;
}

void GridReader::record(std::string_view line) {
  if (!flac3d::split_values(line, values_)) fail(line_no_, "a quote that is not closed");
  if (values_.empty()) return;
  long long first = 0;
  if (parse_integer(values_[0], first)) {
    if (open_group_ == kNone) fail(line_no_, "a line of ids outside a ZGROUP or FGROUP");
    Group& g = groups_[open_group_];
    for (std::string_view v : values_) {
      g.ids.push_back(id(v, g.record == 'Z' ? "zone id" : "face id"));
      g.lines.push_back(line_no_);
    }
    return;
  }
  open_group_ = kNone;
  const std::string keyword = upper_case(values_[0]);
  if (keyword == "G")
    gridpoint();
  else if (keyword == "Z" || keyword == "F")
    element(keyword == "Z" ? zones_ : faces_, keyword[0]);
  else if (keyword == "ZGROUP" || keyword == "FGROUP")
    group(keyword[0]);
  else
    fail(line_no_, "record " + quoted_token(values_[0]) +
                       " is none that a FLAC3D grid holds (G, Z, F, ZGROUP, FGROUP, or a comment after '*')");
}

std::vector<index_t> GridReader::nodes_of(const Elements& from, std::size_t e, const IdIndex& node_ids,
                                          const char* what) const {
  std::vector<index_t> nodes;
  for (std::size_t k = 0; k < from.types[e]->nodes; ++k) {
    const long long gp = from.gridpoints[from.first[e] + k];
    const long long n = node_ids.find(gp);
    if (n < 0)
      fail(from.lines[e], std::string(what) + " " + std::to_string(from.ids[e]) + " names gridpoint " +
                              std::to_string(gp) + ", which no G line defines");
    nodes.push_back(static_cast<index_t>(n));
  }
  return nodes;
}

// Tags for `elements` (zones or faces) from the groups of `record`, and the
// names of the groups that hold each tag; none without such groups.
void GridReader::resolve_groups(char record, const Elements& elements, std::vector<int>& tags, int dimension,
                                RegionNames& names) const {
  const IdIndex ids(elements.ids);
  RegionSplitter regions(elements.ids.size());
  bool any = false;
  for (const Group& g : groups_) {
    if (g.record != record) continue;
    any = true;
    std::vector<std::size_t> members;
    for (std::size_t i = 0; i < g.ids.size(); ++i) {
      const long long e = ids.find(g.ids[i]);
      if (e < 0)
        fail(g.lines[i], std::string(record == 'Z' ? "zone " : "face ") + std::to_string(g.ids[i]) + " of group " +
                             quoted_token(g.name) + " is not defined");
      members.push_back(static_cast<std::size_t>(e));
    }
    regions.split(members);
  }
  if (!any) return;
  tags = regions.tags();
  // Each tag is named by the groups that hold its first element.
  std::vector<std::size_t> first_of(elements.ids.size() + 1, elements.ids.size());
  for (std::size_t e = elements.ids.size(); e-- > 0;) first_of[static_cast<std::size_t>(tags[e])] = e;
  std::vector<std::string> named(elements.ids.size() + 1);
  for (const Group& g : groups_) {
    if (g.record != record) continue;
    std::string* last = nullptr;  // a group that lists an element twice names its tag once
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
}

void GridReader::resolve() {
  FileExtras& e = mesh_.extras;
  const IdIndex node_ids(e.node_tags);
  if (const auto twice = node_ids.repeated())
    fail(node_lines_[*twice], "gridpoint " + std::to_string(e.node_tags[*twice]) + " is defined a second time");
  for (const auto& [elements, what] : {std::pair{&zones_, "zone "}, std::pair{&faces_, "face "}})
    if (const auto twice = IdIndex(elements->ids).repeated())
      fail(elements->lines[*twice], what + std::to_string(elements->ids[*twice]) + " is defined a second time");

  RegionNames names;
  std::vector<int> zone_tags, face_tags;
  resolve_groups('Z', zones_, zone_tags, 3, names);
  resolve_groups('F', faces_, face_tags, 2, names);

  std::vector<std::uint8_t> pinned(mesh_.num_nodes(), 0);
  std::size_t cut_bricks = 0;
  const auto place = [&](const Elements& from, const std::vector<int>& tags, const char* what) {
    for (std::size_t z = 0; z < from.ids.size(); ++z) {
      const ZoneType& type = *from.types[z];
      const std::vector<index_t> nodes = nodes_of(from, z, node_ids, what);
      const int tag = tags.empty() ? 0 : tags[z];
      if (type.kind == std::string_view("tetra")) {
        mesh_.tets.insert(mesh_.tets.end(), nodes.begin(), nodes.end());
        e.tet_element_tags.push_back(from.ids[z]);
        if (!tags.empty()) e.tet_tags.push_back(tag);
        continue;
      }
      for (index_t n : nodes) pinned[static_cast<std::size_t>(n)] = 1;
      if (*type.kind == '\0') {
        ++cut_bricks;
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
      if (!tags.empty()) block->tags.push_back(tag);
    }
  };
  place(zones_, zone_tags, "zone");
  place(faces_, face_tags, "face");
  if (mesh_.tets.empty()) throw InputError(source_, "no T4 zones: tetsmooth smooths tetrahedral grids");
  for (const auto& [gp, line] : pins_) {
    const long long n = node_ids.find(gp);
    if (n < 0) fail(line, "pinned gridpoint " + std::to_string(gp) + " is not defined");
    pinned[static_cast<std::size_t>(n)] = 1;
  }
  if (std::find(pinned.begin(), pinned.end(), 1) != pinned.end()) mesh_.fixed = std::move(pinned);
  if (!names.empty()) e.raw_sections.emplace_back("$PhysicalNames", names.msh_body());
  if (cut_bricks > 0)
    e.raw_sections.emplace_back("flac3d:cut-bricks", std::to_string(cut_bricks));
}

TetMesh GridReader::read() {
  if (text_.find('\0') != std::string::npos)
    throw InputError(source_, "a binary FLAC3D grid, which tetsmooth does not read: export it as text "
                              "(FLAC3D's zone export without the binary keyword)");
  std::size_t start = text_.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // a UTF-8 byte order mark
  while (start < text_.size()) {
    std::size_t end = text_.find('\n', start);
    if (end == std::string::npos) end = text_.size();
    const std::string_view line(text_.data() + start, end - start);
    ++line_no_;
    std::vector<std::string_view> ids;
    if (flac3d::pinned_comment(line, ids)) {
      for (std::string_view v : ids) pins_.emplace_back(id(v, "pinned gridpoint"), line_no_);
      open_group_ = kNone;
    } else if (flac3d::is_comment(line)) {
      open_group_ = kNone;
    } else {
      record(line);
    }
    start = end + 1;
  }
  resolve();
  validate_mesh(mesh_, source_);
  mesh_.extras.raw_sections.emplace_back("flac3d:text", std::move(text_));
  stamp_kept_deck(mesh_, "flac3d");
  return std::move(mesh_);
}

}  // namespace

TetMesh read_flac3d(std::istream& in, const std::string& source) {
  return GridReader(read_all(in, source), source).read();
}

TetMesh read_flac3d_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_flac3d(in, path);
}

}  // namespace tetsmooth
