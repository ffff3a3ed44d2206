// Exodus II files: blocks as regions with their names, node and side sets
// as pins, 10-node tets, the older coord variable and float coordinates, a
// file written back with only its coordinates changed, new files that read
// back as written, and errors naming the file and the variable.
#include <gtest/gtest.h>

#include "mesh/errors.hpp"
#include "mesh/io/exodus_io.hpp"
#include "mesh/io/mesh_io.hpp"

#if TETSMOOTH_HAVE_EXODUS
#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/io/netcdf/netcdf_dataset.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/writable_check.hpp"
#include "mesh/second_order.hpp"
#include "support/exodus_spec.hpp"
#include "support/input_error.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"
#endif

namespace tetsmooth {
namespace {

TEST(ExodusFormat, NamesAndExtensions) {
  for (const char* path : {"m.exo", "m.e", "m.EX2", "m.g", "m.gen"})
    EXPECT_EQ(format_from_path(path), MeshFormat::Exodus) << path;
  EXPECT_EQ(parse_format("exodus"), MeshFormat::Exodus);
  EXPECT_EQ(parse_format("exo"), MeshFormat::Exodus);
  EXPECT_STREQ(format_name(MeshFormat::Exodus), "exodus");
}

#if !TETSMOOTH_HAVE_EXODUS

TEST(ExodusFiles, NeedNetcdf) {
  EXPECT_FALSE(exodus_available());
  EXPECT_THROW(read_exodus_file("m.exo"), UsageError);
  GTEST_SKIP() << "built without netCDF (TETSMOOTH_EXODUS=OFF or libnetcdf-dev missing): Exodus files are not read";
}

#else

using testing::build_exodus;
using testing::ExodusBlock;
using testing::ExodusSideSet;
using testing::ExodusSpec;

// cube_grid(n) as a spec: its tets in two TETRA blocks (those whose
// centroid lies below x = n/2 in block 10 "rock", the rest in 20 "soil").
ExodusSpec grid_spec(int n = 3) {
  const TetMesh mesh = testing::cube_grid(n);
  ExodusSpec s;
  s.xyz = mesh.xyz;
  s.blocks = {ExodusBlock{"TETRA", 4, {}, 10, "rock"}, ExodusBlock{"tetra4", 4, {}, 20, "soil"}};
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    double x = 0;
    for (std::size_t k = 0; k < 4; ++k) x += mesh.xyz[3 * static_cast<std::size_t>(mesh.tets[4 * t + k])];
    ExodusBlock& b = s.blocks[x / 4 < n / 2.0 ? 0 : 1];
    for (std::size_t k = 0; k < 4; ++k) b.connect.push_back(mesh.tets[4 * t + k] + 1);
  }
  return s;
}

// The node of spec s nearest (x, y, z), 1-based.
int node_at(const ExodusSpec& s, double x, double y, double z) {
  for (std::size_t i = 0; i < s.xyz.size() / 3; ++i)
    if (s.xyz[3 * i] == x && s.xyz[3 * i + 1] == y && s.xyz[3 * i + 2] == z) return static_cast<int>(i) + 1;
  ADD_FAILURE() << "no node at " << x << " " << y << " " << z;
  return 0;
}

std::string read_error(const ExodusSpec& s) {
  return testing::input_error_message([&] { read_exodus(build_exodus(s), "t.exo"); }, "an Exodus file");
}

std::set<std::size_t> pinned_of(const TetMesh& mesh) {
  std::set<std::size_t> pinned;
  for (std::size_t i = 0; i < mesh.fixed.size(); ++i)
    if (mesh.fixed[i]) pinned.insert(i);
  return pinned;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

bool has_note(const std::vector<std::string>& notes, const std::string& part) {
  return std::any_of(notes.begin(), notes.end(),
                     [&](const std::string& n) { return n.find(part) != std::string::npos; });
}

TEST(ExodusFiles, BlocksAreRegionsWithTheirNames) {
  ExodusSpec s = grid_spec();
  s.blocks.push_back(ExodusBlock{"TRISHELL3", 3, {1, 2, 5}, 7, "top"});
  const TetMesh mesh = read_exodus(build_exodus(s), "t.exo");
  ASSERT_TRUE(exodus_available());
  EXPECT_EQ(mesh.num_nodes(), 64u);
  EXPECT_EQ(mesh.num_tets(), 162u);
  // Tets in block order, with their blocks' ids as region tags.
  const std::size_t first = s.blocks[0].connect.size() / 4;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    const ExodusBlock& b = s.blocks[t < first ? 0 : 1];
    const std::size_t k = t < first ? t : t - first;
    for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(mesh.tets[4 * t + c] + 1, b.connect[4 * k + c]);
    EXPECT_EQ(mesh.extras.tet_tags[t], b.id);
  }
  ASSERT_EQ(mesh.extras.blocks.size(), 1u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "triangle");
  EXPECT_EQ(mesh.extras.blocks[0].tags, std::vector<int>{7});
  EXPECT_EQ(pinned_of(mesh), (std::set<std::size_t>{0, 1, 4}));
  const std::string* names = raw_section(mesh.extras, "$PhysicalNames");
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(physical_names_of(*names, 3), (std::map<int, std::string>{{10, "rock"}, {20, "soil"}}));
  EXPECT_EQ(physical_names_of(*names, 2), (std::map<int, std::string>{{7, "top"}}));
}

TEST(ExodusFiles, BlocksThatShareAnIdStayApart) {
  ExodusSpec s = grid_spec();
  s.blocks[1].id = s.blocks[0].id;
  const TetMesh mesh = read_exodus(build_exodus(s), "t.exo");
  const std::size_t first = s.blocks[0].connect.size() / 4;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) EXPECT_EQ(mesh.extras.tet_tags[t], t < first ? 1 : 2);
  EXPECT_TRUE(has_note(mesh.extras.read_notes, "block ids that repeat (id 10 is that of blocks 1 and 2)"));
}

