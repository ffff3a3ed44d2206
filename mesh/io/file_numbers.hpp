#pragma once
// The file's own node and element numbers (FileExtras::node_tags,
// tet_element_tags and each block's element_tags) as a new deck can keep
// them (Abaqus, Nastran): one per item, positive, distinct and at most the
// format's largest, else 1, 2, ... in order (not a public API).
#include <cstddef>
#include <string>
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

// The numbers of every element, the tets' first and then each block's, in
// order, as numbers_or_positions gives them.
std::vector<long long> element_numbers(const TetMesh& mesh, long long largest);

// The numbers (from `node_numbers`, one per node) of the pinned nodes that
// no pass-through element pins, in node order: those a new deck lists
// itself (a node set, a comment line) to keep them pinned.
std::vector<long long> pins_to_list(const TetMesh& mesh, const std::vector<long long>& node_numbers);

// The file's numbers that a new deck cannot keep: "node", "element", "node
// and element", or "" when it keeps them all (or the file had none).
std::string numbers_lost(const TetMesh& mesh, long long largest);

}  // namespace tetsmooth
