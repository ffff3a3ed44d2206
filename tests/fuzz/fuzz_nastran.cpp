// libFuzzer target: the Nastran bulk data reader and writer. What the reader
// accepts must read back the same from the deck written back as read; the
// deck with some nodes moved (their GRIDs rewritten in large field) and a
// new deck of the mesh must read back with the same tets (up to turning:
// rounded coordinates may turn a flat tet round) and pins, and coordinates
// within the large field's rounding. Reading back what the writer wrote
// must never fail.
#include "fuzz_reader.hpp"
#include "mesh/io/nastran_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tetsmooth;
  return fuzz::run_reader(data, size, [](std::istream& in) {
    fuzz::deck_round_trips(
        read_nastran(in, "fuzz.bdf"), [](const TetMesh& m, std::ostream& out) { write_nastran(m, out); },
        [](std::istream& again, const char* source) { return read_nastran(again, source); }, "Nastran", 1e-8);
  });
}
