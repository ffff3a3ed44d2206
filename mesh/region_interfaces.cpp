#include "mesh/region_interfaces.hpp"

#include <algorithm>
#include <array>
#include <tuple>

namespace tetsmooth {

std::vector<std::uint8_t> region_interface_nodes(const TetMesh& mesh) {
  std::vector<std::uint8_t> interface(mesh.num_nodes(), 0);
  const std::vector<int>& tags = mesh.extras.tet_tags;
  if (tags.size() != mesh.num_tets()) return interface;
  struct FaceUse {
    std::array<index_t, 3> face;  // ascending
    index_t opposite;             // the fourth node: which tet, whatever its listing
    int tag;
    bool operator<(const FaceUse& o) const {
      return std::tie(face, opposite, tag) < std::tie(o.face, o.opposite, o.tag);
    }
  };
  std::vector<FaceUse> uses(4 * mesh.num_tets());
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      FaceUse& u = uses[4 * t + f];
      for (int k = 0; k < 3; ++k) u.face[k] = mesh.tets[4 * t + kTetFaces[f][k]];
      std::sort(u.face.begin(), u.face.end());
      u.opposite = mesh.tets[4 * t + f];
      u.tag = tags[t];
    }
  std::sort(uses.begin(), uses.end());
  // The tags of the uses [b, e) of one face by one tet, without repeats.
  const auto tag_set = [&](std::size_t b, std::size_t e) {
    std::vector<int> set;
    for (std::size_t k = b; k < e; ++k)
      if (set.empty() || set.back() != uses[k].tag) set.push_back(uses[k].tag);
    return set;
  };
  for (std::size_t first = 0, last; first < uses.size(); first = last) {
    for (last = first + 1; last < uses.size() && uses[last].face == uses[first].face; ++last) {
    }
    // The run holds the face's tets one after another (sorted by fourth
    // node); the face is an interface when two of them differ in tags.
    std::vector<int> seen;
    bool differs = false;
    for (std::size_t b = first, e; b < last && !differs; b = e) {
      for (e = b + 1; e < last && uses[e].opposite == uses[b].opposite; ++e) {
      }
      std::vector<int> set = tag_set(b, e);
      differs = b != first && set != seen;
      seen = std::move(set);
    }
    if (differs)
      for (index_t n : uses[first].face) interface[static_cast<std::size_t>(n)] = 1;
  }
  return interface;
}

}  // namespace tetsmooth
