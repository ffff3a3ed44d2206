#pragma once
// What a mesh file carries besides node coordinates and tets, kept so that a
// read-smooth-write round trip loses nothing. The smoother never looks here.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tetsmooth {

// A block of non-tet elements passed through unchanged (triangles, lines,
// points, ...). Their nodes are fixed by the reader (TetMesh::fixed).
struct PassThroughBlock {
  std::string kind;  // "triangle", "line", "vertex", "quad", ...
  int nodes_per_element = 0;
  std::vector<std::int32_t> connectivity;  // 0-based node indices
  std::vector<int> tags;                   // per element: physical/region tag, or empty
  std::vector<int> entity_tags;            // per element: geometric entity tag (Gmsh), or empty
  std::vector<long long> element_tags;     // per element: the file's element id (Gmsh), or empty
};

// The dimension of a pass-through block's elements (0 for points, 1 for
// lines, 2 for triangles and quads, 3 for solids), that of the physical
// names ($PhysicalNames) of their region tags.
inline int kind_dimension(std::string_view kind) {
  if (kind == "vertex") return 0;
  if (kind.substr(0, 4) == "line") return 1;
  if (kind.substr(0, 8) == "triangle" || kind.substr(0, 4) == "quad") return 2;
  return 3;
}

struct FileExtras {
  std::vector<long long> node_tags;  // original node ids (sparse Gmsh tags), or empty
  std::vector<int> tet_tags;         // per tet: physical/region attribute, or empty
  std::vector<int> tet_entity_tags;  // per tet: geometric entity tag (Gmsh), or empty
  // Per tet: the file's element id (Gmsh element tag), or empty. Written back
  // when every element has one and they are positive and distinct, so that
  // ids a simulation deck refers to survive a round trip.
  std::vector<long long> tet_element_tags;
  std::vector<PassThroughBlock> blocks;
  // Format sections reproduced verbatim on write (e.g. "$Entities", "$PhysicalNames"
  // bodies for Gmsh), keyed by section name.
  std::vector<std::pair<std::string, std::string>> raw_sections;
  // TetGen .node boundary markers (one per node) and node attributes
  // (node_attribute_count per node, row-major), or empty.
  std::vector<int> node_markers;
  int node_attribute_count = 0;
  std::vector<double> node_attributes;
  // TetGen .ele attributes (tet_attribute_count per tet, row-major), kept
  // when tet_tags cannot give them back: more than one per tet, or a region
  // attribute (the first) that is not a whole number in int range. Empty
  // otherwise, tet_tags then holding the region attribute itself.
  int tet_attribute_count = 0;
  std::vector<double> tet_attributes;
  // Gmsh MSH 4.1 (and meshio's gmsh:dim_tags in VTU and VTK): the model
  // entity (dimension, tag) each node is classified on, one pair per node,
  // or empty. Medit vertex references go to node_markers, the same per-node
  // label as TetGen's boundary markers.
  std::vector<int> node_entity_dims;
  std::vector<int> node_entity_tags;
  // Medit RequiredVertices and Corners: 0-based node indices, kept apart
  // from TetMesh::fixed (which also holds the nodes of pass-through
  // elements) so that a Medit file is written back as it was read.
  std::vector<std::int32_t> required_nodes;
  std::vector<std::int32_t> corner_nodes;
  // What the reader read but will not write back, or could not map (a
  // section it skips, a data array it does not carry), one sentence each
  // without the file's name; the command line prints them as warnings.
  std::vector<std::string> read_notes;
};

// The body of the raw section `name`, or nullptr when the file had none.
inline const std::string* raw_section(const FileExtras& extras, std::string_view name) {
  for (const auto& [key, body] : extras.raw_sections)
    if (key == name) return &body;
  return nullptr;
}

// Whether a file's numbers (node_tags, tet_element_tags) are just the
// positions 1, 2, ... in order, which the 0-based indices already give and
// every format keeps by writing the items in order; true for none.
inline bool numbered_by_position(const std::vector<long long>& numbers) {
  for (std::size_t i = 0; i < numbers.size(); ++i)
    if (numbers[i] != static_cast<long long>(i) + 1) return false;
  return true;
}

// Whether the extras hold TetGen tet attributes for each of `tets` tets.
inline bool has_tet_attributes(const FileExtras& extras, std::size_t tets) {
  return extras.tet_attribute_count > 0 &&
         extras.tet_attributes.size() == static_cast<std::size_t>(extras.tet_attribute_count) * tets;
}

// Sets flags[n] for every node of a pass-through element (`flags` holds one
// per node): the nodes that the elements pin.
inline void mark_element_nodes(const std::vector<PassThroughBlock>& blocks, std::vector<std::uint8_t>& flags) {
  for (const PassThroughBlock& block : blocks)
    for (std::int32_t n : block.connectivity) flags[static_cast<std::size_t>(n)] = 1;
}

}  // namespace tetsmooth
