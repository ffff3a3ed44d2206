#include "mesh/io/vtk_scalars.hpp"

#include <cctype>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "mesh/io/little_endian.hpp"

namespace tetsmooth {
namespace {

constexpr VtkScalarInfo kScalars[] = {
    {"Int8", VtkScalar::Int8, 1, false},     {"UInt8", VtkScalar::UInt8, 1, false},
    {"Int16", VtkScalar::Int16, 2, false},   {"UInt16", VtkScalar::UInt16, 2, false},
    {"Int32", VtkScalar::Int32, 4, false},   {"UInt32", VtkScalar::UInt32, 4, false},
    {"Int64", VtkScalar::Int64, 8, false},   {"UInt64", VtkScalar::UInt64, 8, false},
    {"Float32", VtkScalar::Float32, 4, true}, {"Float64", VtkScalar::Float64, 8, true},
};

const VtkScalarInfo* info_of(VtkScalar s) {
  for (const VtkScalarInfo& info : kScalars)
    if (info.scalar == s) return &info;
  return nullptr;
}

struct LegacyName {
  const char* name;  // lower case
  VtkScalar scalar;
};
constexpr LegacyName kLegacyNames[] = {
    {"unsigned_char", VtkScalar::UInt8},   {"char", VtkScalar::Int8},
    {"signed_char", VtkScalar::Int8},      {"unsigned_short", VtkScalar::UInt16},
    {"short", VtkScalar::Int16},           {"unsigned_int", VtkScalar::UInt32},
    {"int", VtkScalar::Int32},             {"unsigned_long", VtkScalar::UInt64},
    {"long", VtkScalar::Int64},            {"float", VtkScalar::Float32},
    {"double", VtkScalar::Float64},        {"vtktypeint8", VtkScalar::Int8},
    {"vtktypeuint8", VtkScalar::UInt8},    {"vtktypeint16", VtkScalar::Int16},
    {"vtktypeuint16", VtkScalar::UInt16},  {"vtktypeint32", VtkScalar::Int32},
    {"vtktypeuint32", VtkScalar::UInt32},  {"vtktypeint64", VtkScalar::Int64},
    {"vtktypeuint64", VtkScalar::UInt64},  {"vtktypefloat32", VtkScalar::Float32},
    {"vtktypefloat64", VtkScalar::Float64}, {"vtkidtype", VtkScalar::Int32},
};

bool equal_lower(std::string_view text, std::string_view lower) {
  if (text.size() != lower.size()) return false;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) != lower[i]) return false;
  return true;
}

template <class T, class Out>
bool decode(const unsigned char* p, std::size_t n, bool big, std::vector<Out>& out) {
  for (std::size_t i = 0; i < n; ++i) {
    const T v = load_le<T>(p + i * sizeof(T), big);
    if constexpr (std::is_same_v<T, std::uint64_t> && std::is_integral_v<Out>) {
      if (v > static_cast<std::uint64_t>(std::numeric_limits<Out>::max())) return false;
    }
    out.push_back(static_cast<Out>(v));
  }
  return true;
}

}  // namespace

const VtkScalarInfo* vtu_scalar(std::string_view name) {
  for (const VtkScalarInfo& info : kScalars)
    if (name == info.name) return &info;
  return nullptr;
}

const VtkScalarInfo* legacy_vtk_scalar(std::string_view name) {
  for (const LegacyName& legacy : kLegacyNames)
    if (equal_lower(name, legacy.name)) return info_of(legacy.scalar);
  return nullptr;
}

template <class Out>
bool decode_vtk_scalars(VtkScalar s, const unsigned char* p, std::size_t n, bool big_endian, std::vector<Out>& out) {
  switch (s) {
    case VtkScalar::Int8:
      return decode<std::int8_t>(p, n, big_endian, out);
    case VtkScalar::UInt8:
      return decode<std::uint8_t>(p, n, big_endian, out);
    case VtkScalar::Int16:
      return decode<std::int16_t>(p, n, big_endian, out);
    case VtkScalar::UInt16:
      return decode<std::uint16_t>(p, n, big_endian, out);
    case VtkScalar::Int32:
      return decode<std::int32_t>(p, n, big_endian, out);
    case VtkScalar::UInt32:
      return decode<std::uint32_t>(p, n, big_endian, out);
    case VtkScalar::Int64:
      return decode<std::int64_t>(p, n, big_endian, out);
    case VtkScalar::UInt64:
      return decode<std::uint64_t>(p, n, big_endian, out);
    case VtkScalar::Float32:
      return decode<float>(p, n, big_endian, out);
    case VtkScalar::Float64:
      return decode<double>(p, n, big_endian, out);
  }
  return false;
}

template bool decode_vtk_scalars<double>(VtkScalar, const unsigned char*, std::size_t, bool, std::vector<double>&);
template bool decode_vtk_scalars<long long>(VtkScalar, const unsigned char*, std::size_t, bool,
                                            std::vector<long long>&);

}  // namespace tetsmooth
