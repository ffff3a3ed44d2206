#include "mesh/io/abaqus_deck_lines.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "mesh/errors.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::abaqus {
namespace {

// The keywords the reader interprets (or refuses), each with the parameters
// it reads, in full and normalized: the names an abbreviation may stand for.
struct Known {
  const char* keyword;
  std::vector<const char*> params;
};
const std::vector<Known>& known_keywords() {
  static const std::vector<Known> known = {
      {"HEADING", {}},
      {"NODE", {"NSET", "SYSTEM", "INPUT"}},
      {"ELEMENT", {"TYPE", "ELSET", "INPUT"}},
      {"NSET", {"NSET", "ELSET", "GENERATE", "INSTANCE", "INPUT"}},
      {"ELSET", {"ELSET", "GENERATE", "INSTANCE", "INPUT"}},
      {"SOLIDSECTION", {"ELSET", "MATERIAL"}},
      {"BOUNDARY", {"INPUT"}},
      {"CLOAD", {"INPUT"}},
      {"CFLUX", {"INPUT"}},
      {"CFLOW", {"INPUT"}},
      {"EQUATION", {"INPUT"}},
      {"MPC", {"INPUT"}},
      {"INCLUDE", {"INPUT"}},
      {"PART", {"NAME"}},
      {"ENDPART", {}},
      {"ASSEMBLY", {"NAME"}},
      {"ENDASSEMBLY", {}},
      {"INSTANCE", {"NAME", "PART", "INSTANCE"}},
      {"ENDINSTANCE", {}},
      {"NGEN", {}},
      {"NFILL", {}},
      {"NCOPY", {}},
      {"NMAP", {}},
      {"SYSTEM", {}},
      {"ELGEN", {}},
      {"ELCOPY", {}},
  };
  return known;
}

// `name` in full: itself when it is one of `names` or a prefix of none,
// the one it begins if it begins one. Throws std::invalid_argument when it
// begins several: Abaqus would refuse it, and taking one could misread the
// deck.
template <class Names, class NameOf>
std::string in_full(const std::string& name, const Names& names, NameOf name_of, const char* what) {
  std::vector<std::string_view> begun;
  for (const auto& n : names) {
    const std::string_view full = name_of(n);
    if (full == name) return name;
    if (!name.empty() && full.substr(0, name.size()) == name) begun.push_back(full);
  }
  if (begun.size() == 1) return std::string(begun.front());
  if (begun.empty()) return name;
  std::string list;
  for (std::size_t i = 0; i < begun.size(); ++i)
    list += std::string(i == 0 ? "" : i + 1 == begun.size() ? " or " : ", ") + std::string(begun[i]);
  throw std::invalid_argument(std::string(what) + " " + name + " could be short for " + list + ": write more of it");
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

}  // namespace

std::string unquoted(std::string_view value) {
  value = trimmed(value);
  if (value.size() >= 2 && value.front() == '"' && value.back() == '"') value = value.substr(1, value.size() - 2);
  return std::string(value);
}

std::string normalized(std::string_view name) {
  std::string out = upper_case(name);
  out.erase(std::remove_if(out.begin(), out.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); }),
            out.end());
  return out;
}

std::string set_name(std::string_view name) {
  name = trimmed(name);
  if (name.size() < 2 || name.front() != '"' || name.back() != '"') return normalized(name);
  return upper_case(name.substr(1, name.size() - 2));
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
  const auto& known = known_keywords();
  Keyword kw;
  kw.name = in_full(normalized(parts.front().substr(1)), known, [](const Known& k) { return std::string_view(k.keyword); },
                    "the keyword");
  const auto it = std::find_if(known.begin(), known.end(), [&](const Known& k) { return kw.name == k.keyword; });
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const std::string_view part = trimmed(parts[i]);
    if (part.empty()) continue;  // the comma before a continuation line
    const std::size_t eq = part.find('=');
    std::string name = normalized(part.substr(0, eq));
    // A data line joined to a keyword line that ended in a comma.
    if (name.empty() || !std::isalpha(static_cast<unsigned char>(name.front())))
      throw std::invalid_argument("'" + std::string(part.substr(0, 40)) +
                                  "' is no parameter (does a comma at the end of the keyword line join a data line "
                                  "to it?)");
    if (it != known.end()) name = in_full(name, it->params, [](const char* p) { return std::string_view(p); }, "the parameter");
    kw.params.emplace_back(std::move(name), eq == std::string_view::npos ? "" : std::string(trimmed(part.substr(eq + 1))));
  }
  return kw;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  bool quoted = false;  // a quoted set name may hold commas
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i < line.size() && line[i] == '"') quoted = !quoted;
    if (i == line.size() || (line[i] == ',' && !quoted)) {
      fields.push_back(trimmed(line.substr(start, i - start)));
      start = i + 1;
    }
  }
  if (fields.size() > 1 && fields.back().empty()) fields.pop_back();
  return fields;
}

bool ends_with_comma(std::string_view line) {
  const std::string_view t = trimmed(line);
  return !t.empty() && t.back() == ',';
}

DeckLines::DeckLines(std::istream& in, std::string source) : lines_(in, std::move(source)) {}

DeckLines::~DeckLines() = default;

void DeckLines::include(const Keyword& kw) {
  const std::string* input = kw.param("INPUT");
  std::string file = input == nullptr ? "" : unquoted(*input);
  if (file.empty()) fail("*INCLUDE without INPUT=file");
  lines_.include(std::move(file), "*INCLUDE", mark_);
}

bool DeckLines::next() {
  for (;;) {
    if (!raw_line(text_)) return false;
    mark_ = lines_.mark();
    if (is_comment(text_)) {
      kind_ = Kind::Comment;
      return true;
    }
    if (!is_keyword(text_)) {
      kind_ = Kind::Data;
      return true;
    }
    // A keyword line that ends with a comma goes on on the next line of its
    // file, which must be no keyword line.
    std::string more;
    while (ends_with_comma(text_)) {
      const std::size_t depth = lines_.depth();
      if (!raw_line(more) || lines_.depth() != depth)
        fail("the keyword line ends with a comma, and its file ends after it");
      if (is_keyword(more)) fail("the keyword line ends with a comma, and the next line is a keyword line");
      text_ += '\n';
      text_ += more;
    }
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

std::string DeckLines::where() const { return where_of(mark_); }

void DeckLines::fail(const std::string& what) const { throw InputError(where(), what); }

}  // namespace tetsmooth::abaqus
