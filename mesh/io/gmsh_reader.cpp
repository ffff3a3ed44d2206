// Gmsh MSH reading: the $MeshFormat header decides the version and encoding,
// then one loop over the sections serves every flavour. Partitioned MSH 4.1
// files are read as one mesh (see "partitioned files" below).
#include <algorithm>
#include <charconv>
#include <cstring>
#include <istream>
#include <optional>
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
    src.fail("expected the number of physical names, found " + quoted_token(body));
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

// Gmsh keeps model and partitioned entities in one model, so their tags
// differ; an element on a tag declared in both could be on either.
template <class Source>
void check_partition_tags(Source& src, const ReadState& state) {
  if (!state.has_entities || !state.has_partitions) return;
  for (const gmsh::Entity& e : state.partitions.list())
    if (state.entities.find(e.dim, e.tag) != nullptr)
      src.fail("entity of dimension " + std::to_string(e.dim) + " with tag " + std::to_string(e.tag) +
               " is declared in both $Entities and $PartitionedEntities");
}

// The format asks readers to ignore the sections they do not know ($Periodic,
// $GhostElements, post-processing data, ...); the user hears of each kind
// once, and of data sections once a view (`view`, their first string tag:
// a field such as "pore_pressure" over many time steps is one note).
// $Comments holds nothing a mesh would miss.
void note_skipped(const std::string& section, FileExtras& extras, const std::string& view = "") {
  if (section == "$Comments") return;
  std::string note = text_excerpt(section) + (view.empty() ? "" : " " + quoted_token(view)) +
                     " section skipped; it will not be in the written file";
  if (std::find(extras.read_notes.begin(), extras.read_notes.end(), note) == extras.read_notes.end())
    extras.read_notes.push_back(std::move(note));
}

// Skips a $NodeData or $ElementData section and returns its view name (the
// first string tag, unquoted), or "" when it has none. Its first lines are
// text in binary files too.
template <class Source>
std::string skip_data_section(Source& src, const std::string& end) {
  const std::string_view count = src.line("the number of string tags");
  if (count == end) return "";
  int tags = 0;
  std::from_chars(count.data(), count.data() + count.size(), tags);
  if (tags < 1) {
    src.skip_section(end);
    return "";
  }
  std::string name(src.line("the view name"));
  if (name == end) return "";
  if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
  src.skip_section(end);
  return name;
}

// The fields the command line writes into every MSH file (per-tet
// "quality", per-node "boundary"; apps/output_fields.cpp) are computed afresh
// on each write, so reading them loses nothing, and a note on them would
// warn about every file tetsmooth wrote (the VTK readers do the same).
bool is_recomputed_field(const std::string& section, const std::string& view) {
  return (section == "$ElementData" && view == "quality") || (section == "$NodeData" && view == "boundary");
}

template <class Source>
void read_sections(Source& src, ReadState& state) {
  for (;;) {
    const std::string section(src.next_section());
    if (section.empty()) return;
    if (section[0] != '$' || section.compare(0, 4, "$End") == 0 || section.find_first_of(" \t") != std::string::npos)
      src.fail("expected a section such as $Nodes, found " + quoted_token(section));
    const std::string end = "$End" + section.substr(1);
    const auto once = [&](bool& seen) {
      if (seen) src.fail("a second " + section + " section");
      seen = true;
    };
    if (section == "$Nodes" || (section == "$ParametricNodes" && state.major == 2)) {
      // MSH 2.2 with Mesh.SaveParametric gives its nodes in $ParametricNodes
      // instead (MSH 4.1 flags parametric node blocks inside $Nodes).
      if (state.has_nodes)
        src.fail(state.major == 2 ? "a second node section: " + section + " after $Nodes or $ParametricNodes"
                                  : "a second $Nodes section");
      state.has_nodes = true;
      state.major == 4 ? gmsh::read_nodes_v41(src, state)
                       : gmsh::read_nodes_v22(src, state, section == "$ParametricNodes");
    } else if (section == "$Elements") {
      if (!state.has_nodes)
        src.fail(state.major == 2 ? "$Elements before $Nodes or $ParametricNodes" : "$Elements before $Nodes");
      once(state.has_elements);
      state.major == 4 ? gmsh::read_elements_v41(src, state) : gmsh::read_elements_v22(src, state);
    } else if (section == "$Entities" && state.major == 4) {
      once(state.has_entities);
      read_entities_section(src, state);
      check_partition_tags(src, state);
    } else if (section == "$PartitionedEntities" && state.major == 4) {
      once(state.has_partitions);
      state.partitions = gmsh::read_partitioned_entities(src);
      check_partition_tags(src, state);
    } else if (section == "$PhysicalNames") {
      for (const auto& [name, body] : state.mesh.extras.raw_sections)
        if (name == section) src.fail("a second $PhysicalNames section");
      read_physical_names(src, state);
    } else if (section == "$MeshFormat") {
      src.fail("a second $MeshFormat section");
    } else if (section == "$NodeData" || section == "$ElementData") {
      const std::string view = skip_data_section(src, end);
      if (!is_recomputed_field(section, view)) note_skipped(section, state.mesh.extras, view);
      continue;
    } else {
      src.skip_section(end);
      note_skipped(section, state.mesh.extras);
      continue;
    }
    src.expect_end(end);
  }
}

