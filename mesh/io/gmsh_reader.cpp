// Gmsh MSH reading: the $MeshFormat header decides the version and encoding,
// then one loop over the sections serves every flavour.
#include <cstring>
#include <istream>
#include <sstream>

#include "mesh/errors.hpp"
#include "mesh/io/gmsh_io.hpp"
#include "mesh/io/gmsh_source.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace {

using gmsh::AsciiSource;
using gmsh::BinarySource;
using gmsh::ReadState;

// True for a line `dim tag "name"`: enough to tell physical names from a
// garbled section; the lines themselves are kept verbatim.
bool is_physical_name(std::string_view line) {
  const std::size_t quote = line.find('"');
  if (quote == std::string_view::npos || line.size() < quote + 2 || line.back() != '"') return false;
  std::istringstream numbers{std::string(line.substr(0, quote))};
  long long dim = -1, tag = 0;
  std::string rest;
  return (numbers >> dim >> tag) && !(numbers >> rest) && dim >= 0 && dim <= 3;
}

template <class Source>
void read_physical_names(Source& src, ReadState& state) {
  std::string body(src.line("the number of physical names"));
  long long count = 0;
  if (!parse_integer(body, count) || count < 0)
    src.fail("expected the number of physical names, found '" + body.substr(0, 40) + "'");
  body += '\n';
  for (long long i = 0; i < count; ++i) {
    const std::string_view line = src.line("a physical name");
    if (!is_physical_name(line)) src.fail("expected a physical name as 'dimension tag \"name\"'");
    body += line;
    body += '\n';
  }
  state.mesh.extras.raw_sections.emplace_back("$PhysicalNames", std::move(body));
}

template <class Source>
void read_entities_section(Source& src, ReadState& state) {
  std::string text;
  if constexpr (Source::kBinary) {
    state.entities = gmsh::read_entities(src);
    text = gmsh::format_entities_text(state.entities);
  } else {
    src.start_recording();
    state.entities = gmsh::read_entities(src);
    text = src.stop_recording();
  }
  state.has_entities = true;
  state.mesh.extras.raw_sections.emplace_back("$Entities", std::move(text));
}

template <class Source>
void read_sections(Source& src, ReadState& state) {
  for (;;) {
    const std::string section(src.next_section());
    if (section.empty()) return;
    if (section[0] != '$' || section.compare(0, 4, "$End") == 0 || section.find_first_of(" \t") != std::string::npos)
      src.fail("expected a section such as $Nodes, found '" + section.substr(0, 40) + "'");
    const std::string end = "$End" + section.substr(1);
    const auto once = [&](bool& seen) {
      if (seen) src.fail("a second " + section + " section");
      seen = true;
    };
    if (section == "$Nodes") {
      once(state.has_nodes);
      state.major == 4 ? gmsh::read_nodes_v41(src, state) : gmsh::read_nodes_v22(src, state);
    } else if (section == "$Elements") {
      if (!state.has_nodes) src.fail("$Elements before $Nodes");
      once(state.has_elements);
      state.major == 4 ? gmsh::read_elements_v41(src, state) : gmsh::read_elements_v22(src, state);
    } else if (section == "$Entities" && state.major == 4) {
      once(state.has_entities);
      read_entities_section(src, state);
    } else if (section == "$PhysicalNames") {
      for (const auto& [name, body] : state.mesh.extras.raw_sections)
        if (name == section) src.fail("a second $PhysicalNames section");
      read_physical_names(src, state);
    } else if (section == "$MeshFormat") {
      src.fail("a second $MeshFormat section");
    } else {
      // The format asks readers to ignore sections they do not know
      // ($Comments, $Periodic, post-processing data, ...).
      src.skip_section(end);
      continue;
    }
    src.expect_end(end);
  }
}

// MSH 4 elements carry only their entity; the physical tag is the entity's
// (its first, when it belongs to several groups).
void map_physicals(ReadState& state) {
  bool any = false;
  for (const gmsh::Entity& e : state.entities.list()) any = any || !e.physicals.empty();
  if (!any) return;
  FileExtras& extras = state.mesh.extras;
  extras.tet_tags.clear();
  for (int entity : extras.tet_entity_tags) extras.tet_tags.push_back(gmsh::first_physical(state.entities, 3, entity));
  for (PassThroughBlock& block : extras.blocks) {
    const int dim = gmsh::element_type_of_kind(block.kind)->dim;
    block.tags.clear();
    for (int entity : block.entity_tags) block.tags.push_back(gmsh::first_physical(state.entities, dim, entity));
  }
}

template <class Source>
TetMesh finish(Source& src, ReadState& state, const std::string& source) {
  read_sections(src, state);
  if (!state.has_nodes) src.fail("no $Nodes section");
  if (!state.has_elements) src.fail("no $Elements section");
  if (state.mesh.tets.empty()) src.fail("no tetrahedra (element type 4): a volume mesh is needed");
  if (state.major == 4 && state.has_entities) map_physicals(state);

  TetMesh& mesh = state.mesh;
  // `fixed` stays empty when no pass-through element pins a node.
  for (const PassThroughBlock& block : mesh.extras.blocks) {
    if (!block.connectivity.empty()) mesh.fixed.resize(mesh.num_nodes(), 0);
    for (index_t n : block.connectivity) mesh.fixed[static_cast<std::size_t>(n)] = 1;
  }
  validate_mesh(mesh, source);
  return std::move(mesh);
}

}  // namespace

TetMesh read_gmsh(std::istream& in, const std::string& source) {
  TextLines lines(in, source, '\0');
  lines.require_line("$MeshFormat");
  if (lines.token(0, "$MeshFormat") != "$MeshFormat")
    lines.fail("not a Gmsh MSH file: expected $MeshFormat on the first line");
  lines.require_line("the MSH version line");
  const std::string_view version = lines.token(0, "the MSH version");
  const long long file_type = lines.integer(1, "file type");
  const long long data_size = lines.integer(2, "data size");

  ReadState state;
  if (version == "4.1") {
    state.major = 4;
  } else if (version == "2.2" || version == "2.1" || version == "2" || version == "2.0") {
    state.major = 2;
  } else {
    lines.fail("unsupported MSH version '" + std::string(version.substr(0, 20)) +
               "'; 4.1 and 2.2 are read (Gmsh can convert others)");
  }
  if (file_type != 0 && file_type != 1) lines.fail("file type " + std::to_string(file_type) + " is not 0 or 1");

  if (file_type == 0) {
    AsciiSource src(lines);
    src.expect_end("$EndMeshFormat");
    return finish(src, state, source);
  }
  if (data_size != 8) lines.fail("binary data size " + std::to_string(data_size) + " is not 8 (64-bit size_t)");
  // The binary part starts right after the version line, which TextLines
  // consumed whole.
  const std::streamoff base = in.tellg();
  std::string data = read_all(in, source);
  // The integer 1 written in the writer's byte order tells whether to swap.
  std::int32_t one = 0;
  if (data.size() >= sizeof one) std::memcpy(&one, data.data(), sizeof one);
  const bool swap = one == 0x01000000;
  BinarySource src(std::move(data), base > 0 ? static_cast<std::size_t>(base) : 0, swap, source);
  if (src.int_value("the byte-order integer") != 1)
    src.fail("the byte-order integer after the version line is not 1 in either byte order");
  src.expect_end("$EndMeshFormat");
  return finish(src, state, source);
}

TetMesh read_gmsh_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_gmsh(in, path);
}

}  // namespace tetsmooth
