#pragma once
// Compressed sparse rows: row r holds items[offsets[r] .. offsets[r+1]).
// offsets has rows()+1 entries and starts at 0.
#include <cstddef>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

struct Csr {
  std::vector<index_t> offsets{0};
  std::vector<index_t> items;

  std::size_t rows() const { return offsets.size() - 1; }
  index_t row_size(std::size_t r) const { return offsets[r + 1] - offsets[r]; }
  const index_t* row_begin(std::size_t r) const { return items.data() + offsets[r]; }
  const index_t* row_end(std::size_t r) const { return items.data() + offsets[r + 1]; }
  friend bool operator==(const Csr& a, const Csr& b) { return a.offsets == b.offsets && a.items == b.items; }
};

}  // namespace tetsmooth
