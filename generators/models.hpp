#pragma once
// Mesh generators: the five models of the paper (Table 2) through TetGen, and
// a fast jittered-lattice generator for scaling studies.
//
// Every generator returns tets positively oriented ((b-a)·((c-a)×(d-a)) > 0,
// see mesh/tet_mesh.hpp), 0-based, with every node referenced, and is
// deterministic: the same arguments give a bit-identical mesh on every
// platform (the random numbers are the library's own, generators/rng.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// The model names `generate_model` knows, in the paper's order.
const std::vector<std::string>& paper_model_names();  // {"5k","10k","59k","slope-77k","109k"}

// Builds a model by name: one of paper_model_names(), or "lattice-N" (N cubes
// per axis, (N+1)^3 nodes, 6 N^3 tets, jitter kLatticeDefaultJitter).
// Deterministic for a seed. All tets are positively oriented. Throws
// UsageError for an unknown name.
//
//   name       nodes    tets (Table 2)  built as
//   5k          5,000   ~32,978         3^3 lattice + 4,973 random nodes
//   10k        10,000   ~66,542         3^3 lattice + 9,973 random nodes
//   59k        59,261   ~391,220        21^3 lattice + 50,000 random nodes
//   slope-77k  ~76,928  ~388,428        generate_slope(76928)
//   109k      109,260   ~727,088        21^3 lattice + 99,999 random nodes
TetMesh generate_model(const std::string& name, std::uint64_t seed = 1);

// Whether `name`'s mesh depends on the seed (all but slope-77k, whose
// geometry and TetGen run are fixed).
bool model_uses_seed(const std::string& name);

// Lattice-plus-random-nodes in the unit box [0,1]^3, Delaunay-tetrahedralised
// by TetGen without Steiner points: exactly lattice_per_axis^3 +
// random_nodes nodes, the lattice first (x fastest), then the random nodes
// (uniform in the open box, drawn from `seed`). lattice_per_axis >= 2 makes
// the box corners nodes, so the mesh fills the box; 0 means random nodes
// only, meshing their convex hull (whose boundary tets are often slivers).
TetMesh generate_box_delaunay(int lattice_per_axis, int random_nodes, std::uint64_t seed);

// The embankment of generate_slope, in metres. Its cross-section in the x-z
// plane is a foundation block [0,length] x [0,base_height] under a fill that
// rises on an inclined face from the toe (toe_x, base_height) to the crest
// (crest_x, crest_height) and stays level to x = length; the prism spans
// y in [0, width]. The defaults make a 1:1.5 slope (33.7 degrees).
struct SlopeGeometry {
  double length = 60.0;
  double width = 20.0;
  double base_height = 10.0;
  double crest_height = 30.0;
  double toe_x = 15.0;
  double crest_x = 45.0;
};
const SlopeGeometry& slope_geometry();

// The embankment of slope_geometry() meshed by TetGen from its PLC with a
// radius-edge bound of 1.4, and volume and surface-area bounds chosen for
// about `target_nodes` nodes (within 1% at the paper's 76,928; other targets
// get a geometrically similar mesh, within a few per cent). TetGen's refinement is
// deterministic and the geometry fixed, so the mesh does not depend on
// `seed`; the parameter keeps the generators' signatures uniform.
TetMesh generate_slope(int target_nodes, std::uint64_t seed);

// Jitter, as a fraction of the cell size, below which no lattice tet can
// invert: 1/(2 sqrt 3), the smallest radius at which displacing the four
// nodes of a Kuhn tet within balls of that radius can flatten it (found by
// minimising its volume over all such displacements).
inline constexpr double kLatticeSafeJitter = 0.28867513459481287;
// The jitter "lattice-N" uses: safely below kLatticeSafeJitter, so the
// worst-case tet keeps a positive volume, yet enough to make the lattice
// irregular for the smoother.
inline constexpr double kLatticeDefaultJitter = 0.25;

// n^3 jittered unit cubes spanning [0,n]^3, each split into 6 tets along its
// (0,0,0)-(1,1,1) diagonal (Kuhn/Freudenthal), so neighbouring cubes share
// faces exactly. Node (i,j,k) has index i + (n+1)(j + (n+1)k); cube (i,j,k)
// owns tets 6(i + n(j + n k)) .. +5. Each interior node moves by a
// vector drawn uniformly from the ball of radius `jitter` cell sizes
// (0 <= jitter < 0.5); boundary nodes stay put, so the box is kept. Throws UsageError for
// n < 1, a jitter out of range, or node or tet counts beyond 32-bit indices.
// OpenMP-parallel; the mesh does not depend on the number of threads.
TetMesh generate_lattice(int n, double jitter, std::uint64_t seed);

// The largest n generate_lattice (and "lattice-N") takes: the node-to-tet
// table holds 4 entries a tet under 32-bit offsets (validate_mesh), and
// 24 n^3 reaches that limit long before (n+1)^3 nodes reach theirs.
inline constexpr int kMaxLatticeN = 447;

}  // namespace tetsmooth
