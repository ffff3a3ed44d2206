#include "mesh/topology.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>

#include "mesh/counting_sort.hpp"
#include "mesh/errors.hpp"
#include "mesh/team_size.hpp"

namespace tetsmooth {
namespace {

// Calls body(r) for every row r < rows, on `threads` OpenMP threads when
// threads > 1. Rows differ in length, so they are dealt in small chunks.
template <class Body>
void for_each_row(std::size_t rows, int threads, const Body& body) {
  const bool shared = threads > 1;
#pragma omp parallel for num_threads(shared ? threads : 1) if (shared) schedule(dynamic, 512)
  for (std::ptrdiff_t r = 0; r < static_cast<std::ptrdiff_t>(rows); ++r) body(static_cast<std::size_t>(r));
}

// The node rows of a table sorted into rows by a counting sort
// (counting_sort.hpp): the row counts' exclusive scan places every item, as
// the paper's scan of the sorted pairs' row counts does, and only a row's
// own items are left to order. `finish(row, first, last)` orders the row's
// items in place and returns the end of those it keeps (rows are finished
// side by side when threads > 1); the kept items are then packed.
template <class Finish>
Csr pack_rows(RowBuckets<index_t>&& b, const Finish& finish, int threads) {
  const std::size_t rows = b.offsets.size() - 1;
  std::vector<std::size_t> kept(rows);
  for_each_row(rows, threads, [&](std::size_t r) {
    index_t* const first = b.items.data() + b.offsets[r];
    kept[r] = static_cast<std::size_t>(finish(r, first, b.items.data() + b.offsets[r + 1]) - first);
  });
  Csr csr;
  csr.offsets.assign(rows + 1, 0);
  std::size_t out = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    out += kept[r];
    // validate_mesh bounds the tets, and so the incidence rows; a mesh whose
    // tets share hardly an edge could still overflow the neighbour rows.
    if (out > static_cast<std::size_t>(std::numeric_limits<index_t>::max()))
      throw InputError("", "the mesh's topology needs more than " +
                               std::to_string(std::numeric_limits<index_t>::max()) +
                               " entries in one table (the neighbour rows, 2 an edge), past its 32-bit offsets");
    csr.offsets[r + 1] = static_cast<index_t>(out);
  }
  csr.items.resize(out);
  for_each_row(rows, threads, [&](std::size_t r) {
    const index_t* const first = b.items.data() + b.offsets[r];
    std::copy(first, first + kept[r], csr.items.data() + csr.offsets[r]);
  });
  return csr;
}

// A face's nodes ascending, by min and max: a tet's corner order is
// arbitrary, and the branches of a general sort mispredicted on about every
// face (on the 1M-node lattice, most of the face sort's time).
std::array<index_t, 3> ascending(index_t a, index_t b, index_t c) {
  const index_t lo = std::min(a, b), hi = std::max(a, b);
  const index_t top = std::max(hi, c), rest = std::min(hi, c);
  return {std::min(lo, rest), std::max(lo, rest), top};
}

// One more than the largest node index in `tets` (0 for none): the rows of
// the tables below that are sorted by node without a node count given.
std::size_t node_rows(const std::vector<index_t>& tets) {
  index_t top = -1;
  for (index_t v : tets) top = std::max(top, v);
  return static_cast<std::size_t>(top) + 1;
}

}  // namespace

