// FLAC3D grid writing (flac3d_io.hpp): a grid read with the mesh comes back
// as it was read, the G lines of moved gridpoints rewritten; any other mesh
// gets a new grid of its zones, faces, groups and pins.
#include <algorithm>
#include <array>
#include <map>
#include <ostream>
#include <set>
#include <string_view>
#include <utility>

#include "mesh/errors.hpp"
#include "mesh/io/file_numbers.hpp"
#include "mesh/io/flac3d_grid_records.hpp"
#include "mesh/io/flac3d_group_names.hpp"
#include "mesh/io/flac3d_io.hpp"
#include "mesh/io/flac3d_records.hpp"
#include "mesh/io/flac3d_zone_types.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/little_endian.hpp"
#include "mesh/io/number_text.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/second_order.hpp"
#include "mesh/vec3.hpp"

namespace tetsmooth {
namespace {

using flac3d::ZoneType;

// FLAC3D's ids are positive; its binary grids hold them in 32 bits, and
// ids up to 2^31 - 1 are safe in both.
constexpr long long kLargestId = 2147483647;
// Ids a line of a group or of a pin comment lists.
constexpr std::size_t kIdsPerLine = 10;

// --- A grid read with the mesh ----------------------------------------------

void write_gridpoint(std::ostream& out, std::string_view id, const double* xyz) {
  out << "G " << id;
  for (std::size_t c = 0; c < 3; ++c) {
    out << ' ';
    put_real(out, xyz[c]);
  }
}

// A binary grid's bytes as read, but for the coordinates, the mesh's
// (unchanged ones come out as they were).
void write_kept_binary_grid(const TetMesh& mesh, std::string bytes, std::ostream& out) {
  for (std::size_t k = 0; k < mesh.num_nodes(); ++k)
    for (std::size_t c = 0; c < 3; ++c)
      store_le(reinterpret_cast<unsigned char*>(&bytes[flac3d::binary_coordinates_at(k) + 8 * c]), mesh.xyz[3 * k + c]);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The grid's lines as read, but for the G lines of moved gridpoints.
void write_kept_grid(const TetMesh& mesh, std::ostream& out) {
  if (const std::string* bytes = raw_section(mesh.extras, "flac3d:binary"))
    return write_kept_binary_grid(mesh, *bytes, out);
  const std::string* kept = raw_section(mesh.extras, "flac3d:text");
  if (kept == nullptr) throw OutputError("the mesh is stamped as read from a FLAC3D grid, and carries no grid");
  const std::string& text = *kept;
  std::size_t start = bom_length(text);
  out << text.substr(0, start);
  std::size_t node = 0;
  std::vector<std::string_view> values;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    const bool broken = end != std::string::npos;
    if (!broken) end = text.size();
    const std::string_view line(text.data() + start, end - start);
    start = end + 1;
    // The reader took each such line for the next gridpoint.
    const bool gridpoint =
        !flac3d::is_comment(line) && flac3d::split_values(line, values) && flac3d::is_gridpoint(values);
    bool moved = false;
    if (gridpoint) {
      if (node >= mesh.num_nodes()) throw OutputError("the kept FLAC3D grid has more G lines than the mesh nodes");
      for (std::size_t c = 0; c < 3; ++c) {
        double v = 0;
        moved = moved || !parse_real(values[2 + c], v) || v != mesh.xyz[3 * node + c];
      }
    }
    if (moved) {
      write_gridpoint(out, values[1], &mesh.xyz[3 * node]);
      if (!line.empty() && line.back() == '\r') out << '\r';
    } else {
      out << line;
    }
    if (broken) out << '\n';
    node += gridpoint;
  }
}

// --- A new grid ---------------------------------------------------------------

// Whether a block's elements are written as zones or faces of `record`.
bool written_as(const PassThroughBlock& b, char record) {
  return flac3d_writes_kind(b.kind, b.nodes_per_element) && flac3d::zone_type_of_kind(b.kind)->record == record;
}

// The zones (record 'Z': the tets, then the elements of each block written
// as zones) or the faces ('F'), which FLAC3D numbers apart.
ElementSet elements_of(char record) {
  return ElementSet{record == 'Z', [record](const PassThroughBlock& b) { return written_as(b, record); }};
}

void check_new_grid(const TetMesh& mesh) {
  if (mesh.num_tets() == 0) throw OutputError("the mesh has no tetrahedra to write");
  check_first_order_output(mesh, "FLAC3D");
  std::size_t elements = mesh.num_tets();
  for (const PassThroughBlock& b : mesh.extras.blocks) elements += elements_in(b);
  if (mesh.num_nodes() > static_cast<std::size_t>(kLargestId) || elements > static_cast<std::size_t>(kLargestId))
    throw OutputError("FLAC3D ids are at most 2^31 - 1, and the mesh has more nodes or elements");
}

// A group's name in quotes: double ones, or single ones for a name that
// holds a double quote (with any single quote in it made a double one).
std::string quoted_name(std::string name) {
  if (name.find('"') == std::string::npos) return '"' + name + '"';
  for (char& c : name)
    if (c == '\'') c = '"';
  return '\'' + name + '\'';
}

// A slot's name as it is where it can be (SLOT Default), else quoted.
std::string slot_text(const std::string& slot) {
  const bool plain = !slot.empty() && slot.find_first_of(" \t,'\"") == std::string::npos;
  return plain ? slot : quoted_name(slot);
}

void write_ids(std::ostream& out, const char* first_line, const char* next_lines, const std::vector<long long>& ids) {
  for (std::size_t k = 0; k < ids.size(); ++k) {
    out << (k == 0 ? first_line : k % kIdsPerLine == 0 ? next_lines : " ");
    put_integer(out, ids[k]);
  }
  if (!ids.empty()) out << '\n';
}

// A group as FLAC3D tells groups apart: by slot (the default one however
// spelled) and name, in any case.
std::string group_key(const flac3d::Membership& m) {
  return (flac3d::is_default_slot(m.slot) ? std::string("DEFAULT") : upper_case(m.slot)) + '\n' + upper_case(m.group);
}

// A set of groups, whatever their order.
std::string set_key(const std::vector<flac3d::Membership>& groups) {
  std::vector<std::string> keys;
  for (const flac3d::Membership& m : groups) keys.push_back(group_key(m));
  std::sort(keys.begin(), keys.end());
  std::string key;
  for (const std::string& k : keys) key += k + '\n';
  return key;
}

// The elements of each region tag, and the tags in the order met.
class Groups {
 public:
  void add(int tag, long long id) {
    auto [it, added] = members_.try_emplace(tag);
    if (added) order_.push_back(tag);
    it->second.push_back(id);
  }
  // The GROUP lines ("ZGROUP", say) of the tags: each tag's name (from
  // `names`, else "region <tag>") read as groups in their slots
  // (flac3d_group_names.hpp), each group once with every element of the
  // tags it holds. Every tag keeps a set of groups of its own, so that the
  // regions read back apart: a tag whose groups another tag has got gets a
  // group of its own ("<name> (tag <tag>)"), and where one tag alone has no
  // name (the zones a grid put in no group) it gets no group at all.
  void write(std::ostream& out, const char* keyword, const std::map<int, std::string>& names) const {
    std::vector<flac3d::Membership> groups;    // in the order met
    std::map<std::string, std::size_t> index;  // slot and group, as group_key gives them -> in groups
    std::vector<std::vector<long long>> members;
    std::set<std::string> held;  // the set of groups of each tag so far, as set_key gives it
    std::size_t unnamed = 0;
    for (int tag : order_) unnamed += names.count(tag) == 0;
    for (int tag : order_) {
      const auto named = names.find(tag);
      if (named == names.end() && unnamed == 1) {
        held.insert("");
        continue;
      }
      const std::string name = named != names.end() ? named->second : "region " + std::to_string(tag);
      std::vector<flac3d::Membership> of_tag = flac3d::memberships_of(name);
      for (int n = 0; !held.insert(set_key(of_tag)).second; ++n)
        of_tag = {flac3d::Membership{
            "Default", name + " (tag " + std::to_string(tag) + (n == 0 ? "" : ", " + std::to_string(n)) + ")"}};
      for (const flac3d::Membership& m : of_tag) {
        const auto [it, added] = index.try_emplace(group_key(m), groups.size());
        if (added) {
          groups.push_back(flac3d::Membership{flac3d::is_default_slot(m.slot) ? "Default" : m.slot, m.group});
          members.emplace_back();
        }
        const std::vector<long long>& ids = members_.at(tag);
        members[it->second].insert(members[it->second].end(), ids.begin(), ids.end());
      }
    }
    for (std::size_t g = 0; g < groups.size(); ++g) {
      out << keyword << ' ' << quoted_name(groups[g].group) << " SLOT " << slot_text(groups[g].slot) << '\n';
      write_ids(out, " ", "\n ", members[g]);
    }
  }

