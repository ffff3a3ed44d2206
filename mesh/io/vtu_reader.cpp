#include <algorithm>
#include <limits>

#include "mesh/errors.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/io/vtk_arrays.hpp"
#include "mesh/io/vtk_cells.hpp"
#include "mesh/io/vtu_data_array.hpp"
#include "mesh/io/vtu_io.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace {

// What the XML part of a .vtu holds that the reader needs.
struct VtuLayout {
  VtuEncoding encoding;
  long long points = -1, cells = -1;
  std::size_t piece_at = 0;
  const VtuDataArray* points_array = nullptr;
  const VtuDataArray* connectivity = nullptr;
  const VtuDataArray* offsets = nullptr;
  const VtuDataArray* types = nullptr;
  // The PointData and CellData arrays, in file order.
  std::vector<const VtuDataArray*> data;
  std::vector<VtkArrayDecl> data_decls;
  std::vector<std::string> field_data;  // names of the FieldData arrays, which are not read
  std::vector<VtuDataArray> arrays;  // stable once scanning is done
};

long long count_attribute(const XmlScanner& xml, const XmlTag& tag, const char* key) {
  const std::string* v = tag.attribute(key);
  long long n = -1;
  if (!v || !parse_integer(*v, n) || n < 0) xml.fail(tag.begin, std::string("missing or bad ") + key + " in <Piece>");
  return n;
}

void read_vtkfile_tag(const XmlScanner& xml, const XmlTag& tag, VtuEncoding& enc) {
  if (tag.name != "VTKFile")
    xml.fail(tag.begin, "not a VTK XML file: the first element is " + quoted_token(tag.name) + ", not VTKFile");
  const std::string* type = tag.attribute("type");
  if (!type || *type != "UnstructuredGrid")
    xml.fail(tag.begin, "VTK XML type " + quoted_token(type ? *type : std::string()) + " is not UnstructuredGrid");
  if (const std::string* c = tag.attribute("compressor"); c && !vtu_compressor(*c, enc.compressor))
    xml.fail(tag.begin, "compressed VTU data (" + text_excerpt(*c) +
                            ") is not supported: tetsmooth reads zlib (vtkZLibDataCompressor) and LZMA "
                            "(vtkLZMADataCompressor) compression; save the file with one of those or uncompressed "
                            "(ParaView: Compressor Type ZLib or None)");
  if (const std::string* order = tag.attribute("byte_order")) {
    if (*order != "LittleEndian" && *order != "BigEndian")
      xml.fail(tag.begin, "unknown byte_order " + quoted_token(*order));
    enc.big_endian = *order == "BigEndian";
  }
  if (const std::string* h = tag.attribute("header_type")) {
    if (*h != "UInt32" && *h != "UInt64")
      xml.fail(tag.begin, "header_type " + quoted_token(*h) + " is neither UInt32 nor UInt64");
    enc.header_bytes = *h == "UInt64" ? 8 : 4;
  }
}

// Reads the DataArray element whose start tag is `open`: for a non-empty
// element its text runs from the end of the last nested element (VTK puts
// <InformationKey> elements first) to </DataArray>.
VtuDataArray read_data_array(XmlScanner& xml, const XmlTag& open) {
  VtuDataArray a{open, open.end, open.end};
  if (open.kind == XmlTag::Kind::Empty) return a;
  XmlTag tag;
  int depth = 0;
  while (xml.next(tag)) {
    if (tag.kind == XmlTag::Kind::Open) ++depth;
    if (tag.kind == XmlTag::Kind::Close && depth-- == 0) {
      if (tag.name != "DataArray") xml.fail(tag.begin, "end tag " + quoted_token(tag.name) + " closes <DataArray>");
      a.content_end = tag.begin;
      return a;
    }
    a.content_begin = tag.end;
  }
  xml.fail(open.begin, "unterminated <DataArray>");
}

// NumberOfComponents, 1 when absent; 0 when unreadable, which no array the
// reader carries over has.
std::size_t components(const XmlTag& tag) {
  const std::string* v = tag.attribute("NumberOfComponents");
  long long n = 1;
  if (v && (!parse_integer(*v, n) || n < 0)) n = 0;
  return static_cast<std::size_t>(n);
}

