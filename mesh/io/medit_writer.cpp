// Medit .mesh (ASCII) writing, version 2 (double precision).
#include <algorithm>
#include <ostream>

#include "mesh/errors.hpp"
#include "mesh/second_order.hpp"
#include "mesh/io/atomic_file.hpp"
#include "mesh/io/medit_detail.hpp"
#include "mesh/io/medit_io.hpp"
#include "mesh/io/number_text.hpp"

namespace tetsmooth {
namespace {

// A per-item reference array is written when it has one entry per item,
// otherwise every reference is 0.
int ref_of(const std::vector<int>& refs, std::size_t i, std::size_t count) {
  return refs.size() == count ? refs[i] : 0;
}

const medit::ElementKeyword* keyword_of_kind(const std::string& kind) {
  for (const medit::ElementKeyword& kw : medit::kElementKeywords)
    if (kind == kw.kind) return &kw;
  return nullptr;
}

void write_indices(std::ostream& out, const index_t* v, int count) {
  for (int k = 0; k < count; ++k) {
    put_integer(out, static_cast<long long>(v[k]) + 1);
    out << ' ';
  }
}

void write_vertex_list(std::ostream& out, const char* keyword, const std::vector<std::int32_t>& nodes) {
  if (nodes.empty()) return;
  out << '\n' << keyword << '\n' << nodes.size() << '\n';
  for (std::int32_t n : nodes) {
    put_integer(out, static_cast<long long>(n) + 1);
    out << '\n';
  }
}

// RequiredVertices: the file's own, then the nodes of "vertex" blocks (Gmsh
// points: Medit has no point elements), then every other pinned node that
// no element or corner pins (a VTU's tetsmooth:fixed, say), so that each
// pin survives the next read. Indices are checked in range first (check()).
std::vector<std::int32_t> required_nodes(const TetMesh& mesh) {
  std::vector<std::uint8_t> pinned(mesh.num_nodes(), 0);
  std::vector<std::int32_t> nodes;
  const auto add = [&](index_t n) {
    if (pinned[static_cast<std::size_t>(n)]) return;
    pinned[static_cast<std::size_t>(n)] = 1;
    nodes.push_back(n);
  };
  for (index_t n : mesh.extras.required_nodes) add(n);
  for (const PassThroughBlock& block : mesh.extras.blocks)
    if (block.kind == "vertex")
      for (index_t n : block.connectivity) add(n);
  for (index_t n : mesh.extras.corner_nodes) pinned[static_cast<std::size_t>(n)] = 1;
  mark_element_nodes(mesh.extras.blocks, pinned);
  for (std::size_t i = 0; i < std::min(mesh.fixed.size(), mesh.num_nodes()); ++i)
    if (mesh.fixed[i]) add(static_cast<index_t>(i));
  return nodes;
}

void check(const TetMesh& mesh) {
  if (mesh.num_tets() == 0) throw OutputError("the mesh has no tetrahedra to write");
  check_first_order_output(mesh, "Medit");
  const auto in_range = [&](index_t n) { return n >= 0 && static_cast<std::size_t>(n) < mesh.num_nodes(); };
  const auto check_all = [&](const auto& indices, const std::string& what) {
    for (index_t n : indices)
      if (!in_range(n)) throw OutputError(what + " refers to node " + std::to_string(n) + ", outside the mesh");
  };
  check_all(mesh.tets, "a tet");
  check_all(mesh.extras.required_nodes, "RequiredVertices");
  check_all(mesh.extras.corner_nodes, "Corners");
  for (const PassThroughBlock& block : mesh.extras.blocks) {
    const medit::ElementKeyword* kw = keyword_of_kind(block.kind);
    if (block.kind != "vertex" && (kw == nullptr || kw->nodes != block.nodes_per_element))
      throw OutputError("Medit output cannot hold the pass-through '" + block.kind + "' block (" +
                        std::to_string(block.nodes_per_element) + " nodes per element)");
    check_all(block.connectivity, "a " + block.kind + " element");
  }
}

// The sections read under `keyword` (FileExtras::raw_sections), as read.
void write_kept(std::ostream& out, const TetMesh& mesh, const char* keyword) {
  for (const auto& [name, body] : mesh.extras.raw_sections)
    if (name == keyword) out << '\n' << name << '\n' << body;
}

void write_body(const TetMesh& mesh, std::ostream& out) {
  out << "MeshVersionFormatted 2\n\nDimension 3\n";
  for (const char* keyword : medit::kStringKeywords) write_kept(out, mesh, keyword);
  out << "\nVertices\n" << mesh.num_nodes() << '\n';
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    for (int c = 0; c < 3; ++c) {
      put_real(out, mesh.xyz[3 * i + c]);
      out << ' ';
    }
    put_integer(out, ref_of(mesh.extras.node_markers, i, mesh.num_nodes()));
    out << '\n';
  }
  out << "\nTetrahedra\n" << mesh.num_tets() << '\n';
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    write_indices(out, &mesh.tets[4 * t], 4);
    put_integer(out, ref_of(mesh.extras.tet_tags, t, mesh.num_tets()));
    out << '\n';
  }
  for (const PassThroughBlock& block : mesh.extras.blocks) {
    const medit::ElementKeyword* kw = keyword_of_kind(block.kind);
    if (kw == nullptr) continue;  // a vertex block, see required_nodes()
    const std::size_t count = block.connectivity.size() / static_cast<std::size_t>(kw->nodes);
    out << '\n' << kw->keyword << '\n' << count << '\n';
    for (std::size_t e = 0; e < count; ++e) {
      write_indices(out, &block.connectivity[e * static_cast<std::size_t>(kw->nodes)], kw->nodes);
      put_integer(out, ref_of(block.tags, e, count));
      out << '\n';
    }
  }
  write_vertex_list(out, "Corners", mesh.extras.corner_nodes);
  write_vertex_list(out, "RequiredVertices", required_nodes(mesh));
  for (const medit::KeptKeyword& kw : medit::kKeptKeywords) write_kept(out, mesh, kw.keyword);
  out << "\nEnd\n";
}

}  // namespace

void write_medit(const TetMesh& mesh, std::ostream& out) {
  check(mesh);
  write_body(mesh, out);
  if (!out) throw OutputError("the Medit output stream failed");
}

void write_medit_file(const TetMesh& mesh, const std::string& path) {
  checked_for(path, [&] { check(mesh); });
  write_atomically(path, [&](std::ostream& out) { write_body(mesh, out); });
}

}  // namespace tetsmooth
