#pragma once
// The ids a file gives its nodes or elements (Abaqus numbers, Nastran ids),
// found by id once every line is read, since a deck may name an item before
// the line that defines it (not a public API).
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace tetsmooth {

// The file's ids of a kind of item in read order, found by id.
class IdIndex {
 public:
  explicit IdIndex(const std::vector<long long>& ids);
  // The later of two items with the same id, if any.
  std::optional<std::size_t> repeated() const { return repeated_; }
  // The item with this id, or -1.
  long long find(long long id) const;
  // Every item whose id is first, first + step, ... up to last (Abaqus's
  // GENERATE, Nastran's THRU), in id order; ids that no item has are
  // skipped.
  void append_range(long long first, long long last, long long step, std::vector<std::size_t>& out) const;

 private:
  std::vector<std::pair<long long, std::size_t>> sorted_;
  std::optional<std::size_t> repeated_;
};

}  // namespace tetsmooth