TEST(ExodusFiles, NodeAndSideSetsPinTheirNodes) {
  ExodusSpec s = grid_spec();
  const int a = node_at(s, 1, 1, 1), b = node_at(s, 2, 2, 2);
  s.node_sets = {{a}, {}};
  // Side 2 of the first tet of block 10 that has node b: its corners 2, 3, 4.
  std::size_t tet = 0;
  while (std::find(&s.blocks[0].connect[4 * tet], &s.blocks[0].connect[4 * tet + 4], b) ==
         &s.blocks[0].connect[4 * tet + 4])
    ++tet;
  s.side_sets = {ExodusSideSet{{static_cast<int>(tet) + 1}, {2}}};
  const TetMesh mesh = read_exodus(build_exodus(s), "t.exo");
  std::set<std::size_t> expected{static_cast<std::size_t>(a - 1)};
  for (int c : {1, 2, 3})
    expected.insert(static_cast<std::size_t>(s.blocks[0].connect[4 * tet + static_cast<std::size_t>(c)] - 1));
  EXPECT_EQ(pinned_of(mesh), expected);
  EXPECT_NE(raw_section(mesh.extras, "exodus:rest"), nullptr);
  EXPECT_EQ(*raw_section(mesh.extras, "exodus:rest"), "2 node sets, 1 side set");
  // Another format is told what it drops.
  EXPECT_TRUE(has_note(output_losses(mesh, "out.vtu"), "the rest of the Exodus file (2 node sets, 1 side set)"));
  EXPECT_FALSE(has_note(output_losses(mesh, "out.exo"), "the rest of the Exodus file"));
}

TEST(ExodusFiles, TenNodeTetsAndTheirSides) {
  const TetMesh quadratic = testing::with_midsides(testing::cube_grid(2));
  ExodusSpec s;
  s.xyz = quadratic.xyz;
  s.blocks = {ExodusBlock{"TETRA10", 10, {}, 1, ""}};
  for (std::size_t t = 0; t < quadratic.num_tets(); ++t) {
    index_t nodes[10];
    file_tet10(quadratic, t, {4, 5, 6, 7, 8, 9}, nodes);
    for (index_t n : nodes) s.blocks[0].connect.push_back(n + 1);
  }
  s.side_sets = {ExodusSideSet{{1}, {4}}};  // corners 1, 2, 3 and the midside nodes of their edges
  const TetMesh mesh = read_exodus(build_exodus(s), "t.exo");
  EXPECT_EQ(mesh.tets, quadratic.tets);
  EXPECT_EQ(mesh.midsides, quadratic.midsides);
  std::set<std::size_t> expected;
  for (std::size_t k : {0, 1, 2, 4, 5, 6}) expected.insert(static_cast<std::size_t>(s.blocks[0].connect[k] - 1));
  EXPECT_EQ(pinned_of(mesh), expected);
  s.blocks.push_back(ExodusBlock{"TETRA", 4, {1, 2, 3, 4}, 2, ""});
  EXPECT_NE(read_error(s).find("connect2: a 4-node tet after 10-node ones"), std::string::npos);
}

