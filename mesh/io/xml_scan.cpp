#include "mesh/io/xml_scan.hpp"

#include <algorithm>
#include <cstdint>

#include "mesh/errors.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth {
namespace {

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }
bool is_name_char(char c) {
  return !is_space(c) && c != '=' && c != '>' && c != '/' && c != '<' && c != '"' && c != '\'';
}

void append_utf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

// "element 'name'", for messages.
std::string in_tag(const XmlTag& tag) { return "element " + quoted_token(tag.name); }

}  // namespace

const std::string* XmlTag::attribute(std::string_view key) const {
  for (const auto& [k, v] : attributes)
    if (k == key) return &v;
  return nullptr;
}

std::string XmlScanner::where(std::size_t offset) const {
  offset = std::min(offset, text_.size());
  const auto line = 1 + std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(offset), '\n');
  return source_ + ":" + std::to_string(line);
}

void XmlScanner::fail(std::size_t offset, const std::string& what) const { throw InputError(where(offset), what); }

std::size_t XmlScanner::skip_past(std::size_t from, std::string_view terminator, std::size_t start,
                                  const char* what) const {
  const std::size_t at = text_.find(terminator, from);
  if (at == std::string_view::npos) fail(start, std::string("unterminated ") + what);
  return at + terminator.size();
}

std::string XmlScanner::decode(std::string_view raw, std::size_t at) const {
  std::string out;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] != '&') {
      out += raw[i];
      continue;
    }
    const std::size_t semi = raw.find(';', i);
    if (semi == std::string_view::npos) fail(at, "unterminated character reference in an attribute value");
    const std::string_view ref = raw.substr(i + 1, semi - i - 1);
    if (ref == "amp")
      out += '&';
    else if (ref == "lt")
      out += '<';
    else if (ref == "gt")
      out += '>';
    else if (ref == "quot")
      out += '"';
    else if (ref == "apos")
      out += '\'';
    else if (ref.size() > 1 && ref[0] == '#') {
      const bool hex = ref[1] == 'x' || ref[1] == 'X';
      const std::string digits(ref.substr(hex ? 2 : 1));
      long long cp = -1;
      if (!digits.empty() &&
          digits.find_first_not_of(hex ? "0123456789abcdefABCDEF" : "0123456789") == std::string::npos &&
          digits.size() <= 8)
        cp = std::stoll(digits, nullptr, hex ? 16 : 10);
      if (cp <= 0 || cp > 0x10FFFF) fail(at, "bad character reference " + quoted_token("&" + std::string(ref) + ";"));
      append_utf8(out, static_cast<std::uint32_t>(cp));
    } else {
      fail(at, "unknown entity " + quoted_token("&" + std::string(ref) + ";"));
    }
    i = semi;
  }
  return out;
}

bool XmlScanner::next(XmlTag& tag) {
  for (;;) {
    const std::size_t lt = text_.find('<', pos_);
    if (lt == std::string_view::npos) {
      pos_ = text_.size();
      return false;
    }
    const std::string_view rest = text_.substr(lt);
    if (rest.substr(0, 4) == "<!--") {
      pos_ = skip_past(lt + 4, "-->", lt, "comment");
    } else if (rest.substr(0, 9) == "<![CDATA[") {
      pos_ = skip_past(lt + 9, "]]>", lt, "CDATA section");
    } else if (rest.substr(0, 2) == "<?") {
      pos_ = skip_past(lt + 2, "?>", lt, "processing instruction");
    } else if (rest.substr(0, 2) == "<!") {
      pos_ = skip_past(lt + 2, ">", lt, "declaration");
    } else {
      break;
    }
  }
  const std::size_t lt = text_.find('<', pos_);
  std::size_t i = lt + 1;
  tag = XmlTag{};
  tag.begin = lt;
  if (i < text_.size() && text_[i] == '/') {
    tag.kind = XmlTag::Kind::Close;
    ++i;
  }
  const std::size_t name_start = i;
  while (i < text_.size() && is_name_char(text_[i])) ++i;
  tag.name = std::string(text_.substr(name_start, i - name_start));
  if (tag.name.empty()) fail(lt, "expected a tag name after '<'");
  for (;;) {
    while (i < text_.size() && is_space(text_[i])) ++i;
    if (i >= text_.size()) fail(lt, "unterminated tag " + quoted_token("<" + tag.name));
    if (text_[i] == '>') {
      ++i;
      break;
    }
    if (text_[i] == '/' && tag.kind == XmlTag::Kind::Open && i + 1 < text_.size() && text_[i + 1] == '>') {
      tag.kind = XmlTag::Kind::Empty;
      i += 2;
      break;
    }
    if (tag.kind == XmlTag::Kind::Close) fail(i, "unexpected characters in the end tag " + quoted_token(tag.name));
    const std::size_t key_start = i;
    while (i < text_.size() && is_name_char(text_[i])) ++i;
    if (i == key_start) fail(i, "malformed attribute in " + in_tag(tag));
    std::string key(text_.substr(key_start, i - key_start));
    while (i < text_.size() && is_space(text_[i])) ++i;
    if (i >= text_.size() || text_[i] != '=')
      fail(i, "expected '=' after attribute " + quoted_token(key) + " in " + in_tag(tag));
    ++i;
    while (i < text_.size() && is_space(text_[i])) ++i;
    if (i >= text_.size() || (text_[i] != '"' && text_[i] != '\''))
      fail(i, "expected a quoted value for attribute " + quoted_token(key) + " in " + in_tag(tag));
    const char quote = text_[i];
    const std::size_t close = text_.find(quote, i + 1);
    if (close == std::string_view::npos) fail(i, "unterminated value of attribute " + quoted_token(key));
    tag.attributes.emplace_back(std::move(key), decode(text_.substr(i + 1, close - i - 1), i));
    i = close + 1;
  }
  tag.end = i;
  pos_ = i;
  return true;
}

std::string xml_escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace tetsmooth
