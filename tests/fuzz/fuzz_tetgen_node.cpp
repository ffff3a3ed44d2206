// libFuzzer target: the TetGen .node reader, then validation of the nodes
// it read under one tet.
#include "fuzz_reader.hpp"
#include "mesh/io/tetgen_io.hpp"
#include "mesh/validate.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tetsmooth;
  return fuzz::run_reader(data, size, [](std::istream& in) {
    TetMesh mesh;
    read_tetgen_node(in, "fuzz.node", mesh);
    mesh.tets = {0, 1, 2, 3};
    validate_mesh(mesh, "fuzz.node");
  });
}
