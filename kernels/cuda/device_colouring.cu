// Jones-Plassmann colouring on the GPU with the CPU's colour_nodes()
// (mesh/colouring.cpp) result: the same colours and the same number of
// rounds, reached without rounds.
//
// In Jones-Plassmann a node is coloured in the first round in which all its
// movable neighbours of higher priority (colours_before) are coloured, and
// none of lower priority can be coloured before it. So it takes the
// smallest colour none of its higher-priority neighbours has, and its round
// is one more than the latest of theirs: a recurrence over the priority
// order that needs no barrier. One cooperative launch works through the
// nodes sorted by descending priority; a group of lanes takes a node, waits
// until each higher-priority neighbour has published its (round, colour)
// word, then publishes its own. Groups take positions in a strided loop,
// so the unfinished node of highest priority always has every input and a
// resident group working on it: the wait always ends. (A launch with every
// block resident is what that needs; the cooperative launch guarantees it.)
//
// Classes: the colours (non-movable nodes as a sentinel past the last
// colour) are radix sorted with the node indices as values; the sort is
// stable, so each class lists its nodes ascending, and only the sentinel's
// bits are sorted. The host reads the colour count back only with the
// classes' offsets (see kQuickColours).
#include <cooperative_groups.h>
#include <cub/device/device_radix_sort.cuh>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/device_topology.hpp"
#include "kernels/cuda/device_topology_detail.cuh"
#include "kernels/cuda/lane_groups.cuh"
#include "kernels/cuda/resident_blocks.cuh"
#include "mesh/colouring.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth::cuda {
namespace {

using detail::blocks_for;
using detail::kBlock;

// A node's published word: round in the high half, colour in the low half.
// Movable nodes start at kWaiting; the others are final from the start:
// round 0, colour -1 (they never compete and give no colour away).
constexpr std::uint64_t kWaiting = ~std::uint64_t{0};
constexpr std::uint64_t kNeverMoves = 0xffffffffull;

__device__ __host__ constexpr std::uint64_t publish_word(unsigned round, int colour) {
  return (static_cast<std::uint64_t>(round) << 32) | static_cast<std::uint32_t>(colour);
}

// Written by the device, read back once.
struct ColourTotals {
  int max_colour;
  unsigned rounds;
};

// Sort keys for the priority order: ascending keys are descending
// priority, and the stable sort keeps ties in index order, as
// colours_before breaks them.
__global__ void priority_order_keys(std::size_t n, std::uint32_t* keys, index_t* nodes) {
  const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (i >= n) return;
  keys[i] = ~colouring_priority(static_cast<std::uint32_t>(i));
  nodes[i] = static_cast<index_t>(i);
}

// Thread 0 also starts the totals, so that no copy from the host (whose
// pageable source would make the stream wait) precedes the launch.
__global__ void start_words(std::size_t n, const std::uint8_t* movable, std::uint64_t* word, ColourTotals* totals) {
  const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (i == 0) *totals = ColourTotals{-1, 0};
  if (i < n) word[i] = movable[i] ? kWaiting : kNeverMoves;
}

// Lanes per node: a row of ~14 neighbours takes 2 rounds of waits. On an
// H100 the 109k model's colouring took 0.242-0.250 ms with 8, 0.254-0.260
// with 4 and 0.269-0.276 with 2 (medians of 5; the polls' sleep, 0 to 512
// ns, changed nothing).
constexpr int kColourLanes = 8;

__device__ std::uint64_t wait_for(const std::uint64_t* word) {
  std::uint64_t w = *reinterpret_cast<const volatile std::uint64_t*>(word);
  while (w == kWaiting) {
    __nanosleep(32);
    w = *reinterpret_cast<const volatile std::uint64_t*>(word);
  }
  return w;
}

// The smallest colour none of i's higher-priority neighbours has, looked
// for 64 colours at a time, on one thread (the rare case of 64+ colours).
// Every word it needs is final by now, but is read past L1 all the same: a
// line cached earlier may predate it.
__device__ int first_free_colour(const index_t* nbr, index_t b, index_t e, std::uint32_t i,
                                 const std::uint64_t* word, int from) {
  for (int base = from;; base += 64) {
    unsigned long long used = 0;
    for (index_t k = b; k < e; ++k) {
      const index_t j = nbr[k];
      if (!colours_before(static_cast<std::uint32_t>(j), i)) continue;
      const int c = static_cast<int>(static_cast<std::uint32_t>(wait_for(word + j))) - base;
      if (c >= 0 && c < 64) used |= 1ull << c;
    }
    if (~used != 0) return base + __ffsll(static_cast<long long>(~used)) - 1;
  }
}

__global__ void __launch_bounds__(kBlock) colour_dataflow_kernel(std::size_t n, const index_t* order,
                                                                 const index_t* nbr_off, const index_t* nbr,
                                                                 std::uint64_t* word, int* colour,
                                                                 ColourTotals* totals) {
  namespace cg = cooperative_groups;
  constexpr int G = kColourLanes;
  cg::grid_group grid = cg::this_grid();
  const unsigned long long tid = grid.thread_rank(), groups = grid.size() / G;
  const int lane = static_cast<int>(tid % G);
  const unsigned mask = group_mask<G>();
  int picked = -1;
  unsigned latest = 0;
  for (unsigned long long pos = tid / G; pos < n; pos += groups) {
    const index_t i = order[pos];
    if (word[i] != kWaiting) continue;  // never moves (the group leaves together)
    const index_t b = nbr_off[i], e = nbr_off[i + 1];
    unsigned round = 0;                 // the latest round among higher-priority neighbours
    unsigned long long used = 0;        // their colours 0..63
    for (index_t k = b + lane; k < e; k += G) {
      const index_t j = nbr[k];
      if (!colours_before(static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(i))) continue;
      const std::uint64_t w = wait_for(word + j);
      round = max(round, static_cast<unsigned>(w >> 32));
      const int c = static_cast<int>(static_cast<std::uint32_t>(w));
      if (c >= 0 && c < 64) used |= 1ull << c;
    }
    round = group_max<G>(round, mask) + 1;
    used = group_or<G>(used, mask);
    if (lane == 0) {
      const int c = ~used != 0 ? __ffsll(static_cast<long long>(~used)) - 1
                               : first_free_colour(nbr, b, e, static_cast<std::uint32_t>(i), word, 64);
      colour[i] = c;
      // The colour array is for later kernels; the word is what waiting
      // groups read, stored in one piece.
      *reinterpret_cast<volatile std::uint64_t*>(word + i) = publish_word(round, c);
      picked = max(picked, c);
      latest = max(latest, round);
    }
  }
  const int warp_colour = __reduce_max_sync(0xffffffffu, picked);
  const unsigned warp_round = __reduce_max_sync(0xffffffffu, latest);
  if ((threadIdx.x & 31) == 0) {
    if (warp_colour >= 0) atomicMax(&totals->max_colour, warp_colour);
    atomicMax(&totals->rounds, warp_round);
  }
}

// Scratch for a radix sort of n (32-bit key, node) pairs over `bits` key
// bits, laid out in topo.scratch after `front_bytes` that the caller keeps
// for itself (at `front`).
struct NodePairSort {
  cub::DoubleBuffer<std::uint32_t> keys;
  cub::DoubleBuffer<index_t> nodes;
  void* temp = nullptr;
  std::size_t temp_bytes = 0;
  unsigned char* front = nullptr;
};

NodePairSort node_pair_sort_scratch(DeviceTopology& topo, std::size_t n, int bits, std::size_t front_bytes) {
  NodePairSort s;
  {
    cub::DoubleBuffer<std::uint32_t> keys(nullptr, nullptr);
    cub::DoubleBuffer<index_t> nodes(nullptr, nullptr);
    CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, s.temp_bytes, keys, nodes, n, 0, bits));
  }
  const auto carve = [&](unsigned char* base) {
    detail::ScratchCarver carver(base);
    s.front = carver.take<unsigned char>(front_bytes);
    std::uint32_t* k0 = carver.take<std::uint32_t>(n);
    std::uint32_t* k1 = carver.take<std::uint32_t>(n);
    index_t* v0 = carver.take<index_t>(n);
    index_t* v1 = carver.take<index_t>(n);
    s.temp = carver.take<unsigned char>(s.temp_bytes);
    s.keys = cub::DoubleBuffer<std::uint32_t>(k0, k1);
    s.nodes = cub::DoubleBuffer<index_t>(v0, v1);
    return carver.used();
  };
  topo.scratch.resize(carve(nullptr));
  carve(topo.scratch.data());
  return s;
}

