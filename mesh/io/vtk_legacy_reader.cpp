#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "mesh/errors.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/io/vtk_arrays.hpp"
#include "mesh/io/vtk_cells.hpp"
#include "mesh/io/vtk_legacy.hpp"
#include "mesh/io/vtk_scalars.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace {

// Undoes the writer's percent-encoding of names ("%20" for a space).
std::string decode_name(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
      out += static_cast<char>(std::stoi(std::string(s.substr(i + 1, 2)), nullptr, 16));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

class LegacyReader {
 public:
  LegacyReader(std::istream& in, const std::string& source) : lines_(in, source, '\0') {}

  TetMesh read() {
    header();
    while (!lines_.at_end()) section(upper_case(lines_.next_token("a section keyword")));
    if (!have_points_) lines_.fail("no POINTS section");
    if (!have_cells_) lines_.fail("no CELLS section");
    if (!have_types_) lines_.fail("no CELL_TYPES section");
    const VtkArrayPick pick = pick_vtk_arrays(arrays_, mesh_.extras.read_notes);
    note_vtk_field_data(field_data_, mesh_.extras.read_notes);
    const auto cell_tags = [&](std::size_t i) {
      return i == kNoVtkArray ? std::vector<int>{}
                              : vtk_region_tags(kept_[i].values, types_.size(), arrays_[i].name, kept_[i].where);
    };
    mesh_from_vtk_cells(mesh_, connectivity_, offsets_, types_, cell_tags(pick.tags), cell_tags(pick.entities),
                        types_where_,
                        [this](VtkCellArray array, std::size_t index, std::size_t cell) {
                          return cell_value_place(array, index, cell);
                        });
    if (pick.fixed != kNoVtkArray)
      fix_vtk_nodes(mesh_, kept_[pick.fixed].values, arrays_[pick.fixed].name, kept_[pick.fixed].where);
    if (const std::size_t i = pick.node_entities; i != kNoVtkArray)
      classify_vtk_nodes(mesh_, kept_[i].values, arrays_[i].components, arrays_[i].name, kept_[i].where);
    validate_mesh(mesh_, lines_.source());
    return std::move(mesh_);
  }

 private:
  enum class Attach { None, Points, Cells };

  // What is kept of a point or cell data array: the values of those that
  // may be carried over (vtk_array_wanted), and where it starts.
  struct Kept {
    std::string where;
    std::vector<double> values;
  };

  // Where an array of cell data starts, to find one of its values again
  // when mesh_from_vtk_cells finds it wrong, without a place kept per value.
  struct ArrayStart {
    const char* name = "";
    std::string where;          // the keyword's line (ASCII) or its start (BINARY)
    std::uint64_t data = 0;     // BINARY: byte offset of the first value
    std::size_t size = 0;       // BINARY: bytes a value
    TextLines::Mark first;      // ASCII: the place of the first value
  };

  // Call right before the array's first value is read.
  ArrayStart array_start(const char* name, std::size_t value_size) const {
    ArrayStart a;
    a.name = name;
    a.where = lines_.where();
    if (binary_) {
      a.data = lines_.next_offset();
      a.size = value_size;
    } else {
      a.first = lines_.mark();
    }
    return a;
  }

  // Value `position` (from 0) of the array that starts at `a`: its byte, or
  // its line found by reading the tokens again; the array's line and the
  // entry where the input cannot be read again.
  VtkValuePlace value_place(const ArrayStart& a, std::uint64_t position) const {
    if (binary_) return {lines_.where_at_byte(a.data + position * a.size), ""};
    std::string where = lines_.where_of_token(a.first, position);
    if (!where.empty()) return {std::move(where), ""};
    return {a.where, "value " + std::to_string(position) + ", counted from 0, of the " + a.name + " data after " +
                         "this keyword"};
  }

  VtkValuePlace cell_value_place(VtkCellArray array, std::size_t index, std::size_t cell) const {
    if (major_ >= 5) return value_place(array == VtkCellArray::Offsets ? offsets_at_ : connectivity_at_, index);
    // Up to 4.2 one CELLS array holds each cell's node count then its nodes;
    // an offset stands for the count of its cell.
    const std::uint64_t before = static_cast<std::uint64_t>(offsets_[cell]) + cell;  // values before cell's count
    return value_place(connectivity_at_, array == VtkCellArray::Offsets ? before : index + cell + 1);
  }

  void header() {
    lines_.require_line("the header \"# vtk DataFile Version x.y\"");
    const bool ok = lines_.size() >= 5 && lines_.token(0, "") == "#" && upper_case(lines_.token(1, "")) == "VTK" &&
                    upper_case(lines_.token(2, "")) == "DATAFILE" && upper_case(lines_.token(3, "")) == "VERSION";
    if (!ok) lines_.fail("not a legacy VTK file: the first line must be \"# vtk DataFile Version x.y\"");
    long long major = 0;
    const std::string_view version = lines_.token(4, "version");
    if (!parse_integer(version.substr(0, version.find('.')), major))
      lines_.fail("bad version " + quoted_token(version));
    major_ = major;
    if (!lines_.next_raw_line()) lines_.fail("unexpected end of file, expected the title line");
    lines_.require_line("ASCII or BINARY");
    const std::string mode = upper_case(lines_.token(0, "ASCII or BINARY"));
    if (mode != "ASCII" && mode != "BINARY") lines_.fail("expected ASCII or BINARY, found " + quoted_token(mode));
    binary_ = mode == "BINARY";
    if (binary_) lines_.locate_by_byte();
    if (upper_case(lines_.next_token("DATASET")) != "DATASET") lines_.fail("expected DATASET");
    const std::string type = upper_case(arg("the dataset type"));
    if (type != "UNSTRUCTURED_GRID")
      lines_.fail("DATASET " + quoted_token(type) + " is not supported, only UNSTRUCTURED_GRID");
  }

  // An argument of a keyword line. In a BINARY file it must be on that line,
  // since the next line may be data.
  std::string_view arg(const char* what) {
    return binary_ ? lines_.next_token_on_line(what) : lines_.next_token(what);
  }

  std::size_t count(const char* what) {
    const std::string_view token = arg(what);
    long long n = 0;
    if (!parse_integer(token, n))
      lines_.fail(std::string("expected an integer ") + what + ", found " + quoted_token(token));
    return checked_count(n, what);
  }

  std::size_t checked_count(long long n, const char* what) const {
    if (n < 0 || n > std::numeric_limits<std::int32_t>::max())
      lines_.fail(std::string("invalid ") + what + " " + std::to_string(n));
    return static_cast<std::size_t>(n);
  }

  // The type of a BINARY block's values, named on the line before it.
  const VtkScalarInfo& binary_type(std::string_view type, const char* what) const {
    const VtkScalarInfo* info = legacy_vtk_scalar(type);
    if (!info)
      lines_.fail(std::string(what) + ": data type " + quoted_token(type) +
                  " cannot be read from a BINARY file (numeric types only; bit arrays are skipped where not "
                  "needed)");
    return *info;
  }

  // What must follow a BINARY block of n values: a line break, as VTK and
  // meshio write it. Anything else means the block was not as long as its
  // count and type say (a wrong type size, a wrong count), and the text read
  // next would be data: it fails here, at the byte after the block.
  void end_of_block(std::size_t n, const char* what) {
    if (n > 0 && !lines_.at_line_break())
      lines_.fail_at_byte(lines_.next_offset(), std::string("expected a line break after the ") + what +
                                                    " data (does the data match its count and type?)");
  }

  // The n values of the BINARY block after the current line, of legacy type
  // `type`, big-endian as the format has them. Read a chunk at a time, so
  // that a count the file cannot hold ends at the end of the file, not in an
  // allocation. A float type where Out is an integer fails at the keyword's
  // line; an unsigned value past long long at its byte.
  template <class Out>
  std::vector<Out> binary_values(std::size_t n, std::string_view type, const char* what) {
    const VtkScalarInfo& info = binary_type(type, what);
    if (std::is_integral_v<Out> && info.is_float)
      lines_.fail(std::string(what) + ": expected an integer data type, found " + quoted_token(type));
    std::vector<Out> out;
    out.reserve(std::min(n, kReserveValues));
    std::vector<unsigned char> chunk;
    const std::uint64_t begin = lines_.next_offset();
    for (std::size_t done = 0; done < n;) {
      const std::size_t k = std::min(n - done, kChunkValues);
      chunk.resize(k * info.size);
      lines_.read_bytes(reinterpret_cast<char*>(chunk.data()), chunk.size(), what);
      if (!decode_vtk_scalars(info.scalar, chunk.data(), k, true, out))
        lines_.fail_at_byte(begin + out.size() * info.size, std::string(what) + ": value out of range");
      done += k;
    }
    end_of_block(n, what);
    return out;
  }

  // Skips n values of legacy type `type`: tokens, or a BINARY block's bytes
  // (bit arrays packed eight values a byte).
  void skip_values(std::size_t n, std::string_view type, const char* what) {
    if (!binary_) {
      for (std::size_t i = 0; i < n; ++i) lines_.next_token(what);
      return;
    }
    const bool bits = upper_case(type) == "BIT";
    const std::size_t size = bits ? 1 : binary_type(type, what).size;
    const std::size_t values = bits ? n / 8 + (n % 8 != 0) : n;
    for (std::size_t done = 0; done < values;) {  // a chunk at a time: values * size may not fit size_t
      const std::size_t k = std::min(values - done, kChunkValues);
      lines_.skip_bytes(k * size, what);
      done += k;
    }
    end_of_block(n, what);
  }

  // n integers of legacy type `type`: tokens, or a BINARY block.
  std::vector<long long> integers(std::size_t n, std::string_view type, const char* what) {
    if (binary_) return binary_values<long long>(n, type, what);
    std::vector<long long> v;
    v.reserve(std::min(n, kReserveValues));  // a lying count ends at end of file, not in allocation
    for (std::size_t i = 0; i < n; ++i) v.push_back(lines_.next_integer(what));
    return v;
  }

  void section(const std::string& kw) {
    if (kw == "POINTS") return points();
    if (kw == "CELLS") return cells();
    if (kw == "CELL_TYPES") {
      types_where_ = lines_.where();
      have_types_ = true;
      types_ = integers(count("cell type count"), "int", "cell type");
      return;
    }
    if (kw == "POINT_DATA" || kw == "CELL_DATA") {
      attach_ = kw == "POINT_DATA" ? Attach::Points : Attach::Cells;
      tuples_ = count("data count");
      return;
    }
    if (kw == "FIELD") return field();
    if (kw == "METADATA") return lines_.skip_past_blank_line();
    if (kw == "LOOKUP_TABLE") {
      // RGBA entries: reals in ASCII, bytes in BINARY.
      arg("table name");
      return skip_values(4 * count("table size"), "unsigned_char", "table value");
    }
    if (attach_ == Attach::None) lines_.fail("unknown or misplaced keyword " + quoted_token(kw));
    if (kw == "SCALARS") return scalars();
    const bool known = kw == "VECTORS" || kw == "NORMALS" || kw == "TENSORS" || kw == "TENSORS6" ||
                       kw == "TEXTURE_COORDINATES" || kw == "COLOR_SCALARS";
    if (!known) lines_.fail("unknown keyword " + quoted_token(kw));
    const std::string name = decode_name(arg("array name"));
    const std::string where = lines_.where();
    const std::size_t per_tuple = kw == "VECTORS" || kw == "NORMALS" ? 3
                                  : kw == "TENSORS"                  ? 9
                                  : kw == "TENSORS6"                 ? 6
                                  : kw == "TEXTURE_COORDINATES"      ? count("dimension")
                                                                     : count("component count");
    // COLOR_SCALARS names no type: reals in ASCII, bytes in BINARY.
    const std::string type(kw == "COLOR_SCALARS" ? "unsigned_char" : arg("type"));
    data_array(name, per_tuple, tuples_, type, where);
  }

  // The values of a point or cell data array: kept when it may be carried
  // over, skipped otherwise. Reals, so that a tag array of a floating-point
  // type is accepted when its values are whole numbers, and rejected naming
  // the cell if not (vtk_region_tags).
  void data_array(const std::string& name, std::size_t components, std::size_t tuples, const std::string& type,
                  const std::string& where) {
    arrays_.push_back(VtkArrayDecl{attach_ == Attach::Cells, name, components});
    Kept& kept = kept_.emplace_back(Kept{where, {}});
    if (!vtk_array_wanted(arrays_.back())) return skip_values(components * tuples, type, "value");
    const std::size_t count = components * tuples;  // vtk_array_wanted bounds components by 3
    if (binary_) {
      kept.values = binary_values<double>(count, type, "value");
      return;
    }
    kept.values.reserve(std::min<std::size_t>(count, 1 << 20));
    for (std::size_t i = 0; i < count; ++i) {
      const std::string_view token = lines_.next_token("value");
      double v = 0;
      if (!parse_real(token, v)) lines_.fail(name + ": bad value " + quoted_token(token));
      kept.values.push_back(v);
    }
  }

  void points() {
    const std::size_t n = count("point count");
    const std::string type(arg("point type"));
    have_points_ = true;
    if (binary_) {
      const std::uint64_t begin = lines_.next_offset();
      mesh_.xyz = binary_values<double>(3 * n, type, "coordinate");
      const std::size_t size = binary_type(type, "coordinate").size;
      for (std::size_t i = 0; i < mesh_.xyz.size(); ++i)
        if (!std::isfinite(mesh_.xyz[i]))
          lines_.fail_at_byte(begin + i * size, "non-finite coordinate of point " + std::to_string(i / 3));
      return;
    }
    mesh_.xyz.reserve(3 * std::min<std::size_t>(n, 1 << 20));
    for (std::size_t i = 0; i < 3 * n; ++i) mesh_.xyz.push_back(lines_.next_real("coordinate"));
  }

  void cells() {
    have_cells_ = true;
    const std::size_t first = count("cell count");
    const std::size_t second = count("cell array size");
    offsets_.clear();
    if (major_ >= 5) {
      // 5.x: "CELLS <#offsets> <#connectivity>", then OFFSETS and CONNECTIVITY arrays.
      if (upper_case(lines_.next_token("OFFSETS")) != "OFFSETS") lines_.fail("expected OFFSETS");
      const std::string offset_type(arg("offset type"));
      offsets_at_ = array_start("OFFSETS", binary_ ? binary_type(offset_type, "offset").size : 0);
      offsets_ = integers(first, offset_type, "offset");
      if (upper_case(lines_.next_token("CONNECTIVITY")) != "CONNECTIVITY") lines_.fail("expected CONNECTIVITY");
      const std::string connectivity_type(arg("connectivity type"));
      connectivity_at_ = array_start("CONNECTIVITY", binary_ ? binary_type(connectivity_type, "node index").size : 0);
      connectivity_ = integers(second, connectivity_type, "node index");
      if (offsets_.empty()) lines_.fail("OFFSETS needs at least the leading 0");
      return;
    }
    // Up to 4.2: "CELLS <#cells> <size>", each cell its node count then its
    // nodes, as tokens or (BINARY) one block of `second` ints.
    const std::uint64_t block_begin = lines_.next_offset();
    connectivity_at_ = array_start("CELLS", 4);
    std::vector<long long> block;
    if (binary_) block = binary_values<long long>(second, "int", "CELLS data");
    std::size_t taken = 0;  // values of the block taken
    const auto next = [&](const char* what) { return binary_ ? block[taken++] : lines_.next_integer(what); };
    // In BINARY at the cell's count in the block (4 bytes a value).
    const auto fail_cell = [&](std::size_t c) {
      const std::string what =
          "cell " + std::to_string(c) + " runs past the " + std::to_string(second) + " values that CELLS declared";
      if (binary_) lines_.fail_at_byte(block_begin + 4 * (connectivity_.size() + c), what);
      lines_.fail(what);
    };
    offsets_.push_back(0);
    connectivity_.clear();
    for (std::size_t c = 0; c < first; ++c) {
      if (connectivity_.size() + c >= second) fail_cell(c);
      const std::size_t k = checked_count(next("cell node count"), "cell node count");
      if (connectivity_.size() + c + 1 + k > second) fail_cell(c);
      for (std::size_t i = 0; i < k; ++i) connectivity_.push_back(next("node index"));
      offsets_.push_back(static_cast<long long>(connectivity_.size()));
    }
    if (connectivity_.size() + first != second)
      lines_.fail("CELLS declared " + std::to_string(second) + " values, the cells hold " +
                  std::to_string(connectivity_.size() + first));
  }

  void scalars() {
    const std::string name = decode_name(arg("array name"));
    const std::string where = lines_.where();
    const std::string type(arg("type"));
    const std::size_t components = lines_.line_has_more() ? count("component count") : 1;
    // Optional in ASCII; in BINARY the line must be there, since without it
    // the look for it has read into the data.
    if (upper_case(lines_.peek_token()) == "LOOKUP_TABLE") {
      lines_.next_token("LOOKUP_TABLE");
      arg("table name");
    } else if (binary_) {
      lines_.fail("SCALARS " + text_excerpt(name) + ": a BINARY file needs the LOOKUP_TABLE line before the values");
    }
    data_array(name, components, tuples_, type, where);
  }

  // FIELD data: in POINT_DATA or CELL_DATA, each array is a point or cell
  // data array (meshio and VTK write their arrays so); before them, data of
  // the whole dataset (TIME, ParaView's TimeValue, ...), which is skipped
  // with a note.
  void field() {
    arg("field name");
    const std::size_t arrays = count("array count");
    for (std::size_t a = 0; a < arrays; ++a) {
      const std::string name = decode_name(lines_.next_token("array name"));
      if (upper_case(name) == "NULL_ARRAY") continue;
      const std::string where = lines_.where();
      const std::size_t components = count("component count");
      const std::size_t tuples = count("tuple count");
      const std::string type(arg("type"));
      if (attach_ == Attach::None) {
        field_data_.push_back(name);
        skip_values(components * tuples, type, "value");
      } else {
        data_array(name, components, tuples, type, where);
      }
      if (upper_case(lines_.peek_token()) == "METADATA") {
        lines_.next_token("METADATA");
        lines_.skip_past_blank_line();
      }
    }
  }

  static constexpr std::size_t kChunkValues = 1 << 16;    // values a BINARY block is read by
  static constexpr std::size_t kReserveValues = 1 << 20;  // the most reserved before the values are there

  TextLines lines_;
  bool binary_ = false;  // BINARY: data blocks are big-endian bytes after their keyword lines
  long long major_ = 0;
  TetMesh mesh_;
  std::vector<long long> connectivity_, offsets_, types_;
  std::vector<VtkArrayDecl> arrays_;  // every point and cell data array, in file order
  std::vector<Kept> kept_;            // one per array
  std::vector<std::string> field_data_;  // arrays of the whole dataset, skipped
  bool have_points_ = false, have_cells_ = false, have_types_ = false;
  std::string types_where_;
  ArrayStart offsets_at_, connectivity_at_;  // CELLS up to 4.2 is connectivity_at_
  Attach attach_ = Attach::None;
  std::size_t tuples_ = 0;
};

}  // namespace

TetMesh read_vtk(std::istream& in, const std::string& source) { return LegacyReader(in, source).read(); }

TetMesh read_vtk_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_vtk(in, path);
}

}  // namespace tetsmooth
