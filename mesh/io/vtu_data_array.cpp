#include "mesh/io/vtu_data_array.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "mesh/errors.hpp"
#include "mesh/io/base64.hpp"
#include "mesh/io/little_endian.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth {
namespace {

enum class Scalar { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

struct ScalarInfo {
  const char* name;
  Scalar scalar;
  std::size_t size;
  bool is_float;
};
constexpr ScalarInfo kScalars[] = {
    {"Int8", Scalar::Int8, 1, false},      {"UInt8", Scalar::UInt8, 1, false},   {"Int16", Scalar::Int16, 2, false},
    {"UInt16", Scalar::UInt16, 2, false},  {"Int32", Scalar::Int32, 4, false},   {"UInt32", Scalar::UInt32, 4, false},
    {"Int64", Scalar::Int64, 8, false},    {"UInt64", Scalar::UInt64, 8, false}, {"Float32", Scalar::Float32, 4, true},
    {"Float64", Scalar::Float64, 8, true},
};

template <class T, class Out>
bool convert(const unsigned char* p, std::size_t n, bool big, std::vector<Out>& out) {
  for (std::size_t i = 0; i < n; ++i) {
    const T v = load_le<T>(p + i * sizeof(T), big);
    if constexpr (std::is_same_v<T, std::uint64_t> && std::is_integral_v<Out>) {
      if (v > static_cast<std::uint64_t>(std::numeric_limits<Out>::max())) return false;
    }
    out.push_back(static_cast<Out>(v));
  }
  return true;
}

template <class Out>
bool convert(Scalar s, const unsigned char* p, std::size_t n, bool big, std::vector<Out>& out) {
  switch (s) {
    case Scalar::Int8:
      return convert<std::int8_t>(p, n, big, out);
    case Scalar::UInt8:
      return convert<std::uint8_t>(p, n, big, out);
    case Scalar::Int16:
      return convert<std::int16_t>(p, n, big, out);
    case Scalar::UInt16:
      return convert<std::uint16_t>(p, n, big, out);
    case Scalar::Int32:
      return convert<std::int32_t>(p, n, big, out);
    case Scalar::UInt32:
      return convert<std::uint32_t>(p, n, big, out);
    case Scalar::Int64:
      return convert<std::int64_t>(p, n, big, out);
    case Scalar::UInt64:
      return convert<std::uint64_t>(p, n, big, out);
    case Scalar::Float32:
      return convert<float>(p, n, big, out);
    case Scalar::Float64:
      return convert<double>(p, n, big, out);
  }
  return false;
}

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

}  // namespace

std::string VtuArrayDecoder::byte_where(std::size_t offset) const {
  return source_ + ", byte " + std::to_string(offset);
}

template <class Out>
void VtuArrayDecoder::parse_ascii(const VtuDataArray& a, std::size_t expected, const char* what,
                                  std::vector<Out>& out) const {
  std::size_t i = a.content_begin;
  while (true) {
    while (i < a.content_end && is_space(text_[i])) ++i;
    if (i >= a.content_end) break;
    const std::size_t start = i;
    while (i < a.content_end && !is_space(text_[i])) ++i;
    const std::string_view token = text_.substr(start, i - start);
    if (out.size() == expected)
      xml_.fail(start, std::string(what) + " holds more than the expected " + std::to_string(expected) + " values");
    bool ok;
    if constexpr (std::is_integral_v<Out>) {
      long long v = 0;
      ok = parse_integer(token, v);
      out.push_back(v);
    } else {
      double v = 0;
      ok = parse_real(token, v);
      out.push_back(v);
    }
    if (!ok) xml_.fail(start, std::string(what) + ": bad value '" + std::string(token.substr(0, 40)) + "'");
  }
  if (out.size() != expected)
    xml_.fail(a.tag.begin, std::string(what) + " holds " + std::to_string(out.size()) + " values, expected " +
                               std::to_string(expected));
}

template <class Out>
std::vector<Out> VtuArrayDecoder::decode(const VtuDataArray& a, std::size_t tuples, int components,
                                         const char* what) const {
  const std::string at_tag = xml_.where(a.tag.begin);
  const auto fail = [&](const std::string& where, const std::string& message) {
    throw InputError(where, std::string(what) + ": " + message);
  };
  const std::string* type_name = a.tag.attribute("type");
  const ScalarInfo* info = nullptr;
  for (const ScalarInfo& s : kScalars)
    if (type_name && *type_name == s.name) info = &s;
  if (!info) fail(at_tag, "unsupported DataArray type '" + (type_name ? *type_name : std::string()) + "'");
  if (std::is_integral_v<Out> && info->is_float)
    fail(at_tag, std::string("needs an integer type, found ") + info->name);
  const std::string* comps = a.tag.attribute("NumberOfComponents");
  if (std::to_string(components) != (comps ? *comps : std::string("1")))
    fail(at_tag, "has " + (comps ? *comps : std::string("1")) + " components, expected " + std::to_string(components));
  // Every value takes at least one byte of the file, which also keeps the
  // byte counts below from overflowing for a lying NumberOfPoints.
  if (tuples > text_.size()) fail(at_tag, "expects " + std::to_string(tuples) + " tuples, more than the file can hold");
  const std::size_t expected = tuples * static_cast<std::size_t>(components);

  std::vector<Out> out;
  out.reserve(std::min(expected, text_.size()));
  const std::string* format = a.tag.attribute("format");
  if (format && *format == "ascii") {
    parse_ascii(a, expected, what, out);
    return out;
  }

  // The block (byte count, then data): decoded into `decoded` for base64,
  // read in place for raw appended data.
  std::vector<unsigned char> decoded;
  const unsigned char* block = nullptr;
  std::size_t block_size = 0;
  std::size_t header_at = 0;  // where the block begins, for messages
  std::size_t bad_at = 0;
  if (format && *format == "binary") {
    header_at = a.content_begin;
    if (!base64_decode(text_.substr(a.content_begin, a.content_end - a.content_begin), decoded, bad_at))
      fail(xml_.where(a.content_begin + bad_at), "invalid base64 data");
  } else if (format && *format == "appended") {
    if (!enc_.has_appended) fail(at_tag, "format=\"appended\" but the file has no AppendedData section");
    const std::string* off = a.tag.attribute("offset");
    long long offset = -1;
    if (!off || !parse_integer(*off, offset) || offset < 0) fail(at_tag, "missing or bad offset attribute");
    header_at = enc_.appended_begin + static_cast<std::size_t>(offset);
    if (header_at > text_.size())
      fail(byte_where(header_at),
           "truncated: the block at appended offset " + *off + " lies beyond the end of the file");
    if (enc_.appended_base64) {
      // The byte count and the data are encoded separately, each padded.
      const std::size_t hchars = base64_length(enc_.header_bytes);
      if (!base64_decode(text_.substr(header_at, hchars), decoded, bad_at) || decoded.size() < enc_.header_bytes)
        fail(byte_where(header_at), "invalid base64 block header");
      const std::uint64_t n = enc_.header_bytes == 8 ? load_le<std::uint64_t>(decoded.data(), enc_.big_endian)
                                                     : load_le<std::uint32_t>(decoded.data(), enc_.big_endian);
      if (n > text_.size()) fail(byte_where(header_at), "block size " + std::to_string(n) + " exceeds the file");
      if (!base64_decode(text_.substr(header_at + hchars, base64_length(n)), decoded, bad_at))
        fail(byte_where(header_at + hchars + bad_at), "invalid base64 data");
    } else {
      block = reinterpret_cast<const unsigned char*>(text_.data()) + header_at;
      block_size = text_.size() - header_at;
    }
  } else {
    fail(at_tag, "unknown format '" + (format ? *format : std::string()) + "'");
  }
  if (!block) {
    block = decoded.data();
    block_size = decoded.size();
  }
  if (block_size < enc_.header_bytes) fail(byte_where(header_at), "truncated block header");
  const std::uint64_t bytes = enc_.header_bytes == 8 ? load_le<std::uint64_t>(block, enc_.big_endian)
                                                     : load_le<std::uint32_t>(block, enc_.big_endian);
  if (bytes != expected * info->size)
    fail(byte_where(header_at), "block holds " + std::to_string(bytes) + " bytes, expected " +
                                    std::to_string(expected * info->size) + " for " + std::to_string(expected) + " " +
                                    info->name + " values");
  if (block_size - enc_.header_bytes < bytes)
    fail(byte_where(header_at), "truncated: the file ends inside the block of " + std::to_string(bytes) + " bytes");
  if (!convert(info->scalar, block + enc_.header_bytes, expected, enc_.big_endian, out))
    fail(byte_where(header_at), "value out of range");
  return out;
}

std::vector<double> VtuArrayDecoder::reals(const VtuDataArray& a, std::size_t tuples, int components,
                                           const char* what) const {
  return decode<double>(a, tuples, components, what);
}

std::vector<long long> VtuArrayDecoder::integers(const VtuDataArray& a, std::size_t values, const char* what) const {
  return decode<long long>(a, values, 1, what);
}

}  // namespace tetsmooth
