#include "mesh/quality_summary.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/team_size.hpp"
#include "mesh/tet_quality.hpp"

namespace tetsmooth {
namespace {

struct Corners {
  Vec3<double> v[4];
};

Corners corners(const TetMesh& mesh, std::size_t t) {
  Corners c;
  for (int k = 0; k < 4; ++k) {
    const std::size_t n = static_cast<std::size_t>(mesh.tets[4 * t + k]);
    c.v[k] = {mesh.xyz[3 * n], mesh.xyz[3 * n + 1], mesh.xyz[3 * n + 2]};
  }
  return c;
}

}  // namespace

std::vector<double> tet_qualities(const TetMesh& mesh) {
  std::vector<double> q(mesh.num_tets());
#pragma omp parallel for schedule(static)
  for (std::size_t t = 0; t < q.size(); ++t) {
    const Corners c = corners(mesh, t);
    q[t] = radius_ratio(c.v[0], c.v[1], c.v[2], c.v[3]);
  }
  return q;
}

MinMeanQuality min_mean_quality(const TetMesh& mesh, int threads) {
  MinMeanQuality r;
  const std::size_t tets = mesh.num_tets();
  if (tets == 0) return r;
  double lowest = 1, sum = 0;
#pragma omp parallel for num_threads(team_size(threads)) schedule(static) \
    reduction(min : lowest) reduction(+ : sum)
  for (std::size_t t = 0; t < tets; ++t) {
    const Corners c = corners(mesh, t);
    const double q = radius_ratio(c.v[0], c.v[1], c.v[2], c.v[3]);
    lowest = std::min(lowest, q);
    sum += q;
  }
  r.min = lowest;
  r.mean = sum / static_cast<double>(tets);
  return r;
}

std::vector<std::uint8_t> inverted_tets(const TetMesh& mesh) {
  std::vector<std::uint8_t> inverted(mesh.num_tets());
#pragma omp parallel for schedule(static)
  for (std::size_t t = 0; t < inverted.size(); ++t) {
    const Corners c = corners(mesh, t);
    inverted[t] = signed_volume6(c.v[0], c.v[1], c.v[2], c.v[3]) < 0;
  }
  return inverted;
}

InversionChange inversion_change(const std::vector<std::uint8_t>& before, const std::vector<std::uint8_t>& after) {
  InversionChange change;
  for (std::size_t t = 0; t < std::min(before.size(), after.size()); ++t) {
    change.made += !before[t] && after[t];
    change.mended += before[t] && !after[t];
  }
  return change;
}

QualitySummary summarize_quality(const TetMesh& mesh, const std::vector<std::uint8_t>& movable) {
  QualitySummary s;
  s.tets = mesh.num_tets();
  if (s.tets == 0) return s;
  s.min = 1;
  s.max = -1;
  s.min_dihedral_deg = 180;
  double sum = 0, sum_mean_ratio = 0;
  for (std::size_t t = 0; t < s.tets; ++t) {
    const Corners c = corners(mesh, t);
    const double q = radius_ratio(c.v[0], c.v[1], c.v[2], c.v[3]);
    const double v6 = signed_volume6(c.v[0], c.v[1], c.v[2], c.v[3]);
    sum += q;
    sum_mean_ratio += mean_ratio(c.v[0], c.v[1], c.v[2], c.v[3]);
    s.min = std::min(s.min, q);
    s.max = std::max(s.max, q);
    s.min_dihedral_deg = std::min(s.min_dihedral_deg, min_dihedral_deg(c.v[0], c.v[1], c.v[2], c.v[3]));
    const int bin = std::clamp(static_cast<int>(std::floor(q * 10.0)), 0, 9);
    ++s.histogram[static_cast<std::size_t>(bin)];
    if (q < 0.1) ++s.below_0_1;
    if (v6 < 0) ++s.inverted;
    if (v6 == 0) ++s.degenerate;
    bool touches_movable = movable.empty();
    for (int k = 0; k < 4 && !touches_movable; ++k) touches_movable = movable[mesh.tets[4 * t + k]] != 0;
    if (touches_movable) {
      s.min_movable = std::min(s.min_movable, q);
      ++s.movable_tets;
    }
  }
  s.mean = sum / static_cast<double>(s.tets);
  s.mean_ratio_mean = sum_mean_ratio / static_cast<double>(s.tets);
  return s;
}

}  // namespace tetsmooth
