// ANSYS file reading (ansys_io.hpp): the lines, commands and blocks.
#include "mesh/io/ansys_reader.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <fstream>

#include "mesh/errors.hpp"
#include "mesh/io/ansys_element_types.hpp"
#include "mesh/io/ansys_io.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth::ansys {
namespace {

// `text` split at `separator` outside single quotes (APDL's strings).
std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  bool quoted = false;
  std::size_t start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\'') quoted = !quoted;
    if (text[i] == separator && !quoted) {
      parts.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  }
  parts.push_back(text.substr(start));
  return parts;
}

// `line` up to its '!' comment (outside quotes).
std::string_view without_comment(std::string_view line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\'') quoted = !quoted;
    if (line[i] == '!' && !quoted) return line.substr(0, i);
  }
  return line;
}

std::string_view field(const std::vector<std::string_view>& fields, std::size_t k) {
  return k < fields.size() ? trimmed(fields[k]) : std::string_view{};
}

void add_once(std::vector<std::string>& list, const std::string& item) {
  if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(item);
}

// Whether a line (split at commas) is 12 or more whole numbers split by
// blanks, as an EBLOCK record is; the data lines of blocks tetsmooth does
// not read hold reals.
bool element_like(const std::vector<std::string_view>& fields) {
  if (fields.size() != 1) return false;
  std::size_t count = 0;
  std::string_view rest = fields[0];
  while (true) {
    while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
    if (rest.empty()) break;
    std::size_t n = 0;
    while (n < rest.size() && rest[n] != ' ' && rest[n] != '\t') ++n;
    long long v = 0;
    if (!parse_integer(rest.substr(0, n), v)) return false;
    ++count;
    rest.remove_prefix(n);
  }
  return count >= 12;
}

// Whether a field is a release, as CDWRITE's block forms give it: "R5.0".
bool is_release(std::string_view text) {
  std::size_t i = 1;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    return i > from;
  };
  if (text.empty() || text[0] != 'R' || !digits() || i >= text.size() || text[i] != '.') return false;
  ++i;
  return digits() && i == text.size();
}

// Whether a line's first field can be an APDL command name: the data lines
// of blocks tetsmooth does not read (SFE's values, RLBLOCK, ...) are not.
bool command_like(std::string_view name) {
  return !name.empty() &&
         (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '/' || name[0] == '*' || name[0] == '_');
}

// The end of a record's data: its length without trailing blanks.
std::size_t data_length(std::string_view record) {
  std::size_t n = record.size();
  while (n > 0 && (record[n - 1] == ' ' || record[n - 1] == '\t')) --n;
  return n;
}

}  // namespace

