#include "mesh/colouring.hpp"

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <string>

#include "mesh/team_size.hpp"

namespace tetsmooth {

namespace {

// Whether pending node i beats every uncoloured movable neighbour.
bool wins_round(const Csr& neighbours, const std::vector<std::uint8_t>& movable,
                const std::vector<std::int32_t>& colour, index_t i) {
  for (const index_t* j = neighbours.row_begin(i); j != neighbours.row_end(i); ++j)
    if (movable[*j] && colour[*j] < 0 && colours_before(*j, i)) return false;
  return true;
}

// The smallest colour no neighbour of i has; `used` is scratch.
int first_free_colour(const Csr& neighbours, const std::vector<std::int32_t>& colour, index_t i,
                      std::vector<std::uint8_t>& used) {
  used.assign(used.size(), 0);
  for (const index_t* j = neighbours.row_begin(i); j != neighbours.row_end(i); ++j) {
    const int c = colour[*j];
    if (c < 0) continue;
    if (static_cast<std::size_t>(c) >= used.size()) used.resize(c + 1, 0);
    used[c] = 1;
  }
  int c = 0;
  while (static_cast<std::size_t>(c) < used.size() && used[c]) ++c;
  return c;
}

}  // namespace

Colouring colour_nodes(const Csr& neighbours, const std::vector<std::uint8_t>& movable, int threads) {
  const std::size_t n = neighbours.rows();
  threads = team_size(threads);
  const bool shared = threads > 1;
  Colouring result;
  result.colour.assign(n, -1);
  std::vector<index_t> pending;
  for (std::size_t i = 0; i < n; ++i)
    if (movable[i]) pending.push_back(static_cast<index_t>(i));

  std::vector<std::uint8_t> wins;
  std::vector<index_t> winners, still;
  while (!pending.empty()) {
    // A round's winners are decided on the colours of earlier rounds only.
    const auto count = static_cast<std::ptrdiff_t>(pending.size());
    wins.resize(pending.size());
#pragma omp parallel for num_threads(shared ? threads : 1) if (shared) schedule(static)
    for (std::ptrdiff_t k = 0; k < count; ++k) wins[k] = wins_round(neighbours, movable, result.colour, pending[k]);
    winners.clear();
    still.clear();
    for (std::ptrdiff_t k = 0; k < count; ++k) (wins[k] ? winners : still).push_back(pending[k]);
    // No two winners are neighbours (of two pending neighbours one goes
    // first, each seeing the other in its symmetric row), so each takes its
    // colour from those of earlier rounds, in whatever order the winners
    // are coloured.
    int top = result.num_colours;
    const auto won = static_cast<std::ptrdiff_t>(winners.size());
#pragma omp parallel num_threads(shared ? threads : 1) if (shared)
    {
      std::vector<std::uint8_t> used;  // colours seen around one node
#pragma omp for schedule(static) reduction(max : top)
      for (std::ptrdiff_t k = 0; k < won; ++k) {
        const int c = first_free_colour(neighbours, result.colour, winners[k], used);
        result.colour[winners[k]] = c;
        top = std::max(top, c + 1);
      }
    }
    result.num_colours = top;
    pending.swap(still);
    ++result.rounds;
  }
  result.classes = colour_classes(result.colour, result.num_colours);
  return result;
}

Csr colour_classes(const std::vector<std::int32_t>& colour, int num_colours) {
  Csr classes;
  classes.offsets.assign(static_cast<std::size_t>(num_colours) + 1, 0);
  for (std::int32_t c : colour)
    if (c >= 0) ++classes.offsets[static_cast<std::size_t>(c) + 1];
  std::partial_sum(classes.offsets.begin(), classes.offsets.end(), classes.offsets.begin());
  classes.items.resize(classes.offsets.back());
  std::vector<index_t> fill(classes.offsets.begin(), classes.offsets.end() - 1);
  for (std::size_t i = 0; i < colour.size(); ++i)
    if (colour[i] >= 0) classes.items[fill[colour[i]]++] = static_cast<index_t>(i);
  return classes;
}

std::string colouring_flaw(const Csr& neighbours, const std::vector<std::uint8_t>& movable, const Colouring& c) {
  const std::size_t n = neighbours.rows();
  if (c.colour.size() != n)
    return "its colour array has " + std::to_string(c.colour.size()) + " entries for " + std::to_string(n) + " nodes";
  // No colouring needs more colours than nodes; a larger count is checked
  // before colour_classes below sizes its offsets by it.
  if (c.num_colours < 0 || static_cast<std::size_t>(c.num_colours) > n)
    return "num_colours " + std::to_string(c.num_colours) + " is outside [0, " + std::to_string(n) + "]";
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t k = c.colour[i];
    if (!movable[i]) {
      if (k != -1) return "node " + std::to_string(i) + ", which never moves, has colour " + std::to_string(k);
      continue;
    }
    if (k < 0 || k >= c.num_colours)
      return "movable node " + std::to_string(i) + " has colour " + std::to_string(k) + ", outside [0, " +
             std::to_string(c.num_colours) + ")";
    for (const index_t* j = neighbours.row_begin(i); j != neighbours.row_end(i); ++j)
      if (movable[*j] && c.colour[*j] == k)
        return "neighbours " + std::to_string(i) + " and " + std::to_string(*j) + " share colour " + std::to_string(k);
  }
  const Csr expected = colour_classes(c.colour, c.num_colours);
  if (c.classes.offsets != expected.offsets || c.classes.items != expected.items)
    return "its classes do not list the nodes of each colour, ascending";
  return "";
}

}  // namespace tetsmooth
