// libFuzzer target: the LS-DYNA keyword deck reader and writer. What the
// reader accepts must read back the same from the deck written back as read;
// the deck with some nodes moved (their *NODE cards rewritten, 13
// significant digits in fixed columns where the exponent has two digits,
// 8 or more with three) and a new deck of the mesh must read back with the
// same tets (up to turning) and pins, and coordinates within that rounding.
// Reading back what the writer wrote must never fail.
#include <cmath>

#include "fuzz_reader.hpp"
#include "mesh/io/lsdyna_io.hpp"

namespace {

using namespace tetsmooth;

TetMesh read_back(const TetMesh& mesh, const char* what) {
  return fuzz::read_back(
      mesh, [](const TetMesh& m, std::ostream& out) { write_lsdyna(m, out); },
      [](std::istream& in, const char* source) { return read_lsdyna(in, source); }, what);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzz::run_reader(data, size, [](std::istream& in) {
    const TetMesh mesh = read_lsdyna(in, "fuzz.k");
    fuzz::require_same(read_back(mesh, "deck written back"), mesh, "LS-DYNA");
    TetMesh moved = mesh;
    for (std::size_t k = 0; k < moved.xyz.size(); k += 4)
      if (std::fabs(moved.xyz[k]) < 1e300) moved.xyz[k] = moved.xyz[k] * (1 + 1.0 / 3) + 1.0 / 7;
    fuzz::require_close(read_back(moved, "deck with moved nodes"), moved, "deck with moved nodes", 1e-8);
    TetMesh fresh = mesh;
    fresh.extras.raw_sections.clear();
    fuzz::require_close(read_back(fresh, "new deck"), fresh, "new deck", 1e-8);
  });
}
