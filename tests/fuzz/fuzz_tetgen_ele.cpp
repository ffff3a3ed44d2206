// libFuzzer target: the TetGen .ele reader over eight fixed nodes numbered
// from 1, then validation of the tets it read.
#include "fuzz_reader.hpp"
#include "mesh/io/tetgen_io.hpp"
#include "mesh/validate.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tetsmooth;
  return fuzz::run_reader(data, size, [](std::istream& in) {
    TetMesh mesh;
    for (int k = 0; k < 8; ++k) mesh.xyz.insert(mesh.xyz.end(), {double(k & 1), double((k >> 1) & 1), double(k >> 2)});
    read_tetgen_ele(in, "fuzz.ele", 1, mesh);
    validate_mesh(mesh, "fuzz.ele");
  });
}
