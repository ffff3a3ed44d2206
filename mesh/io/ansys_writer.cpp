// ANSYS file writing (ansys_io.hpp): a file read with the mesh comes back
// as it was read, the NBLOCK records of moved nodes rewritten; any other
// mesh gets a new file of its nodes, solids and components.
#include <algorithm>
#include <cctype>
#include <map>
#include <ostream>
#include <set>
#include <sstream>

#include "mesh/errors.hpp"
#include "mesh/io/ansys_fields.hpp"
#include "mesh/io/ansys_io.hpp"
#include "mesh/io/file_numbers.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/number_text.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/second_order.hpp"

namespace tetsmooth {
namespace {

using ansys::BlockFormat;

// Node and element numbers of a new file fill 9 columns; 8 digits leave
// them apart for readers that split on blanks.
constexpr long long kLargestNumber = 99999999;
// What MAPDL's CDWRITE writes.
constexpr BlockFormat kNodeFormat{3, 9, 6, 21, 13, 3, 0};
constexpr BlockFormat kElementFormat{19, 9, 0, 0, 0, 2, 0};
constexpr BlockFormat kComponentFormat{8, 10, 0, 0, 0, 2, 0};
const char* const kPinnedComponent = "TETSMOOTH_PINNED";

// --- A file read with the mesh ---------------------------------------------

std::string shortest(double value) {
  std::ostringstream text;
  put_real(text, value);
  return text.str();
}

// The records of one NBLOCK (its format line first), those of moved nodes
// with their X, Y and Z rewritten in the block's format.
void write_nblock(const std::string& body, const TetMesh& mesh, std::size_t& node, std::ostream& out) {
  std::size_t at = body.find('\n');
  out << body.substr(0, at + 1);
  const std::string first = body.substr(0, at);
  const BlockFormat f = *ansys::parse_block_format(first);  // the reader checked it
  const std::size_t ints_end = static_cast<std::size_t>(f.ints * f.int_width);
  const auto rw = static_cast<std::size_t>(f.real_width);
  for (++at; at < body.size();) {
    std::size_t end = body.find('\n', at);
    end = end == std::string::npos ? body.size() : end + 1;
    const std::string_view raw = std::string_view(body).substr(at, end - at);
    at = end;
    std::string_view record = raw;
    std::size_t cut = 0;
    while (cut < record.size() && (record[record.size() - 1 - cut] == '\n' || record[record.size() - 1 - cut] == '\r'))
      ++cut;
    const std::string_view line_end = record.substr(record.size() - cut);
    record.remove_suffix(cut);
    if (node >= mesh.num_nodes())
      throw OutputError("the ANSYS file read with this mesh has more NBLOCK records than the mesh has nodes");
    const double* xyz = &mesh.xyz[3 * node];
    bool moved = false;
    for (std::size_t c = 0; c < 3; ++c) {
      double v = 0;
      ansys::real_field(ansys::field_at(record, ints_end + c * rw, rw), v);
      moved = moved || v != xyz[c];
    }
    if (!moved) {
      out << raw;
      ++node;
      continue;
    }
    // The record's fields as read but for the coordinates that changed.
    std::string text(record.substr(0, ints_end));
    text.append(ints_end - text.size(), ' ');
    for (std::size_t c = 0; c < 3; ++c) {
      const std::string_view was = ansys::field_at(record, ints_end + c * rw, rw);
      double v = 0;
      ansys::real_field(was, v);
      if (v == xyz[c]) {
        text += was;
        text.append(rw - was.size(), ' ');
      } else if (!ansys::format_real(xyz[c], f, text)) {
        throw OutputError("node " + std::to_string(mesh.extras.node_tags[node]) + "'s coordinate " + shortest(xyz[c]) +
                          " does not fit its NBLOCK's format " + quoted_token(trimmed(first)));
      }
    }
    if (record.size() > ints_end + 3 * rw)
      text += record.substr(ints_end + 3 * rw);
    else
      text.erase(text.find_last_not_of(' ') + 1);  // no blank fields at the end
    out << text << line_end;
    ++node;
  }
}

void write_kept_file(const TetMesh& mesh, std::ostream& out) {
  std::size_t node = 0;
  for (const auto& [key, body] : mesh.extras.raw_sections) {
    if (key == "ansys:text")
      out << body;
    else if (key == "ansys:nblock")
      write_nblock(body, mesh, node, out);
  }
  if (node != mesh.num_nodes())
    throw OutputError("the ANSYS file read with this mesh has fewer NBLOCK records than the mesh has nodes");
}

// --- A new file --------------------------------------------------------------

// Solids other than tets that a new file writes (as degenerate SOLID185
// bricks): their nodes in the brick's eight places.
const int* brick_places(const PassThroughBlock& b) {
  static constexpr int kHexahedron[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  static constexpr int kWedge[8] = {0, 1, 2, 2, 3, 4, 5, 5};
  static constexpr int kPyramid[8] = {0, 1, 2, 3, 4, 4, 4, 4};
  if (b.kind == "hexahedron" && b.nodes_per_element == 8) return kHexahedron;
  if (b.kind == "wedge" && b.nodes_per_element == 6) return kWedge;
  if (b.kind == "pyramid" && b.nodes_per_element == 5) return kPyramid;
  return nullptr;
}

bool written_block(const PassThroughBlock& b) { return brick_places(b) != nullptr; }

void put_int(std::ostream& out, long long v, int width) {
  std::string text = std::to_string(v);
  if (text.size() < static_cast<std::size_t>(width))
    out << std::string(static_cast<std::size_t>(width) - text.size(), ' ');
  out << text;
}

// One EBLOCK record: the attributes, then the nodes, eight on the first
// line and the rest on the next.
void write_element(std::ostream& out, int mat, int type, long long number, const std::vector<long long>& nodes) {
  const long long head[11] = {mat, type, 1, 1, 0, 0, 0, 0, static_cast<long long>(nodes.size()), 0, number};
  for (long long v : head) put_int(out, v, kElementFormat.int_width);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if (k == 8) out << '\n';
    put_int(out, nodes[k], kElementFormat.int_width);
  }
  out << '\n';
}

// A component of the given numbers (sorted, once each), runs of two or more
// written as ranges (n, -m).
void write_component(std::ostream& out, const std::string& name, const char* entity, std::vector<long long> numbers) {
  std::sort(numbers.begin(), numbers.end());
  numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
  std::vector<long long> items;
  for (std::size_t i = 0; i < numbers.size();) {
    std::size_t j = i;
    while (j + 1 < numbers.size() && numbers[j + 1] == numbers[j] + 1) ++j;
    items.push_back(numbers[i]);
    if (j > i) items.push_back(-numbers[j]);
    i = j + 1;
  }
  out << "CMBLOCK," << name << ',' << entity << ',';
  put_int(out, static_cast<long long>(items.size()), 8);
  out << "\n(8i10)\n";
  for (std::size_t k = 0; k < items.size(); ++k) {
    put_int(out, items[k], kComponentFormat.int_width);
    if (k % 8 == 7 || k + 1 == items.size()) out << '\n';
  }
}

// A region's name as a component name: letters, digits and '_', upper case
// (APDL's), starting with a letter, at most 32 characters, and none of
// `taken`.
std::string component_name(const std::string& name, std::set<std::string>& taken) {
  std::string base;
  for (char c : name) base += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::toupper(c)) : '_';
  if (base.empty() || !std::isalpha(static_cast<unsigned char>(base[0]))) base = "C_" + base;
  // Words that APDL's component commands take for themselves.
  for (const char* reserved : {"ALL", "NONE", "STAT", "INVE", "P", "S", "R", "A", "U"})
    if (base == reserved) base += "_C";
  base = base.substr(0, 32);
  std::string candidate = base;
  for (int k = 2; !taken.insert(candidate).second; ++k) {
    const std::string suffix = "_" + std::to_string(k);
    candidate = base.substr(0, 32 - suffix.size()) + suffix;
  }
  return candidate;
}

void check_new_file(const TetMesh& mesh) {
  if (mesh.num_tets() == 0) throw OutputError("the mesh has no tetrahedra to write");
}

void write_new_file(const TetMesh& mesh, std::ostream& out) {
  const FileExtras& e = mesh.extras;
  const bool ten = !mesh.midsides.empty();
  const std::vector<long long> node_numbers = numbers_or_positions(e.node_tags, mesh.num_nodes(), kLargestNumber);
  const ElementSet written{true, written_block};
  const std::vector<long long> element_numbers_ = element_numbers(mesh, kLargestNumber, written);
  const std::map<int, int> renumbered = ansys_new_materials(mesh);
  const auto mat_of = [&](const std::vector<int>& tags, std::size_t i) {
    const int tag = i < tags.size() ? tags[i] : 0;
    const auto it = renumbered.find(tag);
    return it == renumbered.end() ? tag : it->second;
  };
  const bool bricks = std::any_of(e.blocks.begin(), e.blocks.end(),
                                  [](const PassThroughBlock& b) { return written_block(b) && elements_in(b) > 0; });
  out << "/COM,ANSYS input written by tetsmooth\n/PREP7\n";
  out << (ten ? "ET,1,187\n" : "ET,1,285\n");
  if (bricks) out << "ET,2,185\n";
  out << "NBLOCK,6,SOLID,";
  put_int(out, *std::max_element(node_numbers.begin(), node_numbers.end()), 9);
  out << ',';
  put_int(out, static_cast<long long>(mesh.num_nodes()), 9);
  out << "\n(3i9,6e21.13e3)\n";
  std::string record;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    put_int(out, node_numbers[i], 9);
    out << "        0        0";
    record.clear();
    for (std::size_t c = 0; c < 3; ++c) ansys::format_real(mesh.xyz[3 * i + c], kNodeFormat, record);
    out << record << '\n';
  }
  out << "N,R5.3,LOC,       -1,\n";
  std::size_t elements = mesh.num_tets();
  for (const PassThroughBlock& b : e.blocks)
    if (written_block(b)) elements += elements_in(b);
  out << "EBLOCK,19,SOLID,";
  put_int(out, *std::max_element(element_numbers_.begin(), element_numbers_.end()), 9);
  out << ',';
  put_int(out, static_cast<long long>(elements), 9);
  out << "\n(19i9)\n";
  std::size_t k = 0;  // element_numbers_' place
  std::vector<long long> nodes;
  static constexpr MidsidePlaces kInOrder = {4, 5, 6, 7, 8, 9};
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    index_t tet[10];
    if (ten)
      file_tet10(mesh, t, kInOrder, tet);
    else
      std::copy_n(&mesh.tets[4 * t], 4, tet);
    nodes.clear();
    for (int c = 0; c < (ten ? 10 : 4); ++c) nodes.push_back(node_numbers[static_cast<std::size_t>(tet[c])]);
    write_element(out, mat_of(e.tet_tags, t), 1, element_numbers_[k++], nodes);
  }
  for (const PassThroughBlock& b : e.blocks) {
    const int* places = brick_places(b);
    if (places == nullptr) continue;
    const auto n = static_cast<std::size_t>(b.nodes_per_element);
    for (std::size_t i = 0; i < elements_in(b); ++i) {
      nodes.clear();
      for (int c = 0; c < 8; ++c)
        nodes.push_back(
            node_numbers[static_cast<std::size_t>(b.connectivity[i * n + static_cast<std::size_t>(places[c])])]);
      write_element(out, mat_of(b.tags, i), 2, element_numbers_[k++], nodes);
    }
  }
  out << "       -1\n";
  std::set<std::string> taken{kPinnedComponent};
  if (const std::vector<long long> pins = pins_to_list(mesh, node_numbers, written_block); !pins.empty())
    write_component(out, kPinnedComponent, "NODE", pins);
  // Named regions: of solids as element components, of the elements a new
  // file does not write (surfaces, lines, points) as node components.
  const std::string* names_body = raw_section(e, "$PhysicalNames");
  for (int dimension = 3; dimension >= 0 && names_body != nullptr; --dimension)
    for (const auto& [tag, name] : physical_names_of(*names_body, dimension)) {
      std::vector<long long> items;
      if (dimension == 3) {
        std::size_t place = 0;
        for (std::size_t t = 0; t < mesh.num_tets(); ++t, ++place)
          if (t < e.tet_tags.size() && e.tet_tags[t] == tag) items.push_back(element_numbers_[place]);
        for (const PassThroughBlock& b : e.blocks)
          if (written_block(b))
            for (std::size_t i = 0; i < elements_in(b); ++i, ++place)
              if (i < b.tags.size() && b.tags[i] == tag) items.push_back(element_numbers_[place]);
      } else {
        for (const PassThroughBlock& b : e.blocks) {
          if (written_block(b) || kind_dimension(b.kind) != dimension) continue;
          const auto n = static_cast<std::size_t>(b.nodes_per_element);
          for (std::size_t i = 0; i < elements_in(b); ++i)
            if (i < b.tags.size() && b.tags[i] == tag)
              for (std::size_t c = 0; c < n; ++c)
                items.push_back(node_numbers[static_cast<std::size_t>(b.connectivity[i * n + c])]);
        }
      }
      if (!items.empty()) write_component(out, component_name(name, taken), dimension == 3 ? "ELEM" : "NODE", items);
    }
  out << "FINISH\n";
}

const DeckWriter kWriter{"ansys", "ANSYS file", check_new_file, write_kept_file, write_new_file};

}  // namespace

std::map<int, int> ansys_new_materials(const TetMesh& mesh) {
  return new_positive_ids(mesh, kLargestNumber, written_block);
}

std::string ansys_numbers_lost(const TetMesh& mesh) {
  return has_kept_deck(mesh, "ansys") ? "" : numbers_lost(mesh, kLargestNumber, {ElementSet{true, written_block}});
}

void write_ansys(const TetMesh& mesh, std::ostream& out) { kWriter.write(mesh, out); }

void write_ansys_file(const TetMesh& mesh, const std::string& path) { kWriter.write_file(mesh, path); }

}  // namespace tetsmooth
