// libFuzzer target: the FLAC3D grid reader and writer. What the reader
// accepts must read back the same from the grid written back as read, from
// the grid with some gridpoints moved (their G lines rewritten) and from a
// new grid of the mesh: the same coordinates (written exactly), tets, pins,
// blocks and regions. Reading back what the writer wrote must never fail.
#include <algorithm>
#include <cmath>

#include "../support/same_partition.hpp"
#include "fuzz_reader.hpp"
#include "mesh/io/file_numbers.hpp"
#include "mesh/io/flac3d_io.hpp"

namespace {

using namespace tetsmooth;

TetMesh read_back(const TetMesh& mesh, const char* what) {
  return fuzz::read_back(
      mesh, [](const TetMesh& m, std::ostream& out) { write_flac3d(m, out); },
      [](std::istream& in, const char* source) { return read_flac3d(in, source); }, what);
}

// Tags as regions: no tags are one region of all `count` elements.
std::vector<int> regions(const std::vector<int>& tags, std::size_t count) {
  return tags.empty() ? std::vector<int>(count, 0) : tags;
}

void require_same_elements(const TetMesh& again, const TetMesh& mesh, const char* what) {
  bool same = again.extras.blocks.size() == mesh.extras.blocks.size() &&
              testing::same_partition(regions(again.extras.tet_tags, again.num_tets()),
                                      regions(mesh.extras.tet_tags, mesh.num_tets()));
  for (std::size_t b = 0; same && b < mesh.extras.blocks.size(); ++b) {
    const PassThroughBlock &x = again.extras.blocks[b], &y = mesh.extras.blocks[b];
    same = x.kind == y.kind && x.connectivity.size() == y.connectivity.size() &&
           testing::same_partition(regions(x.tags, elements_in(x)), regions(y.tags, elements_in(y)));
    // Each element's nodes, as a set: a new grid may list a zone mirrored.
    const auto n = static_cast<std::size_t>(y.nodes_per_element);
    for (std::size_t e = 0; same && e < y.connectivity.size() / n; ++e) {
      std::vector<std::int32_t> p(x.connectivity.begin() + e * n, x.connectivity.begin() + (e + 1) * n);
      std::vector<std::int32_t> q(y.connectivity.begin() + e * n, y.connectivity.begin() + (e + 1) * n);
      std::sort(p.begin(), p.end());
      std::sort(q.begin(), q.end());
      same = p == q;
    }
  }
  if (!same) {
    std::fprintf(stderr, "the %s changed the elements or their regions\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzz::run_reader(data, size, [](std::istream& in) {
    const TetMesh mesh = read_flac3d(in, "fuzz.f3grid");
    fuzz::require_same(read_back(mesh, "grid written back"), mesh, "FLAC3D");
    TetMesh moved = mesh;
    for (std::size_t k = 0; k < moved.xyz.size(); k += 4) moved.xyz[k] = moved.xyz[k] * (1 + 1.0 / 3) + 1.0 / 7;
    for (double& v : moved.xyz)
      if (!std::isfinite(v)) v = 0;
    fuzz::require_same(read_back(moved, "grid with moved gridpoints"), moved, "FLAC3D with moved gridpoints");
    TetMesh fresh = mesh;
    fresh.extras.raw_sections.clear();
    const TetMesh again = read_back(fresh, "new grid");
    fuzz::require_same(again, fresh, "a new FLAC3D grid");
    require_same_elements(again, fresh, "new grid");
  });
}
