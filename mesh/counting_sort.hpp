#pragma once
// A counting sort of items into rows, the first step of every CPU topology
// table (mesh/topology.cpp): the items are produced twice, once to count
// each row's items and once to place them, so no unsorted copy of them is
// ever held. A comparison sort of the 12 directed edges of every tet took
// most of the time of `tetsmooth quality` on large meshes (see topology.cpp).
#include <cstddef>
#include <memory>
#include <new>
#include <numeric>
#include <utility>
#include <vector>

namespace tetsmooth {

// An allocator whose vectors leave new elements of trivial types
// uninitialised, for arrays that are written in full right after they are
// sized: on a 1M-node, 6M-tet mesh, zeroing them first took an eighth of
// `tetsmooth quality`'s time.
template <class T>
struct UninitialisedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitialisedAllocator<U>;
  };
  UninitialisedAllocator() = default;
  template <class U>
  UninitialisedAllocator(const UninitialisedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <class Item>
using RowItems = std::vector<Item, UninitialisedAllocator<Item>>;

// Row r holds items[offsets[r] .. offsets[r+1]), offsets has rows + 1
// entries from 0. Offsets are 64-bit: the unsorted entries of a large mesh
// (12 a tet before duplicates are removed) can pass 2^31.
template <class Item>
struct RowBuckets {
  std::vector<std::size_t> offsets;
  RowItems<Item> items;  // every element written by sort_into_rows
};

// `produce(slot)` must call slot(row), row < rows, once for every item, in
// the same order each time it is called (it is called twice), and write the
// item's fields into the reference that slot returns (on the first call, a
// scratch item that only the count sees). Each row keeps its items in that
// order (the sort is stable). Fields are written into place one by one: an
// item built whole and then copied was read back, in part, from a store
// still in flight, which stalled the 1M-node lattice's face sort.
template <class Item, class Produce>
RowBuckets<Item> sort_into_rows(std::size_t rows, const Produce& produce) {
  RowBuckets<Item> b;
  b.offsets.assign(rows + 1, 0);
  Item scratch;
  produce([&](std::size_t row) -> Item& {
    ++b.offsets[row + 1];
    return scratch;
  });
  std::partial_sum(b.offsets.begin(), b.offsets.end(), b.offsets.begin());
  b.items.resize(b.offsets[rows]);
  std::vector<std::size_t> next(b.offsets.begin(), b.offsets.end() - 1);
  produce([&](std::size_t row) -> Item& { return b.items[next[row]++]; });
  return b;
}

}  // namespace tetsmooth