// The first physical tag of entity (dim, tag), a model or a partitioned
// one; 0 when it has none or is unknown.
int physical_of(const ReadState& state, int dim, int tag) {
  const gmsh::Entities& declared = state.entities.find(dim, tag) != nullptr ? state.entities : state.partitions;
  return gmsh::first_physical(declared, dim, tag);
}

// MSH 4 elements carry only their entity; the physical tag is the entity's
// (its first, when it belongs to several groups).
void map_physicals(ReadState& state) {
  bool any = false;
  for (const gmsh::Entities* entities : {&state.entities, &state.partitions})
    for (const gmsh::Entity& e : entities->list()) any = any || !e.physicals.empty();
  if (!any) return;
  FileExtras& extras = state.mesh.extras;
  extras.tet_tags.clear();
  for (int entity : extras.tet_entity_tags) extras.tet_tags.push_back(physical_of(state, 3, entity));
  for (PassThroughBlock& block : extras.blocks) {
    const int dim = gmsh::element_type_of_kind(block.kind)->dim;
    block.tags.clear();
    for (int entity : block.entity_tags) block.tags.push_back(physical_of(state, dim, entity));
  }
}

// ---- partitioned files ------------------------------------------------------
//
// A partitioned file (Gmsh's mesh.partition) puts every element and node on
// a partitioned entity: the part of a model entity, its parent, in some
// partitions. The reader merges the partitions back into one mesh: elements
// and nodes go to the parent entities, which $Entities declares with the
// physical tags that Gmsh copies onto their parts. The writer then writes an
// ordinary file from the file's own $Entities, which Gmsh and meshio read
// with the same physical groups. (Writing the partitions back instead would
// mean keeping $PartitionedEntities, ghost elements and partition
// boundaries consistent, and meshio reads no partitioned file.)
//
// Gmsh also puts elements on the boundaries between partitions: triangles
// on a surface whose parent is the volume, lines whose parent is a surface
// or a volume, points. They are no part of the model, they carry the
// parent's physical tags on an entity of lower dimension, and as
// pass-through elements they would pin the nodes of those boundaries: they
// are dropped.

// The entity an element of dimension `dim` on entity `tag` belongs to once
// the partitions are merged: the parent of a partitioned entity, otherwise
// `tag` itself; nullopt for an element on a partition boundary.
std::optional<int> merged_entity(const gmsh::Entities& partitions, int dim, int tag) {
  const gmsh::Entity* part = partitions.find(dim, tag);
  if (part == nullptr || part->parent_tag == 0) return tag;
  if (part->parent_dim != dim) return std::nullopt;
  return part->parent_tag;
}

// Moves the elements of `block` to their merged entities and drops those on
// partition boundaries; returns how many it dropped.
std::size_t merge_block(const gmsh::Entities& partitions, PassThroughBlock& block) {
  const int dim = gmsh::element_type_of_kind(block.kind)->dim;
  const auto nodes = static_cast<std::size_t>(block.nodes_per_element);
  const std::size_t count = block.entity_tags.size();
  std::size_t kept = 0;
  for (std::size_t e = 0; e < count; ++e) {
    const std::optional<int> entity = merged_entity(partitions, dim, block.entity_tags[e]);
    if (!entity) continue;
    for (std::size_t k = 0; k < nodes; ++k) block.connectivity[kept * nodes + k] = block.connectivity[e * nodes + k];
    block.entity_tags[kept] = *entity;
    if (!block.tags.empty()) block.tags[kept] = block.tags[e];
    if (!block.element_tags.empty()) block.element_tags[kept] = block.element_tags[e];
    ++kept;
  }
  block.connectivity.resize(kept * nodes);
  block.entity_tags.resize(kept);
  if (!block.tags.empty()) block.tags.resize(kept);
  if (!block.element_tags.empty()) block.element_tags.resize(kept);
  return count - kept;
}