 private:
  std::map<int, std::vector<long long>> members_;
  std::vector<int> order_;
};

// FLAC3D's list of a zone or face from its nodes in the other formats' order
// (flac3d_zone_types.hpp), mirrored where the first four would be
// left-handed.
std::array<index_t, 8> file_order(const TetMesh& mesh, const ZoneType& type, const std::int32_t* nodes) {
  std::array<index_t, 8> listed{}, mirrored{};
  for (std::size_t k = 0; k < type.nodes; ++k) listed[static_cast<std::size_t>(type.from_file[k])] = nodes[k];
  if (type.record != 'Z') return listed;
  const auto at = [&](std::size_t k) {
    const double* p = &mesh.xyz[3 * static_cast<std::size_t>(listed[k])];
    return Vec3<double>{p[0], p[1], p[2]};
  };
  const Vec3<double> o = at(0);
  if (dot(at(1) - o, cross(at(2) - o, at(3) - o)) >= 0) return listed;
  for (std::size_t k = 0; k < type.nodes; ++k) mirrored[k] = listed[static_cast<std::size_t>(type.mirrored[k])];
  return mirrored;
}

void write_new_grid(const TetMesh& mesh, std::ostream& out) {
  const FileExtras& e = mesh.extras;
  const std::vector<long long> node_ids = numbers_or_positions(e.node_tags, mesh.num_nodes(), kLargestId);
  const std::string* physical = raw_section(e, "$PhysicalNames");
  const std::string no_names;
  out << "* FLAC3D grid written by tetsmooth\n* GRIDPOINTS\n";
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    write_gridpoint(out, std::to_string(node_ids[i]), &mesh.xyz[3 * i]);
    out << '\n';
  }
  const auto node_text = [&](index_t n) { return node_ids[static_cast<std::size_t>(n)]; };
  // Zones, then faces, each with their groups.
  for (const char record : {'Z', 'F'}) {
    out << (record == 'Z' ? "* ZONES\n" : "* FACES\n");
    Groups groups;
    const std::vector<long long> ids = element_numbers(mesh, kLargestId, elements_of(record));
    std::size_t next = 0;  // in ids
    if (record == 'Z')
      for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
        out << "Z T4 " << ids[next];
        for (std::size_t k = 0; k < 4; ++k) out << ' ' << node_text(mesh.tets[4 * t + k]);
        out << '\n';
        if (e.tet_tags.size() == mesh.num_tets()) groups.add(e.tet_tags[t], ids[next]);
        ++next;
      }
    for (const PassThroughBlock& b : e.blocks) {
      if (!written_as(b, record)) continue;
      const ZoneType& type = *flac3d::zone_type_of_kind(b.kind);
      const std::size_t count = elements_in(b);
      for (std::size_t i = 0; i < count; ++i, ++next) {
        const std::array<index_t, 8> listed = file_order(mesh, type, &b.connectivity[i * type.nodes]);
        out << record << ' ' << type.code << ' ' << ids[next];
        for (std::size_t k = 0; k < type.nodes; ++k) out << ' ' << node_text(listed[k]);
        out << '\n';
        if (b.tags.size() == count) groups.add(b.tags[i], ids[next]);
      }
    }
    out << (record == 'Z' ? "* ZONE GROUPS\n" : "* FACE GROUPS\n");
    groups.write(out, record == 'Z' ? "ZGROUP" : "FGROUP",
                 physical_names_of(physical != nullptr ? *physical : no_names, record == 'Z' ? 3 : 2));
  }
  // Pins that no zone or face written keeps: the file's own, and the nodes
  // of the elements FLAC3D has no place for.
  const std::string first_line = std::string(flac3d::kPinnedComment) + " ";
  write_ids(out, first_line.c_str(), ("\n" + first_line).c_str(),
            pins_to_list(mesh, node_ids,
                         [](const PassThroughBlock& b) { return flac3d_writes_kind(b.kind, b.nodes_per_element); }));
}

constexpr DeckWriter kWriter{"flac3d", "FLAC3D grid", check_new_grid, write_kept_grid, write_new_grid};

}  // namespace

bool flac3d_writes_kind(const std::string& kind, int nodes_per_element) {
  const ZoneType* type = flac3d::zone_type_of_kind(kind);
  return type != nullptr && *type->kind != '\0' && kind != "tetra" &&
         type->nodes == static_cast<std::size_t>(nodes_per_element);
}

std::string flac3d_numbers_lost(const TetMesh& mesh) {
  return has_kept_deck(mesh, "flac3d") ? "" : numbers_lost(mesh, kLargestId, {elements_of('Z'), elements_of('F')});
}

void write_flac3d(const TetMesh& mesh, std::ostream& out) { kWriter.write(mesh, out); }

void write_flac3d_file(const TetMesh& mesh, const std::string& path) { kWriter.write_file(mesh, path); }

}  // namespace tetsmooth