// Colours the movable nodes; `totals` receives the largest colour and the
// number of rounds.
void run_dataflow(DeviceTopology& topo, ColourTotals* totals, cudaStream_t stream, unsigned max_blocks) {
  const std::size_t n = topo.num_nodes;
  // The published words go in front of the sort's scratch.
  const auto carve_front = [n](unsigned char* base, std::uint64_t*& word) {
    detail::ScratchCarver carver(base);
    word = carver.take<std::uint64_t>(n);
    return carver.used();
  };
  std::uint64_t* word = nullptr;
  NodePairSort sort = node_pair_sort_scratch(topo, n, 32, carve_front(nullptr, word));
  carve_front(sort.front, word);
  if (!topo.priority_order_built) {
    topo.priority_order.resize(n);
    detail::sort_priority_order(n, topo.priority_order.data(), sort.keys.Current(), sort.keys.Alternate(),
                                sort.nodes.Alternate(), sort.temp, sort.temp_bytes, stream);
  }
  start_words<<<blocks_for(n), kBlock, 0, stream>>>(n, topo.movable.data(), word, totals);
  CUDA_CHECK_LAUNCH();
  // Every block resident at once (see the top of the file), or fewer when
  // asked.
  unsigned blocks = std::min(blocks_for(n * kColourLanes), resident_blocks(colour_dataflow_kernel, kBlock));
  if (max_blocks > 0) blocks = std::min(blocks, max_blocks);
  blocks = std::max(blocks, 1u);
  const index_t* order = topo.priority_order.data();
  const index_t* nbr_off = topo.nbr_off.data();
  const index_t* nbr = topo.nbr.data();
  int* colour = topo.colour.data();
  void* params[] = {const_cast<std::size_t*>(&n), &order, &nbr_off, &nbr, &word, &colour, &totals};
  CUDA_CHECK(cudaLaunchCooperativeKernel(reinterpret_cast<const void*>(colour_dataflow_kernel), dim3(blocks),
                                         dim3(kBlock), params, 0, stream));
  CUDA_CHECK_LAUNCH();
}

