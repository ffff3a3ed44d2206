// Mesh topology on the GPU, the paper's way (§3.2-3.3): edges as packed
// keys, radix sort, unique, the reversed copies appended and sorted by start
// node, CSR offsets; the same for node -> tet incidence; boundary faces by
// sorting the faces and comparing equal neighbours (device_topology_boundary.cu);
// then the movable flags.
//
// Keys (w = bits needed for the node count N, u = bits for the tet count T):
//   edge      min << w | max, 6 per tet, then for each unique edge also
//             max << w | min; a self loop of a tet with a repeated node
//             becomes the sentinel N << w, which sorts last and falls in no
//             row. The first sort visits 2w bits, the second the w of the
//             start node (see both_directions).
//   incidence node << u | tet, 4 per tet; a repeated node's second entry is a
//             sentinel N << u, so each (node, tet) appears once, as on the CPU;
//             the sort visits only the w node bits (stable, keys in tet order).
//   face      a 32-bit hash of the sorted triple, the face index as value
//             (device_topology_boundary.cu).
//
// Two streams: the neighbour rows on the caller's, and meanwhile the
// incidence rows and then the boundary on topo.side, joined before the
// movable flags, which need both. The phases are independent, and the radix
// sorts of a mesh of ~10^5 nodes leave the GPU room for another: on an H100
// the 109k model's topology took 0.86 ms with every phase on one stream and
// 0.73-0.75 ms with two (0.76-0.78 once the colouring's priority order was
// sorted on the side stream too, which took 0.07 ms off the colouring).
// Lattice-215's took 48.5 ms, as before: its sorts fill the GPU alone.
//
// Memory, to size a run (bytes per tet T; a lattice has N ~ T / 6):
//   scratch   two key buffers of 12 keys * 8 B = 192 B/tet. The edges take
//             the first 6 keys per tet of both (their sort, its unique
//             copy, then up to 2 * 6 directed keys per tet, whose rows stay
//             in one of them until the end); the incidence and then the
//             face sort work in the last 6 of both meanwhile. Directed edges
//             past the first half (more than 3 unique edges per tet, which
//             no mesh with shared edges has) wait for the side stream to
//             finish first. Plus CUB temp storage for each stream's sorts
//             (and the unique pass): bounded, since onesweep works in
//             portions of 2^28 keys (about 100-200 MB each at most).
//             topo.scratch.bytes() gives the exact figure.
//   results   inc 16 B/tet, nbr 4 B per directed edge (~9 B/tet on a lattice,
//             14 neighbours per node), offsets 8 B/node, flags 2 B/node.
//   So the 10M-node lattice (~60M tets) needs about 60M * 192 B = 11.5 GB of
//   scratch and ~1.6 GB of results on top of the mesh itself. colour_device
//   later reuses the same scratch (about 24 B/node and CUB temp storage).
//
// Two host synchronisations: the unique edge count sizes the second edge
// sort (the side stream keeps the GPU busy meanwhile), and at the end the
// neighbour count sizes `nbr`, which is only allocated then; everything else
// is sized from N and T.
#include <algorithm>
#include <limits>
#include <string>

#include <cub/device/device_radix_sort.cuh>
#include <cub/device/device_select.cuh>

#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/device_topology.hpp"
#include "kernels/cuda/device_topology_detail.cuh"
#include "mesh/errors.hpp"

