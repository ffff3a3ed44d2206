#include "bench/mesh_cache.hpp"

#include <cstdlib>
#include <filesystem>

#include "generators/models.hpp"
#include "mesh/io/tsm_cache.hpp"

namespace tetsmooth::bench {

std::string mesh_cache_dir() {
  const char* env = std::getenv("TETSMOOTH_MESH_CACHE");
  return env && *env ? env : "meshes";
}

TetMesh cached_model(const std::string& model, std::uint64_t seed) {
  const std::filesystem::path dir = mesh_cache_dir();
  const std::filesystem::path file = dir / (model + "-seed" + std::to_string(seed) + ".tsm");
  if (std::filesystem::exists(file)) return read_cache_file(file.string());
  TetMesh mesh = generate_model(model, seed);
  std::filesystem::create_directories(dir);
  write_cache_file(mesh, file.string());
  return mesh;
}

}  // namespace tetsmooth::bench
