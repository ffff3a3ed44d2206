#pragma once
// Whole-mesh quality statistics over the radius ratio q (tet_quality.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

struct QualitySummary {
  std::size_t tets = 0;
  double min = 0, mean = 0, max = 0;  // radius ratio
  // 10 bins of width 0.1 over [0,1]; bin k holds 0.1k <= q < 0.1(k+1), q = 1
  // goes to bin 9 and inverted tets (q < 0) to bin 0.
  std::array<std::size_t, 10> histogram{};
  std::size_t below_0_1 = 0;   // tets with q < 0.1, inverted included
  std::size_t inverted = 0;    // signed volume < 0
  std::size_t degenerate = 0;  // signed volume == 0
  // Minimum q over the movable_tets, those with at least one movable node:
  // the part of the mesh smoothing can change (1 when there are none, which
  // reports print as no value).
  double min_movable = 1;
  std::size_t movable_tets = 0;
  double min_dihedral_deg = 0;  // over all tets
  double mean_ratio_mean = 0;   // mean of the mean-ratio metric
};

// Radius ratio per tet.
std::vector<double> tet_qualities(const TetMesh& mesh);

// The smallest and the mean radius ratio over all tets, as summarize_quality
// counts them (0 and 0 for a mesh without tets), without the rest of its
// work: what a progress display shows while a smoother runs.
struct MinMeanQuality {
  double min = 0, mean = 0;
};

// Over `threads` OpenMP threads (0: OpenMP's default); the mean's sum is
// taken in double, its rounding depending on the thread count.
MinMeanQuality min_mean_quality(const TetMesh& mesh, int threads = 0);

// Which tets are inverted, as QualitySummary::inverted counts them (signed
// volume < 0): 1 a tet, in tet order.
std::vector<std::uint8_t> inverted_tets(const TetMesh& mesh);

// How a run changed the inverted tets, from inverted_tets before and after
// (of the same length): `made` were valid and are inverted, `mended` were
// inverted and are not. A net count would hide one behind the other.
struct InversionChange {
  std::size_t made = 0, mended = 0;
};
InversionChange inversion_change(const std::vector<std::uint8_t>& before, const std::vector<std::uint8_t>& after);

// `movable` may be empty (then min_movable is the overall min).
QualitySummary summarize_quality(const TetMesh& mesh, const std::vector<std::uint8_t>& movable = {});

}  // namespace tetsmooth