bool FileReader::next_line() {
  if (at_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', at_);
  const std::size_t next = end == std::string::npos ? text_.size() : end + 1;
  if (end == std::string::npos) end = text_.size();
  raw_ = std::string_view(text_).substr(at_, next - at_);
  line_ = std::string_view(text_).substr(at_, end - at_);
  if (!line_.empty() && line_.back() == '\r') line_.remove_suffix(1);
  at_ = next;
  ++line_no_;
  return true;
}

void FileReader::keep(bool nblock) {
  const auto at = static_cast<std::size_t>(raw_.data() - text_.data());
  if (nblock != kept_nblock_) flush_kept();
  if (kept_begin_ == kept_end_) kept_begin_ = at;
  kept_nblock_ = nblock;
  kept_end_ = at + raw_.size();
}

void FileReader::flush_kept() {
  if (kept_end_ > kept_begin_)
    mesh_.extras.raw_sections.emplace_back(kept_nblock_ ? "ansys:nblock" : "ansys:text",
                                           text_.substr(kept_begin_, kept_end_ - kept_begin_));
  kept_begin_ = kept_end_;
}

void FileReader::fail(const std::string& what) const { fail_at(line_no_, what); }

void FileReader::fail_at(std::size_t line, const std::string& what) const {
  throw InputError(source_ + ":" + std::to_string(line), what);
}

long long FileReader::int_field(std::string_view record, const BlockFormat& f, std::size_t k, const char* what) const {
  long long value = 0;
  const std::string_view text =
      field_at(record, k * static_cast<std::size_t>(f.int_width), static_cast<std::size_t>(f.int_width));
  if (!integer_field(text, value)) fail(std::string("expected ") + what + ", found " + quoted_token(trimmed(text)));
  return value;
}

BlockFormat FileReader::block_format(const char* block) {
  if (!next_line()) fail(std::string("the file ends after ") + block + ", before its format line");
  keep(std::string_view(block) == "NBLOCK");
  const std::optional<BlockFormat> f = parse_block_format(line_);
  if (!f)
    fail(std::string(block) + "'s format line must be a Fortran format such as (3i9,6e21.13e3), not " +
         quoted_token(line_));
  return *f;
}

void FileReader::nblock() {
  const BlockFormat f = block_format("NBLOCK");
  if (f.texts != 0) fail("NBLOCK's format must hold integers and reals alone, such as (3i9,6e21.13e3)");
  if (f.reals < 3) fail("NBLOCK's format gives " + std::to_string(f.reals) + " real fields: X, Y and Z need 3");
  const std::size_t iw = static_cast<std::size_t>(f.int_width), rw = static_cast<std::size_t>(f.real_width);
  const std::size_t ints_end = static_cast<std::size_t>(f.ints) * iw;
  while (true) {
    const std::size_t start = at_;
    if (!next_line()) fail("the file ends inside an NBLOCK, before its closing N,R5.3,LOC,-1 or -1 record");
    const std::string_view first = trimmed(line_);
    if (first.size() >= 2 && (first[0] == 'N' || first[0] == 'n') && first[1] == ',') {
      at_ = start;  // the closing command, read as one
      --line_no_;
      return;
    }
    if (first.empty()) fail("a blank line inside an NBLOCK (each record is a node)");
    // The closing -1 comes in the width of the block's fields, or in
    // another: a line of -1 alone ends the block either way.
    const long long number = first == "-1" ? -1 : int_field(line_, f, 0, "a node number");
    if (number == -1) {
      keep(false);
      block_closed_ = line_no_;
      return;
    }
    keep(true);
    if (number <= 0) fail("node number " + std::to_string(number) + ": node numbers are positive");
    for (std::size_t k = 1; k < static_cast<std::size_t>(f.ints) && k * iw < data_length(line_); ++k)
      int_field(line_, f, k, "a whole number");
    if (data_length(line_) > ints_end + static_cast<std::size_t>(f.reals) * rw)
      fail("the NBLOCK record is longer than its format (values past its last field)");
    for (std::size_t c = 0; c < static_cast<std::size_t>(f.reals); ++c) {
      double v = 0;
      const std::string_view text = field_at(line_, ints_end + c * rw, rw);
      if (!real_field(text, v))
        fail("expected a real number in field " + std::to_string(f.ints + static_cast<int>(c) + 1) + " of node " +
             std::to_string(number) + ", found " + quoted_token(trimmed(text)));
      if (c < 3) mesh_.xyz.push_back(v);
    }
    node_numbers_.push_back(number);
    node_lines_.push_back(line_no_);
  }
}

void FileReader::eblock(bool solid, long long nodes_per_record) {
  const BlockFormat f = block_format("EBLOCK");
  if (f.reals != 0 || f.texts != 0) fail("EBLOCK's format must hold integers alone, such as (19i9)");
  const std::size_t per_line = static_cast<std::size_t>(f.ints);
  const std::size_t header = solid ? 11 : 5;
  if (per_line <= header) fail("EBLOCK's format holds " + std::to_string(per_line) + " fields a line: too few");
  if (!solid && nodes_per_record > static_cast<long long>(per_line - header))
    fail("a non-solid EBLOCK of " + std::to_string(nodes_per_record) + " nodes an element and " +
         std::to_string(per_line) + " fields a line: records over more than one line are not read");
  const auto check_length = [&] {
    if (data_length(line_) > per_line * static_cast<std::size_t>(f.int_width))
      fail("the EBLOCK record is longer than its format (values past its last field)");
  };
  while (true) {
    if (!next_line()) fail("the file ends inside an EBLOCK, before its closing -1 record");
    keep(false);
    if (trimmed(line_).empty()) fail("a blank line inside an EBLOCK (each record is an element)");
    const long long lead =
        trimmed(line_) == "-1" ? -1 : int_field(line_, f, 0, solid ? "a material number" : "an element number");
    if (lead == -1) {
      block_closed_ = line_no_;
      return;
    }
    check_length();
    Element e;
    e.solid = solid;
    e.line = line_no_;
    e.first = element_nodes_.size();
    long long count = 0;
    const auto material = [&](long long mat) {
      if (mat < -999999999 || mat > 999999999) fail("material number " + std::to_string(mat) + " is out of range");
      return static_cast<int>(mat);
    };
    if (solid) {
      // CDWRITE fills every field of a solid record's header: a shorter
      // line is a record cut off (a file copied in part), not blank fields.
      const std::size_t iw = static_cast<std::size_t>(f.int_width);
      if (data_length(line_) < header * iw)
        fail("an EBLOCK record of " + std::to_string((data_length(line_) + iw - 1) / iw) + " fields, short of the " +
             std::to_string(header) + " of its header (is the file cut short?)");
      e.mat = material(lead);
      e.type = int_field(line_, f, 1, "an element type");
      count = int_field(line_, f, 8, "a node count");
      e.number = int_field(line_, f, 10, "an element number");
      if (count <= 0 || count > static_cast<long long>(kMostNodes))
        fail("an element of " + std::to_string(count) + " nodes (at most " + std::to_string(kMostNodes) + " are read)");
      for (std::size_t k = 2; k < header; ++k) int_field(line_, f, k, "a whole number");
      std::size_t k = header;
      for (long long taken = 0; taken < count; ++taken, ++k) {
        if (k == per_line) {
          if (!next_line()) fail("the file ends inside an EBLOCK record");
          keep(false);
          check_length();
          k = 0;
        }
        element_nodes_.push_back(int_field(line_, f, k, "a node number"));
      }
    } else {
      e.number = lead;
      e.type = int_field(line_, f, 1, "an element type");
      e.mat = material(int_field(line_, f, 3, "a material number"));
      for (std::size_t k = 2; k < header; ++k) int_field(line_, f, k, "a whole number");
      // The record's nodes run to its last field; a blank one is none.
      const std::size_t fields =
          (data_length(line_) + static_cast<std::size_t>(f.int_width) - 1) / static_cast<std::size_t>(f.int_width);
      if (fields > header + kMostNodes)
        fail("an element of " + std::to_string(fields - header) + " nodes (at most " + std::to_string(kMostNodes) +
             " are read)");
      for (std::size_t k = header; k < fields; ++k) element_nodes_.push_back(int_field(line_, f, k, "a node number"));
      count = static_cast<long long>(element_nodes_.size() - e.first);
    }
    if (e.number <= 0) fail("element number " + std::to_string(e.number) + ": element numbers are positive");
    for (std::size_t i = e.first; i < element_nodes_.size(); ++i)
      if (element_nodes_[i] < 0)
        fail("element " + std::to_string(e.number) + " lists node " + std::to_string(element_nodes_[i]) +
             ": node numbers are positive (0 for none)");
    e.count = static_cast<std::size_t>(count);
    elements_.push_back(e);
  }
}

void FileReader::cmblock(const std::vector<std::string_view>& fields) {
  Component c;
  c.name = std::string(field(fields, 1));
  const std::string entity = upper_case(field(fields, 2));
  c.line = line_no_;
  long long count = 0;
  if (!parse_integer(field(fields, 3), count) || count < 0)
    fail("CMBLOCK " + quoted_token(c.name) + " needs its count of items, not " + quoted_token(field(fields, 3)));
  const BlockFormat f = block_format("CMBLOCK");
  if (f.reals != 0 || f.texts != 0) fail("CMBLOCK's format must hold integers alone, such as (8i10)");
  long long taken = 0;
  while (taken < count) {
    if (!next_line())
      fail("the file ends inside CMBLOCK " + quoted_token(c.name) + ", which lists " + std::to_string(count) +
           " items");
    keep(false);
    if (data_length(line_) > static_cast<std::size_t>(f.ints * f.int_width))
      fail("the CMBLOCK record is longer than its format (values past its last field)");
    for (std::size_t k = 0; k < static_cast<std::size_t>(f.ints) && taken < count; ++k, ++taken) {
      const std::size_t width = static_cast<std::size_t>(f.int_width);
      if (trimmed(field_at(line_, k * width, width)).empty())
        fail("CMBLOCK " + quoted_token(c.name) + " holds " + std::to_string(taken) +
             " items on its lines, and its count says " + std::to_string(count));
      const long long v = int_field(line_, f, k, "an item number");
      if (v > 0) {
        c.ranges.emplace_back(v, v);
      } else if (v < 0 && !c.ranges.empty() && c.ranges.back().first == c.ranges.back().second && v > LLONG_MIN &&
                 v <= -c.ranges.back().first) {
        c.ranges.back().second = -v;  // the range from the number before to -v
      } else {
        fail("CMBLOCK " + quoted_token(c.name) + " lists " + std::to_string(v) +
             (v == 0 ? ": item numbers are positive" : ", which follows no number it could end a range from"));
      }
    }
  }
  // Items past the count would be dropped: refused on the last line here,
  // and on a line after it as a record after the block.
  const std::size_t on_last = count == 0 ? 0 : static_cast<std::size_t>((count - 1) % f.ints + 1);
  if (count > 0 && data_length(line_) > on_last * static_cast<std::size_t>(f.int_width))
    fail("CMBLOCK " + quoted_token(c.name) + " lists more items than its count, " + std::to_string(count));
  block_closed_ = line_no_;
  if (entity == "NODE" || entity == "ELEM" || entity == "ELEMENT") {
    c.nodes = entity == "NODE";
    components_.push_back(std::move(c));
  }
}

void FileReader::element_type(const std::vector<std::string_view>& fields) {
  long long itype = 0;
  if (!number_of(field(fields, 1), itype) || itype <= 0)
    fail("ET needs a positive element type number, not " + quoted_token(field(fields, 1)));
  ElementType t;
  t.name = upper_case(field(fields, 2));
  t.number = type_number_of(t.name);
  t.line = line_no_;
  const auto [it, added] = types_.emplace(itype, t);
  if (!added && it->second.number != t.number)
    fail("element type " + std::to_string(itype) + " is defined again, as " + quoted_token(t.name) + " (line " +
         std::to_string(it->second.line) + " made it " + quoted_token(it->second.name) + ")");
}

void FileReader::pin_fields(const std::vector<std::string_view>& fields, std::initializer_list<std::size_t> places,
                            const std::string& name) {
  for (std::size_t k : places) {
    const std::string_view text = field(fields, k);
    long long number = 0;
    if (text.empty()) continue;
    if (number_of(text, number)) {
      if (number > 0) pinned_.push_back({number, number, 1, line_no_});
      continue;
    }
    const std::string word = upper_case(text);
    if (word == "ALL" || word == "P" || word == "P51X")
      add_once(by_selection_, name);
    else  // a component: its nodes are pinned as every node component's are, where a CMBLOCK defines it
      named_components_.emplace_back(word, name);
  }
}

void FileReader::pin_range(const std::vector<std::string_view>& fields, std::size_t node, std::size_t end,
                           const std::string& name) {
  const std::size_t first = pinned_.size();
  pin_fields(fields, {node}, name);
  long long last = 0, step = 1;
  if (pinned_.size() == first || !number_of(field(fields, end), last)) return;  // one node, or none
  if (!number_of(field(fields, end + 1), step) || step == 0 || step == LLONG_MIN) step = 1;
  PinnedRange& range = pinned_.back();
  if (last > range.first) {
    range.last = last;
    range.step = step < 0 ? -step : step;
  }
}

void FileReader::etblock() {
  const BlockFormat f = block_format("ETBLOCK");
  if (f.ints < 2) fail("ETBLOCK's format must start with two integers, such as (2i9,19a9)");
  while (true) {
    if (!next_line()) fail("the file ends inside an ETBLOCK, before its closing -1 record");
    keep(false);
    const std::string_view first = trimmed(line_);
    if (first.empty()) fail("a blank line inside an ETBLOCK (each record is an element type)");
    if (first == "-1" || int_field(line_, f, 0, "an element type number") == -1) {
      block_closed_ = line_no_;
      return;
    }
    const std::string itype = std::to_string(int_field(line_, f, 0, "an element type number"));
    const std::string number = std::to_string(int_field(line_, f, 1, "an element number"));
    element_type({"ET", itype, number});
  }
}

bool FileReader::number_of(std::string_view text, long long& value) const {
  if (parse_integer(text, value)) return true;
  double real = 0;
  // A whole real ("7.0"), as APDL takes a node number.
  if (parse_real(text, real) && std::isfinite(real) && real == std::floor(real) && std::fabs(real) < 9e15) {
    value = static_cast<long long>(real);
    return true;
  }
  const auto it = parameters_.find(upper_case(text));
  if (it == parameters_.end()) return false;
  value = it->second;
  return true;
}

void FileReader::parameter(std::string_view name, std::string_view value) {
  long long number = 0;
  const std::string key = upper_case(trimmed(name));
  if (number_of(trimmed(value), number))
    parameters_[key] = number;
  else
    parameters_.erase(key);  // no longer a number tetsmooth knows
}

void FileReader::command(const std::vector<std::string_view>& fields) {
  const std::string name = upper_case(field(fields, 0));
  if (name.empty()) return;
  // Scalar parameters, which element types and loads may name ("*SET,cid,2"
  // or "cid=2", as Workbench writes its contact types).
  if (const std::size_t equals = name.find('='); equals != std::string::npos) {
    std::string_view value = trimmed(fields[0]);
    value.remove_prefix(value.find('=') + 1);
    return parameter(std::string_view(name).substr(0, equals), value);
  }
  if (name == "*SET" || name == "*SE") return parameter(field(fields, 1), field(fields, 2));
  // Other commands that set a parameter (*GET, *DO, *VGET, ...) give it a
  // value tetsmooth does not know.
  if (name[0] == '*') parameters_.erase(upper_case(field(fields, 1)));
  if (!command_like(name)) {
    // The data lines of blocks tetsmooth does not read (RLBLOCK, SFE's
    // values, ...) are kept as they are; right after a block's -1, though,
    // a record means that the block ended early.
    if (block_closed_ + 1 == line_no_)
      fail("a record after the end of the block above (line " + std::to_string(block_closed_) +
           "): is a -1 among its records, or a count too small?");
    // A line of an element record's whole numbers (12 or more: the fields
    // of an EBLOCK's), wherever it is, would be an element dropped.
    if (!elements_.empty() && element_like(fields)) fail("a line of element fields outside an EBLOCK");
    return;
  }
  const std::string second = upper_case(field(fields, 1));
  // CDWRITE's marks ("N,R5.3,LOC,-1" closing an NBLOCK, "EN,R5.5,ATTR,-1")
  // and its block forms of other commands carry a release ("R5.0") as field
  // 2, or UNBL.
  const bool release_form = second == "UNBL" || is_release(second);
  if (name == "NBLOCK") return nblock();
  if (name == "EBLOCK") {
    long long nodes = 0;
    if (!parse_integer(field(fields, 1), nodes) || nodes <= 0)
      fail("EBLOCK needs its first field (19 for SOLID records, else the most nodes a record lists), not " +
           quoted_token(field(fields, 1)));
    return eblock(upper_case(field(fields, 2)) == "SOLID", nodes);
  }
  if (name == "CMBLOCK") return cmblock(fields);
  if (name == "ET") return element_type(fields);
  if (name == "ETBLOCK") return etblock();
  // The marks close a block (a -1 as field 4); other release forms of N and
  // EN make nodes and elements, refused below.
  if ((name == "N" || name == "EN") && release_form && field(fields, 3) == "-1") return;
  if (name.size() >= 4 && std::string_view("NUMOFF").substr(0, name.size()) == name && !node_numbers_.empty())
    fail(
        "NUMOFF after an NBLOCK renumbers the nodes and elements the file has defined, which tetsmooth does not "
        "follow");
  if (changes_mesh(name))
    fail("the " + name + " command " +
         (name == "CDREAD" || name.substr(0, 4) == "/INP" || name == "*USE" || name.find("READ") != std::string::npos
              ? "reads another file into the model"
              : "makes, moves or deletes nodes or elements") +
         ", which tetsmooth would not see: only NBLOCK and EBLOCK define the mesh it reads (write the model with "
         "CDWRITE)");
  if (seen_commands_.insert(name).second) commands_.push_back(text_excerpt(name));
  if (name == "CE" && release_form && upper_case(field(fields, 2)) == "NODE") {
    pin_fields(fields, {3, 6}, name);  // CDWRITE's CE,R5.0,NODE,N1,Lab1,C1,N2,Lab2,C2
  } else if (release_form &&
             (name == "D" || name == "F" || name == "CP" || name == "CE" || name == "BF" || name == "IC")) {
    if (!(name == "CE" && upper_case(field(fields, 2)) == "DEFI")) add_once(cdwrite_forms_, name);
  } else if (name == "D" || name == "F" || name == "IC") {
    pin_range(fields, 1, 5, name);  // NODE, Lab, VALUE, VALUE2, NEND, NINC
  } else if (name == "M") {
    pin_range(fields, 1, 3, name);  // NODE, Lab1, NEND, NINC
  } else if (name == "BF") {
    pin_fields(fields, {1}, name);
  } else if (name == "CP") {
    pin_fields(fields, {3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19}, name);
  } else if (name == "CE") {
    pin_fields(fields, {3, 6, 9}, name);
  } else if (name == "CERIG") {
    pin_fields(fields, {1, 2}, name);  // MASTE, SLAVE
  } else if (name == "RBE3") {
    pin_fields(fields, {1, 3}, name);  // Master, and the component of its Slaves
  } else if (name == "CPNGEN") {
    pin_range(fields, 3, 4, name);  // NSET, Lab, NODE1, NODE2, NINC
  } else if (name == "CPINTF" || name == "CEINTF") {
    add_once(by_selection_, name);
  } else if (name == "CPSGEN" || name == "CESGEN") {
    add_once(generated_, name);
  }
}

void FileReader::commands(std::string_view line) {
  for (std::string_view one : split(without_comment(line), '$')) {
    if (trimmed(one).empty()) continue;
    command(split(one, ','));
  }
}

TetMesh FileReader::read() {
  // A UTF-8 byte order mark is no command.
  const std::size_t bom = bom_length(text_);
  while (next_line()) {
    keep(false);
    std::string_view line = line_;
    if (line_no_ == 1) line.remove_prefix(std::min(bom, line.size()));
    commands(line);
  }
  flush_kept();
  if (node_numbers_.empty())
    throw InputError(source_, "no NBLOCK with nodes: not an ANSYS mesh (write it with CDWRITE)");
  resolve();
  keep_notes();
  validate_mesh(mesh_, source_);
  return std::move(mesh_);
}

}  // namespace tetsmooth::ansys

namespace tetsmooth {

TetMesh read_ansys(std::istream& in, const std::string& source) {
  return ansys::FileReader(read_all(in, source), source).read();
}

TetMesh read_ansys_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_ansys(in, path);
}

}  // namespace tetsmooth
