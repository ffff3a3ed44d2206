// Medit .mesh (ASCII) reading. The format is a sequence of keywords, each
// followed by its data as whitespace-separated values that may wrap across
// lines at will, so the file is read token by token.
//
// Element sections (Tetrahedra, Triangles, Edges, ...) and the vertex lists
// (RequiredVertices, Corners) may repeat: meshio writes one section per cell
// block, that is per Gmsh entity, so a mesh of three volumes has three
// Tetrahedra sections, and meshio and Gmsh read such a file whole. Repeats
// are read as one section, their entries appended in file order, so element
// indices (RequiredTriangles, Ridges, ...) count across them; the writer then
// writes one section per kind. Every other section comes once: a second
// Vertices would leave each vertex index ambiguous, and the sections kept as
// read (kKeptKeywords, kStringKeywords) have no single body to append to.
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <istream>
#include <vector>

#include "mesh/io/input_file.hpp"
#include "mesh/io/medit_detail.hpp"
#include "mesh/io/medit_io.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace {

bool same_keyword(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

class MeditReader {
 public:
  explicit MeditReader(TextLines& lines) : lines_(lines) {}
  TetMesh read(const std::string& source);

 private:
  std::size_t count(const char* what);
  index_t vertex_index();
  int integer(const char* what);
  void header();
  void vertices();
  void tetrahedra();
  PassThroughBlock& block_of(const medit::ElementKeyword& kw);
  void elements(const medit::ElementKeyword& kw);
  void vertex_list(const char* keyword, std::vector<std::int32_t>& out, std::vector<std::uint8_t>& listed);
  void kept(const medit::KeptKeyword& kw);
  void string_section(const char* keyword);
  void section(const std::string& keyword);
  void check_once(const std::string& keyword) const;
  void need_vertices(const std::string& keyword) const {
    if (!has_vertices_) lines_.fail(keyword + " before Vertices: element sections must follow the vertices");
  }

  TextLines& lines_;
  TetMesh mesh_;
  bool has_vertices_ = false;
  // The sections read so far that may not repeat (see check_once()).
  std::vector<std::string> seen_;
  // Per vertex, whether RequiredVertices / Corners lists it already, so that
  // a vertex listed twice (in one section or two) is kept once.
  std::vector<std::uint8_t> required_listed_, corners_listed_;
};

std::size_t MeditReader::count(const char* what) {
  const long long n = lines_.next_integer(what);
  if (n < 0 || n > INT_MAX) lines_.fail(std::string(what) + " " + std::to_string(n) + " is out of range");
  return static_cast<std::size_t>(n);
}

int MeditReader::integer(const char* what) {
  const long long v = lines_.next_integer(what);
  if (v < INT_MIN || v > INT_MAX)
    lines_.fail(std::string(what) + " " + std::to_string(v) + " is out of the 32-bit range");
  return static_cast<int>(v);
}

index_t MeditReader::vertex_index() {
  const long long v = lines_.next_integer("vertex index");
  if (v < 1 || static_cast<unsigned long long>(v) > mesh_.num_nodes())
    lines_.fail("vertex index " + std::to_string(v) + " is outside 1.." + std::to_string(mesh_.num_nodes()));
  return static_cast<index_t>(v - 1);
}

// Counts come from the file: containers grow as values are actually read
// rather than being sized up front, so a corrupt count cannot allocate.
constexpr std::size_t kReserveCap = std::size_t{1} << 16;
std::size_t capped(std::size_t n) { return n < kReserveCap ? n : kReserveCap; }

// Only a kind's first section reserves: an exact reserve for each repeat
// would reallocate every time, where push_back's growth stays amortised.
template <typename T>
void reserve_first(std::vector<T>& v, std::size_t n) {
  if (v.empty()) v.reserve(n);
}

// Whether sections under `keyword` may repeat (see the top of the file).
bool may_repeat(std::string_view keyword) {
  if (same_keyword(keyword, "Tetrahedra") || same_keyword(keyword, "RequiredVertices") ||
      same_keyword(keyword, "Corners"))
    return true;
  for (const medit::ElementKeyword& kw : medit::kElementKeywords)
    if (same_keyword(keyword, kw.keyword)) return true;
  return false;
}

void MeditReader::header() {
  const std::string_view first = lines_.next_token("MeshVersionFormatted");
  if (!same_keyword(first, "MeshVersionFormatted"))
    lines_.fail("not a Medit mesh: expected MeshVersionFormatted as the first keyword");
  const long long version = lines_.next_integer("mesh version");
  // Versions differ only in the widths of binary (.meshb) values.
  if (version < 1 || version > 4) lines_.fail("unsupported MeshVersionFormatted " + std::to_string(version));
  const std::string_view dim = lines_.next_token("Dimension");
  if (!same_keyword(dim, "Dimension")) lines_.fail("expected Dimension after MeshVersionFormatted");
  const long long d = lines_.next_integer("dimension");
  if (d != 3) lines_.fail("Dimension " + std::to_string(d) + ": only 3-D meshes are read");
}

void MeditReader::vertices() {
  const std::size_t n = count("number of vertices");
  mesh_.xyz.reserve(3 * capped(n));
  mesh_.extras.node_markers.reserve(capped(n));
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) mesh_.xyz.push_back(lines_.next_real("vertex coordinate"));
    mesh_.extras.node_markers.push_back(integer("vertex reference"));
  }
  has_vertices_ = true;
}

