#pragma once
// TetGen .node/.ele files (https://wias-berlin.de/software/tetgen/fformats.html).
//
//   X.node: "<#nodes> 3 <#attributes> <0|1 boundary marker>", then per node
//           "<number> <x> <y> <z> [attributes...] [marker]"
//   X.ele:  "<#tets> <4|10> <#attributes>", then per tet
//           "<number> <n1> <n2> <n3> <n4> [6 midside nodes] [attributes...]"
//
// Numbering starts at the first node's number, 0 or 1, for both files (as
// TetGen decides it); nodes must be numbered consecutively. '#' starts a
// comment anywhere; blank lines are ignored. Node markers and attributes go
// to FileExtras (node_markers, node_attributes). The first tet attribute is
// TetGen's region attribute (-A): FileExtras::tet_tags holds it where every
// one is a whole number in int range, else the regions numbered 1, 2, ... in
// ascending order of attribute value (with a read note). Attributes that
// tet_tags cannot give back (non-whole, or more than one a tet) are kept in
// FileExtras::tet_attributes and written back as they were. Second-order
// tets (10 nodes, TetGen's -o2) are read and written with their midside
// nodes in TetGen's order (tetgen_io.cpp). Markers do not fix nodes: the boundary is
// found from the tets.
#include <istream>
#include <ostream>
#include <string>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// X for a path X.node, X.ele or X.
std::string tetgen_base(const std::string& path);

// Reads base.node and base.ele for any of the three spellings, and validates.
TetMesh read_tetgen(const std::string& path);
TetMesh read_tetgen(std::istream& node, const std::string& node_source, std::istream& ele,
                    const std::string& ele_source);

// The two halves, unvalidated. read_tetgen_node fills the nodes and their
// extras of `mesh` and returns the first node number (0 or 1);
// read_tetgen_ele fills the tets and region attributes, 0-based.
int read_tetgen_node(std::istream& in, const std::string& source, TetMesh& mesh);
void read_tetgen_ele(std::istream& in, const std::string& source, int first_index, TetMesh& mesh);

// Numbering from 1 (TetGen's default); markers and attributes are written
// when the extras hold them for every node or tet: a tet's attributes from
// tet_attributes, else its region attribute from tet_tags.
void write_tetgen_node(const TetMesh& mesh, std::ostream& out);
void write_tetgen_ele(const TetMesh& mesh, std::ostream& out);
// Writes base.node and base.ele together: neither is replaced unless both
// were written completely.
void write_tetgen(const TetMesh& mesh, const std::string& path);

}  // namespace tetsmooth
