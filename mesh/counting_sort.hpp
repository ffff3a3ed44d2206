#pragma once
// A counting sort of items into rows, the first step of every CPU topology
// table (mesh/topology.cpp): the items are produced twice, once to count
// each row's items and once to place them, so no unsorted copy of them is
// ever held. A comparison sort of the 12 directed edges of every tet took
// most of the time of `tetsmooth quality` on large meshes (see topology.cpp).
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

#include "mesh/row_items.hpp"

namespace tetsmooth {

// Row r holds items[offsets[r] .. offsets[r+1]), offsets has rows + 1
// entries from 0. Offsets are 64-bit: the unsorted entries of a large mesh
// (12 a tet before duplicates are removed) can pass 2^31.
template <class Item>
struct RowBuckets {
  std::vector<std::size_t> offsets;
  RowItems<Item> items;  // every element written by sort_into_rows
};

// `produce(k, slot)`, for each producer k in [0, producers), must call
// slot(row), row < rows, once for every item of producer k, in the same order
// each time it is called (it is called twice for each k), and write the
// item's fields into the reference that slot returns (on the first call, a
// scratch item that only the count sees). Fields are written into place one
// by one: an item built whole and then copied was read back, in part, from a
// store still in flight, which stalled the 1M-node lattice's face sort. Each
// row keeps its items in producer order (the sort is stable), so the result
// is the same whatever `threads` is.
//
// With threads > 1 the producers are split into that many runs (at most
// kMaxSortRuns, which bounds the memory), shared out among the threads
// OpenMP gives (the result does not depend on how many), and each run counts
// its items by row in a count array of its own (8 bytes a row a run). A row's items from run c
// then go after those of runs before c, each run placing its own without
// atomics: atomic bumps of shared counts serialised the scattered writes
// (two threads took half as long again as one on the 109k model's edges).
inline constexpr int kMaxSortRuns = 16;

template <class Item, class Produce>
RowBuckets<Item> sort_into_rows(std::size_t rows, std::size_t producers, const Produce& produce, int threads = 1) {
  const std::size_t runs = static_cast<std::size_t>(std::clamp(threads, 1, kMaxSortRuns));
  const bool shared = runs > 1;
  // Run c takes producers [run_begin(c), run_begin(c + 1)).
  const auto run_begin = [&](std::ptrdiff_t c) { return producers * static_cast<std::size_t>(c) / runs; };
  const auto run_count = static_cast<std::ptrdiff_t>(runs);
  const auto row_count = static_cast<std::ptrdiff_t>(rows);
  // counts[c * rows + r]: run c's items in row r, then where the next goes.
  // Each run zeroes its own, so that the zeroing, which grows with the
  // runs, is shared by them too.
  RowItems<std::size_t> counts(runs * rows);
#pragma omp parallel for num_threads(static_cast<int>(runs)) if (shared) schedule(static, 1)
  for (std::ptrdiff_t c = 0; c < run_count; ++c) {
    std::size_t* const mine = counts.data() + static_cast<std::size_t>(c) * rows;
    std::fill(mine, mine + rows, std::size_t{0});
    Item scratch;
    for (std::size_t k = run_begin(c); k < run_begin(c + 1); ++k)
      produce(k, [&](std::size_t row) -> Item& {
        ++mine[row];
        return scratch;
      });
  }
  RowBuckets<Item> b;
  b.offsets.assign(rows + 1, 0);
#pragma omp parallel for num_threads(static_cast<int>(runs)) if (shared) schedule(static)
  for (std::ptrdiff_t r = 0; r < row_count; ++r) {
    const auto row = static_cast<std::size_t>(r);
    for (std::size_t c = 0; c < runs; ++c) b.offsets[row + 1] += counts[c * rows + row];
  }
  std::partial_sum(b.offsets.begin(), b.offsets.end(), b.offsets.begin());
#pragma omp parallel for num_threads(static_cast<int>(runs)) if (shared) schedule(static)
  for (std::ptrdiff_t r = 0; r < row_count; ++r) {
    const auto row = static_cast<std::size_t>(r);
    std::size_t place = b.offsets[row];
    for (std::size_t c = 0; c < runs; ++c) place += std::exchange(counts[c * rows + row], place);
  }
  b.items.resize(b.offsets[rows]);
#pragma omp parallel for num_threads(static_cast<int>(runs)) if (shared) schedule(static, 1)
  for (std::ptrdiff_t c = 0; c < run_count; ++c) {
    std::size_t* const next = counts.data() + static_cast<std::size_t>(c) * rows;
    for (std::size_t k = run_begin(c); k < run_begin(c + 1); ++k)
      produce(k, [&](std::size_t row) -> Item& { return b.items[next[row]++]; });
  }
  return b;
}

}  // namespace tetsmooth
