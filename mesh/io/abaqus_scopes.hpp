#pragma once
// Node and element numbers of an Abaqus deck with parts belong to a part
// (abaqus_io.hpp): two parts may both have a node 1. The reader finds items
// by a key that holds the part (its scope: 1, 2, ... in the order defined;
// 0 outside parts, where the key is the number itself) above the number
// (not a public API).
#include <cstddef>

namespace tetsmooth::abaqus {

// Abaqus numbers items up to 999999999; a part's numbers must stay below
// 2^40 so that the scope fits above them.
constexpr int kScopeShift = 40;
constexpr long long kLargestPartNumber = (1LL << kScopeShift) - 1;

inline long long scoped_key(std::size_t scope, long long number) {
  return scope == 0 ? number : static_cast<long long>(scope) << kScopeShift | number;
}

// The number a key stands for, for a message.
inline long long number_of_key(long long key, bool deck_has_parts) {
  return deck_has_parts ? key & kLargestPartNumber : key;
}

}  // namespace tetsmooth::abaqus