// Nodes on a partitioned entity go to its parent, whatever its dimension:
// a node between two partitions of a volume is inside the volume.
void merge_node_entities(const gmsh::Entities& partitions, FileExtras& extras) {
  for (std::size_t i = 0; i < extras.node_entity_tags.size(); ++i) {
    const gmsh::Entity* part = partitions.find(extras.node_entity_dims[i], extras.node_entity_tags[i]);
    if (part == nullptr || part->parent_tag == 0) continue;
    extras.node_entity_dims[i] = part->parent_dim;
    extras.node_entity_tags[i] = part->parent_tag;
  }
}

// After map_physicals, so that every element keeps the physical tag of the
// partitioned entity it was read on: the parent's in files Gmsh writes, and
// still there when $Entities does not declare the parent (the writer then
// makes entities up from the elements' tags).
void merge_partitions(ReadState& state) {
  FileExtras& extras = state.mesh.extras;
  // The parent of a partitioned volume is a volume (read_partitioned_entities
  // checks), so no tet is dropped.
  for (int& tag : extras.tet_entity_tags) tag = merged_entity(state.partitions, 3, tag).value_or(tag);
  std::size_t dropped = 0;
  for (PassThroughBlock& block : extras.blocks) dropped += merge_block(state.partitions, block);
  extras.blocks.erase(std::remove_if(extras.blocks.begin(), extras.blocks.end(),
                                     [](const PassThroughBlock& block) { return block.connectivity.empty(); }),
                      extras.blocks.end());
  merge_node_entities(state.partitions, extras);
  extras.read_notes.push_back(
      "the partitions are merged" +
      (dropped > 0 ? " and " + std::to_string(dropped) + " elements on partition boundaries dropped" : std::string()) +
      "; the written file is not partitioned");
}

// Element tags that cannot be written back (zero, one used twice, or one
// past the 32-bit ints of field data) are dropped, so that a written file
// numbers its elements 1, 2, ... instead of carrying tags that Gmsh would
// refuse; the user hears of it.
void check_element_tags(FileExtras& extras, std::size_t tets) {
  const std::optional<long long> bad =
      gmsh::unusable_tag(gmsh::file_element_tags(extras, tets), gmsh::kLargestIntTag);
  if (!bad) return;
  extras.tet_element_tags.clear();
  for (PassThroughBlock& block : extras.blocks) block.element_tags.clear();
  const std::string why = *bad <= 0                     ? " is not positive"
                          : *bad > gmsh::kLargestIntTag ? " exceeds " + std::to_string(gmsh::kLargestIntTag)
                                                        : " is used twice";
  extras.read_notes.push_back("element tag " + std::to_string(*bad) + why +
                              "; MSH output numbers the elements 1, 2, ... instead of keeping their tags");
}

template <class Source>
TetMesh finish(Source& src, ReadState& state, const std::string& source) {
  read_sections(src, state);
  if (!state.has_nodes) src.fail(state.major == 2 ? "no $Nodes or $ParametricNodes section" : "no $Nodes section");
  if (!state.has_elements) src.fail("no $Elements section");
  if (state.mesh.tets.empty()) src.fail("no tetrahedra (element type 4 or 11): a volume mesh is needed");
  if (state.major == 4 && (state.has_entities || state.has_partitions)) map_physicals(state);
  if (state.has_partitions) merge_partitions(state);
  if (state.major == 2) gmsh::finish_elements_v22(state);
  check_element_tags(state.mesh.extras, state.mesh.num_tets());

  TetMesh& mesh = state.mesh;
  // `fixed` stays empty when no pass-through element pins a node.
  if (std::any_of(mesh.extras.blocks.begin(), mesh.extras.blocks.end(),
                  [](const PassThroughBlock& block) { return !block.connectivity.empty(); })) {
    mesh.fixed.resize(mesh.num_nodes(), 0);
    mark_element_nodes(mesh.extras.blocks, mesh.fixed);
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
    lines.fail("unsupported MSH version " + quoted_token(version) + "; 4.1 and 2.2 are read (Gmsh can convert others)");
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