VtuLayout scan(std::string_view text, XmlScanner& xml) {
  VtuLayout layout;
  // A file that is not XML at all (another format, a wrong --format) is
  // told by what it holds; "empty" only where it holds nothing.
  constexpr std::string_view kExpected = "expected <VTKFile type=\"UnstructuredGrid\">";
  std::size_t start = bom_length(text);
  start = std::min(text.find_first_not_of(" \t\r\n", start), text.size());
  if (start == text.size()) xml.fail(0, "empty file, " + std::string(kExpected));
  if (text[start] != '<')
    xml.fail(start, "not a VTK XML file: " + std::string(kExpected) + ", found " + quoted_token(text.substr(start)));
  XmlTag tag;
  if (!xml.next(tag)) xml.fail(start, std::string(kExpected) + ", found no element");
  read_vtkfile_tag(xml, tag, layout.encoding);
  std::vector<std::pair<std::string, std::string>> roles;  // (parent, name) per array
  std::vector<std::string> stack{"VTKFile"};
  int pieces = 0;
  while (xml.next(tag)) {
    if (tag.kind == XmlTag::Kind::Close) {
      if (stack.empty() || stack.back() != tag.name)
        xml.fail(tag.begin, "end tag " + quoted_token(tag.name) + " does not match the open element " +
                                quoted_token(stack.empty() ? "" : stack.back()));
      stack.pop_back();
      continue;
    }
    if (tag.name == "AppendedData") {
      const std::string* enc = tag.attribute("encoding");
      if (!enc || (*enc != "raw" && *enc != "base64"))
        xml.fail(tag.begin, "AppendedData encoding " + quoted_token(enc ? *enc : std::string()) +
                                " is neither raw nor base64");
      std::size_t i = tag.end;
      while (i < text.size() && (text[i] == ' ' || text[i] == '\n' || text[i] == '\r' || text[i] == '\t')) ++i;
      if (i >= text.size() || text[i] != '_') xml.fail(i, "AppendedData must start with '_'");
      layout.encoding.has_appended = true;
      layout.encoding.appended_base64 = *enc == "base64";
      layout.encoding.appended_begin = i + 1;
      break;  // raw bytes follow: no more XML to scan
    }
    if (tag.name == "Piece" && ++pieces > 1) xml.fail(tag.begin, "files with several pieces are not supported");
    if (tag.name == "Piece") {
      layout.points = count_attribute(xml, tag, "NumberOfPoints");
      layout.cells = count_attribute(xml, tag, "NumberOfCells");
      layout.piece_at = tag.begin;
    }
    if (tag.name == "DataArray") {
      const std::string parent = stack.size() >= 2 && stack[stack.size() - 2] == "Piece" ? stack.back() : "";
      const std::string* name = tag.attribute("Name");
      if (stack.back() == "FieldData") layout.field_data.push_back(name ? *name : "");
      layout.arrays.push_back(read_data_array(xml, tag));
      roles.emplace_back(parent, name ? *name : "");
      continue;
    }
    if (tag.kind == XmlTag::Kind::Open) stack.push_back(tag.name);
  }
  if (pieces == 0) xml.fail(text.size(), "no <Piece> element");
  for (std::size_t i = 0; i < layout.arrays.size(); ++i) {
    const auto& [parent, name] = roles[i];
    const VtuDataArray* a = &layout.arrays[i];
    if (parent == "Points" && !layout.points_array) layout.points_array = a;
    if (parent == "Cells" && name == "connectivity") layout.connectivity = a;
    if (parent == "Cells" && name == "offsets") layout.offsets = a;
    if (parent == "Cells" && name == "types") layout.types = a;
    if (parent == "PointData" || parent == "CellData") {
      layout.data.push_back(a);
      layout.data_decls.push_back(VtkArrayDecl{parent == "CellData", name, components(a->tag)});
    }
  }
  const auto require = [&](const VtuDataArray* a, const char* what) {
    if (!a) xml.fail(layout.piece_at, std::string("the piece has no ") + what + " array");
  };
  require(layout.points_array, "Points");
  require(layout.connectivity, "Cells connectivity");
  require(layout.offsets, "Cells offsets");
  require(layout.types, "Cells types");
  return layout;
}

}  // namespace

TetMesh read_vtu(std::istream& in, const std::string& source) {
  const std::string text = read_all(in, source);
  XmlScanner xml(text, source);
  const VtuLayout layout = scan(text, xml);
  const VtuArrayDecoder decode(text, xml, source, layout.encoding);
  const auto points = static_cast<std::size_t>(layout.points);
  const auto cells = static_cast<std::size_t>(layout.cells);

  TetMesh mesh;
  mesh.xyz = decode.reals(*layout.points_array, points, 3, "Points");
  std::vector<long long> offsets = decode.integers(*layout.offsets, cells, "offsets");
  offsets.insert(offsets.begin(), 0);  // VTK XML stores only the end of each cell
  const long long conn_size = offsets.back();
  if (conn_size < 0) xml.fail(layout.offsets->tag.begin, "negative cell offset");
  const std::vector<long long> connectivity =
      decode.integers(*layout.connectivity, static_cast<std::size_t>(conn_size), "connectivity");
  const std::vector<long long> types = decode.integers(*layout.types, cells, "types");
  const VtkArrayPick pick = pick_vtk_arrays(layout.data_decls, mesh.extras.read_notes);
  note_vtk_field_data(layout.field_data, mesh.extras.read_notes);
  // Read as reals, so that a tag array of a floating-point type is accepted
  // when its values are whole numbers, and rejected naming the cell if not.
  const auto values = [&](std::size_t i, std::size_t count) {
    const VtkArrayDecl& a = layout.data_decls[i];
    return decode.reals(*layout.data[i], count, static_cast<int>(a.components), a.name.c_str());
  };
  const auto where = [&](std::size_t i) { return xml.where(layout.data[i]->tag.begin); };
  const auto cell_tags = [&](std::size_t i) {
    return i == kNoVtkArray ? std::vector<int>{}
                            : vtk_region_tags(values(i, cells), cells, layout.data_decls[i].name, where(i));
  };
  const std::vector<int> tags = cell_tags(pick.tags), entities = cell_tags(pick.entities);
  // offsets[0] is the 0 put in front above, not a value of the file.
  const auto place = [&](VtkCellArray array, std::size_t index, std::size_t) {
    return array == VtkCellArray::Offsets ? decode.place(*layout.offsets, index - 1, "offsets")
                                          : decode.place(*layout.connectivity, index, "connectivity");
  };
  mesh_from_vtk_cells(mesh, connectivity, offsets, types, tags, entities, xml.where(layout.types->tag.begin), place);
  if (pick.fixed != kNoVtkArray)
    fix_vtk_nodes(mesh, values(pick.fixed, points), layout.data_decls[pick.fixed].name, where(pick.fixed));
  if (const std::size_t i = pick.node_entities; i != kNoVtkArray)
    classify_vtk_nodes(mesh, values(i, points), layout.data_decls[i].components, layout.data_decls[i].name, where(i));
  validate_mesh(mesh, source);
  return mesh;
}

TetMesh read_vtu_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_vtu(in, path);
}

}  // namespace tetsmooth
