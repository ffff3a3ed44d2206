// New Exodus files as the Exodus II library itself reads them (SEACAS's
// libexodus, Debian's libexodusii-dev): counts, coordinates, blocks with
// their types, ids, names and connectivity, and the node set of pins.
#include <gtest/gtest.h>

#if TETSMOOTH_HAVE_EXODUS_LIBRARY
#include <exodusII.h>

#include <string>
#include <vector>

#include "mesh/io/exodus_io.hpp"
#include "mesh/io/region_sets.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"
#endif

namespace tetsmooth {
namespace {

#if !TETSMOOTH_HAVE_EXODUS_LIBRARY

TEST(ExodusLibrary, ReadsNewFiles) {
  GTEST_SKIP() << "built without the Exodus II library (libexodusii-dev) or without netCDF: new files are checked "
                  "by netCDF4-python and meshio alone";
}

#else

TEST(ExodusLibrary, ReadsNewFiles) {
  TetMesh mesh = testing::cube_grid(2);
  FileExtras& e = mesh.extras;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) e.tet_tags.push_back(t < 24 ? 7 : 9);
  RegionNames names;
  names.add(3, 7, "granite");
  names.add(3, 9, "clay");
  names.add(2, 7, "top");
  e.raw_sections.emplace_back("$PhysicalNames", names.msh_body());
  e.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 1, 3}, {7}, {}, {}});
  mesh.fixed.assign(mesh.num_nodes(), 0);
  mesh.fixed[13] = 1;  // the centre, which no element written pins
  testing::ScratchDir dir("exodus_library");
  write_exodus_file(mesh, dir.file("new.exo"));

  int cpu = sizeof(double), io = 0;
  float version = 0;
  const int exo = ex_open(dir.file("new.exo").c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(exo, 0);
  char title[MAX_LINE_LENGTH + 1];
  int dims = 0, nodes = 0, elements = 0, blocks = 0, node_sets = 0, side_sets = 0;
  ASSERT_GE(ex_get_init(exo, title, &dims, &nodes, &elements, &blocks, &node_sets, &side_sets), 0);
  EXPECT_EQ(dims, 3);
  EXPECT_EQ(nodes, 27);
  EXPECT_EQ(elements, 49);
  EXPECT_EQ(blocks, 3);
  EXPECT_EQ(node_sets, 1);
  std::vector<double> x(27), y(27), z(27);
  ASSERT_GE(ex_get_coord(exo, x.data(), y.data(), z.data()), 0);
  for (std::size_t i = 0; i < 27; ++i) {
    EXPECT_EQ(x[i], mesh.xyz[3 * i]);
    EXPECT_EQ(y[i], mesh.xyz[3 * i + 1]);
    EXPECT_EQ(z[i], mesh.xyz[3 * i + 2]);
  }
  std::vector<int> ids(3);
  ASSERT_GE(ex_get_elem_blk_ids(exo, ids.data()), 0);
  EXPECT_EQ(ids, (std::vector<int>{7, 9, 1}));  // the triangles' tag 7 is taken: the next free id
  const char* expected_types[3] = {"TETRA", "TETRA", "TRI3"};
  const char* expected_names[3] = {"granite", "clay", "top"};
  const int expected_counts[3] = {24, 24, 1};
  std::vector<int> tets;
  for (int b = 0; b < 3; ++b) {
    char type[MAX_STR_LENGTH + 1];
    char name[MAX_STR_LENGTH + 1] = "";
    int count = 0, per = 0, attributes = 0;
    ASSERT_GE(ex_get_elem_block(exo, ids[static_cast<std::size_t>(b)], type, &count, &per, &attributes), 0);
    ASSERT_GE(ex_get_name(exo, EX_ELEM_BLOCK, ids[static_cast<std::size_t>(b)], name), 0);
    EXPECT_STREQ(type, expected_types[b]);
    EXPECT_STREQ(name, expected_names[b]);
    EXPECT_EQ(count, expected_counts[b]);
    std::vector<int> connect(static_cast<std::size_t>(count * per));
    ASSERT_GE(ex_get_elem_conn(exo, ids[static_cast<std::size_t>(b)], connect.data()), 0);
    if (b < 2)
      tets.insert(tets.end(), connect.begin(), connect.end());
    else
      EXPECT_EQ(connect, (std::vector<int>{1, 2, 4}));
  }
  for (std::size_t k = 0; k < mesh.tets.size(); ++k) EXPECT_EQ(tets[k], mesh.tets[k] + 1) << k;
  int set_id = 0, members = 0, factors = 0;
  ASSERT_GE(ex_get_node_set_ids(exo, &set_id), 0);
  ASSERT_GE(ex_get_node_set_param(exo, set_id, &members, &factors), 0);
  char set_name[MAX_STR_LENGTH + 1] = "";
  ASSERT_GE(ex_get_name(exo, EX_NODE_SET, set_id, set_name), 0);
  EXPECT_STREQ(set_name, "tetsmooth_pinned");
  std::vector<int> pinned(static_cast<std::size_t>(members));
  ASSERT_GE(ex_get_node_set(exo, set_id, pinned.data()), 0);
  EXPECT_EQ(pinned, std::vector<int>{14});
  ex_close(exo);
}

#endif

}  // namespace
}  // namespace tetsmooth
