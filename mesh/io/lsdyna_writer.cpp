// LS-DYNA keyword deck writing (lsdyna_io.hpp): a deck read with the mesh
// comes back as it was read, the *NODE cards of moved nodes rewritten; any
// other mesh gets a new deck of its parts, nodes, elements and pins.
#include <algorithm>
#include <map>
#include <ostream>
#include <sstream>

#include "mesh/errors.hpp"
#include "mesh/io/file_numbers.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/lsdyna_cards.hpp"
#include "mesh/io/lsdyna_io.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/second_order.hpp"

namespace tetsmooth {
namespace {

using lsdyna::Layout;

// Ids and PIDs of the standard layout have at most 8 digits.
constexpr long long kLargestId = 99999999;
constexpr MidsidePlaces kMidsides = {4, 5, 6, 7, 8, 9};

// --- A deck read with the mesh --------------------------------------------

// One *NODE card, its coordinates rewritten where they changed (the text of
// one that did not change is kept), each in its layout's width.
std::string node_card(const std::string& line, Layout layout, const double* xyz) {
  const std::vector<int>& widths = lsdyna::node_widths(layout);
  const auto width = static_cast<std::size_t>(widths[1]);
  const lsdyna::Card card = lsdyna::card_of(line, widths);
  double was[3];
  bool moved = false;
  for (std::size_t c = 0; c < 3; ++c) {
    if (!lsdyna::real_field(card[1 + c], was[c])) throw OutputError("the kept LS-DYNA deck has a bad *NODE card");
    moved = moved || was[c] != xyz[c];
  }
  if (!moved) return line;
  if (card.free) {
    std::vector<std::string> fields(card.fields.begin(), card.fields.end());
    fields.resize(std::max<std::size_t>(fields.size(), 4));
    for (std::size_t c = 0; c < 3; ++c)
      if (was[c] != xyz[c]) fields[1 + c] = lsdyna::free_coordinate(xyz[c], width);
    std::string out;
    for (std::size_t k = 0; k < fields.size(); ++k) out += (k == 0 ? "" : ",") + fields[k];
    return out;
  }
  const auto id_width = static_cast<std::size_t>(widths[0]);
  std::string out = line.substr(0, std::min(line.size(), id_width));
  out.resize(id_width, ' ');
  for (std::size_t c = 0; c < 3; ++c) {
    const std::size_t at = id_width + c * width;
    std::string field =
        was[c] == xyz[c] && at < line.size() ? line.substr(at, width) : lsdyna::coordinate_field(xyz[c], width);
    if (field.size() < width) field.insert(0, width - field.size(), ' ');
    out += field;
  }
  const std::size_t rest = id_width + 3 * width;
  if (line.size() > rest) out += line.substr(rest);
  return out;
}

void write_kept_deck(const TetMesh& mesh, std::ostream& out) {
  std::size_t next = 0;
  for (const auto& [key, body] : mesh.extras.raw_sections) {
    if (key == "lsdyna:text") out << body;
    if (key != "lsdyna:nodes" && key != "lsdyna:nodes-i10" && key != "lsdyna:nodes-long") continue;
    const Layout layout = key == "lsdyna:nodes-i10"    ? Layout::I10
                          : key == "lsdyna:nodes-long" ? Layout::Long
                                                       : Layout::Standard;
    std::istringstream lines(body);
    for (std::string line; std::getline(lines, line);) {
      if (line.empty() || line[0] == '$' || trimmed(line).empty()) {
        out << line << '\n';
        continue;
      }
      if (next >= mesh.num_nodes())
        throw OutputError("the kept LS-DYNA deck has more *NODE cards than the mesh has nodes");
      out << node_card(line, layout, &mesh.xyz[3 * next]) << '\n';
      ++next;
    }
  }
}

// --- A new deck ---------------------------------------------------------------

// The element keyword a new deck writes a pass-through block under, and
// where each of the element's nodes goes among the card's node fields
// (nullptr for blocks it does not write).
struct WrittenKind {
  const char* keyword;
  std::vector<int> places;
};
const WrittenKind* written_kind(const PassThroughBlock& b) {
  static const WrittenKind kHexahedron{"ELEMENT_SOLID", {0, 1, 2, 3, 4, 5, 6, 7}};
  static const WrittenKind kWedge{"ELEMENT_SOLID", {0, 2, 5, 3, 1, 1, 4, 4}};
  static const WrittenKind kPyramid{"ELEMENT_SOLID", {0, 1, 2, 3, 4, 4, 4, 4}};
  static const WrittenKind kTriangle{"ELEMENT_SHELL", {0, 1, 2, 2}};
  static const WrittenKind kQuad{"ELEMENT_SHELL", {0, 1, 2, 3}};
  static const WrittenKind kLine{"ELEMENT_BEAM", {0, 1}};
  const int n = b.nodes_per_element;
  if (b.kind == "hexahedron" && n == 8) return &kHexahedron;
  if (b.kind == "wedge" && n == 6) return &kWedge;
  if (b.kind == "pyramid" && n == 5) return &kPyramid;
  if (b.kind == "triangle" && n == 3) return &kTriangle;
  if (b.kind == "quad" && n == 4) return &kQuad;
  if (b.kind == "line" && n == 2) return &kLine;
  return nullptr;
}

bool written_block(const PassThroughBlock& b) { return written_kind(b) != nullptr; }

void put(std::ostream& out, const std::string& text, std::size_t width) {
  if (text.size() < width) out << std::string(width - text.size(), ' ');
  out << text;
}

void put(std::ostream& out, long long v, std::size_t width) { put(out, std::to_string(v), width); }

void check_new_deck(const TetMesh& mesh) {
  if (mesh.num_tets() == 0) throw OutputError("the mesh has no tetrahedra to write");
  std::size_t elements = mesh.num_tets();
  for (const PassThroughBlock& b : mesh.extras.blocks) elements += elements_in(b);
  if (mesh.num_nodes() > static_cast<std::size_t>(kLargestId) || elements > static_cast<std::size_t>(kLargestId))
    throw OutputError("LS-DYNA's standard layout holds ids of at most 8 digits, and the mesh has more than "
                      "99,999,999 nodes or elements");
}

void write_parts(std::ostream& out, const TetMesh& mesh, const RegionIds& pids) {
  std::map<long long, std::string> parts;  // PID → heading
  const std::string* names_body = raw_section(mesh.extras, "$PhysicalNames");
  std::map<int, std::string> names[4];
  if (names_body != nullptr)
    for (int d = 0; d <= 3; ++d) names[d] = physical_names_of(*names_body, d);
  const auto add = [&](int dimension, int tag) {
    std::string& heading = parts[pids.of(dimension, tag)];
    const auto it = names[dimension].find(tag);
    if (heading.empty() && it != names[dimension].end()) heading = it->second;
  };
  const std::vector<int>& tags = mesh.extras.tet_tags;
  if (tags.size() != mesh.num_tets()) add(3, 0);
  for (int t : tags) add(3, t);
  for (const PassThroughBlock& b : mesh.extras.blocks) {
    if (!written_block(b)) continue;
    if (b.tags.size() != elements_in(b)) add(kind_dimension(b.kind), 0);
    for (int t : b.tags) add(kind_dimension(b.kind), t);
  }
  for (const auto& [pid, heading] : parts) {
    // A heading that would read as a keyword or a comment starts with a blank.
    const bool marked = !heading.empty() && (heading[0] == '*' || heading[0] == '$');
    out << "*PART\n$# title\n" << (marked ? " " : "") << heading.substr(0, marked ? 79 : 80)
        << "\n$#     pid     secid       mid\n";
    put(out, pid, 10);
    out << '\n';
  }
}

void write_new_deck(const TetMesh& mesh, std::ostream& out) {
  const std::vector<long long> node_ids = numbers_or_positions(mesh.extras.node_tags, mesh.num_nodes(), kLargestId);
  const std::vector<long long> ids = element_numbers(mesh, kLargestId, {true, written_block});
  const RegionIds pids = lsdyna_region_ids(mesh);
  out << "$ written by tetsmooth\n*KEYWORD\n";
  write_parts(out, mesh, pids);
  out << "*NODE\n$#   nid               x               y               z      tc      rc\n";
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    put(out, node_ids[i], 8);
    for (std::size_t c = 0; c < 3; ++c) out << lsdyna::coordinate_field(mesh.xyz[3 * i + c]);
    out << '\n';
  }
  const bool ten = !mesh.midsides.empty();
  const std::vector<int>& tags = mesh.extras.tet_tags;
  out << "*ELEMENT_SOLID\n";
  index_t nodes[10];
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    put(out, ids[t], 8);
    put(out, pids.of(3, tags.size() == mesh.num_tets() ? tags[t] : 0), 8);
    if (ten) {
      out << '\n';  // the nodes on a card of their own
      file_tet10(mesh, t, kMidsides, nodes);
      for (std::size_t k = 0; k < 10; ++k) put(out, node_ids[static_cast<std::size_t>(nodes[k])], 8);
    } else {
      for (std::size_t k = 0; k < 8; ++k)
        put(out, node_ids[static_cast<std::size_t>(mesh.tets[4 * t + std::min<std::size_t>(k, 3)])], 8);
    }
    out << '\n';
  }
  std::size_t first = mesh.num_tets();
  for (const PassThroughBlock& b : mesh.extras.blocks) {
    const WrittenKind* kind = written_kind(b);
    if (kind == nullptr) continue;
    out << '*' << kind->keyword << '\n';
    const auto n = static_cast<std::size_t>(b.nodes_per_element);
    for (std::size_t e = 0; e < elements_in(b); ++e) {
      put(out, ids[first + e], 8);
      put(out, pids.of(kind_dimension(b.kind), b.tags.size() == elements_in(b) ? b.tags[e] : 0), 8);
      for (int p : kind->places)
        put(out, node_ids[static_cast<std::size_t>(b.connectivity[e * n + static_cast<std::size_t>(p)])], 8);
      out << '\n';
    }
    first += elements_in(b);
  }
  const std::vector<long long> pinned = pins_to_list(mesh, node_ids, written_block);
  if (!pinned.empty()) {
    out << "*SET_NODE_LIST_TITLE\nTETSMOOTH_PINNED\n$#     sid\n         1\n";
    for (std::size_t k = 0; k < pinned.size(); ++k) {
      put(out, pinned[k], 10);
      if (k % 8 == 7 || k + 1 == pinned.size()) out << '\n';
    }
  }
  out << "*END\n";
}

constexpr DeckWriter kWriter{"lsdyna", "LS-DYNA deck", check_new_deck, write_kept_deck, write_new_deck};

}  // namespace

bool lsdyna_writes_block(const PassThroughBlock& block) { return written_block(block); }

RegionIds lsdyna_region_ids(const TetMesh& mesh) { return RegionIds(mesh, kLargestId, written_block); }

std::string lsdyna_numbers_lost(const TetMesh& mesh) {
  return has_kept_deck(mesh, "lsdyna") ? "" : numbers_lost(mesh, kLargestId, {ElementSet{true, written_block}});
}

void write_lsdyna(const TetMesh& mesh, std::ostream& out) { kWriter.write(mesh, out); }

void write_lsdyna_file(const TetMesh& mesh, const std::string& path) { kWriter.write_file(mesh, path); }

}  // namespace tetsmooth
