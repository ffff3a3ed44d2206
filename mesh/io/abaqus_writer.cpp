// Abaqus/CalculiX .inp writing (abaqus_io.hpp): a deck read with the mesh
// comes back as it was read with the new coordinates; any other mesh gets a
// new deck of its nodes, elements and pins.
#include <algorithm>
#include <array>
#include <limits>
#include <ostream>
#include <sstream>

#include "mesh/errors.hpp"
#include "mesh/io/abaqus_deck_lines.hpp"
#include "mesh/io/abaqus_element_types.hpp"
#include "mesh/io/abaqus_io.hpp"
#include "mesh/io/abaqus_node_line.hpp"
#include "mesh/io/abaqus_placement.hpp"
#include "mesh/io/abaqus_set_names.hpp"
#include "mesh/io/file_numbers.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/number_text.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/second_order.hpp"

namespace tetsmooth {
namespace {

// Abaqus reads at most 16 entries from a data line of a set.
constexpr std::size_t kSetEntriesPerLine = 16;

void write_node(std::ostream& out, long long id, const double* xyz) { abaqus::write_node_line(out, id, xyz); }

// --- A deck read with the mesh --------------------------------------------

// The nodes of a run in a placed part ("abaqus:placed": the count, the
// placement, the part coordinates as read, a line each): in part
// coordinates, as read where the node is still where they place it.
std::size_t write_placed_nodes(const TetMesh& mesh, const std::string& body, std::size_t next, std::ostream& out) {
  std::istringstream in(body);
  std::size_t count = 0;
  std::string placement_text;
  in >> count;
  in.ignore(1);
  std::getline(in, placement_text);
  const abaqus::Placement placement = abaqus::Placement::from_text(placement_text);
  for (const std::size_t end = next + count; next < end; ++next) {
    std::array<double, 3> part{};
    for (double& v : part) {
      std::string token;
      in >> token;
      parse_real(token, v);
    }
    const double* xyz = &mesh.xyz[3 * next];
    const std::array<double, 3> was = placement.place(part.data());
    if (!std::equal(was.begin(), was.end(), xyz)) part = placement.part_of(xyz);
    write_node(out, mesh.extras.node_tags[next], part.data());
  }
  return next;
}

void write_deck(const TetMesh& mesh, std::ostream& out) {
  std::size_t next = 0;
  for (const auto& [name, body] : mesh.extras.raw_sections) {
    if (name == "abaqus:text") out << body;
    if (name == "abaqus:placed") next = write_placed_nodes(mesh, body, next, out);
    if (name != "abaqus:nodes") continue;
    const std::size_t end = next + std::stoull(body);
    for (; next < end; ++next) write_node(out, mesh.extras.node_tags[next], &mesh.xyz[3 * next]);
  }
}

// --- A new deck -------------------------------------------------------------

// The reader takes any positive number, so a new deck keeps any.
constexpr long long kLargestNumber = std::numeric_limits<long long>::max();

void check_new_deck(const TetMesh& mesh) {
  if (mesh.num_tets() == 0) throw OutputError("the mesh has no tetrahedra to write");
  for (const PassThroughBlock& b : mesh.extras.blocks)
    if (abaqus::type_name_of(b.kind, b.nodes_per_element) == nullptr)
      throw OutputError("Abaqus output cannot hold the pass-through '" + b.kind + "' block (" +
                        std::to_string(b.nodes_per_element) + " nodes per element)");
}

// Writes `count` elements of `type` whose nodes `nodes(e, out)` gives, one
// *ELEMENT block per run of one tag (tags: one per element, or empty), its
// set named by `set_names` for `prefix` and `dimension`.
template <typename Nodes>
void write_elements(std::ostream& out, const char* type, int nodes_each, std::size_t count,
                    const std::vector<int>& tags, const abaqus::NewSetNames& set_names, const std::string& prefix,
                    int dimension, const long long* ids, const std::vector<long long>& node_ids, Nodes nodes) {
  const bool tagged = tags.size() == count;
  std::vector<index_t> element(static_cast<std::size_t>(nodes_each));
  for (std::size_t e = 0; e < count; ++e) {
    if (e == 0 || (tagged && tags[e] != tags[e - 1])) {
      out << "*ELEMENT, TYPE=" << type;
      if (tagged) out << ", ELSET=" << set_names.of(prefix, dimension, tags[e]);
      out << '\n';
    }
    put_integer(out, ids[e]);
    nodes(e, element.data());
    for (index_t n : element) {
      out << ", ";
      put_integer(out, node_ids[static_cast<std::size_t>(n)]);
    }
    out << '\n';
  }
}

// Pinned nodes that no element of a block pins: the reader pins the set.
void write_pinned_set(std::ostream& out, const TetMesh& mesh, const std::vector<long long>& node_ids) {
  const std::vector<long long> listed = pins_to_list(mesh, node_ids);
  for (std::size_t k = 0; k < listed.size(); ++k) {
    out << (k == 0 ? "*NSET, NSET=TETSMOOTH_PINNED\n" : k % kSetEntriesPerLine == 0 ? "\n" : ", ");
    put_integer(out, listed[k]);
  }
  if (!listed.empty()) out << '\n';
}

void write_new_deck(const TetMesh& mesh, std::ostream& out) {
  const std::vector<long long> node_ids = numbers_or_positions(mesh.extras.node_tags, mesh.num_nodes(), kLargestNumber);
  const std::vector<long long> ids = element_numbers(mesh, kLargestNumber);
  out << "*HEADING\nwritten by tetsmooth\n*NODE\n";
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) write_node(out, node_ids[i], &mesh.xyz[3 * i]);
  const bool ten = !mesh.midsides.empty();
  const abaqus::NewSetNames set_names(mesh);
  write_elements(out, ten ? "C3D10" : "C3D4", ten ? 10 : 4, mesh.num_tets(), mesh.extras.tet_tags, set_names, "REGION",
                 3, ids.data(), node_ids, [&](std::size_t t, index_t* nodes) {
                   if (ten) return file_tet10(mesh, t, abaqus::kMidsidePlaces, nodes);
                   std::copy_n(&mesh.tets[4 * t], 4, nodes);
                 });
  std::size_t first = mesh.num_tets();
  for (const PassThroughBlock& b : mesh.extras.blocks) {
    const auto n = static_cast<std::size_t>(b.nodes_per_element);
    write_elements(out, abaqus::type_name_of(b.kind, b.nodes_per_element), b.nodes_per_element, elements_in(b), b.tags,
                   set_names, b.kind, kind_dimension(b.kind), ids.data() + first, node_ids,
                   [&](std::size_t e, index_t* nodes) {
                     for (std::size_t k = 0; k < n; ++k)
                       nodes[abaqus::file_place(b.kind, static_cast<int>(k))] = b.connectivity[e * n + k];
                   });
    first += elements_in(b);
  }
  write_pinned_set(out, mesh, node_ids);
}

constexpr DeckWriter kWriter{"abaqus", "Abaqus deck", check_new_deck, write_deck, write_new_deck};

}  // namespace

std::string abaqus_numbers_lost(const TetMesh& mesh) {
  return has_kept_deck(mesh, "abaqus") ? "" : numbers_lost(mesh, kLargestNumber);
}

bool abaqus_tags_read_back(const TetMesh& mesh) {
  return has_kept_deck(mesh, "abaqus") || abaqus::NewSetNames(mesh).tags_read_back(mesh);
}

std::vector<std::string> abaqus_names_lost(const TetMesh& mesh) {
  return has_kept_deck(mesh, "abaqus") ? std::vector<std::string>{} : abaqus::NewSetNames(mesh).not_written();
}

void write_abaqus(const TetMesh& mesh, std::ostream& out) { kWriter.write(mesh, out); }

void write_abaqus_file(const TetMesh& mesh, const std::string& path) { kWriter.write_file(mesh, path); }

}  // namespace tetsmooth
