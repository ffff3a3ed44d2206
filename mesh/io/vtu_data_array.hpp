#pragma once
// Decoding the values of one VTU DataArray, whatever its form: ascii text,
// inline base64 ("binary"), or appended raw or base64 data, each binary
// array framed by a byte count or, compressed, by a block table
// (vtu_blocks.hpp).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/io/vtk_cells.hpp"
#include "mesh/io/vtu_blocks.hpp"
#include "mesh/io/xml_scan.hpp"

namespace tetsmooth {

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

  // Where value `index` (from 0) of `a`, an array these functions read
  // without error, stands in the file: its line (ascii) or byte (raw
  // uncompressed appended data); else the byte where the array's data start,
  // with the entry named. Found again from the text, so that no place is kept
  // per value.
  VtkValuePlace place(const VtuDataArray& a, std::size_t index, const char* what) const;

 private:
  // An array's framed binary data (vtu_blocks.hpp) and the byte offset in
  // the file where it begins, for messages.
  struct Framed {
    const unsigned char* data;
    std::size_t size;
    std::size_t at;
  };

  template <class Out>
  std::vector<Out> decode(const VtuDataArray& a, std::size_t tuples, int components, const char* what) const;
  template <class Out>
  void parse_ascii(const VtuDataArray& a, std::size_t expected, const char* what, std::vector<Out>& out) const;
  Framed framed(const VtuDataArray& a, const char* what, std::vector<unsigned char>& storage) const;
  std::size_t appended_at(const VtuDataArray& a, const char* what) const;
  void appended_base64(std::size_t at, const char* what, std::vector<unsigned char>& storage) const;
  void base64_run(std::size_t at, std::size_t chars, const char* what, const char* part,
                  std::vector<unsigned char>& storage) const;
  std::size_t max_tuples() const;
  std::string byte_where(std::size_t offset) const;
  [[noreturn]] static void fail(const std::string& where, const char* what, const std::string& message);

  std::string_view text_;
  const XmlScanner& xml_;
  std::string source_;
  VtuEncoding enc_;
};

}  // namespace tetsmooth
