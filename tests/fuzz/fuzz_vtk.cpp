// libFuzzer target: the legacy VTK (.vtk) reader.
#include "fuzz_reader.hpp"
#include "mesh/io/vtk_legacy.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return tetsmooth::fuzz::run_reader(data, size, [](std::istream& in) { tetsmooth::read_vtk(in, "fuzz.vtk"); });
}
