#pragma once
// Whether an output format can hold a mesh, asked before the work that
// produces it, so that a long smoothing run does not end in "cannot write".
#include <string>
#include <vector>

#include "mesh/io/mesh_io.hpp"

namespace tetsmooth {

// Throws OutputError ("cannot write 'path': ...") when `format` (Auto: from
// the name) has no place for a kind of element the mesh carries, a
// 3-node line in Nastran output for instance. The writers' own checks decide: they
// run on a probe that has the mesh's element kinds and tags but only one tet
// and no other elements, written nowhere, so the check costs microseconds
// whatever the mesh's size.
void check_writable(const TetMesh& mesh, const std::string& path, MeshFormat format = MeshFormat::Auto);

// What `format` (Auto: from the name) will not carry of what the mesh holds,
// one sentence each, for a warning before the work:
//  * elements other than tets (TetGen and .tsm hold tets only);
//  * pins that a later run would lose: MSH keeps a pin only through an
//    element on the node, TetGen and .tsm not at all, and boundary nodes
//    and (where the format keeps region tags) interface nodes stay fixed
//    anyway; VTU, VTK and Medit keep every pin;
//  * nodes that stay fixed only through Gmsh's entities (an interface
//    between volumes of one physical group, a point, curve or surface
//    inside the mesh: region_interface_nodes) where the format drops the
//    entity tags (all but MSH, VTU and VTK) or the nodes' classification
//    (all but MSH 4.1, VTU and VTK; MSH 4.1 keeps a node's where it can
//    declare the entity) and pins none of them itself;
//  * TetGen node markers (non-zero ones), node attributes and tet
//    attributes (what tet_tags cannot give back);
//  * Medit-only sections (Ridges, Normals, Identifier, ...);
//  * region tags (.tsm), and the physical groups after the first of
//    elements whose Gmsh entity is in several (one tag per element:
//    VTU, VTK, Medit, TetGen);
//  * Gmsh node and element tags, physical names and entity tags (formats
//    other than MSH), and what node tags past the 32-bit ints of field
//    data cost in MSH (the node fields in 4.1, the tags themselves in 2.2).
std::vector<std::string> output_losses(const TetMesh& mesh, const std::string& path,
                                       MeshFormat format = MeshFormat::Auto);

}  // namespace tetsmooth
