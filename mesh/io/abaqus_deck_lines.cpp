#include "mesh/io/abaqus_deck_lines.hpp"

#include <sys/stat.h>

#include <cctype>
#include <stdexcept>

#include "mesh/errors.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::abaqus {
namespace {

// Nested *INCLUDE files deeper than this are taken for a file that
// includes itself.
constexpr std::size_t kMaxIncludeDepth = 16;

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool is_comment(std::string_view line) {
  const std::string_view t = trimmed(line);
  return t.empty() || t.substr(0, 2) == "**";
}

bool is_keyword(std::string_view line) { return !is_comment(line) && trimmed(line).front() == '*'; }

// Splits at commas outside double quotes.
std::vector<std::string_view> split_quoted(std::string_view line) {
  std::vector<std::string_view> parts;
  bool quoted = false;
  std::size_t start = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    if (line[i] == ',' && !quoted) {
      parts.push_back(line.substr(start, i - start));
      start = i + 1;
    }
  }
  if (quoted) throw std::invalid_argument("a quote that does not close");
  parts.push_back(line.substr(start));
  return parts;
}

std::string unquoted(std::string_view value) {
  value = trimmed(value);
  if (value.size() >= 2 && value.front() == '"' && value.back() == '"') value = value.substr(1, value.size() - 2);
  return std::string(value);
}

std::string directory_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

}  // namespace

std::string normalized(std::string_view name) {
  std::string out;
  for (char c : name)
    if (!std::isspace(static_cast<unsigned char>(c))) out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

const std::string* Keyword::param(std::string_view key) const {
  for (const auto& [param_name, value] : params)
    if (param_name == key) return &value;
  return nullptr;
}

Keyword parse_keyword(std::string_view line) {
  std::string joined(line);
  for (char& c : joined)
    if (c == '\n') c = ' ';
  const std::vector<std::string_view> parts = split_quoted(trimmed(joined));
  Keyword kw;
  kw.name = normalized(parts.front().substr(1));
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const std::string_view part = trimmed(parts[i]);
    if (part.empty()) continue;  // the comma before a continuation line
    const std::size_t eq = part.find('=');
    if (eq == std::string_view::npos)
      kw.params.emplace_back(normalized(part), "");
    else
      kw.params.emplace_back(normalized(part.substr(0, eq)), unquoted(part.substr(eq + 1)));
  }
  return kw;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trimmed(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (fields.size() > 1 && fields.back().empty()) fields.pop_back();
  return fields;
}

bool ends_with_comma(std::string_view line) {
  const std::string_view t = trimmed(line);
  return !t.empty() && t.back() == ',';
}

DeckLines::DeckLines(std::istream& in, std::string source) { stack_.push_back(Source{&in, nullptr, std::move(source)}); }

DeckLines::~DeckLines() = default;

bool DeckLines::raw_line(std::string& out) {
  while (!stack_.empty()) {
    Source& s = stack_.back();
    if (std::getline(*s.in, out)) {
      ++s.line;
      if (!out.empty() && out.back() == '\r') out.pop_back();
      where_ = s.path + ":" + std::to_string(s.line);
      return true;
    }
    if (s.in->bad()) throw InputError(s.path, "read error");
    stack_.pop_back();
  }
  return false;
}

void DeckLines::include(const Keyword& kw) {
  const std::string* file = kw.param("INPUT");
  if (file == nullptr || file->empty()) fail("*INCLUDE without INPUT=file");
  if (stack_.size() > kMaxIncludeDepth)
    fail("*INCLUDE nested more than " + std::to_string(kMaxIncludeDepth) + " deep (does a file include itself?)");
  const std::string path = file->front() == '/' ? *file : directory_of(stack_.back().path) + *file;
  // A device or a pipe (/dev/zero, say) might never end.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode))
    fail("*INCLUDE: " + path + " is not a regular file");
  try {
    auto in = std::make_unique<std::ifstream>(open_input(path));
    std::istream* raw = in.get();
    stack_.push_back(Source{raw, std::move(in), path});
  } catch (const InputError& e) {
    fail(std::string("*INCLUDE: ") + e.what());
  }
  included_.push_back(path);
}

bool DeckLines::next() {
  for (;;) {
    if (!raw_line(text_)) return false;
    if (is_comment(text_)) {
      kind_ = Kind::Comment;
      return true;
    }
    if (!is_keyword(text_)) {
      kind_ = Kind::Data;
      return true;
    }
    const std::string first = where_;
    std::string more;
    while (ends_with_comma(text_)) {
      if (!raw_line(more)) break;
      text_ += '\n';
      text_ += more;
    }
    where_ = first;
    try {
      keyword_ = parse_keyword(text_);
    } catch (const std::invalid_argument& e) {
      fail(std::string("keyword line: ") + e.what());
    }
    if (keyword_.name == "INCLUDE") {
      include(keyword_);
      continue;
    }
    kind_ = Kind::Keyword;
    return true;
  }
}

std::string DeckLines::where() const { return where_; }

void DeckLines::fail(const std::string& what) const { throw InputError(where_, what); }

}  // namespace tetsmooth::abaqus
