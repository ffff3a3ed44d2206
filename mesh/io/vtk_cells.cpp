#include "mesh/io/vtk_cells.hpp"

#include <algorithm>

#include "mesh/errors.hpp"
#include "mesh/second_order.hpp"

namespace tetsmooth {
namespace {

constexpr std::uint8_t kVtkTetra = 10;
// VTK_QUADRATIC_TETRA: the corners, then the midside nodes in kTetEdges
// order, which is VTK's.
constexpr std::uint8_t kVtkQuadraticTetra = 24;
constexpr MidsidePlaces kVtkMidsidePlaces = {4, 5, 6, 7, 8, 9};

struct PassThroughType {
  std::uint8_t vtk;
  const char* kind;  // PassThroughBlock::kind, as the other readers name it
  int nodes;
};
// The quadratic edge and triangle order their nodes as Gmsh's 3-node line
// and 6-node triangle do (gmsh_element_types.cpp), under the same kinds, and
// so do the hexahedron (the bottom quad, then the top) and the pyramid (the
// base, then the apex). A wedge lists a triangle and then the one over it
// in both, but VTK winds the first triangle with its normal out of the cell
// and Gmsh into it (as Abaqus, Nastran and Medit do, and meshio's wedge):
// see kVtkWedge.
constexpr PassThroughType kPassThrough[] = {{1, "vertex", 1},     {3, "line", 2},   {5, "triangle", 3},
                                            {9, "quad", 4},       {12, "hexahedron", 8}, {13, "wedge", 6},
                                            {14, "pyramid", 5},   {21, "line3", 3}, {22, "triangle6", 6}};

// A wedge's node k in VTK is its node kVtkWedge[k] in the other formats'
// order, and the other way round (the swap turns both triangles over).
constexpr int kVtkWedge[6] = {0, 2, 1, 3, 5, 4};
constexpr std::uint8_t kVtkWedgeType = 13;

// Node k of a VTK cell of `type` among its nodes `first`: the same node in
// the kinds' order.
template <class Index>
Index kind_order(std::uint8_t type, const Index* first, std::size_t k) {
  return type == kVtkWedgeType ? first[kVtkWedge[k]] : first[k];
}

const PassThroughType* by_vtk(long long type) {
  for (const auto& p : kPassThrough)
    if (p.vtk == type) return &p;
  return nullptr;
}

const PassThroughType* by_kind(const std::string& kind, int nodes) {
  for (const auto& p : kPassThrough)
    if (kind == p.kind && nodes == p.nodes) return &p;
  return nullptr;
}

}  // namespace

std::string vtk_cell_type_name(long long type) {
  switch (type) {
    case 1:
      return "vertex";
    case 2:
      return "poly-vertex";
    case 3:
      return "line";
    case 4:
      return "poly-line";
    case 5:
      return "triangle";
    case 6:
      return "triangle strip";
    case 7:
      return "polygon";
    case 8:
      return "pixel";
    case 9:
      return "quad";
    case 10:
      return "tetra";
    case 11:
      return "voxel";
    case 12:
      return "hexahedron";
    case 13:
      return "wedge";
    case 14:
      return "pyramid";
    case 21:
      return "quadratic edge";
    case 22:
      return "quadratic triangle";
    case 23:
      return "quadratic quad";
    case 24:
      return "quadratic tetra";
    case 25:
      return "quadratic hexahedron";
    case 42:
      return "polyhedron";
    default:
      return "type " + std::to_string(type);
  }
}

void check_vtk_blocks(const TetMesh& mesh, const std::string& where) {
  for (const PassThroughBlock& b : mesh.extras.blocks)
    if (!by_kind(b.kind, b.nodes_per_element))
      throw OutputError(where + ": pass-through " + b.kind + " elements with " + std::to_string(b.nodes_per_element) +
                        " nodes have no VTK cell type supported here (vertex, line, triangle, quad, hexahedron, wedge, "
                        "pyramid, quadratic edge, quadratic triangle)");
}

VtkCells vtk_cells_of(const TetMesh& mesh) {
  check_vtk_blocks(mesh, "VTK output");
  VtkCells cells;
  const FileExtras& ex = mesh.extras;
  bool tagged = ex.tet_tags.size() == mesh.num_tets();
  bool with_entities = ex.tet_entity_tags.size() == mesh.num_tets();
  std::size_t total = mesh.num_tets();
  for (const PassThroughBlock& b : ex.blocks) {
    total += b.connectivity.size() / b.nodes_per_element;
    tagged = tagged || !b.tags.empty();
    with_entities = with_entities || !b.entity_tags.empty();
  }
  const bool second_order = !mesh.midsides.empty();
  const std::size_t per_tet = second_order ? 10 : 4;
  cells.connectivity.reserve(per_tet * mesh.num_tets());
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    if (second_order) {
      cells.connectivity.resize(cells.connectivity.size() + 10);
      file_tet10(mesh, t, kVtkMidsidePlaces, &cells.connectivity[cells.connectivity.size() - 10]);
    } else {
      cells.connectivity.insert(cells.connectivity.end(), &mesh.tets[4 * t], &mesh.tets[4 * t] + 4);
    }
  }
  cells.offsets.reserve(total + 1);
  cells.types.reserve(total);
  cells.offsets.push_back(0);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    cells.offsets.push_back(static_cast<std::int64_t>(per_tet * (t + 1)));
    cells.types.push_back(second_order ? kVtkQuadraticTetra : kVtkTetra);
  }
  if (tagged) {
    cells.tags = ex.tet_tags;
    cells.tags.resize(mesh.num_tets(), 0);
  }
  if (with_entities) {
    cells.entities = ex.tet_entity_tags;
    cells.entities.resize(mesh.num_tets(), 0);
  }
  for (const PassThroughBlock& b : ex.blocks) {
    const std::size_t count = b.connectivity.size() / b.nodes_per_element;
    const std::uint8_t type = by_kind(b.kind, b.nodes_per_element)->vtk;
    const auto n = static_cast<std::size_t>(b.nodes_per_element);
    for (std::size_t e = 0; e < count; ++e)
      for (std::size_t k = 0; k < n; ++k) cells.connectivity.push_back(kind_order(type, &b.connectivity[e * n], k));
    for (std::size_t e = 0; e < count; ++e) {
      cells.offsets.push_back(cells.offsets.back() + b.nodes_per_element);
      cells.types.push_back(type);
      if (tagged) cells.tags.push_back(b.tags.empty() ? 0 : b.tags[e]);
      if (with_entities) cells.entities.push_back(b.entity_tags.empty() ? 0 : b.entity_tags[e]);
    }
  }
  return cells;
}