// Colours above `sentinel` share its key; build_classes is then run again
// with a larger one.
__global__ void class_keys(std::size_t n, const int* colour, std::uint32_t sentinel, std::uint32_t* keys,
                           index_t* nodes) {
  const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (i >= n) return;
  keys[i] = colour[i] >= 0 ? min(static_cast<std::uint32_t>(colour[i]), sentinel) : sentinel;
  nodes[i] = static_cast<index_t>(i);
}

struct ColourRows {
  const std::uint32_t* keys;
  const index_t* nodes;
  __device__ std::uint32_t row(unsigned long long k) const { return keys[k]; }
  __device__ index_t item(unsigned long long k) const { return nodes[k]; }
};

// Classes 0 .. sentinel - 1 into class_off[0 .. sentinel]; the nodes that
// never move (and any of colour sentinel or more) are in none.
void build_classes(DeviceTopology& topo, std::uint32_t sentinel, cudaStream_t stream) {
  const std::size_t n = topo.num_nodes;
  const int bits = detail::bits_for(sentinel);  // keys run 0..sentinel
  topo.class_nodes.resize(topo.movable_count);

  NodePairSort sort = node_pair_sort_scratch(topo, n, bits, 0);
  auto& keys = sort.keys;
  auto& nodes = sort.nodes;

  if (n > 0) {
    class_keys<<<blocks_for(n), kBlock, 0, stream>>>(n, topo.colour.data(), sentinel, keys.Current(),
                                                     nodes.Current());
    CUDA_CHECK_LAUNCH();
    CUDA_CHECK(cub::DeviceRadixSort::SortPairs(sort.temp, sort.temp_bytes, keys, nodes, n, 0, bits, stream));
  }
  detail::csr_from_sorted<<<blocks_for(n + 1), kBlock, 0, stream>>>(
      ColourRows{keys.Current(), nodes.Current()}, static_cast<const unsigned long long*>(nullptr), n,
      static_cast<index_t>(sentinel), topo.class_off.data(), topo.class_nodes.data());
  CUDA_CHECK_LAUNCH();
}

