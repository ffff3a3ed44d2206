#include "mesh/io/id_index.hpp"

#include <algorithm>

namespace tetsmooth {

IdIndex::IdIndex(const std::vector<long long>& ids) {
  sorted_.reserve(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) sorted_.emplace_back(ids[i], i);
  std::sort(sorted_.begin(), sorted_.end());
  const auto twice = std::adjacent_find(sorted_.begin(), sorted_.end(),
                                        [](const auto& a, const auto& b) { return a.first == b.first; });
  if (twice != sorted_.end()) repeated_ = (twice + 1)->second;
}

long long IdIndex::find(long long id) const {
  const auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::make_pair(id, std::size_t{0}));
  return it != sorted_.end() && it->first == id ? static_cast<long long>(it->second) : -1;
}

void IdIndex::append_range(long long first, long long last, long long step, std::vector<std::size_t>& out) const {
  auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::make_pair(first, std::size_t{0}));
  for (; it != sorted_.end() && it->first <= last; ++it)
    if ((it->first - first) % step == 0) out.push_back(it->second);
}

}  // namespace tetsmooth
