#pragma once
// Mesh topology on the CPU: the tables of the paper's §3.2-3.3, which the
// CUDA version (kernels/cuda/device_topology.cu) builds the paper's way and
// is checked against item by item. Here the pairs are sorted by their first
// node with a counting sort (mesh/counting_sort.hpp), then each row on its
// own: the same order as one comparison sort of all the pairs, with only
// short rows left to compare. On a 2-core host, `tetsmooth quality` of a
// 1M-node, 6M-tet lattice took 9.5 s with the one sort, about half of it
// sorting, and takes 2.5 s with this.
//
// `threads` (1 by default, the serial reference; 0 for all cores) runs the
// tables' counting sorts (on at most kMaxSortRuns of them, with a count
// array of 8 bytes a row for each: 128 MB a million nodes at 16) and row
// sorts on that many OpenMP threads; every table comes out the same
// whatever the count. count_repeated_tets stays serial.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/row_items.hpp"
#include "mesh/csr.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// Node -> neighbour nodes (nodes sharing an edge), each row sorted ascending,
// no self loops. Built from the tets' 6 edges and a reversed copy of each,
// sorted by (start, end), duplicates removed; the offsets are the exclusive
// scan of the row counts.
Csr build_neighbours(const std::vector<index_t>& tets, std::size_t num_nodes, int threads = 1);

// Node -> incident tets, each row sorted ascending.
Csr build_node_tets(const std::vector<index_t>& tets, std::size_t num_nodes, int threads = 1);

// One face of one tet: its nodes ascending, the tet's fourth node (which
// tells the tets on the two sides of a face apart, and a tet listed twice
// from two tets) and the tet's index (tets fit index_t, as in node_tets).
struct FaceUse {
  std::array<index_t, 3> face;
  index_t opposite;
  index_t tet;
};

// The 4 faces of every tet, sorted by (face, opposite, tet): the uses of a
// face lie together, those of each tet on it together within them.
RowItems<FaceUse> sorted_face_uses(const std::vector<index_t>& tets, int threads = 1);

// 1 for nodes on a boundary face: each tet's 4 faces are stored with sorted
// node indices and the tet's fourth node, all faces sorted, and a face is on
// the boundary when one tet uses it. A tet listed twice (Gmsh's MSH 2.2
// writer repeats the tets of a volume in two physical groups) is still one
// tet: the uses of a face count as one when they share the fourth node, so
// such a file keeps its boundary. Nodes in no tet are not boundary nodes
// (they have no faces); they never move because they have no neighbours.
// Given the midside nodes of second-order tets (TetMesh::midsides), those on
// the edges of boundary faces are boundary nodes too.
std::vector<std::uint8_t> find_boundary_nodes(const std::vector<index_t>& tets, std::size_t num_nodes,
                                              int threads = 1, const std::vector<index_t>& midsides = {});

// How many tets have the same four nodes as an earlier tet (in any order).
std::size_t count_repeated_tets(const std::vector<index_t>& tets);

// A node may move when it is not on the boundary, not pinned by the file
// (mesh.fixed) and has at least one neighbour.
std::vector<std::uint8_t> movable_nodes(const TetMesh& mesh, const std::vector<std::uint8_t>& boundary,
                                        const Csr& neighbours);

struct Topology {
  Csr neighbours;
  Csr node_tets;
  std::vector<std::uint8_t> boundary;
  std::vector<std::uint8_t> movable;
};

Topology build_topology(const TetMesh& mesh, int threads = 1);

// The rows of the movable nodes: how many, and their neighbour and incidence
// entries, which is what a sweep that evaluates every movable node reads of
// the two CSRs. Offsets of n + 1 entries each, movable of n.
struct MovableRows {
  std::size_t nodes = 0, neighbour_entries = 0, incidence_entries = 0;
};
MovableRows movable_rows(const index_t* nbr_off, const index_t* inc_off, const std::uint8_t* movable, std::size_t n);
inline MovableRows movable_rows(const Topology& t) {
  return movable_rows(t.neighbours.offsets.data(), t.node_tets.offsets.data(), t.movable.data(), t.movable.size());
}

// Mean length of the unique edges (each row pair i<j counted once).
double mean_edge_length(const std::vector<double>& xyz, const Csr& neighbours);

}  // namespace tetsmooth
