// Nastran bulk data writing (nastran_io.hpp): a deck read with the mesh
// comes back as it was read, the GRID entries of moved nodes rewritten; any
// other mesh gets a new deck of its nodes, elements and pins.
#include <algorithm>
#include <functional>
#include <map>
#include <ostream>
#include <sstream>

#include "mesh/errors.hpp"
#include "mesh/io/file_numbers.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/nastran_cards.hpp"
#include "mesh/io/nastran_entry_types.hpp"
#include "mesh/io/nastran_fields.hpp"
#include "mesh/io/nastran_io.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/second_order.hpp"

namespace tetsmooth {
namespace {

using nastran::real_field;
using nastran::write_entry;

// Nastran ids have at most 8 digits.
constexpr long long kLargestId = 99999999;
constexpr std::size_t kLargeWidth = 16, kSmallWidth = 8;
// Pins a line of the "$TETSMOOTH PINNED" comment lists.
constexpr std::size_t kPinsPerLine = 6;

// --- A deck read with the mesh --------------------------------------------

// A GRID entry as read, or in large field with the node's new coordinates
// where it moved (its other fields as read).
void write_grid(std::ostream& out, const nastran::Card& card, const double* xyz) {
  bool moved = false;
  for (std::size_t c = 0; c < 3; ++c) {
    double v = 0;
    const std::string& f = card.field(2 + c);
    moved = moved || ((f.empty() || nastran::parse_real_field(f, v)) && v != xyz[c]);
  }
  if (!moved) {
    out << card.text;
    return;
  }
  // The entry's comments, those between its lines and those after its
  // data, stay before it; one that would read as a pin line of its own
  // (which inside the entry it was not) is marked off.
  std::istringstream lines(card.text);
  for (std::string line; std::getline(lines, line);)
    if (const std::size_t dollar = line.find('$'); dollar != std::string::npos) {
      const std::string comment = line.substr(dollar);
      out << (nastran::pinned_comment_ids(comment) ? "$" : "") << comment << '\n';
    }
  // The other fields as read (the reader checked them), ids written plain
  // so that they fit the wider columns whatever zeros they had.
  std::vector<std::string> fields(card.fields.begin(), card.fields.begin() + 8);
  for (const std::size_t d : {std::size_t{0}, std::size_t{5}, std::size_t{7}})
    if (long long v = 0; parse_integer(fields[d], v)) fields[d] = std::to_string(v);
  for (std::size_t c = 0; c < 3; ++c) fields[2 + c] = real_field(xyz[c], kLargeWidth);
  write_entry(out, "GRID", fields, true, 0);  // large field: no marker
}

void write_deck(const TetMesh& mesh, std::ostream& out) {
  std::size_t next = 0;
  for (const auto& [name, body] : mesh.extras.raw_sections) {
    if (name == "nastran:text") out << body;
    if (name != "nastran:grids") continue;
    std::istringstream in(body);
    nastran::BulkCards cards(in, "the kept deck");
    for (nastran::BulkCards::Kind kind; (kind = cards.next()) != nastran::BulkCards::Kind::End;) {
      if (kind == nastran::BulkCards::Kind::Text) {
        out << cards.text();
        continue;
      }
      if (next >= mesh.num_nodes())
        throw OutputError("the kept Nastran deck has more GRID entries than the mesh nodes");
      write_grid(out, cards.card(), &mesh.xyz[3 * next]);
      ++next;
    }
  }
}

// --- A new deck -------------------------------------------------------------

std::string text_of(long long v) { return std::to_string(v); }

// An element entry in small field where every field fits, else large.
void write_element(std::ostream& out, const char* name, long long id, const std::vector<std::string>& fields) {
  const bool large =
      std::any_of(fields.begin(), fields.end(), [](const std::string& f) { return f.size() > kSmallWidth; });
  write_entry(out, name, fields, large, id);
}

void check_new_deck(const TetMesh& mesh) {
  if (mesh.num_tets() == 0) throw OutputError("the mesh has no tetrahedra to write");
  for (const PassThroughBlock& b : mesh.extras.blocks)
    if (nastran::entry_type_of_kind(b.kind) == nullptr)
      throw OutputError("Nastran output cannot hold the pass-through '" + b.kind + "' block (" +
                        std::to_string(b.nodes_per_element) + " nodes per element)");
  std::size_t elements = mesh.num_tets();
  for (const PassThroughBlock& b : mesh.extras.blocks) elements += elements_in(b);
  if (mesh.num_nodes() > static_cast<std::size_t>(kLargestId) || elements > static_cast<std::size_t>(kLargestId))
    throw OutputError("Nastran ids have at most 8 digits, and the mesh has more than 99,999,999 nodes or elements");
}

// Pinned nodes that no element of a block pins, in comment lines the reader
// reads back.
void write_pinned_comment(std::ostream& out, const TetMesh& mesh, const std::vector<long long>& node_ids) {
  const std::vector<long long> listed = pins_to_list(mesh, node_ids);
  for (std::size_t k = 0; k < listed.size(); ++k)
    out << (k == 0 ? "$TETSMOOTH PINNED " : k % kPinsPerLine == 0 ? "\n$TETSMOOTH PINNED " : " ") << listed[k];
  if (!listed.empty()) out << '\n';
}

void write_new_deck(const TetMesh& mesh, std::ostream& out) {
  const std::vector<long long> node_ids = numbers_or_positions(mesh.extras.node_tags, mesh.num_nodes(), kLargestId);
  const std::vector<long long> ids = element_numbers(mesh, kLargestId);
  const RegionIds pids = nastran_region_ids(mesh);
  out << "$ written by tetsmooth\nBEGIN BULK\n";
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    std::vector<std::string> fields{text_of(node_ids[i]), ""};
    for (std::size_t c = 0; c < 3; ++c) fields.push_back(real_field(mesh.xyz[3 * i + c], kLargeWidth));
    write_entry(out, "GRID", fields, true, node_ids[i]);
  }
  const bool ten = !mesh.midsides.empty();
  const std::vector<int>& tags = mesh.extras.tet_tags;
  index_t nodes[10];
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    std::vector<std::string> fields{text_of(ids[t]), text_of(pids.of(3, tags.size() == mesh.num_tets() ? tags[t] : 0))};
    if (ten)
      file_tet10(mesh, t, nastran::kCtetraMidsides, nodes);
    else
      std::copy_n(&mesh.tets[4 * t], 4, nodes);
    for (std::size_t k = 0; k < (ten ? 10u : 4u); ++k)
      fields.push_back(text_of(node_ids[static_cast<std::size_t>(nodes[k])]));
    write_element(out, "CTETRA", ids[t], fields);
  }
  std::size_t first = mesh.num_tets();
  for (const PassThroughBlock& b : mesh.extras.blocks) {
    const nastran::EntryType& entry = *nastran::entry_type_of_kind(b.kind);
    const auto n = static_cast<std::size_t>(b.nodes_per_element);
    for (std::size_t e = 0; e < elements_in(b); ++e) {
      std::vector<std::string> fields{text_of(ids[first + e])};
      if (entry.has_pid)
        fields.push_back(text_of(pids.of(kind_dimension(b.kind), b.tags.size() == elements_in(b) ? b.tags[e] : 0)));
      for (std::size_t k = 0; k < n; ++k)
        fields.push_back(text_of(node_ids[static_cast<std::size_t>(b.connectivity[e * n + k])]));
      write_element(out, entry.name, ids[first + e], fields);
    }
    first += elements_in(b);
  }
  write_pinned_comment(out, mesh, node_ids);
  out << "ENDDATA\n";
}

constexpr DeckWriter kWriter{"nastran", "Nastran deck", check_new_deck, write_deck, write_new_deck};

}  // namespace

RegionIds nastran_region_ids(const TetMesh& mesh) {
  return RegionIds(mesh, kLargestId, [](const PassThroughBlock& b) {
    const nastran::EntryType* entry = nastran::entry_type_of_kind(b.kind);
    return entry != nullptr && entry->has_pid;
  });
}

std::string nastran_numbers_lost(const TetMesh& mesh) {
  return has_kept_deck(mesh, "nastran") ? "" : numbers_lost(mesh, kLargestId);
}

void write_nastran(const TetMesh& mesh, std::ostream& out) { kWriter.write(mesh, out); }

void write_nastran_file(const TetMesh& mesh, const std::string& path) { kWriter.write_file(mesh, path); }

}  // namespace tetsmooth
