// sort_into_rows (mesh/counting_sort.hpp): rows in order, items stable
// within a row, empty rows, every slot written, and the same rows and order
// on any number of threads.
#include <gtest/gtest.h>

#include <cstddef>
#include <utility>
#include <vector>

#include "mesh/counting_sort.hpp"

namespace tetsmooth {
namespace {

// (row, item) pairs, rows out of order and repeated; rows 1 and 4 empty.
const std::vector<std::pair<std::size_t, int>> kPairs = {{3, 30}, {0, 1}, {2, 20}, {3, 31}, {0, 2},
                                                         {5, 50}, {2, 21}, {3, 32}, {0, 3}};

TEST(CountingSort, RowsInOrderAndItemsInProducedOrder) {
  for (int threads : {1, 2, 3, 4, 16}) {
    SCOPED_TRACE(threads);
    std::vector<int> calls(kPairs.size(), 0);
    const RowBuckets<int> b = sort_into_rows<int>(
        6, kPairs.size(),
        [&](std::size_t k, const auto& slot) {
          ++calls[k];
          slot(kPairs[k].first) = kPairs[k].second;
        },
        threads);
    EXPECT_EQ(calls, std::vector<int>(kPairs.size(), 2));  // once to count, once to place
    EXPECT_EQ(b.offsets, (std::vector<std::size_t>{0, 3, 3, 5, 8, 8, 9}));
    EXPECT_EQ(std::vector<int>(b.items.begin(), b.items.end()), (std::vector<int>{1, 2, 3, 20, 21, 30, 31, 32, 50}));
  }
}

TEST(CountingSort, NoItemsAndNoRows) {
  for (int threads : {1, 4}) {
    const RowBuckets<int> none = sort_into_rows<int>(3, 0, [](std::size_t, const auto&) {}, threads);
    EXPECT_EQ(none.offsets, (std::vector<std::size_t>{0, 0, 0, 0}));
    EXPECT_TRUE(none.items.empty());
    const RowBuckets<int> silent = sort_into_rows<int>(3, 5, [](std::size_t, const auto&) {}, threads);
    EXPECT_EQ(silent.offsets, (std::vector<std::size_t>{0, 0, 0, 0}));
    const RowBuckets<int> no_rows = sort_into_rows<int>(0, 0, [](std::size_t, const auto&) {}, threads);
    EXPECT_EQ(no_rows.offsets, (std::vector<std::size_t>{0}));
  }
}

// Items of several fields, written field by field into their slots: the
// storage is left uninitialised, so every field read must have been written.
// Several items a producer, and more producers than any thread count, so
// that each run of producers has items in rows that other runs fill too.
TEST(CountingSort, StructItemsWrittenFieldByFieldInProducerOrder) {
  struct Item {
    int a;
    double b;
  };
  const std::size_t rows = 1000;
  const auto produce = [&](std::size_t k, const auto& slot) {
    for (int j = 0; j < 3; ++j) {
      const int id = static_cast<int>(3 * k) + j;
      Item& it = slot(static_cast<std::size_t>(id * 7919) % rows);
      it.a = id;
      it.b = 0.5 * id;
    }
  };
  for (int threads : {1, 2, 7, 16, 64}) {
    SCOPED_TRACE(threads);
    const RowBuckets<Item> s = sort_into_rows<Item>(rows, 5000, produce, threads);
    ASSERT_EQ(s.items.size(), 15000u);
    for (std::size_t r = 0; r < rows; ++r)
      for (std::size_t k = s.offsets[r]; k < s.offsets[r + 1]; ++k) {
        EXPECT_EQ(static_cast<std::size_t>(s.items[k].a * 7919) % rows, r);
        EXPECT_EQ(s.items[k].b, 0.5 * s.items[k].a);
        if (k > s.offsets[r]) {
          EXPECT_LT(s.items[k - 1].a, s.items[k].a);  // stable
        }
      }
  }
}

// Fewer producers than threads: some runs are empty.
TEST(CountingSort, FewerProducersThanThreads) {
  const RowBuckets<int> b = sort_into_rows<int>(
      2, 3, [](std::size_t k, const auto& slot) { slot(k % 2) = static_cast<int>(k); }, 8);
  EXPECT_EQ(b.offsets, (std::vector<std::size_t>{0, 2, 3}));
  EXPECT_EQ(std::vector<int>(b.items.begin(), b.items.end()), (std::vector<int>{0, 2, 1}));
}

}  // namespace
}  // namespace tetsmooth