void MeditReader::tetrahedra() {
  need_vertices("Tetrahedra");
  const std::size_t n = count("number of tetrahedra");
  reserve_first(mesh_.tets, 4 * capped(n));
  reserve_first(mesh_.extras.tet_tags, capped(n));
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 4; ++k) mesh_.tets.push_back(vertex_index());
    mesh_.extras.tet_tags.push_back(integer("tetrahedron reference"));
  }
}

// The block that every section of kw's kind appends to, made by the first
// that has elements.
PassThroughBlock& MeditReader::block_of(const medit::ElementKeyword& kw) {
  for (PassThroughBlock& block : mesh_.extras.blocks)
    if (block.kind == kw.kind) return block;
  PassThroughBlock& block = mesh_.extras.blocks.emplace_back();
  block.kind = kw.kind;
  block.nodes_per_element = kw.nodes;
  return block;
}

void MeditReader::elements(const medit::ElementKeyword& kw) {
  need_vertices(kw.keyword);
  const std::size_t n = count("number of elements");
  // An empty section leaves no block: a block of a kind that another format
  // cannot hold would stop the write, though there is nothing to write.
  if (n == 0) return;
  PassThroughBlock& block = block_of(kw);
  reserve_first(block.connectivity, static_cast<std::size_t>(kw.nodes) * capped(n));
  reserve_first(block.tags, capped(n));
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < kw.nodes; ++k) block.connectivity.push_back(vertex_index());
    block.tags.push_back(integer("element reference"));
  }
}

// The list is a set of pinned vertices: one already listed is not added
// again, so that repeated sections, or a vertex repeated within one, write
// back once.
void MeditReader::vertex_list(const char* keyword, std::vector<std::int32_t>& out,
                              std::vector<std::uint8_t>& listed) {
  need_vertices(keyword);
  const std::size_t n = count("number of vertices in the list");
  reserve_first(out, capped(n));
  listed.resize(mesh_.num_nodes(), 0);  // once: a second Vertices is refused
  for (std::size_t i = 0; i < n; ++i) {
    const index_t v = vertex_index();
    if (listed[static_cast<std::size_t>(v)]) continue;
    listed[static_cast<std::size_t>(v)] = 1;
    out.push_back(v);
  }
}

void MeditReader::kept(const medit::KeptKeyword& kw) {
  const std::size_t n = count("number of entries");
  std::string body = std::to_string(n) + "\n";
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < kw.integers + kw.reals; ++k) {
      // Tokens are kept as written once checked, so that numbers round-trip.
      const std::string_view token = lines_.next_token("a value");
      if (k < kw.integers) {
        long long v = 0;
        if (!parse_integer(token, v) || v < 1)
          lines_.fail("expected a positive index, found " + quoted_token(token));
      } else {
        double v = 0;
        if (!parse_real(token, v) || !std::isfinite(v))
          lines_.fail("expected a finite number, found " + quoted_token(token));
      }
      body += token;
      body += k + 1 < kw.integers + kw.reals ? ' ' : '\n';
    }
  }
  mesh_.extras.raw_sections.emplace_back(kw.keyword, std::move(body));
}

