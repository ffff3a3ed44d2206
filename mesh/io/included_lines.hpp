#pragma once
// The lines of a solver's input deck and of the files it includes (Abaqus's
// *INCLUDE, Nastran's INCLUDE), in reading order, each with a 4-byte mark
// that gives back its "file:line" for a message once the deck is read (not
// a public API). Line ends ("\n", "\r\n", and any more '\r' before them) and
// a UTF-8 byte order mark at the start of a file are not part of a line.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <istream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace tetsmooth {

class IncludedLines {
 public:
  // `source` names the deck in messages; relative include paths start from
  // its directory (the job's directory).
  IncludedLines(std::istream& in, std::string source);
  ~IncludedLines();

  // The next line, from the innermost file still open; false at the end of
  // the deck.
  bool next(std::string& out);
  // Lines come from `file` (as the deck writes it; '\\' read as '/') until
  // it ends, then from the file that named it again. `statement` names the
  // include in messages ("*INCLUDE"), `mark` its (first) line. InputError
  // there for a file that cannot be opened, is no regular file, includes
  // itself through the files that include it, is nested more than 64 deep,
  // or is included more than 256 times in all (files that include others
  // several times multiply their lines, exponentially with the depth).
  void include(std::string file, const char* statement, std::uint32_t mark);

  // The mark of the line next() gave last, and the "file:line" of a mark.
  std::uint32_t mark() const { return lines_read_; }
  std::string where_of(std::uint32_t mark) const;
  std::string where() const { return where_of(mark()); }
  // Files open: 1 for the deck alone.
  std::size_t depth() const { return stack_.size(); }
  // The files include() read, each once, in the order met.
  const std::vector<std::string>& included() const { return included_; }

 private:
  struct Source {
    std::istream* in;
    std::unique_ptr<std::ifstream> owned;
    std::string path;
    std::size_t line = 0;
  };
  // From line `first` of the deck on (counted over every file), lines come
  // from `path`, its line `first` being line `line` of the file.
  struct Stretch {
    std::uint32_t first;
    std::string path;
    std::size_t line;
  };
  void new_stretch();

  std::vector<Source> stack_;
  std::string directory_;  // of the deck first read
  std::uint32_t lines_read_ = 0;
  std::vector<Stretch> stretches_;
  std::vector<std::string> included_;
  std::map<std::string, int> opened_;  // times each file was included
};

}  // namespace tetsmooth
