// libFuzzer target: the Nastran bulk data reader; what it accepts must
// survive a write/read round trip (the deck written back, unmoved GRIDs as
// read).
#include "fuzz_reader.hpp"
#include "mesh/io/nastran_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tetsmooth;
  return fuzz::run_reader(data, size, [](std::istream& in) {
    const TetMesh mesh = read_nastran(in, "fuzz.bdf");
    std::stringstream file;
    write_nastran(mesh, file);
    fuzz::require_same(read_nastran(file, "again.bdf"), mesh, "Nastran");
  });
}
