// sort_into_rows (mesh/counting_sort.hpp): rows in order, items stable
// within a row, empty rows, and every slot written.
#include <gtest/gtest.h>

#include <cstddef>
#include <utility>
#include <vector>

#include "mesh/counting_sort.hpp"

namespace tetsmooth {
namespace {

TEST(CountingSort, RowsInOrderAndItemsInProducedOrder) {
  // (row, item) pairs, rows out of order and repeated; rows 1 and 4 empty.
  const std::vector<std::pair<std::size_t, int>> input = {{3, 30}, {0, 1}, {2, 20}, {3, 31}, {0, 2},
                                                          {5, 50}, {2, 21}, {3, 32}, {0, 3}};
  int calls = 0;
  const RowBuckets<int> b = sort_into_rows<int>(6, [&](const auto& slot) {
    ++calls;
    for (const auto& [row, item] : input) slot(row) = item;
  });
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(b.offsets, (std::vector<std::size_t>{0, 3, 3, 5, 8, 8, 9}));
  EXPECT_EQ(std::vector<int>(b.items.begin(), b.items.end()), (std::vector<int>{1, 2, 3, 20, 21, 30, 31, 32, 50}));
}

TEST(CountingSort, NoItemsAndNoRows) {
  const RowBuckets<int> none = sort_into_rows<int>(3, [](const auto&) {});
  EXPECT_EQ(none.offsets, (std::vector<std::size_t>{0, 0, 0, 0}));
  EXPECT_TRUE(none.items.empty());
  const RowBuckets<int> no_rows = sort_into_rows<int>(0, [](const auto&) {});
  EXPECT_EQ(no_rows.offsets, (std::vector<std::size_t>{0}));
}

// Items of several fields, written field by field into their slots: the
// storage is left uninitialised, so every field read must have been written.
TEST(CountingSort, StructItemsWrittenFieldByField) {
  struct Item {
    int a;
    double b;
  };
  const std::size_t rows = 1000;
  const RowBuckets<Item> s = sort_into_rows<Item>(rows, [&](const auto& slot) {
    for (int k = 0; k < 5000; ++k) {
      Item& it = slot(static_cast<std::size_t>((k * 7919) % rows));
      it.a = k;
      it.b = 0.5 * k;
    }
  });
  ASSERT_EQ(s.items.size(), 5000u);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t k = s.offsets[r]; k < s.offsets[r + 1]; ++k) {
      EXPECT_EQ(static_cast<std::size_t>(s.items[k].a * 7919) % rows, r);
      EXPECT_EQ(s.items[k].b, 0.5 * s.items[k].a);
      if (k > s.offsets[r]) {
        EXPECT_LT(s.items[k - 1].a, s.items[k].a);  // stable
      }
    }
}

}  // namespace
}  // namespace tetsmooth
