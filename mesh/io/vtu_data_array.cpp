#include "mesh/io/vtu_data_array.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "mesh/errors.hpp"
#include "mesh/io/base64.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/io/vtk_scalars.hpp"

namespace tetsmooth {
namespace {

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

// The next whitespace-separated token of text[i, end), i moved past it; empty
// at the end. One tokenizer for reading an ascii array and for finding a
// value of it again.
std::string_view next_ascii_token(std::string_view text, std::size_t& i, std::size_t end) {
  while (i < end && is_space(text[i])) ++i;
  const std::size_t start = i;
  while (i < end && !is_space(text[i])) ++i;
  return text.substr(start, i - start);
}

}  // namespace

std::string VtuArrayDecoder::byte_where(std::size_t offset) const {
  return source_ + ", byte " + std::to_string(offset);
}

void VtuArrayDecoder::fail(const std::string& where, const char* what, const std::string& message) {
  throw InputError(where, std::string(what) + ": " + message);
}

std::size_t VtuArrayDecoder::max_tuples() const {
  // Every value takes at least one byte of the file, or 1/kVtuMaxExpansion
  // of one when compressed; the bound also keeps the byte counts of decode()
  // from overflowing for a lying NumberOfPoints.
  if (enc_.compressor == VtuCompressor::None) return text_.size();
  constexpr std::size_t kMostBytes = std::numeric_limits<std::size_t>::max() / 64 / kVtuMaxExpansion;
  return std::min(text_.size(), kMostBytes) * kVtuMaxExpansion;
}

template <class Out>
void VtuArrayDecoder::parse_ascii(const VtuDataArray& a, std::size_t expected, const char* what,
                                  std::vector<Out>& out) const {
  std::size_t i = a.content_begin;
  while (true) {
    const std::string_view token = next_ascii_token(text_, i, a.content_end);
    if (token.empty()) break;
    const std::size_t start = i - token.size();
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
    if (!ok) xml_.fail(start, std::string(what) + ": bad value " + quoted_token(token));
  }
  if (out.size() != expected)
    xml_.fail(a.tag.begin, std::string(what) + " holds " + std::to_string(out.size()) + " values, expected " +
                               std::to_string(expected));
}

template <class Out>
std::vector<Out> VtuArrayDecoder::decode(const VtuDataArray& a, std::size_t tuples, int components,
                                         const char* what) const {
  const std::string at_tag = xml_.where(a.tag.begin);
  const std::string* type_name = a.tag.attribute("type");
  const VtkScalarInfo* info = type_name ? vtu_scalar(*type_name) : nullptr;
  if (!info) fail(at_tag, what, "unsupported DataArray type " + quoted_token(type_name ? *type_name : std::string()));
  if (std::is_integral_v<Out> && info->is_float)
    fail(at_tag, what, std::string("needs an integer type, found ") + info->name);
  const std::string* comps = a.tag.attribute("NumberOfComponents");
  if (std::to_string(components) != (comps ? *comps : std::string("1")))
    fail(at_tag, what,
         "has " + (comps ? quoted_token(*comps) : std::string("1")) + " components, expected " +
             std::to_string(components));
  if (tuples > max_tuples())
    fail(at_tag, what, "expects " + std::to_string(tuples) + " tuples, more than the file can hold");
  const std::size_t expected = tuples * static_cast<std::size_t>(components);

  std::vector<Out> out;
  out.reserve(std::min(expected, text_.size()));
  const std::string* format = a.tag.attribute("format");
  if (format && *format == "ascii") {
    parse_ascii(a, expected, what, out);
    return out;
  }
  std::vector<unsigned char> storage, inflated;
  const Framed f = framed(a, what, storage);
  const std::string where = byte_where(f.at);
  const VtuBlocks blocks(enc_, where, what);
  const unsigned char* values = blocks.values(f.data, f.size, expected * info->size,
                                              std::to_string(expected) + " " + info->name + " values", inflated);
  if (!decode_vtk_scalars(info->scalar, values, expected, enc_.big_endian, out))
    fail(where, what, "value out of range");
  return out;
}

VtuArrayDecoder::Framed VtuArrayDecoder::framed(const VtuDataArray& a, const char* what,
                                                std::vector<unsigned char>& storage) const {
  const std::string* format = a.tag.attribute("format");
  if (format && *format == "binary") {
    // All of the element's text at once: base64_decode takes padding inside
    // the text, so a header and data encoded separately (as VTK and meshio
    // do) decode as one byte sequence, as does one run holding both.
    std::size_t bad_at = 0;
    if (!base64_decode(text_.substr(a.content_begin, a.content_end - a.content_begin), storage, bad_at))
      fail(xml_.where(a.content_begin + bad_at), what, "invalid base64 data");
    return {storage.data(), storage.size(), a.content_begin};
  }
  if (format && *format == "appended") {
    const std::size_t at = appended_at(a, what);
    if (enc_.appended_base64) {
      appended_base64(at, what, storage);
      return {storage.data(), storage.size(), at};
    }
    // Raw: the array's data run from its offset to at most the end of the file.
    return {reinterpret_cast<const unsigned char*>(text_.data()) + at, text_.size() - at, at};
  }
  fail(xml_.where(a.tag.begin), what, "unknown format " + quoted_token(format ? *format : std::string()));
}

std::size_t VtuArrayDecoder::appended_at(const VtuDataArray& a, const char* what) const {
  const std::string at_tag = xml_.where(a.tag.begin);
  if (!enc_.has_appended) fail(at_tag, what, "format=\"appended\" but the file has no AppendedData section");
  const std::string* off = a.tag.attribute("offset");
  long long offset = -1;
  if (!off || !parse_integer(*off, offset) || offset < 0) fail(at_tag, what, "missing or bad offset attribute");
  const std::size_t at = enc_.appended_begin + static_cast<std::size_t>(offset);
  if (at > text_.size())
    fail(byte_where(at), what,
         "truncated: the block at appended offset " + std::to_string(offset) + " lies beyond the end of the file");
  return at;
}

// Appended base64 data: the header and the data are encoded separately,
// each padded, so the data begin where the header's characters end. An
// uncompressed header is one item; a compressed one is as long as its
// first item, the block count, says.
void VtuArrayDecoder::appended_base64(std::size_t at, const char* what, std::vector<unsigned char>& storage) const {
  const VtuBlocks blocks(enc_, byte_where(at), what);
  // Valid base64 that decodes to fewer bytes than the header needs: padding
  // inside it, or the end of the file.
  const auto check_header = [&](std::size_t due) {
    if (storage.size() < due)
      fail(byte_where(at), what,
           "truncated block header: " + std::to_string(storage.size()) + " of its " + std::to_string(due) + " bytes");
  };
  base64_run(at, base64_length(enc_.header_bytes), what, "block header", storage);
  check_header(enc_.header_bytes);
  const std::size_t header = blocks.header_size(storage.data(), text_.size());
  const std::size_t header_chars = base64_length(header);
  storage.clear();
  base64_run(at, header_chars, what, "block header", storage);
  check_header(header);
  const std::uint64_t data = blocks.data_size(storage.data(), text_.size());
  base64_run(at + header_chars, base64_length(data), what, "data", storage);
}

// Decodes the `chars` characters at `at`, or what of them the file holds,
// onto `storage`.
void VtuArrayDecoder::base64_run(std::size_t at, std::size_t chars, const char* what, const char* part,
                                 std::vector<unsigned char>& storage) const {
  const std::string_view run = at < text_.size() ? text_.substr(at, chars) : std::string_view();
  std::size_t bad_at = 0;
  if (!base64_decode(run, storage, bad_at)) fail(byte_where(at + bad_at), what, std::string("invalid base64 ") + part);
}

VtkValuePlace VtuArrayDecoder::place(const VtuDataArray& a, std::size_t index, const char* what) const {
  const std::string* format = a.tag.attribute("format");
  if (format && *format == "ascii") {
    std::size_t i = a.content_begin;
    for (std::size_t k = 0;; ++k) {
      const std::string_view token = next_ascii_token(text_, i, a.content_end);
      if (token.empty()) break;
      if (k == index) return {xml_.where(i - token.size()), ""};
    }
    return {xml_.where(a.tag.begin), "value " + std::to_string(index) + " of the " + what + " array"};
  }
  const std::string* type_name = a.tag.attribute("type");
  const VtkScalarInfo* info = type_name ? vtu_scalar(*type_name) : nullptr;
  const bool appended = format && *format == "appended";
  // Raw uncompressed appended data hold the value itself at a known byte;
  // base64 and compressed data only the start of the array's data.
  if (appended && !enc_.appended_base64 && enc_.compressor == VtuCompressor::None && info)
    return {byte_where(appended_at(a, what) + enc_.header_bytes + index * info->size), ""};
  std::size_t at = a.content_begin;
  if (appended) {
    at = appended_at(a, what);
  } else {
    while (at < a.content_end && is_space(text_[at])) ++at;
  }
  return {byte_where(at), "value " + std::to_string(index) + ", counted from 0, of the " + what + " array, whose " +
                              (enc_.compressor == VtuCompressor::None ? "encoded" : "compressed") +
                              " data start at this byte"};
}

std::vector<double> VtuArrayDecoder::reals(const VtuDataArray& a, std::size_t tuples, int components,
                                           const char* what) const {
  return decode<double>(a, tuples, components, what);
}

std::vector<long long> VtuArrayDecoder::integers(const VtuDataArray& a, std::size_t values, const char* what) const {
  return decode<long long>(a, values, 1, what);
}

}  // namespace tetsmooth
