#pragma once
// Material interfaces of a mesh whose tets carry region tags
// (FileExtras::tet_tags: Gmsh physical groups, TetGen region attributes,
// Medit references, VTK tag arrays), and the rest of the geometry a Gmsh
// mesh tells of: the volume entity of each tet (FileExtras::tet_entity_tags:
// MSH 2.2 elementary tags, MSH 4.1 entity blocks, gmsh:geometrical cell data
// in VTU and VTK), as one physical group may hold several volumes side by
// side, and the point, curve or surface entity Gmsh classified a node on
// (FileExtras::node_entity_dims: MSH 4.1, gmsh:dim_tags point data in VTU
// and VTK), which shows surfaces, curves and points embedded in a volume
// even where the file has no elements on them.
#include <cstdint>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// What tells where the interfaces are besides the region tags. All of it
// by default; a caller asking what an output format keeps turns off what
// the format drops.
struct InterfaceSources {
  // Tets of different Gmsh volume entities are on different sides of an
  // interface, even within one region (physical group).
  bool entity_tags = true;
  // Nodes Gmsh classified on an entity of dimension 0, 1 or 2 lie on a
  // geometric feature that Gmsh's mesh conforms to.
  bool node_entities = true;
};

// Per node, why it stays in place besides the boundary and the file's pins.
// Boundary nodes (on a face of one tet, as find_boundary_nodes finds them)
// are kNotPinned: they stay in place anyway.
inline constexpr std::uint8_t kNotPinned = 0;
// On a face shared by tets of different regions or, with entity_tags, of
// different Gmsh volume entities, and not on the boundary (the interface's
// rim is).
inline constexpr std::uint8_t kOnInterface = 1;
// With node_entities: classified by Gmsh on a point, curve or surface, in
// a tet but on no boundary face and no interface face, and not pinned by
// the file (mesh.fixed; those stay anyway): a feature inside the mesh (an
// embedded surface, say).
inline constexpr std::uint8_t kOnGmshFeature = 2;

// kOnInterface or kOnGmshFeature for the nodes that must stay in place,
// kNotPinned for the others; all kNotPinned when the mesh carries none of
// the data above. A tet listed more than once (Gmsh's MSH 2.2 writer
// repeats the tets of a volume in two physical groups, under both tags) is
// one tet with all of its (region, entity) pairs: a face is an interface
// when its two tets' sets of pairs differ. The face sort runs on `threads`
// (as build_topology's: 1 the default, 0 all cores; the same result).
std::vector<std::uint8_t> region_interface_nodes(const TetMesh& mesh, InterfaceSources sources = {},
                                                 int threads = 1);

// Whether the Gmsh entity tags of the tets tell apart tets of one region
// (of the whole mesh, where the tets carry no region tags): only then do
// they add interfaces.
bool tet_entities_split_regions(const TetMesh& mesh);

}  // namespace tetsmooth
