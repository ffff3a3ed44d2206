// libFuzzer target: the tetsmooth binary cache (.tsm) reader.
#include "fuzz_reader.hpp"
#include "mesh/io/tsm_cache.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return tetsmooth::fuzz::run_reader(data, size, [](std::istream& in) { tetsmooth::read_cache(in, "fuzz.tsm"); });
}
