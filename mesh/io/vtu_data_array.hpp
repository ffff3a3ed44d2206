#pragma once
// Decoding the values of one VTU DataArray, whatever its form: ascii text,
// inline base64 ("binary"), or appended raw or base64 data, each binary
// block preceded by its byte count (UInt32 or UInt64 per header_type).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/io/xml_scan.hpp"

namespace tetsmooth {

// How a file frames its binary data, from the VTKFile and AppendedData tags.
struct VtuEncoding {
  bool big_endian = false;
  std::size_t header_bytes = 4;  // UInt32 unless header_type says UInt64
  bool has_appended = false;
  bool appended_base64 = false;
  std::size_t appended_begin = 0;  // offset of the byte after the '_'
};

struct VtuDataArray {
  XmlTag tag;
  std::size_t content_begin = 0, content_end = 0;  // the element's text, for inline data
};

class VtuArrayDecoder {
 public:
  VtuArrayDecoder(std::string_view text, const XmlScanner& xml, std::string source, VtuEncoding encoding)
      : text_(text), xml_(xml), source_(std::move(source)), enc_(encoding) {}

  // `tuples` tuples of `components` values each; throws InputError with the
  // line of the element or the byte offset of its data when the array has
  // another shape, a type that does not fit, or bad data. `what` names the
  // array in messages.
  std::vector<double> reals(const VtuDataArray& a, std::size_t tuples, int components, const char* what) const;
  std::vector<long long> integers(const VtuDataArray& a, std::size_t values, const char* what) const;

 private:
  template <class Out>
  std::vector<Out> decode(const VtuDataArray& a, std::size_t tuples, int components, const char* what) const;
  template <class Out>
  void parse_ascii(const VtuDataArray& a, std::size_t expected, const char* what, std::vector<Out>& out) const;
  std::string byte_where(std::size_t offset) const;

  std::string_view text_;
  const XmlScanner& xml_;
  std::string source_;
  VtuEncoding enc_;
};

}  // namespace tetsmooth
