#pragma once
// Errors about a mesh as a whole, named after the file it came from.
#include <string>

#include "mesh/errors.hpp"

namespace tetsmooth::cli {

// Runs `step` (topology, smoothing) on the mesh read from `input`. The
// library throws InputError without a file for a mesh too large for its
// tables (mesh/topology.cpp, the CUDA topology); the message then names it.
template <class Step>
decltype(auto) on_input_mesh(const std::string& input, Step&& step) {
  try {
    return step();
  } catch (const InputError& e) {
    throw InputError(input, e.what());
  }
}

}  // namespace tetsmooth::cli
