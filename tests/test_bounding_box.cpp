// The boxes around a mesh (mesh/bounding_box.hpp).
#include <gtest/gtest.h>

#include "mesh/bounding_box.hpp"
#include "test_meshes.hpp"

namespace tetsmooth {
namespace {

TEST(BoundingBox, AllNodesOrTheTetsCornersAlone) {
  TetMesh mesh = testing::cube_with_centre();
  mesh.xyz.insert(mesh.xyz.end(), {1e6, -2e6, 3.0});  // a node no tet uses
  const BoundingBox all = bounding_box(mesh), corners = tet_corners_bounding_box(mesh);
  EXPECT_EQ(all.hi[0], 1e6);
  EXPECT_EQ(all.lo[1], -2e6);
  EXPECT_EQ(all.hi[2], 3.0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(corners.lo[k], 0.0) << k;
    EXPECT_EQ(corners.hi[k], 1.0) << k;
  }
  EXPECT_EQ(corners.largest_side(), 1.0);
  // Without tets, the corners' box is the whole mesh's.
  mesh.tets.clear();
  EXPECT_EQ(tet_corners_bounding_box(mesh).hi[0], 1e6);
  EXPECT_EQ(bounding_box(TetMesh{}).largest_side(), 0.0);
}

}  // namespace
}  // namespace tetsmooth
