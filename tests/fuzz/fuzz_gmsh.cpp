// libFuzzer target: the Gmsh MSH reader (every version and encoding); what
// it accepts must survive a write/read round trip in every flavour.
#include "fuzz_reader.hpp"
#include "mesh/io/gmsh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tetsmooth;
  return fuzz::run_reader(data, size, [](std::istream& in) {
    const TetMesh mesh = read_gmsh(in, "fuzz.msh");
    for (MshFlavour flavour : {MshFlavour::V41Ascii, MshFlavour::V41Binary, MshFlavour::V22Ascii}) {
      std::stringstream file;
      write_gmsh(mesh, file, flavour, {});
      fuzz::require_same(read_gmsh(file, "again.msh"), mesh, "MSH");
    }
  });
}
