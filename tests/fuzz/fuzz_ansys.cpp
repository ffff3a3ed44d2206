// libFuzzer target: the ANSYS archive (.cdb) reader and writer. What the
// reader accepts must read back the same from the file written back as
// read; the file with some nodes moved (their NBLOCK records rewritten) and
// a new file of the mesh must read back with the same tets and pins, and
// coordinates within the 14 significant digits the records hold. Reading
// back what the writer wrote must never fail.
#include <cmath>

#include "fuzz_reader.hpp"
#include "mesh/io/ansys_io.hpp"

namespace {

using namespace tetsmooth;

TetMesh read_back(const TetMesh& mesh, const char* what) {
  return fuzz::read_back(
      mesh, [](const TetMesh& m, std::ostream& out) { write_ansys(m, out); },
      [](std::istream& in, const char* source) { return read_ansys(in, source); }, what);
}

void require_close(const TetMesh& again, const TetMesh& mesh, const char* what) {
  bool close = again.xyz.size() == mesh.xyz.size();
  // 14 significant digits, and a residue below 1e-99 written as 0 where the
  // format's exponent has two digits.
  for (std::size_t k = 0; close && k < mesh.xyz.size(); ++k)
    close = std::fabs(again.xyz[k] - mesh.xyz[k]) <= 1e-13 * std::fabs(mesh.xyz[k]) + 1e-99;
  if (!close || again.tets != mesh.tets || again.midsides != mesh.midsides || again.fixed != mesh.fixed) {
    std::fprintf(stderr, "the %s changed the mesh\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzz::run_reader(data, size, [](std::istream& in) {
    const TetMesh mesh = read_ansys(in, "fuzz.cdb");
    fuzz::require_same(read_back(mesh, "file written back"), mesh, "ANSYS");
    // Moved values stay where every format's exponent holds them.
    TetMesh moved = mesh;
    for (std::size_t k = 0; k < moved.xyz.size(); k += 4)
      if (std::fabs(moved.xyz[k]) < 1e90) moved.xyz[k] = moved.xyz[k] * (1 + 1.0 / 3) + 1.0 / 7;
    require_close(read_back(moved, "file with moved nodes"), moved, "file with moved nodes");
    TetMesh fresh = mesh;
    fresh.extras.raw_sections.clear();
    require_close(read_back(fresh, "new file"), fresh, "new file");
  });
}
