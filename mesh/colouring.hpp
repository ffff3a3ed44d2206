#pragma once
// Graph colouring of the movable nodes so that no two neighbours share a
// colour: nodes of one colour can move at once without a race.
//
// Jones-Plassmann with first fit: every node has the priority
// colouring_priority(i); in each round every uncoloured node whose priority
// beats all its uncoloured movable neighbours takes the smallest colour no
// coloured neighbour has. The nodes of a round are independent, so the
// result does not depend on the order they are processed in: the CUDA
// version produces exactly the same colouring.
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/csr.hpp"
#include "mesh/hd.hpp"

namespace tetsmooth {

// A fixed hash of the node index (splitmix-like); ties broken by index.
TS_HD std::uint32_t colouring_priority(std::uint32_t i) {
  std::uint32_t x = i * 0x9E3779B9u + 0x7F4A7C15u;
  x ^= x >> 16;
  x *= 0x85EBCA6Bu;
  x ^= x >> 13;
  x *= 0xC2B2AE35u;
  x ^= x >> 16;
  return x;
}

// True when node a goes before node b (higher priority, then lower index).
TS_HD bool colours_before(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t pa = colouring_priority(a), pb = colouring_priority(b);
  return pa > pb || (pa == pb && a < b);
}

struct Colouring {
  std::vector<std::int32_t> colour;  // per node; -1 for nodes that never move
  int num_colours = 0;
  int rounds = 0;                    // Jones-Plassmann rounds taken
  Csr classes;                       // colour -> its nodes, ascending
};

// On `threads` OpenMP threads (1 by default; 0 for all cores): a round's
// nodes are independent, so the colouring is the same whatever the count.
// The rows must be symmetric (j in row i exactly when i is in row j), as
// build_neighbours makes them: with a one-sided row two neighbours could
// both win a round, and on several threads one would read the colour the
// other is writing.
Colouring colour_nodes(const Csr& neighbours, const std::vector<std::uint8_t>& movable, int threads = 1);

// Builds `classes` from a per-node colour array (-1 = uncoloured).
Csr colour_classes(const std::vector<std::int32_t>& colour, int num_colours);

// What keeps a colouring from fitting a mesh, in words, or "" when it fits:
// one colour per node, a colour in [0, num_colours) for every movable node
// and -1 for every other (the coloured sweeps would move a coloured boundary
// node), no two movable neighbours of one colour, and `classes` exactly
// colour_classes(colour, num_colours) (the sweeps walk the classes).
std::string colouring_flaw(const Csr& neighbours, const std::vector<std::uint8_t>& movable, const Colouring& c);

inline bool is_valid_colouring(const Csr& neighbours, const std::vector<std::uint8_t>& movable, const Colouring& c) {
  return colouring_flaw(neighbours, movable, c).empty();
}

}  // namespace tetsmooth
