#pragma once
// Region tags of an Abaqus deck's elements, by the rules of abaqus_io.hpp
// (not a public API).
#include <cstdint>
#include <string>
#include <vector>

namespace tetsmooth::abaqus {

// Tags for elements that carry the index (1-based; 0 for none) of their
// *ELEMENT line's ELSET in `names`: each name's trailing number where every
// name met has a different one other than 0 ("_M" before it for a negative
// one, as the writer names them), else the names numbered 1, 2, ... in the
// order met.
// Empty when no element has a set.
std::vector<int> tags_from_element_sets(const std::vector<std::uint32_t>& elsets, const std::vector<std::string>& names);

}  // namespace tetsmooth::abaqus
