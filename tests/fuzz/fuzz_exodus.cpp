// libFuzzer target: the Exodus II reader and writer. The first byte picks
// what the rest is:
//  * even: the description of an Exodus file (exodus_spec.hpp), which is
//    netCDF-correct: nodes, blocks of any type with node numbers in and out
//    of range, node and side sets, id maps, names, the older coord variable,
//    floats. This fuzzes what tetsmooth makes of a file.
//  * odd: a classic netCDF file's bytes as they are, which the header check
//    (netcdf_classic_header.hpp) must make safe for netCDF to read. (HDF5's
//    parsing of netCDF-4 files is HDF5's own.)
// What the reader accepts must read back the same from the file written
// back with moved coordinates, and from a new file of the mesh: the same
// coordinates, tets, pins and regions.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>

#include "../support/exodus_spec.hpp"
#include "../support/same_partition.hpp"
#include "fuzz_reader.hpp"
#include "mesh/io/exodus_io.hpp"

namespace {

using namespace tetsmooth;

struct TypeChoice {
  const char* name;
  int nodes;
};
// Types and node counts, tets most often; some tetsmooth does not carry,
// and some whose count does not fit the name.
constexpr TypeChoice kTypes[] = {{"TETRA", 4},  {"tetra4", 4}, {"TET4", 4},   {"TETRA10", 10}, {"TETRA", 10},
                                 {"TETRA", 4},  {"HEX8", 8},   {"WEDGE", 6},  {"PYRAMID", 5},  {"TRISHELL3", 3},
                                 {"SHELL4", 4}, {"BAR2", 2},   {"SPHERE", 1}, {"HEX20", 20},   {"TETRA", 5},
                                 {"NSIDED", 3}, {"TR", 3}};

testing::ExodusSpec spec_of(FuzzedDataProvider& in) {
  testing::ExodusSpec s;
  const int nodes = in.ConsumeIntegralInRange(1, 24);
  for (int k = 0; k < 3 * nodes; ++k)
    s.xyz.push_back(in.ConsumeIntegralInRange(-4, 4) / 2.0 + in.ConsumeIntegralInRange(0, 3) / 7.0);
  const auto node_number = [&] { return in.ConsumeIntegralInRange(-1, nodes + 1); };
  int elements = 0;
  for (int b = in.ConsumeIntegralInRange(1, 4); b > 0; --b) {
    const TypeChoice& type = kTypes[in.ConsumeIntegralInRange<std::size_t>(0, std::size(kTypes) - 1)];
    testing::ExodusBlock block{type.name, type.nodes, {}, in.ConsumeIntegral<int>(), in.ConsumeRandomLengthString(40)};
    const int count = in.ConsumeIntegralInRange(0, 8);
    for (int k = 0; k < count * type.nodes; ++k) block.connect.push_back(node_number());
    elements += count;
    s.blocks.push_back(block);
  }
  for (int k = in.ConsumeIntegralInRange(0, 2); k > 0; --k) {
    std::vector<int> set;
    for (int m = in.ConsumeIntegralInRange(0, 4); m > 0; --m) set.push_back(node_number());
    s.node_sets.push_back(set);
  }
  for (int k = in.ConsumeIntegralInRange(0, 2); k > 0; --k) {
    testing::ExodusSideSet set;
    for (int m = in.ConsumeIntegralInRange(0, 4); m > 0; --m) {
      set.elements.push_back(in.ConsumeIntegralInRange(0, elements + 1));
      set.sides.push_back(in.ConsumeIntegralInRange(0, 5));
    }
    s.side_sets.push_back(set);
  }
  if (in.ConsumeBool())
    for (int k = 0; k < nodes; ++k) s.node_map.push_back(in.ConsumeIntegralInRange(-2, 3 * nodes));
  if (in.ConsumeBool() && elements > 0)
    for (int k = 0; k < elements; ++k) s.element_map.push_back(in.ConsumeIntegralInRange(-2, 3 * elements));
  s.coord = in.ConsumeBool();
  s.floats = in.ConsumeBool();
  return s;
}

TetMesh read_back(const TetMesh& mesh, const char* what) {
  try {
    return read_exodus(write_exodus(mesh), "again.exo");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "the %s does not read back: %s\n", what, e.what());
    std::abort();
  }
}

