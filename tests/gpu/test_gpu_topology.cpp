// GPU topology and colouring against the CPU reference, array for array:
// both build the same sorted CSR rows, flags and Jones-Plassmann colouring,
// so everything must be exactly equal (integers, no tolerance).
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "generators/models.hpp"
#include "kernels/cuda/topology_snapshot.hpp"
#include "kernels/smoother.hpp"
#include "mesh/colouring.hpp"
#include "mesh/topology.hpp"
#include "test_meshes.hpp"

namespace tetsmooth {
namespace {

class GpuTopology : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!cuda_available(&why)) GTEST_SKIP() << why;
  }
};

// Names the first differing entry instead of printing whole arrays.
template <class T>
::testing::AssertionResult same(const std::vector<T>& gpu, const std::vector<T>& cpu) {
  if (gpu.size() != cpu.size())
    return ::testing::AssertionFailure() << "sizes differ: gpu " << gpu.size() << ", cpu " << cpu.size();
  for (std::size_t k = 0; k < gpu.size(); ++k)
    if (gpu[k] != cpu[k]) {
      std::ostringstream msg;
      msg << "entry " << k << ": gpu " << +gpu[k] << ", cpu " << +cpu[k];
      return ::testing::AssertionFailure() << msg.str();
    }
  return ::testing::AssertionSuccess();
}

void expect_same_as_cpu(const TetMesh& mesh, unsigned colour_blocks, bool order_with_topology) {
  const Topology cpu = build_topology(mesh);
  const Colouring cpu_colouring = colour_nodes(cpu.neighbours, cpu.movable);
  const cuda::TopologySnapshot gpu = cuda::gpu_topology_snapshot(mesh, colour_blocks, order_with_topology);

  EXPECT_TRUE(same(gpu.neighbours.offsets, cpu.neighbours.offsets)) << "neighbour offsets";
  EXPECT_TRUE(same(gpu.neighbours.items, cpu.neighbours.items)) << "neighbours";
  EXPECT_TRUE(same(gpu.node_tets.offsets, cpu.node_tets.offsets)) << "incidence offsets";
  EXPECT_TRUE(same(gpu.node_tets.items, cpu.node_tets.items)) << "incident tets";
  EXPECT_TRUE(same(gpu.boundary, cpu.boundary)) << "boundary";
  EXPECT_TRUE(same(gpu.movable, cpu.movable)) << "movable";

  EXPECT_TRUE(same(gpu.colouring.colour, cpu_colouring.colour)) << "colours";
  EXPECT_EQ(gpu.colouring.num_colours, cpu_colouring.num_colours);
  EXPECT_EQ(gpu.colouring.rounds, cpu_colouring.rounds);
  EXPECT_TRUE(same(gpu.colouring.classes.offsets, cpu_colouring.classes.offsets)) << "class offsets";
  EXPECT_TRUE(same(gpu.colouring.classes.items, cpu_colouring.classes.items)) << "class nodes";
  EXPECT_TRUE(is_valid_colouring(cpu.neighbours, cpu.movable, gpu.colouring));
}

// Twice: with the colouring's priority order sorted by the colouring, and
// by the topology build on its side stream (as the pipeline's Coloured runs
// do).
void expect_same_as_cpu(const TetMesh& mesh, unsigned colour_blocks = 0) {
  for (bool order_with_topology : {false, true}) {
    SCOPED_TRACE(order_with_topology ? "priority order from the topology build" : "priority order by colour_device");
    expect_same_as_cpu(mesh, colour_blocks, order_with_topology);
  }
}

TEST_F(GpuTopology, RegularTet) { expect_same_as_cpu(testing::regular_tet()); }

TEST_F(GpuTopology, CubeWithCentre) { expect_same_as_cpu(testing::cube_with_centre()); }

TEST_F(GpuTopology, JitteredCubeGrid) { expect_same_as_cpu(testing::cube_grid(4, 0.2)); }

TEST_F(GpuTopology, RandomDelaunay) { expect_same_as_cpu(testing::random_delaunay(2000, 3)); }

TEST_F(GpuTopology, Model5k) { expect_same_as_cpu(generate_model("5k")); }

// One block of the colouring kernel: each thread group colours ~80 nodes of
// the 5k model in priority order, waiting on other groups' nodes, as groups
// do on meshes far larger than the GPU.
TEST_F(GpuTopology, Model5kWithOneColouringBlock) { expect_same_as_cpu(generate_model("5k"), 1); }