Csr build_neighbours(const std::vector<index_t>& tets, std::size_t num_nodes, int threads) {
  threads = team_size(threads);
  // Each edge in both directions, so every node's row is complete.
  RowBuckets<index_t> pairs = sort_into_rows<index_t>(
      num_nodes, tets.size() / 4,
      [&](std::size_t t, const auto& slot) {
        for (const auto& e : kTetEdges) {
          const index_t a = tets[4 * t + e[0]], b = tets[4 * t + e[1]];
          slot(static_cast<std::size_t>(a)) = b;
          slot(static_cast<std::size_t>(b)) = a;
        }
      },
      threads);
  // A row lists each neighbour once for every tet on their edge (about 80
  // entries for 14 neighbours in a lattice): each is kept at its first
  // sight, marked with the row in `seen`, and only the few kept are sorted
  // (sorting whole rows took three times as long). A tet with a repeated
  // node would give a self loop; it is no neighbour. Rows finished side by
  // side share `seen`: another row's mark may replace this row's between two
  // sightings of a neighbour, which is then kept twice (never dropped: only
  // this row writes its own mark), so the kept entries are made unique.
  std::vector<index_t> seen(num_nodes, -1);
  return pack_rows(
      std::move(pairs),
      [&](std::size_t row, index_t* first, index_t* last) {
        const index_t self = static_cast<index_t>(row);
        index_t* kept = first;
        for (const index_t* p = first; p != last; ++p) {
          index_t& mark = seen[static_cast<std::size_t>(*p)];
          index_t marked;
#pragma omp atomic read
          marked = mark;
          if (*p != self && marked != self) {
#pragma omp atomic write
            mark = self;
            *kept++ = *p;
          }
        }
        std::sort(first, kept);
        return std::unique(first, kept);
      },
      threads);
}

Csr build_node_tets(const std::vector<index_t>& tets, std::size_t num_nodes, int threads) {
  threads = team_size(threads);
  // Produced in tet order, so each row is already ascending; a tet that
  // names a node twice lists itself twice in a row, side by side.
  RowBuckets<index_t> uses = sort_into_rows<index_t>(
      num_nodes, tets.size() / 4,
      [&](std::size_t t, const auto& slot) {
        for (int k = 0; k < 4; ++k) slot(static_cast<std::size_t>(tets[4 * t + k])) = static_cast<index_t>(t);
      },
      threads);
  return pack_rows(
      std::move(uses),
      [](std::size_t, index_t* first, index_t* last) { return std::unique(first, last); },
      threads);
}

RowItems<FaceUse> sorted_face_uses(const std::vector<index_t>& tets, int threads) {
  threads = team_size(threads);
  // Into rows by the face's lowest node, then each row sorted on its own:
  // the rows in order are the whole sorted list.
  RowBuckets<FaceUse> uses = sort_into_rows<FaceUse>(
      node_rows(tets), tets.size() / 4,
      [&](std::size_t t, const auto& slot) {
        for (int f = 0; f < 4; ++f) {
          const std::array<index_t, 3> face =
              ascending(tets[4 * t + kTetFaces[f][0]], tets[4 * t + kTetFaces[f][1]], tets[4 * t + kTetFaces[f][2]]);
          FaceUse& u = slot(static_cast<std::size_t>(face[0]));
          u.face = face;
          u.opposite = tets[4 * t + f];
          u.tet = static_cast<index_t>(t);
        }
      },
      threads);
  const auto before = [](const FaceUse& a, const FaceUse& b) {
    return std::tie(a.face, a.opposite, a.tet) < std::tie(b.face, b.opposite, b.tet);
  };
  for_each_row(uses.offsets.size() - 1, threads, [&](std::size_t r) {
    std::sort(uses.items.begin() + uses.offsets[r], uses.items.begin() + uses.offsets[r + 1], before);
  });
  return std::move(uses.items);
}

std::vector<std::uint8_t> find_boundary_nodes(const std::vector<index_t>& tets, std::size_t num_nodes, int threads,
                                              const std::vector<index_t>& midsides) {
  const RowItems<FaceUse> uses = sorted_face_uses(tets, threads);
  std::vector<std::uint8_t> boundary(num_nodes, 0);
  for (std::size_t first = 0, last; first < uses.size(); first = last) {
    for (last = first + 1; last < uses.size() && uses[last].face == uses[first].face; ++last) {
    }
    // Sorted by opposite node within the run: all uses agree on it exactly
    // when the first and the last do.
    if (uses[first].opposite != uses[last - 1].opposite) continue;
    for (index_t n : uses[first].face) boundary[static_cast<std::size_t>(n)] = 1;
    if (midsides.empty()) continue;
    // The face's three edges are the tet's edges without the opposite node.
    const auto t = static_cast<std::size_t>(uses[first].tet);
    const index_t opposite = uses[first].opposite;
    for (int e = 0; e < 6; ++e)
      if (tets[4 * t + kTetEdges[e][0]] != opposite && tets[4 * t + kTetEdges[e][1]] != opposite)
        boundary[static_cast<std::size_t>(midsides[6 * t + static_cast<std::size_t>(e)])] = 1;
  }
  return boundary;
}

