#include "mesh/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "mesh/errors.hpp"
#include "mesh/tet_quality.hpp"

namespace tetsmooth {
namespace {

[[noreturn]] void fail(const std::string& source, const std::string& what) { throw InputError(source, what); }

void check_shapes(const TetMesh& mesh, const std::string& source) {
  if (mesh.xyz.size() % 3 != 0)
    fail(source, "coordinate array holds " + std::to_string(mesh.xyz.size()) + " values, not a multiple of 3");
  if (mesh.tets.size() % 4 != 0)
    fail(source, "tet array holds " + std::to_string(mesh.tets.size()) + " indices, not a multiple of 4");
  if (mesh.num_nodes() > static_cast<std::size_t>(std::numeric_limits<index_t>::max()))
    fail(source, std::to_string(mesh.num_nodes()) + " nodes exceed the 32-bit index range");
  if (mesh.num_tets() == 0) fail(source, "the mesh has no tetrahedra");
  if (mesh.num_tets() > max_tets())
    fail(source, std::to_string(mesh.num_tets()) + " tets exceed the " + std::to_string(max_tets()) +
                     " that 32-bit offsets of the node-to-tet table (4 entries a tet) allow");

  const auto per_node = [&](std::size_t size, const char* name) {
    if (size != 0 && size != mesh.num_nodes())
      fail(source, std::string(name) + " has " + std::to_string(size) + " entries for " +
                       std::to_string(mesh.num_nodes()) + " nodes");
  };
  const auto per_tet = [&](std::size_t size, const char* name) {
    if (size != 0 && size != mesh.num_tets())
      fail(source, std::string(name) + " has " + std::to_string(size) + " entries for " +
                       std::to_string(mesh.num_tets()) + " tets");
  };
  per_node(mesh.fixed.size(), "the fixed-node flag array");
  per_node(mesh.extras.node_tags.size(), "the node tag array");
  per_node(mesh.extras.node_markers.size(), "the node marker array");
  // Attribute arrays: `count` values per item, row-major, or empty.
  const auto rows = [&](const std::vector<double>& values, int count, std::size_t items, const char* item) {
    const std::size_t per = static_cast<std::size_t>(std::max(count, 0));
    if (values.size() != per * items && !values.empty())
      fail(source, std::string(item) + " attribute array has " + std::to_string(values.size()) + " values, expected " +
                       std::to_string(per) + " per " + item);
  };
  rows(mesh.extras.node_attributes, mesh.extras.node_attribute_count, mesh.num_nodes(), "node");
  rows(mesh.extras.tet_attributes, mesh.extras.tet_attribute_count, mesh.num_tets(), "tet");
  per_tet(mesh.extras.tet_tags.size(), "the tet tag array");
  per_tet(mesh.extras.tet_entity_tags.size(), "the tet entity tag array");
  per_tet(mesh.extras.tet_element_tags.size(), "the tet element tag array");
  if (!mesh.midsides.empty() && mesh.midsides.size() != 6 * mesh.num_tets())
    fail(source, "the midside node array has " + std::to_string(mesh.midsides.size()) + " entries for " +
                     std::to_string(mesh.num_tets()) + " tets (6 a tet)");
}

void check_coordinates(const TetMesh& mesh, const std::string& source) {
  for (std::size_t i = 0; i < mesh.xyz.size(); ++i)
    if (!std::isfinite(mesh.xyz[i]))
      fail(source, "node " + std::to_string(i / 3) + " has a non-finite coordinate " + "xyz"[i % 3] + " = " +
                       std::to_string(mesh.xyz[i]));
}

void check_indices(const std::vector<index_t>& conn, std::size_t per_element, std::size_t nodes,
                   const std::string& source, const std::string& element) {
  for (std::size_t i = 0; i < conn.size(); ++i)
    if (conn[i] < 0 || static_cast<std::size_t>(conn[i]) >= nodes)
      fail(source, element + " " + std::to_string(i / per_element) + " refers to node " + std::to_string(conn[i]) +
                       ", outside [0, " + std::to_string(nodes) + ")");
}

void check_blocks(const TetMesh& mesh, const std::string& source) {
  for (const PassThroughBlock& block : mesh.extras.blocks) {
    const std::string name = block.kind + " element";
    if (block.nodes_per_element <= 0 || block.connectivity.size() % block.nodes_per_element != 0)
      fail(source, "the " + block.kind + " block holds " + std::to_string(block.connectivity.size()) +
                       " indices, not a multiple of " + std::to_string(block.nodes_per_element));
    const std::size_t count = block.connectivity.size() / block.nodes_per_element;
    if ((!block.tags.empty() && block.tags.size() != count) ||
        (!block.entity_tags.empty() && block.entity_tags.size() != count) ||
        (!block.element_tags.empty() && block.element_tags.size() != count))
      fail(source, "the " + block.kind + " block has a tag array that does not match its " + std::to_string(count) +
                       " elements");
    check_indices(block.connectivity, block.nodes_per_element, mesh.num_nodes(), source, name);
  }
}

// A midside node belongs to one edge and is no corner: smoothing moves it
// with that edge's corners (mesh/second_order.hpp), which only works when
// the edge is the same in every tet that lists it.
void check_midsides(const TetMesh& mesh, const std::string& source) {
  if (mesh.midsides.empty()) return;
  check_indices(mesh.midsides, 6, mesh.num_nodes(), source, "the midside nodes of tet");
  constexpr index_t kNone = -1;
  std::vector<index_t> corner_of(mesh.num_nodes(), kNone);  // a tet that has the node as a corner
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (int k = 0; k < 4; ++k) corner_of[static_cast<std::size_t>(mesh.tets[4 * t + k])] = static_cast<index_t>(t);
  std::vector<std::pair<index_t, index_t>> edge_of(mesh.num_nodes(), {kNone, kNone});
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (int e = 0; e < 6; ++e) {
      const index_t m = mesh.midsides[6 * t + static_cast<std::size_t>(e)];
      const index_t a = mesh.tets[4 * t + kTetEdges[e][0]], b = mesh.tets[4 * t + kTetEdges[e][1]];
      const std::pair<index_t, index_t> edge{std::min(a, b), std::max(a, b)};
      const std::string where = "node " + std::to_string(m) + ", the midside node of edge (" + std::to_string(a) +
                                ", " + std::to_string(b) + ") of tet " + std::to_string(t);
      if (corner_of[static_cast<std::size_t>(m)] != kNone)
        fail(source, where + ", is also a corner of tet " + std::to_string(corner_of[static_cast<std::size_t>(m)]));
      std::pair<index_t, index_t>& seen = edge_of[static_cast<std::size_t>(m)];
      if (seen.first == kNone) seen = edge;
      if (seen != edge)
        fail(source, where + ", is also the midside node of edge (" + std::to_string(seen.first) + ", " +
                         std::to_string(seen.second) + ") of another tet");
    }
}

bool has_repeated_node(const index_t* t) {
  return t[0] == t[1] || t[0] == t[2] || t[0] == t[3] || t[1] == t[2] || t[1] == t[3] || t[2] == t[3];
}

}  // namespace

std::size_t max_tets() { return static_cast<std::size_t>(std::numeric_limits<index_t>::max()) / 4; }

ValidationReport validate_mesh(const TetMesh& mesh, const std::string& source, const std::string& element_source) {
  const std::string& elements = element_source.empty() ? source : element_source;
  check_shapes(mesh, source);
  check_coordinates(mesh, source);
  check_indices(mesh.tets, 4, mesh.num_nodes(), elements, "tet");
  check_blocks(mesh, elements);
  check_midsides(mesh, elements);

  ValidationReport report;
  report.nodes = mesh.num_nodes();
  report.tets = mesh.num_tets();
  report.nodes_per_tet = mesh.midsides.empty() ? 4 : 10;
  std::vector<std::uint8_t> referenced(mesh.num_nodes(), 0);
  const auto point = [&](index_t n) {
    const double* p = &mesh.xyz[3 * static_cast<std::size_t>(n)];
    return Vec3<double>{p[0], p[1], p[2]};
  };
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    const index_t* v = &mesh.tets[4 * t];
    for (int k = 0; k < 4; ++k) referenced[v[k]] = 1;
    if (has_repeated_node(v)) {
      ++report.degenerate;
      continue;
    }
    const double v6 = signed_volume6(point(v[0]), point(v[1]), point(v[2]), point(v[3]));
    if (v6 < 0)
      ++report.inverted;
    else if (v6 == 0)
      ++report.degenerate;
  }
  for (index_t m : mesh.midsides) referenced[static_cast<std::size_t>(m)] = 1;
  for (std::uint8_t r : referenced) report.unreferenced += r == 0;
  return report;
}

}  // namespace tetsmooth
