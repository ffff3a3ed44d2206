#pragma once
// VTK's scalar types as the two VTK formats name them (VTU's "Float64",
// legacy VTK's "double" or "vtktypefloat64"), and their values decoded from
// raw bytes of either byte order. One table and one decoder, so that the VTU
// reader and the legacy reader's BINARY blocks take the same types the same
// way.
#include <cstddef>
#include <string_view>
#include <vector>

namespace tetsmooth {

enum class VtkScalar { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

struct VtkScalarInfo {
  const char* name;  // VTU's name
  VtkScalar scalar;
  std::size_t size;  // bytes a value
  bool is_float;
};

// The type of a VTU DataArray's type attribute ("Int8" ... "Float64",
// case-sensitive as VTK writes them), or nullptr.
const VtkScalarInfo* vtu_scalar(std::string_view name);

// The type of a legacy VTK data type name, in any letter case: unsigned_char,
// char, signed_char, unsigned_short, short, unsigned_int, int, unsigned_long,
// long, float, double, the vtktype* names of version 5 files (vtktypeint8 ...
// vtktypeuint64, vtktypefloat32, vtktypefloat64) and vtkIdType. long and
// unsigned_long are 8 bytes, as VTK writes them on 64-bit Linux and macOS;
// vtkIdType 4, since VTK's legacy writer writes ids as int whatever its id
// size (vtkOriginalPointIds in ParaView's output). nullptr for another name
// ("bit", "string", ...).
const VtkScalarInfo* legacy_vtk_scalar(std::string_view name);

// Appends the n values of type s stored at p (most significant byte first
// when big_endian) to out, as double or long long. False when a value does
// not fit long long (an unsigned 64-bit value past its range); the values
// before it are appended.
template <class Out>
bool decode_vtk_scalars(VtkScalar s, const unsigned char* p, std::size_t n, bool big_endian, std::vector<Out>& out);

}  // namespace tetsmooth