// File-pinned nodes leave the colouring; a node in no tet has an empty row
// and is neither boundary nor movable.
TEST_F(GpuTopology, PinnedAndUnreferencedNodes) {
  TetMesh m = testing::cube_grid(4, 0.2);
  m.fixed.assign(m.num_nodes(), 0);
  for (std::size_t i = 0; i < m.num_nodes(); i += 3) m.fixed[i] = 1;
  m.xyz.insert(m.xyz.end(), {9.0, 9.0, 9.0});
  m.fixed.push_back(0);
  expect_same_as_cpu(m);
}

// A tet with a repeated node: its self-loop edges are no neighbours and the
// node lists that tet once.
TEST_F(GpuTopology, RepeatedNodeInATet) {
  TetMesh m = testing::cube_grid(3, 0.2);
  const index_t a = m.tets[0], b = m.tets[1], c = m.tets[2];
  m.tets.insert(m.tets.end(), {a, b, a, c});
  expect_same_as_cpu(m);
}

// Tets listed twice (as Gmsh's MSH 2.2 writer lists a volume in two
// physical groups), one of them with its nodes in another order: the same
// boundary as without the repeats, and each copy in its nodes' rows.
TEST_F(GpuTopology, RepeatedTets) {
  TetMesh m = testing::cube_grid(3, 0.2);
  const std::size_t nt = m.num_tets();
  for (std::size_t t = 0; t < nt; t += 2) {
    const index_t* v = &m.tets[4 * t];
    m.tets.insert(m.tets.end(), {v[1], v[2], v[0], v[3]});
  }
  expect_same_as_cpu(m);
}

// Node indices above 2^22, as in the 10M-node lattice: 23 bits each, so
// edge keys of 46 bits and faces whose packed triple would need 69 (the
// face sort hashes them). The nodes below the shift are unreferenced.
TEST_F(GpuTopology, NodeIndicesAbove2To22) {
  const TetMesh grid = testing::cube_grid(3, 0.2);
  const index_t shift = (index_t{1} << 22) - 20;  // the grid straddles 2^22
  TetMesh m;
  m.xyz.assign(3 * static_cast<std::size_t>(shift), 0.0);
  m.xyz.insert(m.xyz.end(), grid.xyz.begin(), grid.xyz.end());
  for (index_t v : grid.tets) m.tets.push_back(v + shift);
  expect_same_as_cpu(m);
}

// Every pair of k nodes shares tets, so the nodes form a clique: k colours.
// Each pair i, j takes the three tets {i, j, a, b} over two of three pinned
// hub nodes, so every face has two tets with different fourth nodes: none is
// single, and the k nodes are all movable.
void expect_clique_coloured_as_on_cpu(index_t k) {
  const index_t hub[3] = {k, k + 1, k + 2};
  TetMesh m;
  for (index_t i = 0; i < k + 3; ++i) m.xyz.insert(m.xyz.end(), {double(i), double(i * i % 7), double(i % 5)});
  for (index_t i = 0; i < k; ++i)
    for (index_t j = i + 1; j < k; ++j)
      for (int skip = 0; skip < 3; ++skip) m.tets.insert(m.tets.end(), {i, j, hub[(skip + 1) % 3], hub[(skip + 2) % 3]});
  m.fixed.assign(static_cast<std::size_t>(k) + 3, 0);
  for (index_t h : hub) m.fixed[static_cast<std::size_t>(h)] = 1;
  expect_same_as_cpu(m);
  const Topology cpu = build_topology(m);
  EXPECT_EQ(std::count(cpu.movable.begin(), cpu.movable.end(), 1), k);
  EXPECT_EQ(colour_nodes(cpu.neighbours, cpu.movable).num_colours, k);
}

// 70 colours, past the 64 that one mask of used colours holds.
TEST_F(GpuTopology, CliqueNeedsMoreThan64Colours) { expect_clique_coloured_as_on_cpu(70); }

// 260 colours, past the 255 for which the classes are built before the
// colour count is read back (device_colouring.cu): they are built again.
TEST_F(GpuTopology, CliqueNeedsMoreThan255Colours) { expect_clique_coloured_as_on_cpu(260); }

}  // namespace
}  // namespace tetsmooth
