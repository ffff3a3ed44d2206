#pragma once
// Meshes for the benchmarks, generated once and kept as .tsm files so that
// generation never runs inside a measurement and later runs start fast.
#include <string>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth::bench {

// The cache folder: $TETSMOOTH_MESH_CACHE, else ./meshes.
std::string mesh_cache_dir();

// Loads <dir>/<model>-seed<seed>.tsm, or generates the model and stores it.
TetMesh cached_model(const std::string& model, std::uint64_t seed = 1);

}  // namespace tetsmooth::bench
