// Medit .mesh (ASCII) reading. The format is a sequence of keywords, each
// followed by its data as whitespace-separated values that may wrap across
// lines at will, so the file is read token by token.
#include <cctype>
#include <climits>
#include <cmath>
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
  void elements(const medit::ElementKeyword& kw);
  void vertex_list(std::vector<std::int32_t>& out);
  void kept(const medit::KeptKeyword& kw);
  void string_section(const char* keyword);
  void section(const std::string& keyword);
  void need_vertices(const std::string& keyword) const {
    if (!has_vertices_) lines_.fail(keyword + " before Vertices: element sections must follow the vertices");
  }

  TextLines& lines_;
  TetMesh mesh_;
  bool has_vertices_ = false;
  bool has_tets_ = false;
  std::vector<std::string> seen_;
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
  mesh_.tets.reserve(4 * capped(n));
  mesh_.extras.tet_tags.reserve(capped(n));
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 4; ++k) mesh_.tets.push_back(vertex_index());
    mesh_.extras.tet_tags.push_back(integer("tetrahedron reference"));
  }
  has_tets_ = n > 0;
}

void MeditReader::elements(const medit::ElementKeyword& kw) {
  need_vertices(kw.keyword);
  const std::size_t n = count("number of elements");
  // An empty section leaves no block: a block of a kind that another format
  // cannot hold would stop the write, though there is nothing to write.
  if (n == 0) return;
  PassThroughBlock& block = mesh_.extras.blocks.emplace_back();
  block.kind = kw.kind;
  block.nodes_per_element = kw.nodes;
  block.connectivity.reserve(static_cast<std::size_t>(kw.nodes) * capped(n));
  block.tags.reserve(capped(n));
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < kw.nodes; ++k) block.connectivity.push_back(vertex_index());
    block.tags.push_back(integer("element reference"));
  }
}

void MeditReader::vertex_list(std::vector<std::int32_t>& out) {
  need_vertices("a vertex list");
  const std::size_t n = count("number of vertices in the list");
  out.reserve(capped(n));
  for (std::size_t i = 0; i < n; ++i) out.push_back(vertex_index());
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
  if (same_keyword(keyword, "RequiredVertices")) return vertex_list(mesh_.extras.required_nodes);
  if (same_keyword(keyword, "Corners")) return vertex_list(mesh_.extras.corner_nodes);
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

TetMesh MeditReader::read(const std::string& source) {
  header();
  while (!lines_.at_end()) {
    const std::string keyword(lines_.next_token("a keyword"));
    if (same_keyword(keyword, "End")) break;
    for (const std::string& s : seen_)
      if (same_keyword(s, keyword)) lines_.fail("a second " + keyword + " section");
    seen_.push_back(keyword);
    section(keyword);
  }
  if (!has_vertices_) lines_.fail("no Vertices section");
  if (!has_tets_) lines_.fail("no Tetrahedra: a volume mesh is needed");

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
