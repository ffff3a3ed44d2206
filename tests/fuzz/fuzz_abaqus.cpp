// libFuzzer target: the Abaqus .inp reader; what it accepts must survive a
// write/read round trip (the deck written back with its coordinates).
// *INCLUDE paths are relative to a folder that does not exist, so that only
// absolute ones reach files.
#include "fuzz_reader.hpp"
#include "mesh/io/abaqus_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tetsmooth;
  return fuzz::run_reader(data, size, [](std::istream& in) {
    const TetMesh mesh = read_abaqus(in, "/nonexistent-fuzz-folder/fuzz.inp");
    std::stringstream file;
    write_abaqus(mesh, file);
    fuzz::require_same(read_abaqus(file, "/nonexistent-fuzz-folder/again.inp"), mesh, "Abaqus");
  });
}
