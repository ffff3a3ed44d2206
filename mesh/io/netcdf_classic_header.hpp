#pragma once
// The header of a classic netCDF file (CDF-1, CDF-2 and CDF-5: the
// formats of netCDF 3 and its 64-bit extensions), checked before the
// netCDF library reads it (not a public API).
//
// netCDF 4.9 trusts the header it is given: a corrupt one (a name that
// runs past the end, a count of billions, two dimensions of one name) can
// crash it or have it allocate without bound. So every list, name, type,
// dimension id and data range of the header is checked here against the
// format's specification and the file's length first, and a bad one is
// refused with its byte offset. Big-endian throughout; counts, lengths and
// ids are 4 bytes (8 in CDF-5), data offsets 4 bytes in CDF-1 and 8 in
// CDF-2 and CDF-5, names and values padded to 4 bytes.
#include <string>

namespace tetsmooth::netcdf {

// Throws InputError(source, "byte N: ...") unless `bytes` (a whole file
// beginning "CDF" with version 1, 2 or 5) has a well-formed header whose
// variables' data lie within the file.
void check_classic_header(const std::string& bytes, const std::string& source);

}  // namespace tetsmooth::netcdf
