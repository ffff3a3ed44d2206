#include "mesh/io/included_lines.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>

#include "mesh/errors.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth {
namespace {

// Deeper nesting is refused, whatever the files.
constexpr std::size_t kMaxIncludeDepth = 64;
// So is a file included more often, which bounds the lines that a few small
// files naming each other several times can make (2^40 lines from 40 files
// that each include the next twice).
constexpr int kMaxIncludesOfAFile = 256;

std::string directory_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

}  // namespace

IncludedLines::IncludedLines(std::istream& in, std::string source) : directory_(directory_of(source)) {
  stack_.push_back(Source{&in, nullptr, std::move(source)});
  new_stretch();
}

IncludedLines::~IncludedLines() = default;

void IncludedLines::new_stretch() {
  if (!stack_.empty()) stretches_.push_back(Stretch{lines_read_ + 1, stack_.back().path, stack_.back().line + 1});
}

bool IncludedLines::next(std::string& out) {
  while (!stack_.empty()) {
    Source& s = stack_.back();
    if (std::getline(*s.in, out)) {
      ++s.line;
      ++lines_read_;
      if (s.line == 1) out.erase(0, bom_length(out));
      while (!out.empty() && out.back() == '\r') out.pop_back();
      return true;
    }
    if (s.in->bad()) throw InputError(s.path, "read error");
    stack_.pop_back();
    new_stretch();
  }
  return false;
}

void IncludedLines::include(std::string file, const char* statement, std::uint32_t mark) {
  const std::string at = where_of(mark);
  const auto fail = [&](const std::string& what) { throw InputError(at, std::string(statement) + ": " + what); };
  if (file.empty()) fail("no file named");
  std::replace(file.begin(), file.end(), '\\', '/');
  const std::string path = file.front() == '/' ? file : directory_ + file;
  if (stack_.size() > kMaxIncludeDepth) fail("nested more than " + std::to_string(kMaxIncludeDepth) + " files deep");
  std::error_code ec;
  const auto canonical = std::filesystem::weakly_canonical(path, ec);
  const std::string key = ec ? path : canonical.string();
  for (const Source& s : stack_)
    if (!ec && std::filesystem::weakly_canonical(s.path, ec) == canonical && !ec)
      fail(path + " includes itself, through the files that include it");
  if (++opened_[key] > kMaxIncludesOfAFile)
    fail(path + " is included more than " + std::to_string(kMaxIncludesOfAFile) +
         " times in all: files that include others several times multiply their lines");
  // A device or a pipe (/dev/zero, say) might never end.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode))
    fail(path + " is not a regular file");
  try {
    auto in = std::make_unique<std::ifstream>(open_input(path));
    std::istream* raw = in.get();
    stack_.push_back(Source{raw, std::move(in), path});
  } catch (const InputError& e) {
    fail(std::string(e.what()) +
         (file.front() == '/' ? "" : " (a relative path starts from the job's directory, that of the deck first read)"));
  }
  new_stretch();
  if (std::find(included_.begin(), included_.end(), path) == included_.end()) included_.push_back(path);
}

std::string IncludedLines::where_of(std::uint32_t mark) const {
  const auto after = std::upper_bound(stretches_.begin(), stretches_.end(), mark,
                                      [](std::uint32_t m, const Stretch& s) { return m < s.first; });
  if (after == stretches_.begin()) return "";
  const Stretch& s = *(after - 1);
  return s.path + ":" + std::to_string(s.line + (mark - s.first));
}

}  // namespace tetsmooth