// The classes are built for up to kQuickColours colours before the colour
// count is known on the host, so that one read-back (the offsets, with the
// totals after them) serves both: a one-pass sort of 8-bit keys costs what
// one of 4 bits does. A colouring with more colours builds them again.
constexpr std::uint32_t kQuickColours = 255;

}  // namespace

namespace detail {

std::size_t priority_order_temp_bytes(std::size_t n) {
  cub::DoubleBuffer<std::uint32_t> keys(nullptr, nullptr);
  cub::DoubleBuffer<index_t> nodes(nullptr, nullptr);
  std::size_t bytes = 0;
  CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, bytes, keys, nodes, n, 0, 32));
  return bytes;
}

void sort_priority_order(std::size_t n, index_t* order, std::uint32_t* keys0, std::uint32_t* keys1, index_t* alt,
                         void* temp, std::size_t temp_bytes, cudaStream_t stream) {
  if (n == 0) return;
  priority_order_keys<<<blocks_for(n), kBlock, 0, stream>>>(n, keys0, order);
  CUDA_CHECK_LAUNCH();
  cub::DoubleBuffer<std::uint32_t> keys(keys0, keys1);
  cub::DoubleBuffer<index_t> nodes(order, alt);
  CUDA_CHECK(cub::DeviceRadixSort::SortPairs(temp, temp_bytes, keys, nodes, n, 0, 32, stream));
  if (nodes.Current() != order)
    CUDA_CHECK(cudaMemcpyAsync(order, nodes.Current(), n * sizeof(index_t), cudaMemcpyDeviceToDevice, stream));
}

}  // namespace detail

void colour_device(DeviceTopology& topo, cudaStream_t stream, unsigned max_blocks) {
  static_assert(sizeof(ColourTotals) == 2 * sizeof(index_t) && alignof(ColourTotals) <= alignof(index_t));
  topo.colour.resize(topo.num_nodes);
  if (topo.num_nodes > 0) CUDA_CHECK(cudaMemsetAsync(topo.colour.data(), 0xff, topo.colour.bytes(), stream));
  // class_off: the offsets of kQuickColours classes, then the totals.
  topo.class_off.resize(kQuickColours + 1 + 2);
  auto* totals = reinterpret_cast<ColourTotals*>(topo.class_off.data() + kQuickColours + 1);
  if (topo.movable_count > 0) run_dataflow(topo, totals, stream, max_blocks);
  build_classes(topo, kQuickColours, stream);
  std::vector<index_t> off = topo.class_off.download(stream);
  ColourTotals host{-1, 0};
  if (topo.movable_count > 0) std::memcpy(&host, off.data() + kQuickColours + 1, sizeof host);
  const auto nc = static_cast<std::uint32_t>(host.max_colour + 1);
  topo.num_colours = static_cast<int>(nc);
  topo.colour_rounds = static_cast<int>(host.rounds);
  if (nc > kQuickColours) {
    topo.class_off.resize(nc + 1);
    build_classes(topo, nc, stream);
    off = topo.class_off.download(stream);
  }
  off.resize(nc + 1);
  topo.class_off.resize(nc + 1);
  topo.class_off_host = std::move(off);
}

}  // namespace tetsmooth::cuda
