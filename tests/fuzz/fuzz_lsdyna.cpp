// libFuzzer target: the LS-DYNA keyword deck reader and writer. What the
// reader accepts must read back the same from the deck written back as read;
// the deck with some nodes moved (their *NODE cards rewritten, 13
// significant digits in 16 columns where the exponent has two digits, 8 or
// more with three, and more in the long layout's 20) and a new deck of the mesh must read back with the
// same tets (up to turning) and pins, and coordinates within that rounding.
// Reading back what the writer wrote must never fail.
#include "fuzz_reader.hpp"
#include "mesh/io/lsdyna_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tetsmooth;
  return fuzz::run_reader(data, size, [](std::istream& in) {
    fuzz::deck_round_trips(
        read_lsdyna(in, "fuzz.k"), [](const TetMesh& m, std::ostream& out) { write_lsdyna(m, out); },
        [](std::istream& again, const char* source) { return read_lsdyna(again, source); }, "LS-DYNA", 1e-8);
  });
}
