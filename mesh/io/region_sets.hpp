#pragma once
// Region tags from the named sets of a file's elements (Abaqus element
// sets, FLAC3D zone and face groups), and the names that go with them (not
// a public API).
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace tetsmooth {

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

// The names that the body of a $PhysicalNames section (as RegionNames
// writes it, or as read from an MSH file) gives the tags of `dimension`.
std::map<int, std::string> physical_names_of(const std::string& msh_body, int dimension);

}  // namespace tetsmooth
