// libFuzzer target: the ANSYS archive (.cdb) reader and writer. What the
// reader accepts must read back the same from the file written back as
// read; the file with some nodes moved (their NBLOCK records rewritten) and
// a new file of the mesh must read back with the same tets and pins, and
// coordinates within the digits the records hold (14 in a new file). Reading
// back what the writer wrote must never fail.
#include <algorithm>
#include <cmath>

#include "fuzz_reader.hpp"
#include "mesh/io/ansys_fields.hpp"
#include "mesh/io/ansys_io.hpp"

namespace {

using namespace tetsmooth;

TetMesh read_back(const TetMesh& mesh, const char* what) {
  return fuzz::read_back(
      mesh, [](const TetMesh& m, std::ostream& out) { write_ansys(m, out); },
      [](std::istream& in, const char* source) { return read_ansys(in, source); }, what);
}

// The relative rounding of the coordinates a file's NBLOCKs write: 1e-13
// for 14 significant digits, more where a block's format holds fewer.
double rounding_of(const TetMesh& mesh) {
  int digits = 13;
  for (const auto& [key, body] : mesh.extras.raw_sections)
    if (key == "ansys:nblock")
      if (const auto f = ansys::parse_block_format(body.substr(0, body.find('\n'))); f)
        digits = std::min(digits, std::max(0, std::min(f->decimals, f->real_width - 5 - f->exponent_digits)));
  return std::pow(10.0, -digits);
}

void require_close(const TetMesh& again, const TetMesh& mesh, double rounding, const char* what) {
  bool close = again.xyz.size() == mesh.xyz.size();
  // The written digits, and a residue below the exponent's reach written
  // as 0.
  for (std::size_t k = 0; close && k < mesh.xyz.size(); ++k)
    close = std::fabs(again.xyz[k] - mesh.xyz[k]) <= rounding * std::fabs(mesh.xyz[k]) + 1e-99;
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
    try {
      require_close(read_back(moved, "file with moved nodes"), moved, rounding_of(mesh), "file with moved nodes");
    } catch (const OutputError&) {
      // A moved value past what the block's exponent holds (e21.13e1 and
      // 1e10, say): refused, with nothing written.
    }
    TetMesh fresh = mesh;
    fresh.extras.raw_sections.clear();
    require_close(read_back(fresh, "new file"), fresh, 1e-13, "new file");
  });
}
