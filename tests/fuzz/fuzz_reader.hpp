#pragma once
// Shared by the libFuzzer targets: feeds the fuzzer's bytes to a reader as a
// stream. A reader must turn any bad input into InputError; every other
// outcome (another exception, a crash, a sanitizer report, a broken round
// trip) is a bug and escapes to libFuzzer, which saves the input.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/errors.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::fuzz {

template <class Read>
int run_reader(const std::uint8_t* data, std::size_t size, Read read) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    read(in);
  } catch (const InputError&) {
    // The expected answer to bad input.
  }
  return 0;
}

// The mesh as `read(stream, name)` reads back what `write(mesh, stream)`
// wrote of it. What the writer writes must read back: a failure is a bug,
// reported with `what` (abort, so that libFuzzer saves the input).
template <class Write, class Read>
TetMesh read_back(const TetMesh& mesh, Write write, Read read, const char* what) {
  std::stringstream file;
  write(mesh, file);
  try {
    return read(file, "again");
  } catch (const InputError& e) {
    std::fprintf(stderr, "the %s does not read back: %s\n", what, e.what());
    std::abort();
  }
}

// A mesh that was read must read back the same after writing.
inline void require_same(const TetMesh& again, const TetMesh& mesh, const char* what) {
  if (again.xyz != mesh.xyz || again.tets != mesh.tets || again.fixed != mesh.fixed) {
    std::fprintf(stderr, "round trip through %s changed the mesh\n", what);
    std::abort();
  }
}

// Each tet's corners as a sorted set: the tets up to turning (rounded
// coordinates may turn a flat tet round, which the decks' readers undo).
inline std::vector<std::array<index_t, 4>> corner_sets(const TetMesh& mesh) {
  std::vector<std::array<index_t, 4>> sets(mesh.num_tets());
  for (std::size_t t = 0; t < sets.size(); ++t) {
    std::copy_n(&mesh.tets[4 * t], 4, sets[t].begin());
    std::sort(sets[t].begin(), sets[t].end());
  }
  return sets;
}

// A mesh written with rounded coordinates must read back with the same tets
// (up to turning) and pins, and each coordinate within `relative` of its
// value.
inline void require_close(const TetMesh& again, const TetMesh& mesh, const char* what, double relative) {
  bool close = again.xyz.size() == mesh.xyz.size();
  for (std::size_t k = 0; close && k < mesh.xyz.size(); ++k)
    close = std::fabs(again.xyz[k] - mesh.xyz[k]) <= relative * std::fabs(mesh.xyz[k]);
  if (!close || corner_sets(again) != corner_sets(mesh) || again.fixed != mesh.fixed) {
    std::fprintf(stderr, "the %s changed the mesh\n", what);
    std::abort();
  }
}

// The round trips of a deck format whose writer keeps the deck read and
// rewrites moved nodes with rounded coordinates (Nastran, LS-DYNA): the deck
// written back as read must read back the same; with some nodes moved, and
// as a new deck, the mesh must read back within `relative`.
template <class Write, class Read>
void deck_round_trips(const TetMesh& mesh, Write write, Read read, const char* format, double relative) {
  require_same(read_back(mesh, write, read, "deck written back"), mesh, format);
  TetMesh moved = mesh;
  for (std::size_t k = 0; k < moved.xyz.size(); k += 4)
    if (std::fabs(moved.xyz[k]) < 1e300) moved.xyz[k] = moved.xyz[k] * (1 + 1.0 / 3) + 1.0 / 7;
  require_close(read_back(moved, write, read, "deck with moved nodes"), moved, "deck with moved nodes", relative);
  TetMesh fresh = mesh;
  fresh.extras.raw_sections.clear();
  require_close(read_back(fresh, write, read, "new deck"), fresh, "new deck", relative);
}

}  // namespace tetsmooth::fuzz
