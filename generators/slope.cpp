// The slope model: an embankment of the kind used in slope-stability
// analysis, a prism whose cross-section is a foundation block with a sloping
// fill on top, meshed by TetGen from a piecewise linear complex with a
// quality bound.
#include <array>
#include <cstdint>
#include <initializer_list>
#include <locale>
#include <sstream>
#include <string>
#include <tuple>

#include "generators/models.hpp"
#include "generators/tetgen_bridge.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth {
namespace {

// Size bounds measured (TetGen 1.5.0) to give Table 2's slope, 76,928 nodes
// and 388,428 tets, within 0.5%. Its 5.05 tets per node is well below the
// ~5.5 of a uniformly sized quality mesh of this volume, which suggests that
// the paper's surface was meshed finer than its interior. So the facets get
// their own area bound besides the volume bound, as FE meshes that resolve
// boundary stresses often do.
constexpr double kReferenceMaxVolume = 0.157;  // m^3
constexpr double kReferenceMaxArea = 0.145;    // m^2
constexpr double kRadiusEdgeBound = 1.4;
constexpr int kFacetMarker = 1;

// With lengths scaled by s (areas s^2, volumes s^3) the node count follows
// interior / s^3 + surface / s^2. Fitted to meshes of 25k and 77k nodes, the
// two terms predict TetGen's counts from 5k to 200k nodes within 1%.
constexpr double kInteriorNodes = 42'995;
constexpr double kSurfaceNodes = 33'913;

// The s whose predicted node count is `target`, by bisection on u = 1/s,
// where the prediction is increasing.
double length_scale_for(int target) {
  const auto nodes = [](double u) { return u * u * (kInteriorNodes * u + kSurfaceNodes); };
  double lo = 0.0, hi = 1.0;
  while (nodes(hi) < target) hi *= 2.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (nodes(mid) < target ? lo : hi) = mid;
  }
  return 2.0 / (lo + hi);
}

// The cross-section in the x-z plane, counter-clockwise from the origin:
// base, far end, crest plateau, inclined face down to the toe, toe berm, near
// end. The prism runs along y from 0 to the width.
std::array<std::array<double, 2>, 6> slope_profile(const SlopeGeometry& g) {
  return {{{0.0, 0.0},
           {g.length, 0.0},
           {g.length, g.crest_height},
           {g.crest_x, g.crest_height},
           {g.toe_x, g.base_height},
           {0.0, g.base_height}}};
}

void fill_polygon(tetgenio::facet& f, std::initializer_list<int> corners) {
  tetgenio::init(&f);
  f.numberofpolygons = 1;
  f.polygonlist = new tetgenio::polygon[1];  // owned and freed by tetgenio
  tetgenio::polygon& poly = f.polygonlist[0];
  tetgenio::init(&poly);
  poly.numberofvertices = static_cast<int>(corners.size());
  poly.vertexlist = new int[corners.size()];
  int i = 0;
  for (int c : corners) poly.vertexlist[i++] = c;
}

// The PLC: 12 corners (the profile at y = 0, then at y = width), two
// hexagonal end caps and six side faces, one per profile edge, all carrying
// the marker that the facet area bound applies to.
void fill_slope_plc(tetgenio& in, const SlopeGeometry& g, double max_area) {
  const auto profile = slope_profile(g);
  constexpr int kCorners = static_cast<int>(std::tuple_size<decltype(profile)>::value);
  in.numberofpoints = 2 * kCorners;
  in.pointlist = new REAL[3 * 2 * kCorners];
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < kCorners; ++i) {
      REAL* p = &in.pointlist[3 * (side * kCorners + i)];
      p[0] = profile[i][0];
      p[1] = side == 0 ? 0.0 : g.width;
      p[2] = profile[i][1];
    }
  in.numberoffacets = 2 + kCorners;
  in.facetlist = new tetgenio::facet[in.numberoffacets];
  fill_polygon(in.facetlist[0], {0, 1, 2, 3, 4, 5});
  fill_polygon(in.facetlist[1], {6, 7, 8, 9, 10, 11});
  for (int i = 0; i < kCorners; ++i) {
    const int j = (i + 1) % kCorners;
    fill_polygon(in.facetlist[2 + i], {i, j, j + kCorners, i + kCorners});
  }
  in.facetmarkerlist = new int[in.numberoffacets];
  for (int f = 0; f < in.numberoffacets; ++f) in.facetmarkerlist[f] = kFacetMarker;
  in.numberoffacetconstraints = 1;
  in.facetconstraintlist = new REAL[2]{kFacetMarker, max_area};
}

}  // namespace

const SlopeGeometry& slope_geometry() {
  static const SlopeGeometry geometry{};
  return geometry;
}

TetMesh generate_slope(int target_nodes, std::uint64_t /*seed: the mesh is fixed, see models.hpp*/) {
  if (target_nodes < 100)
    throw UsageError("slope model: target_nodes must be >= 100, got " + std::to_string(target_nodes));
  const double s = length_scale_for(target_nodes);
  const double max_volume = kReferenceMaxVolume * s * s * s;
  const double max_area = kReferenceMaxArea * s * s;

  tetgenio in;
  fill_slope_plc(in, slope_geometry(), max_area);
  // 'p': mesh the PLC; 'q': bound the radius-edge ratio, as a quality mesher
  // for FE analysis would; 'a': the volume bound (the facet area bound is
  // read from `in`). Fixed notation, because TetGen's parser takes digits and
  // a point; twelve decimals keep the bound exact enough for any target.
  std::ostringstream switches;
  switches.imbue(std::locale::classic());
  switches.setf(std::ios::fixed);
  switches.precision(12);
  switches << "pq" << kRadiusEdgeBound << "a" << max_volume;
  return run_tetgen(in, switches.str(), "slope model (" + std::to_string(target_nodes) + " nodes)");
}

}  // namespace tetsmooth