std::size_t count_repeated_tets(const std::vector<index_t>& tets) {
  // Each tet's nodes ascending, into rows by the lowest: repeats share a row.
  using Sorted = std::array<index_t, 4>;
  const auto produce = [&](std::size_t t, const auto& slot) {
    Sorted s;
    std::copy(tets.begin() + 4 * t, tets.begin() + 4 * t + 4, s.begin());
    std::sort(s.begin(), s.end());
    slot(static_cast<std::size_t>(s[0])) = s;
  };
  RowBuckets<Sorted> sorted = sort_into_rows<Sorted>(node_rows(tets), tets.size() / 4, produce);
  std::size_t repeated = 0;
  for (std::size_t r = 0; r + 1 < sorted.offsets.size(); ++r) {
    const auto first = sorted.items.begin() + sorted.offsets[r], last = sorted.items.begin() + sorted.offsets[r + 1];
    std::sort(first, last);
    for (auto it = first; it != last && it + 1 != last; ++it) repeated += *it == *(it + 1);
  }
  return repeated;
}

std::vector<std::uint8_t> movable_nodes(const TetMesh& mesh, const std::vector<std::uint8_t>& boundary,
                                        const Csr& neighbours) {
  const std::size_t n = mesh.num_nodes();
  std::vector<std::uint8_t> movable(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const bool pinned = !mesh.fixed.empty() && mesh.fixed[i];
    movable[i] = !boundary[i] && !pinned && neighbours.row_size(i) > 0;
  }
  return movable;
}

Topology build_topology(const TetMesh& mesh, int threads) {
  threads = team_size(threads);
  Topology topo;
  topo.neighbours = build_neighbours(mesh.tets, mesh.num_nodes(), threads);
  topo.node_tets = build_node_tets(mesh.tets, mesh.num_nodes(), threads);
  topo.boundary = find_boundary_nodes(mesh.tets, mesh.num_nodes(), threads);
  topo.movable = movable_nodes(mesh, topo.boundary, topo.neighbours);
  return topo;
}

MovableRows movable_rows(const index_t* nbr_off, const index_t* inc_off, const std::uint8_t* movable, std::size_t n) {
  MovableRows r;
  for (std::size_t i = 0; i < n; ++i)
    if (movable[i]) {
      ++r.nodes;
      r.neighbour_entries += static_cast<std::size_t>(nbr_off[i + 1] - nbr_off[i]);
      r.incidence_entries += static_cast<std::size_t>(inc_off[i + 1] - inc_off[i]);
    }
  return r;
}

double mean_edge_length(const std::vector<double>& xyz, const Csr& neighbours) {
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < neighbours.rows(); ++i)
    for (const index_t* j = neighbours.row_begin(i); j != neighbours.row_end(i); ++j) {
      // In 64 bits: 3 * j wraps in index_t past 715 M nodes.
      const std::size_t k = static_cast<std::size_t>(*j);
      if (k <= i) continue;
      const double dx = xyz[3 * i] - xyz[3 * k], dy = xyz[3 * i + 1] - xyz[3 * k + 1],
                   dz = xyz[3 * i + 2] - xyz[3 * k + 2];
      sum += std::sqrt(dx * dx + dy * dy + dz * dz);
      ++count;
    }
  return count ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace tetsmooth
