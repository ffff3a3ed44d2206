// libFuzzer target: the Medit .mesh reader; what it accepts must survive a
// write/read round trip.
#include "fuzz_reader.hpp"
#include "mesh/io/medit_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tetsmooth;
  return fuzz::run_reader(data, size, [](std::istream& in) {
    const TetMesh mesh = read_medit(in, "fuzz.mesh");
    std::stringstream file;
    write_medit(mesh, file);
    fuzz::require_same(read_medit(file, "again.mesh"), mesh, "Medit");
  });
}
