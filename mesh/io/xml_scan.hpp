#pragma once
// A small non-validating XML tag scanner, enough for VTK XML files: it yields
// start, end and empty-element tags with their attributes, skips text,
// comments, processing instructions, DOCTYPE and CDATA, and decodes the
// predefined and numeric character references in attribute values. It is
// not a general XML parser (no namespaces, no DTD, no well-formedness
// checks beyond tag syntax); the VTU reader checks nesting itself.
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tetsmooth {

struct XmlTag {
  enum class Kind { Open, Close, Empty };
  Kind kind = Kind::Open;
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::size_t begin = 0;  // offset of '<'
  std::size_t end = 0;    // offset just past '>'

  const std::string* attribute(std::string_view key) const;
};

class XmlScanner {
 public:
  XmlScanner(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

  // Scans to the next tag; false at the end of the text.
  bool next(XmlTag& tag);

  // "source:line" for an offset into the text.
  std::string where(std::size_t offset) const;
  [[noreturn]] void fail(std::size_t offset, const std::string& what) const;

 private:
  std::size_t skip_past(std::size_t from, std::string_view terminator, std::size_t start, const char* what) const;
  std::string decode(std::string_view raw, std::size_t at) const;

  std::string_view text_;
  std::string source_;
  std::size_t pos_ = 0;
};

// Escapes &, <, >, " and ' for an attribute value.
std::string xml_escape(std::string_view s);

}  // namespace tetsmooth
