// The Exodus II entry points of a build without netCDF (exodus_io.hpp):
// each says so, and how to get a build that has it.
#include "mesh/errors.hpp"
#include "mesh/io/exodus_io.hpp"

namespace tetsmooth {
namespace {

[[noreturn]] void unavailable() {
  throw UsageError(
      "this tetsmooth was built without netCDF, which Exodus II files need: install it (Debian: "
      "libnetcdf-dev) and build again");
}

}  // namespace

bool exodus_available() { return false; }
TetMesh read_exodus(std::string, const std::string&) { unavailable(); }
TetMesh read_exodus_file(const std::string&) { unavailable(); }
std::string write_exodus(const TetMesh&) { unavailable(); }
void write_exodus_file(const TetMesh&, const std::string&) { unavailable(); }
void check_exodus_writable(const TetMesh&) { unavailable(); }
std::string exodus_numbers_lost(const TetMesh&) { return ""; }

}  // namespace tetsmooth