TEST(ExodusFiles, TheOlderCoordVariableAndFloats) {
  ExodusSpec s = grid_spec();
  s.coord = true;
  const TetMesh doubles = read_exodus(build_exodus(s), "t.exo");
  EXPECT_EQ(doubles.xyz, s.xyz);
  EXPECT_EQ(*raw_section(doubles.extras, "exodus:coordinates"), "coord");
  s.floats = true;
  for (double& v : s.xyz) v += 0.1;  // not exact in float
  TetMesh floats = read_exodus(build_exodus(s), "t.exo");
  for (std::size_t k = 0; k < s.xyz.size(); ++k)
    EXPECT_EQ(floats.xyz[k], static_cast<double>(static_cast<float>(s.xyz[k])));
  EXPECT_TRUE(has_note(floats.extras.read_notes, "4-byte floats"));
  // Written back: a moved node rounded to float, the others as they were.
  testing::ScratchDir dir("exodus");
  const std::vector<double> read = floats.xyz;
  const std::size_t moved = static_cast<std::size_t>(node_at(grid_spec(), 1, 1, 1) - 1);
  floats.xyz[3 * moved] += 1e-9;
  write_exodus_file(floats, dir.file("out.exo"));
  const TetMesh back = read_exodus_file(dir.file("out.exo"));
  for (std::size_t k = 0; k < read.size(); ++k)
    EXPECT_EQ(back.xyz[k], k == 3 * moved ? static_cast<double>(static_cast<float>(floats.xyz[k])) : read[k]) << k;
}

// Every variable of two files, by name: values, or text rows.
std::map<std::string, std::vector<double> > numbers_of(const std::string& bytes) {
  netcdf::Dataset f(bytes, "t.exo");
  std::map<std::string, std::vector<double> > values;
  for (const std::string& name : f.variable_names()) {
    if (name == "eb_names") continue;  // text
    values[name] = f.reals(name);
  }
  return values;
}

TEST(ExodusFiles, WrittenBackWithOnlyTheCoordinatesChanged) {
  ExodusSpec s = grid_spec();
  s.node_sets = {{node_at(s, 1, 1, 1)}};
  s.node_map.resize(64);
  for (int i = 0; i < 64; ++i) s.node_map[static_cast<std::size_t>(i)] = 1000 + 3 * i;
  s.results = true;
  const std::string bytes = build_exodus(s);
  TetMesh mesh = read_exodus(bytes, "t.exo");
  EXPECT_TRUE(has_note(mesh.extras.read_notes, "results over 2 time steps"));
  EXPECT_EQ(mesh.extras.node_tags[5], 1015);
  const std::size_t moved = static_cast<std::size_t>(node_at(s, 2, 1, 1) - 1);
  mesh.xyz[3 * moved + 1] = 1.25;
  testing::ScratchDir dir("exodus");
  write_exodus_file(mesh, dir.file("out.exo"));
  const std::string out = slurp(dir.file("out.exo"));
  EXPECT_EQ(out.size(), bytes.size());
  auto before = numbers_of(bytes), after = numbers_of(out);
  ASSERT_EQ(before.size(), after.size());
  before["coordy"][moved] = 1.25;
  EXPECT_EQ(before, after);
  // Only the coordinates' bytes differ: one double.
  std::size_t differ = 0;
  for (std::size_t k = 0; k < out.size(); ++k) differ += out[k] != bytes[k];
  EXPECT_GE(differ, 1u);
  EXPECT_LE(differ, 8u);
  // A mesh that no longer matches the file is not written as it.
  mesh.tets.resize(mesh.tets.size() - 4);
  EXPECT_THROW(write_exodus_file(mesh, dir.file("bad.exo")), OutputError);
  EXPECT_FALSE(std::ifstream(dir.file("bad.exo")).good());
}

// A map that a new file could not keep (a repeated and a zero id) draws no
// "renumbered" warning when the file is written back: its maps stay as read.
TEST(ExodusFiles, WrittenBackKeepsEvenMapsANewFileCouldNot) {
  ExodusSpec s = grid_spec();
  s.node_map.resize(64);
  for (int i = 0; i < 64; ++i) s.node_map[static_cast<std::size_t>(i)] = 1000 + i;
  s.node_map[1] = s.node_map[0];
  s.node_map[2] = 0;
  TetMesh mesh = read_exodus(build_exodus(s), "t.exo");
  EXPECT_EQ(exodus_numbers_lost(mesh), "");
  TetMesh fresh = testing::cube_grid(3);  // the same ids in a new file are renumbered, and said so
  fresh.extras.node_tags = mesh.extras.node_tags;
  EXPECT_NE(exodus_numbers_lost(fresh), "");
}