void mesh_from_vtk_cells(TetMesh& mesh, const std::vector<long long>& connectivity,
                         const std::vector<long long>& offsets, const std::vector<long long>& types,
                         const std::vector<int>& tags, const std::vector<int>& entities, const std::string& where,
                         const VtkCellPlace& place) {
  const std::size_t count = types.size();
  const auto fail = [&](std::size_t cell, const std::string& what) {
    throw InputError(where, "cell " + std::to_string(cell) + ": " + what);
  };
  const auto fail_at = [&](VtkCellArray array, std::size_t index, std::size_t cell, const std::string& what) {
    const VtkValuePlace at = place(array, index, cell);
    throw InputError(at.where,
                     "cell " + std::to_string(cell) + ": " + what + (at.entry.empty() ? "" : " (" + at.entry + ")"));
  };
  if (offsets.size() != count + 1 || offsets.front() != 0)
    throw InputError(where, "cell offsets do not match the " + std::to_string(count) + " cell types");
  if (!tags.empty() && tags.size() != count)
    throw InputError(where, std::to_string(tags.size()) + " region tags for " + std::to_string(count) + " cells");
  if (!entities.empty() && entities.size() != count)
    throw InputError(where, std::to_string(entities.size()) + " entity tags for " + std::to_string(count) + " cells");
  const long long num_nodes = static_cast<long long>(mesh.num_nodes());
  std::vector<std::size_t> block_of_type(256, SIZE_MAX);
  mesh.tets.clear();
  mesh.midsides.clear();
  mesh.extras.tet_tags.clear();
  mesh.extras.tet_entity_tags.clear();
  mesh.extras.blocks.clear();
  long long tet_type = -1;  // the type of the first tet
  for (std::size_t c = 0; c < count; ++c) {
    const long long begin = offsets[c], end = offsets[c + 1];
    if (end < begin || end > static_cast<long long>(connectivity.size()))
      fail_at(VtkCellArray::Offsets, c + 1, c,
              "offset " + std::to_string(end) + " outside the connectivity array of " +
                  std::to_string(connectivity.size()));
    for (long long k = begin; k < end; ++k)
      if (connectivity[k] < 0 || connectivity[k] >= num_nodes)
        fail_at(VtkCellArray::Connectivity, static_cast<std::size_t>(k), c,
                "node " + std::to_string(connectivity[k]) + " out of range [0, " + std::to_string(num_nodes) + ")");
    const long long type = types[c];
    const PassThroughType* pass = by_vtk(type);
    const bool tet = type == kVtkTetra || type == kVtkQuadraticTetra;
    const long long expected = type == kVtkTetra ? 4 : type == kVtkQuadraticTetra ? 10 : pass ? pass->nodes : -1;
    if (expected < 0) {
      fail(c, "unsupported VTK cell type " + std::to_string(type) + " (" + vtk_cell_type_name(type) +
                  "); only tetra and quadratic tetra, and vertex, line, triangle, quad, hexahedron, wedge, pyramid, "
                  "quadratic edge and quadratic triangle passed through, are read");
    }
    if (end - begin != expected)
      fail(c, vtk_cell_type_name(type) + " with " + std::to_string(end - begin) + " nodes instead of " +
                  std::to_string(expected));
    if (tet) {
      if (tet_type < 0) tet_type = type;
      if (type != tet_type) fail(c, mixed_tet_kinds(static_cast<int>(expected)));
      index_t nodes[10];
      for (long long k = begin; k < end; ++k) nodes[k - begin] = static_cast<index_t>(connectivity[k]);
      append_file_tet(mesh, nodes, expected == 10, kVtkMidsidePlaces);
      if (!tags.empty()) mesh.extras.tet_tags.push_back(tags[c]);
      if (!entities.empty()) mesh.extras.tet_entity_tags.push_back(entities[c]);
      continue;
    }
    std::size_t& slot = block_of_type[static_cast<std::size_t>(type)];
    if (slot == SIZE_MAX) {
      slot = mesh.extras.blocks.size();
      mesh.extras.blocks.push_back(PassThroughBlock{pass->kind, pass->nodes, {}, {}, {}, {}});
    }
    PassThroughBlock& block = mesh.extras.blocks[slot];
    for (long long k = 0; k < end - begin; ++k)
      block.connectivity.push_back(
          static_cast<index_t>(kind_order(static_cast<std::uint8_t>(type), &connectivity[begin], static_cast<std::size_t>(k))));
    if (!tags.empty()) block.tags.push_back(tags[c]);
    if (!entities.empty()) block.entity_tags.push_back(entities[c]);
  }
  // Every offset is now within the connectivity array. VTK's cell arrays end
  // it at the last offset: values past it are a malformed file (a count or
  // an offset written wrong), not spare room to skip.
  const auto used = static_cast<std::size_t>(offsets.back());
  if (used != connectivity.size()) {
    const VtkValuePlace at = count ? place(VtkCellArray::Offsets, count, count - 1) : VtkValuePlace{where, ""};
    throw InputError(at.where, "the cells use " + std::to_string(used) + " of the connectivity array's " +
                                   std::to_string(connectivity.size()) + " values" +
                                   (at.entry.empty() ? "" : " (" + at.entry + ")"));
  }
  if (mesh.extras.blocks.empty()) return;
  mesh.fixed.resize(mesh.num_nodes(), 0);
  mark_element_nodes(mesh.extras.blocks, mesh.fixed);
}

}  // namespace tetsmooth
