#pragma once
// Small meshes built in code for tests.
#include <cstdint>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth::testing {

// The regular tet with unit edges, positively oriented.
TetMesh regular_tet();

// n^3 cubes of a unit-spaced grid split into 6 tets each (no jitter unless
// jitter > 0; interior nodes only), via the lattice generator.
TetMesh cube_grid(int n, double jitter = 0.0, std::uint64_t seed = 7);

// cube_grid with every `every`-th node that is movable pushed `push` lattice
// spacings along x: far enough (about 1.5) inverts tets of its star, and
// Form A's movers then conflict in shared tets.
TetMesh pushed_cube_grid(int n, double jitter, std::uint64_t seed, int every, double push);

// A cube of 8 corners plus one interior node, as a fan of 12 tets around
// the interior node: the smallest mesh with one movable node.
TetMesh cube_with_centre(double cx = 0.5, double cy = 0.5, double cz = 0.5);

// Random points in a box, Delaunay-tetrahedralised by TetGen.
TetMesh random_delaunay(int points, std::uint64_t seed);

// The same mesh as second-order tets: a new node at the midpoint of each
// edge (appended after the mesh's nodes, in order of first use), listed in
// TetMesh::midsides.
TetMesh with_midsides(TetMesh mesh);

// How far the midside nodes of a second-order mesh lie off their edges'
// midpoints, at most (the largest coordinate difference).
double largest_midside_offset(const TetMesh& mesh);

// Path to tests/data/<name>.
const char* data_path(const char* name);

}  // namespace tetsmooth::testing

namespace tetsmooth::testing {

// The paper's Figure 2 situation: one interior node whose star (8 boundary
// nodes around it) is concave, so the centroid of its neighbours lies
// outside the star's kernel and moving there inverts a tet.
TetMesh concave_star();

}  // namespace tetsmooth::testing