TEST(ExodusFiles, NewFilesReadBackAsWritten) {
  TetMesh mesh = testing::cube_grid(3);
  FileExtras& e = mesh.extras;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) e.tet_tags.push_back(t % 3 == 0 ? 5 : -2);
  RegionNames names;
  names.add(3, 5, "granite");
  names.add(2, 5, "a face group");
  e.raw_sections.emplace_back("$PhysicalNames", names.msh_body());
  e.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 1, 4, 1, 5, 4}, {5, 5}, {}, {}});
  e.blocks.push_back(PassThroughBlock{"vertex", 1, {21}, {}, {}, {}});
  mesh.fixed.assign(mesh.num_nodes(), 0);
  mesh.fixed[0] = mesh.fixed[1] = mesh.fixed[4] = mesh.fixed[5] = mesh.fixed[21] = 1;
  mesh.fixed[42] = 1;  // pinned by no element: the node set keeps it
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) e.node_tags.push_back(static_cast<long long>(7 * i + 3));
  testing::ScratchDir dir("exodus");
  write_mesh(mesh, dir.file("new.exo"));
  const TetMesh back = read_mesh(dir.file("new.exo"));
  EXPECT_EQ(back.xyz, mesh.xyz);
  EXPECT_EQ(back.extras.node_tags, e.node_tags);
  EXPECT_EQ(pinned_of(back), pinned_of(mesh));
  // The tets by block: tag 5's, then the others' under a new id (tags are
  // ids only where positive).
  std::multiset<std::vector<index_t> > by_tag[2], back_by_tag[2];
  std::set<int> new_ids;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    by_tag[e.tet_tags[t] == 5].insert({&mesh.tets[4 * t], &mesh.tets[4 * t + 4]});
    back_by_tag[back.extras.tet_tags[t] == 5].insert({&back.tets[4 * t], &back.tets[4 * t + 4]});
    if (back.extras.tet_tags[t] != 5) new_ids.insert(back.extras.tet_tags[t]);
  }
  EXPECT_EQ(by_tag[0], back_by_tag[0]);
  EXPECT_EQ(by_tag[1], back_by_tag[1]);
  EXPECT_EQ(new_ids.size(), 1u);
  EXPECT_GT(*new_ids.begin(), 0);
  ASSERT_EQ(back.extras.blocks.size(), 2u);
  EXPECT_EQ(back.extras.blocks[0].kind, "triangle");
  EXPECT_EQ(back.extras.blocks[0].connectivity, e.blocks[0].connectivity);
  EXPECT_EQ(back.extras.blocks[1].kind, "vertex");
  const std::string* back_names = raw_section(back.extras, "$PhysicalNames");
  ASSERT_NE(back_names, nullptr);
  EXPECT_EQ(physical_names_of(*back_names, 3), (std::map<int, std::string>{{5, "granite"}}));
  // The triangles' tag 5 is taken by the tets' block: they get another id,
  // with their name.
  const int face_id = back.extras.blocks[0].tags.at(0);
  EXPECT_NE(face_id, 5);
  EXPECT_EQ(physical_names_of(*back_names, 2), (std::map<int, std::string>{{face_id, "a face group"}}));
  // The node set lists node 43 alone (1-based): the others are pinned by
  // the elements written.
  netcdf::Dataset f(slurp(dir.file("new.exo")), "new.exo");
  EXPECT_EQ(f.integers("node_ns1"), std::vector<long long>{43});
  EXPECT_EQ(f.rows_of_text("ns_names"), std::vector<std::string>{"tetsmooth_pinned"});
  EXPECT_EQ(*f.text_attribute("connect1", "elem_type"), "TETRA");
  // Names that two blocks would share are made unique, as SEACAS wants
  // them: the second takes its type.
  RegionNames same;
  same.add(3, 5, "rock");
  same.add(2, 5, "rock");
  TetMesh twice = mesh;
  twice.extras.raw_sections = {{"$PhysicalNames", same.msh_body()}};
  write_mesh(twice, dir.file("twice.exo"));
  netcdf::Dataset g(slurp(dir.file("twice.exo")), "twice.exo");
  const std::vector<std::string> block_names = g.rows_of_text("eb_names");
  EXPECT_EQ(std::count(block_names.begin(), block_names.end(), "rock"), 1);
  EXPECT_EQ(std::count(block_names.begin(), block_names.end(), "rock_TRI3"), 1);
  // Second-order tets come back with their midside nodes.
  const TetMesh quadratic = testing::with_midsides(testing::cube_grid(2));
  write_mesh(quadratic, dir.file("quadratic.exo"));
  const TetMesh quadratic_back = read_mesh(dir.file("quadratic.exo"));
  EXPECT_EQ(quadratic_back.tets, quadratic.tets);
  EXPECT_EQ(quadratic_back.midsides, quadratic.midsides);
}

