#pragma once
// Region tags of an Abaqus deck's elements, by the rules of abaqus_io.hpp
// (not a public API).
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace tetsmooth::abaqus {

// Tags for elements that carry the index (1-based; 0 for none) of their
// *ELEMENT line's ELSET in `names`: each name's trailing number where every
// name met has a different one other than 0 ("_M" before it for a negative
// one, as the writer names them), else the names numbered 1, 2, ... in the
// order met.
// Empty when no element has a set.
std::vector<int> tags_from_element_sets(const std::vector<std::uint32_t>& elsets, const std::vector<std::string>& names);

// The names of region tags, for Gmsh's $PhysicalNames: (dimension, tag)
// pairs, each named once, by the first name given it; negative tags, which
// MSH output renumbers, are left unnamed.
class RegionNames {
 public:
  // Names each tag of `tags` (one per element) by the set its element's
  // `elsets` entry indexes in `names` (1-based; 0 for none).
  void add(int dimension, const std::vector<int>& tags, const std::vector<std::uint32_t>& elsets,
           const std::vector<std::string>& names);
  void add(int dimension, int tag, const std::string& name);
  bool empty() const { return entries_.empty(); }
  // The body of a $PhysicalNames section: the count, then a line
  // `dimension tag "name"` each ('"' in a name written as '\'').
  std::string msh_body() const;

 private:
  struct Entry {
    int dimension, tag;
    std::string name;
  };
  std::vector<Entry> entries_;
  std::set<std::pair<int, int>> named_;  // (dimension, tag) of each entry
};

// Regions as the sets that hold each element: two elements share a region
// when every set holds both or neither. Each set costs time in its own
// size, whatever the number of elements.
class RegionSplitter {
 public:
  explicit RegionSplitter(std::size_t elements) : regions_(elements, 0), round_of_(elements, 0) {}
  // One more set, by element index (an element may come more than once).
  void split(const std::vector<std::size_t>& members);
  // The regions, numbered 1, 2, ... in the order of their first elements.
  std::vector<int> tags() const;

 private:
  std::vector<int> regions_;
  std::vector<std::uint32_t> round_of_;  // the last split that met each element
  std::uint32_t round_ = 0;
  int next_ = 1;
};

}  // namespace tetsmooth::abaqus