void MeditReader::string_section(const char* keyword) {
  std::string text(lines_.next_token("a string"));
  if (text.front() == '"')
    while (text.size() < 2 || text.back() != '"') {
      text += ' ';
      text += lines_.next_token("the closing quote of the string");
    }
  mesh_.extras.raw_sections.emplace_back(keyword, text + "\n");
}

void MeditReader::section(const std::string& keyword) {
  if (same_keyword(keyword, "Vertices")) return vertices();
  if (same_keyword(keyword, "Tetrahedra")) return tetrahedra();
  if (same_keyword(keyword, "RequiredVertices"))
    return vertex_list("RequiredVertices", mesh_.extras.required_nodes, required_listed_);
  if (same_keyword(keyword, "Corners")) return vertex_list("Corners", mesh_.extras.corner_nodes, corners_listed_);
  for (const medit::ElementKeyword& kw : medit::kElementKeywords)
    if (same_keyword(keyword, kw.keyword)) return elements(kw);
  for (const medit::KeptKeyword& kw : medit::kKeptKeywords)
    if (same_keyword(keyword, kw.keyword)) return kept(kw);
  for (const char* kw : medit::kStringKeywords)
    if (same_keyword(keyword, kw)) return string_section(kw);
  const char c = keyword[0];
  if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.')
    lines_.fail("unexpected number " + quoted_token(keyword) +
                " where a keyword belongs (does the previous section's count match its data?)");
  lines_.fail("unknown or unsupported Medit keyword " + quoted_token(keyword));
}

// Fails on a second section of a keyword that comes once (see the top of
// the file), saying why.
void MeditReader::check_once(const std::string& keyword) const {
  for (const std::string& s : seen_) {
    if (!same_keyword(s, keyword)) continue;
    const bool of_vertices = same_keyword(keyword, "Vertices");
    const bool of_header = same_keyword(keyword, "Dimension") || same_keyword(keyword, "MeshVersionFormatted");
    lines_.fail("a second " + keyword + " section: " +
                (of_vertices ? "the elements' vertex indices would be ambiguous"
                 : of_header ? "the header comes once, at the start of the file"
                             : "only element sections, RequiredVertices and Corners may repeat"));
  }
}

TetMesh MeditReader::read(const std::string& source) {
  header();
  seen_ = {"MeshVersionFormatted", "Dimension"};
  while (!lines_.at_end()) {
    const std::string keyword(lines_.next_token("a keyword"));
    if (same_keyword(keyword, "End")) break;
    check_once(keyword);
    section(keyword);  // throws on a word that is no keyword: seen_ holds sections only
    if (!may_repeat(keyword)) seen_.push_back(keyword);
  }
  if (!has_vertices_) lines_.fail("no Vertices section");
  if (mesh_.tets.empty()) lines_.fail("no Tetrahedra: a volume mesh is needed");

  // `fixed` stays empty when nothing pins a node.
  const auto pin = [&](const std::vector<index_t>& nodes) {
    if (!nodes.empty()) mesh_.fixed.resize(mesh_.num_nodes(), 0);
    for (index_t n : nodes) mesh_.fixed[static_cast<std::size_t>(n)] = 1;
  };
  for (const PassThroughBlock& block : mesh_.extras.blocks) pin(block.connectivity);
  pin(mesh_.extras.required_nodes);
  pin(mesh_.extras.corner_nodes);
  validate_mesh(mesh_, source);
  return std::move(mesh_);
}

}  // namespace

TetMesh read_medit(std::istream& in, const std::string& source) {
  TextLines lines(in, source, '#');
  return MeditReader(lines).read(source);
}

TetMesh read_medit_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_medit(in, path);
}

}  // namespace tetsmooth
