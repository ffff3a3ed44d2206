#pragma once
// Region tags compared as the regions they make, not as numbers: a format
// that numbers its regions itself (FLAC3D's groups, Abaqus's sets) gives the
// same regions other tags. Header-only, for the tests and the fuzz targets.
#include <map>
#include <vector>

namespace tetsmooth::testing {

// Whether two tag lists split their elements alike: equal tags in one
// exactly where the other's are equal.
inline bool same_partition(const std::vector<int>& a, const std::vector<int>& b) {
  if (a.size() != b.size()) return false;
  std::map<int, int> ab, ba;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (ab.try_emplace(a[i], b[i]).first->second != b[i] || ba.try_emplace(b[i], a[i]).first->second != a[i])
      return false;
  return true;
}

}  // namespace tetsmooth::testing