TEST(ExodusFiles, TypesNotCarriedPinTheirNodes) {
  ExodusSpec s = grid_spec(2);
  ExodusBlock hex20{"HEX20", 20, {}, 3, "curved"};
  for (int k = 1; k <= 20; ++k) hex20.connect.push_back(k);
  s.blocks.push_back(hex20);
  const TetMesh mesh = read_exodus(build_exodus(s), "t.exo");
  EXPECT_EQ(pinned_of(mesh).size(), 20u);
  EXPECT_TRUE(mesh.extras.blocks.empty());
  EXPECT_TRUE(has_note(mesh.extras.read_notes, "1 HEX20 (20 nodes)"));
  EXPECT_TRUE(has_note(output_losses(mesh, "out.msh"), "the elements of 1 HEX20 (20 nodes) will not be written"));
}

TEST(ExodusFiles, ErrorsNameTheVariable) {
  const auto expect_error = [](const ExodusSpec& s, const std::string& part) {
    const std::string message = read_error(s);
    SCOPED_TRACE(part);
    EXPECT_NE(message.find("t.exo: "), std::string::npos) << message;
    EXPECT_NE(message.find(part), std::string::npos) << message;
  };
  ExodusSpec s = grid_spec(2);
  s.blocks[0].connect[5] = 99;
  expect_error(s, "entry 6 of connect1 names node 99, outside 1..27");
  s = grid_spec(2);
  s.side_sets = {ExodusSideSet{{1}, {7}}};
  expect_error(s, "entry 1 of side_ss1 names side 7 of a tet");
  s.side_sets = {ExodusSideSet{{400}, {1}}};
  expect_error(s, "entry 1 of elem_ss1 names element 400, outside 1..48");
  s = grid_spec(2);
  s.node_sets = {{0}};
  expect_error(s, "entry 1 of node_ns1 names node 0");
  s = grid_spec(2);
  s.dims = 2;
  s.coord = true;
  s.xyz.resize(2 * 27);  // num_dim 2: the file has only x and y, which the builder reads from here
  s.xyz.resize(3 * 27);
  expect_error(s, "a 2-D mesh (num_dim 2)");
  s = grid_spec(2);
  s.blocks = {ExodusBlock{"TRI3", 3, {1, 2, 3}, 1, ""}};
  expect_error(s, "no blocks of 4- or 10-node tets");
  s.blocks.push_back(ExodusBlock{"TETRA14", 14, {}, 2, ""});
  for (int k = 1; k <= 14; ++k) s.blocks.back().connect.push_back(k);
  expect_error(s, "no blocks of 4- or 10-node tets (TETRA, TET4, TETRA10, ...), only blocks of types tetsmooth");
  const std::string not_netcdf =
      testing::input_error_message([] { read_exodus("$MeshFormat\n4.1 0 8\n", "t.exo"); }, "an MSH file");
  EXPECT_NE(not_netcdf.find("t.exo: not an Exodus II file"), std::string::npos) << not_netcdf;
  // A netCDF-4 file one byte off a good one, which crashes HDF5 1.10 as
  // netCDF opens it (in its global heap reader): refused, not a crash.
  const std::string corrupt = testing::input_error_message(
      [] { read_exodus_file(testing::data_path("exodus_hdf5_corrupt.exo")); }, "a corrupt HDF5 file");
  EXPECT_NE(corrupt.find("exodus_hdf5_corrupt.exo: "), std::string::npos) << corrupt;
  std::string cut = build_exodus(grid_spec(2));
  cut.resize(cut.size() / 2);
  const std::string cut_message = testing::input_error_message([&] { read_exodus(cut, "t.exo"); }, "a file cut short");
  EXPECT_NE(cut_message.find("t.exo: "), std::string::npos) << cut_message;
}

#endif

}  // namespace
}  // namespace tetsmooth
