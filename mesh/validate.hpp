#pragma once
// Checks a mesh as it comes in from a file or generator.
#include <cstddef>
#include <string>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

struct ValidationReport {
  std::size_t nodes = 0, tets = 0;
  int nodes_per_tet = 4;         // 10 for second-order tets (TetMesh::midsides)
  std::size_t inverted = 0;      // signed volume < 0
  std::size_t degenerate = 0;    // signed volume == 0 or a repeated node
  std::size_t unreferenced = 0;  // nodes in no tet, neither corners nor midside nodes
  // Tets with the node set of an earlier tet (count_repeated_tets in
  // mesh/topology.hpp). A sort of every tet, which the readers' own
  // validation does not need: validate_mesh leaves it 0 and the command
  // line fills it in.
  std::size_t repeated = 0;
};

// Throws InputError (naming `source` and the offending tet or node) when a
// node index is out of range, a coordinate is not finite, the arrays have
// the wrong shape, there are no tets, or a midside node of a second-order
// tet is also a corner or the midside node of another edge. Inverted and
// degenerate tets are counted, not rejected: the caller decides whether to
// warn. Errors in the tets, midside nodes and other elements name
// `element_source` instead where it is given (TetGen keeps them in the .ele
// file, the nodes in the .node).
ValidationReport validate_mesh(const TetMesh& mesh, const std::string& source = "mesh",
                               const std::string& element_source = "");

// The most tets a mesh may have: the node-to-tet table holds 4 entries a tet
// under 32-bit offsets (536,870,911). validate_mesh refuses more, and the
// .tsm reader does so from its header, before reading the tets.
std::size_t max_tets();

}  // namespace tetsmooth