// Tags as regions: no tags are one region of all `count` elements.
std::vector<int> regions(const std::vector<int>& tags, std::size_t count) {
  return tags.empty() ? std::vector<int>(count, 0) : tags;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::string file;
  if (data[0] % 2 == 1) {
    file.assign(reinterpret_cast<const char*>(data) + 1, size - 1);
    if (file.compare(0, 3, "CDF") != 0) return 0;  // HDF5 and the rest are not this target's
  } else {
    FuzzedDataProvider in(data + 1, size - 1);
    file = testing::build_exodus(spec_of(in));
  }
  TetMesh mesh;
  try {
    mesh = read_exodus(file, "fuzz.exo");
  } catch (const InputError&) {
    return 0;  // the expected answer to a bad file
  }
  // Written back with moved coordinates (floats round them: compare what
  // the file holds).
  TetMesh moved = mesh;
  for (std::size_t k = 0; k < moved.xyz.size(); k += 4) moved.xyz[k] = moved.xyz[k] * (1 + 1.0 / 3) + 1.0 / 8;
  const TetMesh again = read_back(moved, "file written back");
  for (std::size_t k = 0; k < moved.xyz.size(); ++k) {
    const double kept = moved.extras.read_notes.empty() ? moved.xyz[k] : again.xyz[k];
    if (again.xyz[k] != kept && again.xyz[k] != static_cast<double>(static_cast<float>(moved.xyz[k]))) {
      std::fprintf(stderr, "the file written back changed coordinate %zu\n", k);
      std::abort();
    }
  }
  if (again.tets != mesh.tets || again.fixed != mesh.fixed || again.extras.tet_tags != mesh.extras.tet_tags) {
    std::fprintf(stderr, "the file written back changed the tets, pins or regions\n");
    std::abort();
  }
  // A new file: the tets come block by block, so compare them as sets per region.
  TetMesh fresh = mesh;
  fresh.extras.raw_sections.erase(std::remove_if(fresh.extras.raw_sections.begin(), fresh.extras.raw_sections.end(),
                                                 [](const auto& s) { return s.first.rfind("exodus:", 0) == 0; }),
                                  fresh.extras.raw_sections.end());
  const TetMesh made = read_back(fresh, "new file");
  bool same = made.xyz == fresh.xyz && made.fixed == fresh.fixed && made.num_tets() == fresh.num_tets() &&
              made.midsides.size() == fresh.midsides.size() && made.extras.blocks.size() <= fresh.extras.blocks.size();
  if (same) {
    // Each region's tets, as lists of nodes, sorted.
    const auto tets_by_region = [](const TetMesh& m) {
      const std::vector<int> tags = regions(m.extras.tet_tags, m.num_tets());
      std::vector<std::pair<int, std::vector<index_t>>> all;
      for (std::size_t t = 0; t < m.num_tets(); ++t) all.push_back({tags[t], {&m.tets[4 * t], &m.tets[4 * t + 4]}});
      return all;
    };
    auto x = tets_by_region(fresh), y = tets_by_region(made);
    // The same partition of the same tets: sort both by tets, then compare tags as partitions.
    std::sort(x.begin(), x.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    std::sort(y.begin(), y.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    std::vector<int> tx, ty;
    for (std::size_t k = 0; k < x.size() && same; ++k) {
      same = x[k].second == y[k].second;
      tx.push_back(x[k].first);
      ty.push_back(y[k].first);
    }
    same = same && testing::same_partition(tx, ty);
  }
  if (!same) {
    std::fprintf(stderr, "a new Exodus file changed the mesh\n");
    std::abort();
  }
  return 0;
}
