#include "mesh/io/writable_check.hpp"

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <streambuf>
#include <unordered_map>

#include "mesh/errors.hpp"
#include "mesh/io/abaqus_io.hpp"
#include "mesh/io/ansys_io.hpp"
#include "mesh/io/atomic_file.hpp"
#include "mesh/io/exodus_io.hpp"
#include "mesh/io/file_numbers.hpp"
#include "mesh/io/flac3d_io.hpp"
#include "mesh/io/gmsh_detail.hpp"
#include "mesh/io/gmsh_io.hpp"
#include "mesh/io/gmsh_write_plan.hpp"
#include "mesh/io/lsdyna_io.hpp"
#include "mesh/io/medit_detail.hpp"
#include "mesh/io/medit_io.hpp"
#include "mesh/io/nastran_io.hpp"
#include "mesh/io/number_text.hpp"
#include "mesh/io/tetgen_io.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/io/tsm_cache.hpp"
#include "mesh/io/vtk_legacy.hpp"
#include "mesh/io/vtu_io.hpp"
#include "mesh/region_interfaces.hpp"
#include "mesh/second_order.hpp"
#include "mesh/topology.hpp"

namespace tetsmooth {
namespace {

// Accepts and drops every byte, so a writer runs to the end without failing.
class NullBuf : public std::streambuf {
 protected:
  int_type overflow(int_type ch) override { return traits_type::not_eof(ch); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// One tet over four nodes (ten for a second-order mesh), and each of the
// mesh's blocks with its kind and no elements; tags are kept where the mesh
// has them, one per element.
TetMesh probe_of(const TetMesh& mesh) {
  TetMesh probe;
  probe.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  probe.tets = {0, 1, 2, 3};
  if (!mesh.midsides.empty())
    for (const auto& edge : kTetEdges) {
      probe.midsides.push_back(static_cast<index_t>(probe.num_nodes()));
      for (int c = 0; c < 3; ++c)
        probe.xyz.push_back(0.5 * (probe.xyz[3 * static_cast<std::size_t>(edge[0]) + static_cast<std::size_t>(c)] +
                                   probe.xyz[3 * static_cast<std::size_t>(edge[1]) + static_cast<std::size_t>(c)]));
    }
  const FileExtras& e = mesh.extras;
  if (!e.tet_tags.empty()) probe.extras.tet_tags = {e.tet_tags.front()};
  if (!e.tet_entity_tags.empty()) probe.extras.tet_entity_tags = {e.tet_entity_tags.front()};
  for (const PassThroughBlock& b : e.blocks)
    probe.extras.blocks.push_back(PassThroughBlock{b.kind, b.nodes_per_element, {}, {}, {}, {}});
  return probe;
}

void write_probe(const TetMesh& probe, MeshFormat format, std::ostream& out) {
  switch (format) {
    case MeshFormat::TetGen:
      write_tetgen_node(probe, out);
      return write_tetgen_ele(probe, out);
    case MeshFormat::Vtu:
      return write_vtu(probe, out, {});
    case MeshFormat::Vtk:
      return write_vtk(probe, out, {});
    case MeshFormat::Msh41:
      return write_gmsh(probe, out, MshFlavour::V41Ascii, {});
    case MeshFormat::Msh41Binary:
      return write_gmsh(probe, out, MshFlavour::V41Binary, {});
    case MeshFormat::Msh22:
      return write_gmsh(probe, out, MshFlavour::V22Ascii, {});
    case MeshFormat::Medit:
      return write_medit(probe, out);
    case MeshFormat::Cache:
      return write_cache(probe, out);
    case MeshFormat::Abaqus:
      return write_abaqus(probe, out);
    case MeshFormat::Nastran:
      return write_nastran(probe, out);
    case MeshFormat::Flac3d:
      return write_flac3d(probe, out);
    case MeshFormat::Exodus:
      return check_exodus_writable(probe);
    case MeshFormat::Ansys:
      return write_ansys(probe, out);
    case MeshFormat::Lsdyna:
      return write_lsdyna(probe, out);
    case MeshFormat::Auto:
      break;
  }
}

bool is_msh(MeshFormat format) {
  return format == MeshFormat::Msh41 || format == MeshFormat::Msh41Binary || format == MeshFormat::Msh22;
}

// MSH, and VTU and VTK (as meshio's gmsh:geometrical cell data), keep the
// Gmsh entity tags of the elements.
bool keeps_entity_tags(MeshFormat format) {
  return is_msh(format) || format == MeshFormat::Vtu || format == MeshFormat::Vtk;
}

bool is_msh41(MeshFormat format) { return format == MeshFormat::Msh41 || format == MeshFormat::Msh41Binary; }

// Whether `format` keeps the entity each node of `mesh` is classified on:
// MSH 4.1 where the writer keeps every node of a point, curve or surface on
// one (msh41_feature_nodes), VTU and VTK (as meshio's gmsh:dim_tags point
// data).
bool keeps_node_classification(const TetMesh& mesh, MeshFormat format) {
  if (!is_msh41(format)) return format == MeshFormat::Vtu || format == MeshFormat::Vtk;
  const std::vector<std::uint8_t> features = gmsh::msh41_feature_nodes(mesh);
  if (features.empty()) return false;
  for (std::size_t i = 0; i < features.size(); ++i)
    if (mesh.extras.node_entity_dims[i] < 3 && !features[i]) return false;
  return true;
}

// What `format` keeps of the data that region_interface_nodes reads besides
// the region tags: Gmsh entity tags (keeps_entity_tags), and the nodes'
// classification (keeps_node_classification).
InterfaceSources kept_sources(const TetMesh& mesh, MeshFormat format) {
  return {keeps_entity_tags(format), keeps_node_classification(mesh, format)};
}

// Interface nodes as a run on the output would find them: the regions stay
// apart where the format keeps them (MSH and TetGen do, MSH by renumbering
// negative tags; .tsm not), and Gmsh's entities where it keeps those.
std::vector<std::uint8_t> kept_interface_nodes(const TetMesh& mesh, MeshFormat format) {
  if (format == MeshFormat::Cache) return std::vector<std::uint8_t>(mesh.num_nodes(), kNotPinned);
  return region_interface_nodes(mesh, kept_sources(mesh, format));
}

// Pinned nodes that the format loses and that a later run would move: VTU,
// VTK, Medit (RequiredVertices), Abaqus (the deck, or a node set) and
// Nastran and FLAC3D (the deck or grid, or a comment it reads back) and
// Exodus (the file, or a node set), ANSYS (the file, or a node
// component) and LS-DYNA (the deck, or a node set) write every pin, MSH only
// element nodes,
// TetGen and .tsm none. Boundary nodes stay fixed anyway, and so do nodes on
// an interface where the format keeps what tells of it.
std::size_t pins_lost(const TetMesh& mesh, MeshFormat format) {
  if (mesh.fixed.empty() || format == MeshFormat::Vtu || format == MeshFormat::Vtk || format == MeshFormat::Medit ||
      format == MeshFormat::Abaqus || format == MeshFormat::Nastran || format == MeshFormat::Flac3d ||
      format == MeshFormat::Exodus || format == MeshFormat::Ansys || format == MeshFormat::Lsdyna)
    return 0;
  std::vector<std::uint8_t> kept(mesh.num_nodes(), 0);
  if (format != MeshFormat::TetGen && format != MeshFormat::Cache) mark_element_nodes(mesh.extras.blocks, kept);
  std::size_t candidates = 0;
  for (std::size_t i = 0; i < mesh.fixed.size(); ++i) candidates += mesh.fixed[i] && !kept[i];
  if (candidates == 0) return 0;  // spares the topology below
  // What stays in the output: the boundary, kept interfaces and kept pins,
  // and the midside nodes of edges between such nodes (those of a 6-node
  // boundary triangle, say).
  std::vector<std::uint8_t> stays = find_boundary_nodes(mesh.tets, mesh.num_nodes());
  const std::vector<std::uint8_t> interface = kept_interface_nodes(mesh, format);
  for (std::size_t i = 0; i < stays.size(); ++i) stays[i] = stays[i] || interface[i] != kNotPinned || kept[i];
  mark_midsides_of_marked_edges(mesh, stays);
  std::size_t lost = 0;
  for (std::size_t i = 0; i < mesh.fixed.size(); ++i) lost += mesh.fixed[i] && !stays[i];
  return lost;
}

// Nodes that a run on this mesh keeps in place through Gmsh's entities
// alone (on an interface between volumes of one region, or on a point,
// curve or surface inside the mesh; region_interface_nodes) and that a run
// on the output would move: the format drops the entity tags or the node
// classification that tell of them. Nodes the file pins are left to
// pins_lost, and region interfaces that .tsm loses to the note on its
// region tags.
std::size_t entity_pins_lost(const TetMesh& mesh, MeshFormat format) {
  const FileExtras& e = mesh.extras;
  const std::size_t nodes = mesh.num_nodes();
  const auto pinned_by_file = [&](std::size_t i) { return !mesh.fixed.empty() && mesh.fixed[i]; };
  // Cheap checks first: most meshes lose nothing here, and those spare the
  // topology below.
  const bool entities_lost = !keeps_entity_tags(format) && tet_entities_split_regions(mesh);
  bool classified = false;
  if (e.node_entity_dims.size() == nodes)
    for (std::size_t i = 0; i < nodes && !classified; ++i)
      classified = e.node_entity_dims[i] < 3 && !pinned_by_file(i);
  const InterfaceSources kept_sources{keeps_entity_tags(format), classified && keeps_node_classification(mesh, format)};
  if (!entities_lost && (!classified || kept_sources.node_entities)) return 0;
  // Neither marks a boundary node: those stay fixed anyway.
  const std::vector<std::uint8_t> all = region_interface_nodes(mesh);
  const std::vector<std::uint8_t> kept = region_interface_nodes(mesh, kept_sources);
  // MSH 4.1 loses only the classification of the nodes whose entity it
  // cannot declare (gmsh_write_plan.hpp): the others stay on their feature.
  // (It keeps the entity tags, so no interface is lost with them.)
  std::vector<std::uint8_t> features;
  if (is_msh41(format) && !kept_sources.node_entities) features = gmsh::msh41_feature_nodes(mesh);
  const auto feature_kept = [&](std::size_t i) { return !features.empty() && features[i]; };
  std::size_t lost = 0;
  for (std::size_t i = 0; i < nodes; ++i)
    lost += all[i] != kNotPinned && kept[i] == kNotPinned && !pinned_by_file(i) && !feature_kept(i);
  return lost;
}

// Whether Gmsh entity tags tell apart elements of one region (or, without
// region tags, of one block), in the tets or in a pass-through block (the
// surface patches of a boundary, say): only then does their loss lose
// anything that the region tags do not carry.
bool entities_split_regions(const FileExtras& e) {
  const auto splits = [](const std::vector<int>& entities, const std::vector<int>& regions) {
    const bool tagged = regions.size() == entities.size();
    std::unordered_map<int, int> entity_of_region;
    for (std::size_t k = 0; k < entities.size(); ++k)
      if (entity_of_region.try_emplace(tagged ? regions[k] : 0, entities[k]).first->second != entities[k])
        return true;
    return false;
  };
  return splits(e.tet_entity_tags, e.tet_tags) ||
         std::any_of(e.blocks.begin(), e.blocks.end(),
                     [&](const PassThroughBlock& b) { return splits(b.entity_tags, b.tags); });
}

// The first `shown` of `names` in double quotes, and how many more there are.
std::string quoted_list(std::vector<std::string> names, std::size_t shown) {
  for (std::string& name : names) name = "\"" + name + "\"";
  return listed(names, shown);
}

}  // namespace

std::vector<std::string> output_losses(const TetMesh& mesh, const std::string& path, MeshFormat format) {
  const MeshFormat f = format_from_path(path, format);
  const std::string name = format_name(f);
  const FileExtras& e = mesh.extras;
  std::vector<std::string> notes;
  if (f == MeshFormat::TetGen || f == MeshFormat::Cache) {
    std::string kinds;
    std::size_t elements = 0;
    for (const PassThroughBlock& b : e.blocks) {
      const std::size_t n = b.connectivity.size() / static_cast<std::size_t>(std::max(b.nodes_per_element, 1));
      if (n == 0) continue;
      elements += n;
      kinds += (kinds.empty() ? "" : ", ") + count_of(n, b.kind);
    }
    if (elements > 0) notes.push_back(kinds + " will not be written: " + name + " holds tets only");
  }
  if (f == MeshFormat::Medit) {
    std::size_t points = 0;
    for (const PassThroughBlock& b : e.blocks)
      if (b.kind == "vertex") points += b.connectivity.size();
    if (points > 0)
      notes.push_back(count_of(points, "point element") + " will be written as RequiredVertices, without " +
                      (points == 1 ? "its tag or element id (its node stays"
                                   : "their tags or element ids (their nodes stay") +
                      " pinned): " + name + " has no point elements");
  }
  if (const std::size_t lost = pins_lost(mesh, f); lost > 0)
    notes.push_back(count_of(lost, "pinned node") + " will not be pinned in the " + name +
                    " output, so a later run may move " + (lost == 1 ? "it" : "them"));
  if (const std::size_t lost = entity_pins_lost(mesh, f); lost > 0)
    notes.push_back(count_of(lost, "node") + " that Gmsh's entities keep in place (between volumes of one " +
                    "physical group, or on points, curves or surfaces inside the mesh) will not be pinned in the " +
                    name + " output, " +
                    (f == MeshFormat::Msh41 || f == MeshFormat::Msh41Binary
                         ? "which has no entity of a tag below 1 to put them on"
                     : keeps_entity_tags(f) ? "which does not keep the nodes' entities"
                                            : "which has no place for Gmsh entities") +
                    ", so a later run may move " + (lost == 1 ? "it" : "them"));
  const bool any_marker = std::any_of(e.node_markers.begin(), e.node_markers.end(), [](int m) { return m != 0; });
  if (f != MeshFormat::TetGen && f != MeshFormat::Medit && any_marker)
    notes.push_back("the node markers will not be written: " + name + " has no place for them");
  if (f != MeshFormat::TetGen && e.node_attribute_count > 0 && !e.node_attributes.empty())
    notes.push_back("the node attributes (" + std::to_string(e.node_attribute_count) +
                    " per node) will not be written: " + name + " has no place for them");
  if (f != MeshFormat::Medit) {
    std::string sections;
    std::size_t count = 0;
    for (const auto& [section, body] : e.raw_sections)
      if (medit::is_medit_section(section)) sections += (count++ == 0 ? "" : ", ") + section;
    if (count > 0)
      notes.push_back(std::string("the Medit section") + (count == 1 ? " " : "s ") + sections +
                      " will not be written: " + name + " has no place for " + (count == 1 ? "it" : "them"));
  }
  if (f != MeshFormat::TetGen && has_tet_attributes(e, mesh.num_tets()))
    notes.push_back("the TetGen tet attributes (" + std::to_string(e.tet_attribute_count) +
                    " per tet) will not be written: " + name +
                    (f == MeshFormat::Cache ? " has no place for them"
                                            : " keeps only the region tags (the first attribute's values where "
                                              "whole, else their ranks)"));
  const bool msh = f == MeshFormat::Msh41 || f == MeshFormat::Msh41Binary || f == MeshFormat::Msh22;
  // MSH, Abaqus, Nastran and FLAC3D keep the file's node and element numbers.
  const bool node_ids = !numbered_by_position(e.node_tags), element_ids = !numbered_by_position(e.tet_element_tags);
  const bool abaqus = raw_section(e, "abaqus:deck") != nullptr, nastran = raw_section(e, "nastran:deck") != nullptr;
  const bool flac3d = raw_section(e, "flac3d:deck") != nullptr;
  const bool exodus = raw_section(e, "exodus:deck") != nullptr;
  const bool ansys = raw_section(e, "ansys:deck") != nullptr;
  const bool lsdyna = raw_section(e, "lsdyna:deck") != nullptr;
  const bool keeps_numbers = msh || f == MeshFormat::Abaqus || f == MeshFormat::Nastran || f == MeshFormat::Flac3d ||
                             f == MeshFormat::Exodus || f == MeshFormat::Ansys || f == MeshFormat::Lsdyna;
  if (!keeps_numbers && (node_ids || element_ids))
    notes.push_back(std::string(abaqus    ? "the Abaqus "
                                : nastran ? "the Nastran "
                                : flac3d  ? "the FLAC3D "
                                : exodus  ? "the Exodus "
                                : ansys   ? "the ANSYS "
                                : lsdyna  ? "the LS-DYNA "
                                          : "the Gmsh ") +
                    (flac3d ? (node_ids && element_ids ? "gridpoint and zone" : node_ids ? "gridpoint" : "zone")
                            : (node_ids && element_ids ? "node and element" : node_ids ? "node" : "element")) +
                    (abaqus || ansys ? " numbers" : nastran || flac3d || exodus || lsdyna ? " ids" : " tags") +
                    " will not be written: " + name +
                    " numbers them by position");
  const std::string lost = f == MeshFormat::Abaqus ? abaqus_numbers_lost(mesh)
                           : f == MeshFormat::Nastran ? nastran_numbers_lost(mesh)
                           : f == MeshFormat::Flac3d  ? flac3d_numbers_lost(mesh)
                           : f == MeshFormat::Exodus  ? exodus_numbers_lost(mesh)
                           : f == MeshFormat::Ansys   ? ansys_numbers_lost(mesh)
                           : f == MeshFormat::Lsdyna  ? lsdyna_numbers_lost(mesh)
                                                      : "";
  // MSH numbers every element in one sequence: ids that are distinct only
  // within their kind (FLAC3D's zones and faces) cannot all be kept.
  if (const std::string msh_lost = msh ? numbers_lost(mesh, gmsh::kLargestIntTag) : "";
      msh_lost.find("element") != std::string::npos)
    notes.push_back(std::string(flac3d ? "the FLAC3D zone and face ids" : "the element numbers of the file") +
                    " cannot all be kept (MSH element tags must be positive and distinct across all elements, at most " +
                    std::to_string(gmsh::kLargestIntTag) + "): " + name + " numbers the elements 1, 2, ... instead");
  // Node tags may be as large as MSH 4.1 reads them, but must be distinct
  // (the parts of an Abaqus deck each number their nodes 1, 2, ...).
  if (const std::string msh_lost =
          msh ? numbers_lost(mesh, f == MeshFormat::Msh22 ? gmsh::kLargestIntTag : INT64_MAX) : "";
      msh_lost.find("node") != std::string::npos)
    notes.push_back("the node numbers of the file cannot all be kept (MSH node tags must be positive and distinct): " +
                    name + " numbers the nodes 1, 2, ... instead");
  if (!lost.empty())
    notes.push_back("the " + lost + " numbers of the file cannot all be kept (each must be positive and distinct" +
                    (f == MeshFormat::Nastran || f == MeshFormat::Ansys || f == MeshFormat::Lsdyna ? ", at most 99,999,999"
                     : f == MeshFormat::Flac3d || f == MeshFormat::Exodus ? ", at most 2,147,483,647"
                                               : "") +
                    "): " + name + " numbers them 1, 2, ... instead");
  if (const std::string* files = raw_section(e, "abaqus:includes"); files != nullptr && f == MeshFormat::Abaqus)
    notes.push_back("the *INCLUDE files (" + *files + ") will be written inline, in the one output deck");
  if (const std::string* files = raw_section(e, "nastran:includes"); files != nullptr && f == MeshFormat::Nastran)
    notes.push_back("the INCLUDE files (" + *files + ") will be written inline, in the one output deck");
  if (const std::string* keywords = raw_section(e, "abaqus:keywords"); keywords != nullptr && f != MeshFormat::Abaqus)
    notes.push_back("the rest of the Abaqus deck (" + *keywords + ") will not be written: " + name +
                    " holds the mesh alone");
  if (const std::string* types = raw_section(e, "nastran:types"); types != nullptr && f != MeshFormat::Nastran)
    notes.push_back("the rest of the Nastran deck (" + *types + ") will not be written: " + name +
                    " holds the mesh alone");
  if (const std::string* types = raw_section(e, "nastran:uncarried"); types != nullptr && f != MeshFormat::Nastran)
    notes.push_back("the " + *types + " elements will not be written: " + name +
                    " has no place for them (their nodes were pinned)");
  if (const std::string* count = raw_section(e, "flac3d:cut-bricks"); count != nullptr && f != MeshFormat::Flac3d) {
    const bool one = *count == "1";
    notes.push_back(*count + (one ? " B7 zone" : " B7 zones") + " will not be written: " + name + " has no place for " +
                    (one ? "it (its nodes were pinned)" : "them (their nodes were pinned)"));
  }
  if (const std::string* rest = raw_section(e, "exodus:rest"); rest != nullptr && f != MeshFormat::Exodus)
    notes.push_back("the rest of the Exodus file (" + *rest + ") will not be written: " + name +
                    " holds the mesh alone");
  if (const std::string* types = raw_section(e, "exodus:uncarried"); types != nullptr && f != MeshFormat::Exodus)
    notes.push_back("the elements of " + *types + " will not be written: " + name +
                    " has no place for them (their nodes were pinned)");
  if (const std::string* commands = raw_section(e, "ansys:commands"); commands != nullptr && f != MeshFormat::Ansys)
    notes.push_back("the rest of the ANSYS file (" + *commands + ") will not be written: " + name +
                    " holds the mesh alone");
  if (const std::string* types = raw_section(e, "ansys:uncarried"); types != nullptr && f != MeshFormat::Ansys)
    notes.push_back("the " + *types + " elements will not be written: " + name +
                    " has no place for them (their nodes were pinned)");
  if (const std::string* files = raw_section(e, "lsdyna:includes"); files != nullptr && f == MeshFormat::Lsdyna)
    notes.push_back("the *INCLUDE files (" + *files + ") will be written inline, in the one output deck");
  if (const std::string* keywords = raw_section(e, "lsdyna:keywords"); keywords != nullptr && f != MeshFormat::Lsdyna)
    notes.push_back("the rest of the LS-DYNA deck (" + *keywords + ") will not be written: " + name +
                    " holds the mesh alone");
  if (const std::string* types = raw_section(e, "lsdyna:uncarried"); types != nullptr && f != MeshFormat::Lsdyna)
    notes.push_back("the elements of " + *types + " that other formats have no shape for will not be written: " +
                    name + " has no place for them (their nodes were pinned)");
  if (f == MeshFormat::Lsdyna && !lsdyna) {
    std::string kinds;
    for (const PassThroughBlock& b : e.blocks)
      if (const std::size_t n = elements_in(b); n > 0 && !lsdyna_writes_block(b))
        kinds += (kinds.empty() ? "" : ", ") + count_of(n, b.kind);
    if (!kinds.empty())
      notes.push_back(kinds + " will not be written: a new " + name +
                      " deck holds solids, shells and beams (their nodes are pinned in the node set "
                      "TETSMOOTH_PINNED)");
  }
  if (f == MeshFormat::Ansys && !ansys) {
    std::string kinds;
    for (const PassThroughBlock& b : e.blocks)
      if (const std::size_t n = elements_in(b); n > 0 && kind_dimension(b.kind) < 3)
        kinds += (kinds.empty() ? "" : ", ") + count_of(n, b.kind);
    if (!kinds.empty())
      notes.push_back(kinds + " will not be written: a new " + name +
                      " file holds solids (their nodes are pinned in the node component TETSMOOTH_PINNED, and "
                      "named regions of them become node components)");
  }
  if (f == MeshFormat::Flac3d && !flac3d) {
    std::string kinds;
    for (const PassThroughBlock& b : e.blocks)
      if (const std::size_t n = elements_in(b); n > 0 && !flac3d_writes_kind(b.kind, b.nodes_per_element))
        kinds += (kinds.empty() ? "" : ", ") + count_of(n, b.kind);
    if (!kinds.empty())
      notes.push_back(kinds + " will not be written: " + name +
                      " holds tets, bricks, wedges, pyramids, triangles and quads (their nodes are listed as pins)");
  }
  // MSH writes the names of the regions as physical names, FLAC3D as its
  // groups' names, Exodus as its blocks' names, ANSYS as its components',
  // LS-DYNA as its parts' headings, Abaqus as its element sets' names (a
  // deck kept keeps its own; a new one those that are plain set names).
  // (Exodus writes every kind of element the readers give: none is
  // dropped.)
  const bool keeps_names = msh || f == MeshFormat::Flac3d || f == MeshFormat::Exodus || f == MeshFormat::Ansys ||
                           f == MeshFormat::Lsdyna || f == MeshFormat::Abaqus;
  const char* names_are = abaqus   ? "the deck's element sets"
                          : flac3d ? "the grid's zone and face groups"
                          : ansys  ? "the file's element components"
                          : lsdyna ? "the deck's part headings"
                          : exodus ? "the file's element block names"
                                   : "Gmsh physical names";
  if ((abaqus || flac3d || exodus || ansys || lsdyna) && !keeps_names && raw_section(e, "$PhysicalNames") != nullptr)
    notes.push_back(std::string("the names of the regions (") + names_are + ") will not be written: " + name +
                    " has no place for them");
  if (const std::vector<std::string> names_lost =
          f == MeshFormat::Abaqus ? abaqus_names_lost(mesh) : std::vector<std::string>{};
      !names_lost.empty())
    notes.push_back("the names of " + count_of(names_lost.size(), "region") + " (" + names_are + ": " +
                    quoted_list(names_lost, 5) + ") will not be written: a new " + name +
                    " deck names a region's element set by its tag where the name is no plain set name (1 to 80 "
                    "letters, digits and underscores, the first a letter) or is another's in any case");
  if (f == MeshFormat::Abaqus && !abaqus_tags_read_back(mesh))
    notes.push_back(
        "the region tags will not be kept: a new abaqus deck names its element sets, and a run that reads it "
        "back takes the tags from the names' trailing numbers where those all differ, else numbers the sets 1, 2, "
        "... in order (the regions stay apart, under other numbers)");
  if (!msh && !abaqus && !flac3d && !exodus && !ansys && !lsdyna) {
    const bool names = !keeps_names && raw_section(e, "$PhysicalNames") != nullptr;
    const bool entities = !keeps_entity_tags(f) && entities_split_regions(e);
    if (names || entities)
      notes.push_back(std::string("the Gmsh ") + (names && entities ? "physical names and entity tags" : names ? "physical names" : "entity tags") +
                      " will not be written: " + name + " has no place for them");
  }
  // MSH keeps an element in every physical group of its entity; the other
  // formats with region tags give a cell one, the first group.
  if (!msh && f != MeshFormat::Cache)
    if (const std::size_t several = gmsh::elements_in_several_groups(e, f != MeshFormat::TetGen); several > 0)
      notes.push_back(count_of(several, "element") + " in several Gmsh physical groups will keep only the first: " +
                      name + " holds one region tag per " + (f == MeshFormat::TetGen ? "tet" : "element"));
  if (const std::map<int, int> renumbered = gmsh::negative_tag_renumbering(e); msh && !renumbered.empty()) {
    std::string pairs;
    for (const auto& [from, to] : renumbered)
      pairs += (pairs.empty() ? "" : ", ") + std::to_string(from) + " as " + std::to_string(to);
    notes.push_back("negative region tags are written as new positive ones (" + pairs +
                    "): MSH physical tags are positive");
  }
  if ((f == MeshFormat::Nastran && !nastran) || (f == MeshFormat::Ansys && !ansys) ||
      (f == MeshFormat::Lsdyna && !lsdyna)) {
    // Tags the mesh has that are no PIDs (materials); a mesh without tags
    // has none to lose.
    const auto not_id = [](int t) { return t <= 0 || t > 99999999; };
    bool tag_lost = std::any_of(e.tet_tags.begin(), e.tet_tags.end(), not_id);
    for (const PassThroughBlock& b : e.blocks) tag_lost = tag_lost || std::any_of(b.tags.begin(), b.tags.end(), not_id);
    std::string pairs;
    for (const auto& [from, to] : f == MeshFormat::Nastran ? nastran_region_ids(mesh).renumbered()
                                  : f == MeshFormat::Ansys ? ansys_new_materials(mesh)
                                                           : lsdyna_region_ids(mesh).renumbered())
      pairs += (pairs.empty() ? "" : ", ") + std::to_string(from) + " as " + std::to_string(to);
    if (tag_lost && !pairs.empty())
      notes.push_back(f == MeshFormat::Ansys
                          ? "region tags that are no material numbers are written as new ones (" + pairs +
                                "): ANSYS's material numbers are positive"
                          : "region tags that are no PIDs are written as new ones (" + pairs + "): " +
                                (f == MeshFormat::Nastran ? "Nastran's" : "LS-DYNA's") +
                                " PIDs are positive, of at most 8 digits");
  }
  if ((f == MeshFormat::Nastran && !nastran) || (f == MeshFormat::Lsdyna && !lsdyna)) {
    // A PID names one kind of property: shells and lines that share a tag
    // with solids (or lines with shells) get PIDs of their own.
    std::string pairs;
    const RegionIds pids = f == MeshFormat::Nastran ? nastran_region_ids(mesh) : lsdyna_region_ids(mesh);
    for (auto it = pids.split().rbegin(); it != pids.split().rend(); ++it)  // shells first
      pairs += (pairs.empty() ? "" : ", ") + std::string(it->first.first == 2 ? "shells" : "lines") + " of region " +
               std::to_string(it->first.second) + " as PID " + std::to_string(it->second);
    if (!pairs.empty())
      notes.push_back("elements of several dimensions in one region get PIDs of their own (" + pairs + "): " +
                      (f == MeshFormat::Nastran ? "a Nastran PID names one property entry (PSOLID, PSHELL or PROD)"
                                                : "an LS-DYNA part takes one section (solid, shell or beam)"));
  }
  if (msh && !gmsh::node_tags_fit_int(e.node_tags)) {
    const std::string largest = std::to_string(*std::max_element(e.node_tags.begin(), e.node_tags.end()));
    notes.push_back(f == MeshFormat::Msh22
                        ? "the Gmsh node tags will not be written (nodes are numbered 1, 2, ...): MSH 2.2 numbers "
                          "nodes by 32-bit int and node tag " + largest + " is larger"
                        : "no node field data will be written: MSH names the nodes of field data by 32-bit int and "
                          "node tag " + largest + " is larger");
  }
  if (f == MeshFormat::Cache && !e.tet_tags.empty())
    notes.push_back("the region tags will not be written: " + name + " holds coordinates and tets only");
  return notes;
}

void check_writable(const TetMesh& mesh, const std::string& path, MeshFormat format) {
  NullBuf nowhere;
  std::ostream out(&nowhere);
  checked_for(path, [&] { write_probe(probe_of(mesh), format_from_path(path, format), out); });
}

}  // namespace tetsmooth
