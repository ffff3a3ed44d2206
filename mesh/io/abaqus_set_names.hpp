#pragma once
// The ELSET= names of a new Abaqus deck's *ELEMENT blocks (abaqus_io.hpp;
// not a public API): each region's name where Abaqus and CalculiX take it
// as it is, else one made of the region tag, which the reader turns back
// into the tag (abaqus_regions.hpp).
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth::abaqus {

// The set name made of a tag: REGION_4 for tets of tag 4, TRIANGLE_5 for
// triangles of tag 5 (`prefix` the block's kind), REGION_M2 for -2.
std::string tag_set_name(const std::string& prefix, int tag);

class NewSetNames {
 public:
  // Names from the mesh's $PhysicalNames, by the dimension of the elements
  // and their tag, for the tags a new deck of `mesh` writes.
  explicit NewSetNames(const TetMesh& mesh);
  // The ELSET= name of elements of `prefix` ("REGION" for tets, else the
  // block's kind), `dimension` (kind_dimension) and `tag`.
  std::string of(const std::string& prefix, int dimension, int tag) const;
  // The regions' names (other than empty ones) that the deck names by tag
  // instead, in the order of dimension and tag.
  const std::vector<std::string>& not_written() const { return not_written_; }
  // Whether a reader of the deck (tags_from_element_sets) gives the regions
  // of `mesh` (the mesh these names were made for) their tags back: a name
  // without a trailing number, or two with one alike, renumber every set 1,
  // 2, ... in order, and a name's own number may be another region's tag.
  bool tags_read_back(const TetMesh& mesh) const;

 private:
  std::map<std::pair<int, int>, std::string> written_;  // (dimension, tag) -> name
  std::vector<std::string> not_written_;
};

}  // namespace tetsmooth::abaqus
