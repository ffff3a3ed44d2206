// libFuzzer target: the VTK XML (.vtu) reader.
#include "fuzz_reader.hpp"
#include "mesh/io/vtu_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return tetsmooth::fuzz::run_reader(data, size, [](std::istream& in) { tetsmooth::read_vtu(in, "fuzz.vtu"); });
}