namespace tetsmooth::cuda {
namespace {

using detail::blocks_for;
using detail::kBlock;

// Written by the device: the unique edge count is read back after the first
// edge sort, the rest at the end.
struct BuildCounts {
  unsigned long long unique_edges;  // sentinel included
  index_t neighbours;               // nbr_off[N]
  index_t incidences;               // inc_off[N]
  unsigned movable;
};

// One thread per key, so neighbouring threads write neighbouring keys: key
// 6t + p is edge p of tet t ((0,1) (0,2) (0,3) (1,2) (1,3) (2,3)) as
// min << w | max.
__global__ void emit_edges(const index_t* tets, std::size_t num_tets, std::uint64_t num_nodes, int w,
                           std::uint64_t* keys) {
  const std::size_t k = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (k >= 6 * num_tets) return;
  const std::size_t t = k / 6;
  const int p = static_cast<int>(k % 6);
  const int first = p < 3 ? 0 : (p < 5 ? 1 : 2);
  const int second = p < 3 ? p + 1 : (p < 5 ? p - 1 : 3);
  const std::uint64_t a = static_cast<std::uint32_t>(tets[4 * t + first]);
  const std::uint64_t b = static_cast<std::uint32_t>(tets[4 * t + second]);
  keys[k] = a == b ? num_nodes << w : (a < b ? a << w | b : b << w | a);
}

// Each unique edge in both directions: the reversed copies (max << w | min)
// first, then the edges as they are, each part in the order of `edges`
// (sorted by min, then max); the sentinel stays a sentinel. A stable sort
// on the start node alone then gives each row its lower neighbours
// ascending (from the reversed part), then its higher ones (from the
// other): the row sorted, for a sort of w bits instead of 2w.
__global__ void both_directions(const std::uint64_t* edges, std::size_t count, std::uint64_t num_nodes, int w,
                                std::uint64_t* out) {
  const std::size_t k = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (k >= count) return;
  const std::uint64_t e = edges[k], low = (1ull << w) - 1;
  out[k] = (e >> w) == num_nodes ? e : ((e & low) << w | e >> w);
  out[count + k] = e;
}

// One thread per key, as emit_edges: key 4t + k is corner k of tet t.
__global__ void emit_incidence(const index_t* tets, std::size_t num_tets, std::uint64_t num_nodes, int u,
                               std::uint64_t* keys) {
  const std::size_t key = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (key >= 4 * num_tets) return;
  const std::size_t t = key / 4;
  const int k = static_cast<int>(key % 4);
  const index_t v = tets[key];
  bool repeat = false;
  for (int j = 0; j < k; ++j) repeat = repeat || tets[4 * t + j] == v;
  keys[key] = (repeat ? num_nodes : static_cast<std::uint32_t>(v)) << u | t;
}

__global__ void low_bits(const std::uint64_t* keys, std::size_t n, int w, index_t* out) {
  const std::size_t k = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (k < n) out[k] = static_cast<index_t>(keys[k] & ((1ull << w) - 1));
}

// Launched over whole blocks: __syncthreads_count needs every thread.
__global__ void mark_movable(std::size_t num_nodes, const index_t* nbr_off, const std::uint8_t* boundary,
                             const std::uint8_t* fixed, std::uint8_t* movable, unsigned* count) {
  const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  bool m = false;
  if (i < num_nodes) {
    m = !boundary[i] && !(fixed && fixed[i]) && nbr_off[i + 1] > nbr_off[i];
    movable[i] = m;
  }
  const int in_block = __syncthreads_count(m);
  if (threadIdx.x == 0 && in_block > 0) atomicAdd(count, static_cast<unsigned>(in_block));
}

// Where the phases keep their data inside topo.scratch.
struct BuildScratch {
  BuildCounts* counts;
  std::uint64_t* keys[2];  // 12 keys per tet each: the first 6 for the edges, the last 6 for the side stream
  void* temp;              // CUB storage of the edges' sorts and unique pass
  void* side_temp;         // and of the side stream's sorts
  std::size_t temp_bytes, side_temp_bytes;
  std::size_t bytes;  // all of it
};

BuildScratch carve(unsigned char* base, std::size_t num_tets, std::size_t temp_bytes, std::size_t side_temp_bytes) {
  detail::ScratchCarver carver(base);
  BuildScratch s{};
  s.counts = carver.take<BuildCounts>(1);
  s.keys[0] = carver.take<std::uint64_t>(12 * num_tets);
  s.keys[1] = carver.take<std::uint64_t>(12 * num_tets);
  s.temp = carver.take<unsigned char>(temp_bytes);
  s.side_temp = carver.take<unsigned char>(side_temp_bytes);
  s.temp_bytes = temp_bytes;
  s.side_temp_bytes = side_temp_bytes;
  s.bytes = carver.used();
  return s;
}

// The CUB temp storage the edges' phase needs, for the bit widths used.
std::size_t edge_temp_bytes(std::size_t num_tets, int w) {
  std::size_t need = 0, bytes = 0;
  cub::DoubleBuffer<std::uint64_t> none(nullptr, nullptr);
  CUDA_CHECK(cub::DeviceRadixSort::SortKeys(nullptr, bytes, none, 12 * num_tets, 0, 2 * w));
  need = std::max(need, bytes);
  CUDA_CHECK(cub::DeviceSelect::Unique(nullptr, bytes, none.Current(), none.Current(),
                                       static_cast<unsigned long long*>(nullptr), 6 * num_tets));
  return std::max(need, bytes);
}

// And the side stream's: the incidence sort, the face sort and, where asked
// for, the priority order's.
std::size_t side_temp_bytes(std::size_t num_tets, std::size_t num_nodes, int w, int u, bool priority_order) {
  std::size_t bytes = 0;
  cub::DoubleBuffer<std::uint64_t> none(nullptr, nullptr);
  CUDA_CHECK(cub::DeviceRadixSort::SortKeys(nullptr, bytes, none, 4 * num_tets, u, w + u));
  bytes = std::max(bytes, detail::face_temp_bytes(num_tets));
  return priority_order ? std::max(bytes, detail::priority_order_temp_bytes(num_nodes)) : bytes;
}

// Node -> tets on `side`: 4 keys per tet, sorted; row = node, item = tet.
// Then the boundary flags. Works in `half[0]` and `half[1]`, 6 keys per tet
// each.
void build_incidence_and_boundary(DeviceTopology& topo, const index_t* d_tets, std::size_t nt, std::size_t n, int w,
                                  int u, std::uint64_t* const half[2], void* temp, std::size_t temp_bytes,
                                  cudaStream_t side) {
  const auto rows = static_cast<index_t>(n);
  cub::DoubleBuffer<std::uint64_t> inc(half[0], half[1]);
  std::size_t temp_size = temp_bytes;
  if (nt > 0) {
    emit_incidence<<<blocks_for(4 * nt), kBlock, 0, side>>>(d_tets, nt, n, u, inc.Current());
    CUDA_CHECK_LAUNCH();
    // Keys are emitted in tet order and the radix sort is stable, so sorting
    // the node bits alone leaves each row's tets ascending.
    CUDA_CHECK(cub::DeviceRadixSort::SortKeys(temp, temp_size, inc, 4 * nt, u, w + u, side));
  }
  detail::csr_from_sorted<<<blocks_for(4 * nt + 1), kBlock, 0, side>>>(
      detail::PackedRows{inc.Current(), u}, static_cast<const unsigned long long*>(nullptr), 4 * nt, rows,
      topo.inc_off.data(), topo.inc.data());
  CUDA_CHECK_LAUNCH();
  detail::mark_boundary_nodes(d_tets, nt, n, half[0], half[1], temp, temp_bytes, topo.boundary.data(), side);
}

}  // namespace

void build_device_topology(DeviceTopology& topo, const index_t* d_tets, std::size_t num_tets, std::size_t num_nodes,
                           const std::uint8_t* d_fixed, cudaStream_t stream, bool priority_order) {
  const std::size_t n = num_nodes, nt = num_tets;
  const auto rows = static_cast<index_t>(n);
  const int w = detail::bits_for(n);                     // node indices and the sentinel N
  const int u = detail::bits_for(nt > 0 ? nt - 1 : 0);  // tet indices
  topo.num_nodes = n;
  topo.num_tets = nt;
  topo.nbr_off.resize(n + 1);
  topo.inc_off.resize(n + 1);
  topo.inc.resize(4 * nt);  // an upper bound, trimmed below without reallocating
  topo.boundary.resize(n);
  topo.movable.resize(n);

  // The priority order's sort takes 3 words a node from the side's half,
  // which has 12 a tet: every mesh whose nodes all belong to tets.
  topo.priority_order_built = priority_order && n > 0 && 3 * n <= 12 * nt;
  if (topo.priority_order_built) topo.priority_order.resize(n);
  const std::size_t temp_bytes = edge_temp_bytes(nt, w),
                    side_bytes = side_temp_bytes(nt, n, w, u, topo.priority_order_built);
  topo.scratch.resize(carve(nullptr, nt, temp_bytes, side_bytes).bytes);
  const BuildScratch s = carve(topo.scratch.data(), nt, temp_bytes, side_bytes);
  std::size_t temp_size = s.temp_bytes;
  CUDA_CHECK(cudaMemsetAsync(s.counts, 0, sizeof(BuildCounts), stream));

  std::uint64_t* const side_half[2] = {s.keys[0] + 6 * nt, s.keys[1] + 6 * nt};
  const cudaStream_t side = topo.side.begin(stream);
  build_incidence_and_boundary(topo, d_tets, nt, n, w, u, side_half, s.side_temp, s.side_temp_bytes, side);
  if (topo.priority_order_built) {
    auto* words = reinterpret_cast<std::uint32_t*>(side_half[0]);
    detail::sort_priority_order(n, topo.priority_order.data(), words, words + n,
                                reinterpret_cast<index_t*>(words + 2 * n), s.side_temp, s.side_temp_bytes, side);
  }
  topo.side.end();

  // Neighbours: each tet's 6 edges as (min, max), sorted and made unique;
  // then each unique edge in both directions, sorted by start node; rows
  // follow. (The paper appends the reversed copies before the one sort;
  // appending them to the unique edges sorts a sixth as many keys the
  // second time, on half the bits.)
  cub::DoubleBuffer<std::uint64_t> edges(s.keys[0], s.keys[1]);
  BuildCounts counts{};
  if (nt > 0) {
    emit_edges<<<blocks_for(6 * nt), kBlock, 0, stream>>>(d_tets, nt, n, w, s.keys[0]);
    CUDA_CHECK_LAUNCH();
    CUDA_CHECK(cub::DeviceRadixSort::SortKeys(s.temp, temp_size, edges, 6 * nt, 0, 2 * w, stream));
    CUDA_CHECK(cub::DeviceSelect::Unique(s.temp, temp_size, edges.Current(), edges.Alternate(),
                                         &s.counts->unique_edges, 6 * nt, stream));
    // The unique count sizes the second sort: a read-back.
    CUDA_CHECK(cudaMemcpyAsync(&counts.unique_edges, &s.counts->unique_edges, sizeof counts.unique_edges,
                               cudaMemcpyDeviceToHost, stream));
    CUDA_CHECK(cudaStreamSynchronize(stream));
  }
  const std::size_t directed = 2 * static_cast<std::size_t>(counts.unique_edges);
  // 32-bit offsets: validate_mesh bounds the incidence rows (4 entries a
  // tet); the neighbour rows of tets that share hardly an edge could still
  // pass them, and are checked here, exactly, before they are built.
  if (directed > static_cast<std::size_t>(std::numeric_limits<index_t>::max()))
    throw InputError("", "the mesh's edges need more than " + std::to_string(std::numeric_limits<index_t>::max()) +
                             " neighbour entries (2 an edge), past the 32-bit offsets of the neighbour table");
  // Up to 12 keys per tet (tets that share no edge): past the first half,
  // into the side stream's.
  if (directed > 6 * nt) topo.side.await(stream);
  cub::DoubleBuffer<std::uint64_t> rows_sorted(edges.Current(), edges.Alternate());
  if (directed > 0) {
    both_directions<<<blocks_for(directed / 2), kBlock, 0, stream>>>(edges.Alternate(), directed / 2, n, w,
                                                                     edges.Current());
    CUDA_CHECK_LAUNCH();
    CUDA_CHECK(cub::DeviceRadixSort::SortKeys(s.temp, temp_size, rows_sorted, directed, w, 2 * w, stream));
  }
  // The directed edges stay where they are until low_bits reads them.
  const std::uint64_t* directed_edges = rows_sorted.Current();
  detail::csr_from_sorted<<<blocks_for(directed + 1), kBlock, 0, stream>>>(
      detail::PackedRows{directed_edges, w}, static_cast<const unsigned long long*>(nullptr), directed, rows,
      topo.nbr_off.data(), static_cast<index_t*>(nullptr));
  CUDA_CHECK_LAUNCH();

  topo.side.await(stream);  // the boundary flags and the incidence rows
  if (n > 0) {
    mark_movable<<<blocks_for(n), kBlock, 0, stream>>>(n, topo.nbr_off.data(), topo.boundary.data(), d_fixed,
                                                       topo.movable.data(), &s.counts->movable);
    CUDA_CHECK_LAUNCH();
  }

  // The last read-back: the sizes the host must know.
  CUDA_CHECK(cudaMemcpyAsync(&s.counts->neighbours, topo.nbr_off.data() + n, sizeof(index_t),
                             cudaMemcpyDeviceToDevice, stream));
  CUDA_CHECK(cudaMemcpyAsync(&s.counts->incidences, topo.inc_off.data() + n, sizeof(index_t),
                             cudaMemcpyDeviceToDevice, stream));
  CUDA_CHECK(cudaMemcpyAsync(&counts, s.counts, sizeof(BuildCounts), cudaMemcpyDeviceToHost, stream));
  CUDA_CHECK(cudaStreamSynchronize(stream));
  topo.movable_count = counts.movable;
  topo.inc.resize(static_cast<std::size_t>(counts.incidences));
  topo.nbr.resize(static_cast<std::size_t>(counts.neighbours));
  if (counts.neighbours > 0) {
    low_bits<<<blocks_for(counts.neighbours), kBlock, 0, stream>>>(directed_edges, counts.neighbours, w,
                                                                   topo.nbr.data());
    CUDA_CHECK_LAUNCH();
  }
}

}  // namespace tetsmooth::cuda
