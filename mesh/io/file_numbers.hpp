#pragma once
// The file's own node and element numbers (FileExtras::node_tags,
// tet_element_tags and each block's element_tags) as a new deck or grid
// can keep them (Abaqus, Nastran, FLAC3D, Exodus, ANSYS): one per item, positive, distinct
// and at most the format's largest, else 1, 2, ... in order (not a public
// API).
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// Whether `ids` numbers `count` items: one each, positive, distinct and at
// most `largest`.
bool usable_numbers(const std::vector<long long>& ids, std::size_t count, long long largest);

// `ids` where usable_numbers, else 1, 2, ..., count.
std::vector<long long> numbers_or_positions(const std::vector<long long>& ids, std::size_t count, long long largest);

// Elements in a pass-through block.
std::size_t elements_in(const PassThroughBlock& b);

// Which elements a format numbers in one sequence: the tets or not, and the
// blocks `block` accepts (all of them where it is empty). FLAC3D numbers its
// zones and its faces apart; the other formats all their elements as one.
struct ElementSet {
  bool tets = true;
  std::function<bool(const PassThroughBlock&)> block;
};

// The file's numbers of a set's elements, the tets' first and then each
// block's, in order, and how many elements the set has; the numbers are
// empty unless every element of the set has one.
std::pair<std::vector<long long>, std::size_t> file_element_numbers(const TetMesh& mesh, const ElementSet& set = {});

// The numbers of a set's elements (file_element_numbers' order), as
// numbers_or_positions gives them.
std::vector<long long> element_numbers(const TetMesh& mesh, long long largest, const ElementSet& set = {});

// The numbers (from `node_numbers`, one per node) of the pinned nodes that
// no written element pins, in node order: those a new deck lists itself (a
// node set, a comment line) to keep them pinned. `written` says which blocks
// the deck writes (all where it is empty); the nodes of the others are
// listed too.
std::vector<long long> pins_to_list(const TetMesh& mesh, const std::vector<long long>& node_numbers,
                                    const std::function<bool(const PassThroughBlock&)>& written = {});

// New ids for the region tags that a format cannot take as ids (0 and
// below, and past `largest`), and for elements without a tag (as tag 0),
// over the tags of the tets and of the blocks `block` accepts (all where it
// is empty): ids that no tag holds, from above the largest tag kept on
// (then from 1 up), 0 first, then -1, -2, ..., then the large tags in
// order. Nastran's PIDs and ANSYS's materials are positive.
std::map<int, int> new_positive_ids(const TetMesh& mesh, long long largest,
                                    const std::function<bool(const PassThroughBlock&)>& block = {});

// Region ids for a format whose ids each name the properties of one kind of
// element (LS-DYNA's parts take one section, Nastran's PIDs one property
// entry, PSOLID or PSHELL): each tag's id (new_positive_ids), except where
// elements of a lower dimension (shells, 2; beams, 1) share a tag with
// elements of a higher one; those get ids of their own, ids no element
// holds, from above the largest in use (then from 1 up). Elements without a
// tag count as tag 0.
class RegionIds {
 public:
  RegionIds(const TetMesh& mesh, long long largest, const std::function<bool(const PassThroughBlock&)>& block = {});
  // The id of `tag` for elements of `dimension` (kind_dimension; tets 3).
  long long of(int dimension, int tag) const;
  // Tags that are no ids → their new ids (new_positive_ids).
  const std::map<int, int>& renumbered() const { return renumbered_; }
  // (dimension, tag) → the id of the lower-dimension elements that share a
  // tag with higher ones.
  const std::map<std::pair<int, int>, long long>& split() const { return split_; }

 private:
  std::map<int, int> renumbered_;
  std::map<std::pair<int, int>, long long> split_;
};

// The file's numbers that a new deck cannot keep: "node", "element", "node
// and element", or "" when it keeps them all (or the file had none). Each
// of `sets` is numbered on its own (one set of all elements by default).
std::string numbers_lost(const TetMesh& mesh, long long largest, const std::vector<ElementSet>& sets = {ElementSet{}});

}  // namespace tetsmooth
