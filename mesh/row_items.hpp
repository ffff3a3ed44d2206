#pragma once
// Arrays of table rows that are written in full right after they are sized
// (mesh/counting_sort.hpp fills them), so their elements are not zeroed.
#include <memory>
#include <new>
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

}  // namespace tetsmooth
