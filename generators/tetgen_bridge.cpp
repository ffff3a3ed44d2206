#include "generators/tetgen_bridge.hpp"

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

#include "mesh/tet_quality.hpp"

namespace tetsmooth {
namespace {

// TetGen 1.5 throws a bare int from terminatetetgen(); these are its codes.
std::string tetgen_error_text(int code) {
  switch (code) {
    case 1: return "out of memory";
    case 2: return "internal error";
    case 3: return "self-intersecting input facets";
    case 4: return "input feature smaller than the tolerance";
    case 5: return "two input facets too close together";
    case 10: return "invalid input";
    default: return "error code " + std::to_string(code);
  }
}

}  // namespace

TetMesh run_tetgen(tetgenio& in, const std::string& switches, const std::string& what) {
  // tetrahedralize() wants a mutable C string.
  std::string all = switches + "zQF";
  std::vector<char> buffer(all.begin(), all.end());
  buffer.push_back('\0');

  tetgenio out;
  try {
    tetrahedralize(buffer.data(), &in, &out);
  } catch (int code) {
    throw std::runtime_error(what + ": TetGen failed (" + tetgen_error_text(code) + ")");
  }
  if (out.numberofcorners != 4)
    throw std::runtime_error(what + ": TetGen returned " + std::to_string(out.numberofcorners) +
                             "-node elements, expected linear tets");
  if (static_cast<long long>(out.numberofpoints) > std::numeric_limits<index_t>::max())
    throw std::runtime_error(what + ": TetGen returned more nodes than 32-bit indices can address");

  TetMesh mesh;
  mesh.xyz.assign(out.pointlist, out.pointlist + 3 * static_cast<std::size_t>(out.numberofpoints));
  mesh.tets.assign(out.tetrahedronlist, out.tetrahedronlist + 4 * static_cast<std::size_t>(out.numberoftetrahedra));

  // TetGen 1.5 already orders tets as this library does ((b-a)·((c-a)×(d-a))
  // > 0). Checking it here, in floating point, turns a convention change in a
  // future TetGen, or a flat tet, into an error instead of a wrong benchmark.
  std::size_t bad = 0;
  const auto node = [&](index_t i) {
    const double* p = &mesh.xyz[3 * static_cast<std::size_t>(i)];
    return Vec3<double>{p[0], p[1], p[2]};
  };
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    const index_t* v = &mesh.tets[4 * t];
    if (!(signed_volume6(node(v[0]), node(v[1]), node(v[2]), node(v[3])) > 0.0)) ++bad;
  }
  if (bad != 0)
    throw std::runtime_error(what + ": TetGen returned " + std::to_string(bad) + " of " +
                             std::to_string(mesh.num_tets()) + " tets that are not positively oriented");
  return mesh;
}

}  // namespace tetsmooth
