#pragma once
// FLAC3D grids (.f3grid, or .flac3d as older versions named them; text or
// binary), the grid files of Itasca's
// FLAC3D (zone import / zone export) that geomechanics models are built
// from. A grid is read with its file kept, so that a smoothed grid is the
// input with only the coordinates of moved gridpoints changed.
//
// A binary grid (zone export ... binary) holds the same records in the
// layout flac3d_binary.cpp gives, without pin comments; a file with a zero
// byte in it is read as one. The text format (one record a line; a line whose first character other than
// blanks is '*' is a comment; blank lines are skipped; commas may separate
// values, as blanks do; keywords in any case):
//  * G id x y z: a gridpoint. Ids are positive whole numbers, in any order
//    and with gaps, kept as FileExtras::node_tags.
//  * Z type id gp...: a zone of `type` over the gridpoints with those ids.
//    T4 (4 gridpoints) is a tet, read as it is listed: FLAC3D's first four
//    gridpoints of a zone are right-handed, as tetsmooth's positive tets
//    (tet_mesh.hpp). B8, W6 and P5 (brick, wedge, pyramid) pass through as
//    hexahedron, wedge and pyramid blocks, their gridpoints reordered from
//    FLAC3D's (the corners of a brick in the order origin, x, y, z, xy, yz,
//    xz, xyz; a wedge and a pyramid the first six and the first five of
//    those, collapsed) to Gmsh's (flac3d_zone_types.hpp); B7 (a brick with a
//    corner cut off) only pins, kept in the FLAC3D output alone. Zone ids
//    are kept as tet_element_tags and the blocks' element_tags.
//  * F type id gp...: a face, T3 or Q4 (triangle, quad blocks); face ids
//    are their own numbering.
//  * ZGROUP name [SLOT slot] and FGROUP name [SLOT slot], then lines of
//    zone or face ids up to the next record (comments may come among them):
//    a group. A name or slot may be quoted ('...' or "...", and may then
//    hold blanks). As in FLAC3D, headers of one name (in any case) in one
//    slot make one group, an element is in one group a slot (the last that
//    lists it, with a note), and "Default", "1" and no slot at all name the
//    default slot.
//  * Comment lines "* TETSMOOTH PINNED id ...", which the writer leaves for
//    pins nothing else keeps (one with other words than ids pins nothing,
//    with a note).
//
// Reading: zones and faces other than tets pin their gridpoints, as do the
// pin comments. A zone's region tag is the set of groups that hold it, in
// every slot: two zones share a tag when each group holds both or neither
// (numbered 1, 2, ... in zone order), so that the interfaces of materials,
// excavation stages and any other grouping stay in place. Faces are tagged
// so by their FGROUPs. A grid without groups has no region tags. The names
// of the groups holding each tag go to $PhysicalNames (dimension 3 for
// zones, 2 for faces), which MSH output writes, as flac3d_group_names.hpp
// spells them ("Soil + stage 1=excavated"), so that a new grid made from
// them has the same groups in the same slots.
// A record of another kind, and the lines of ids after it, are kept in the
// text (FLAC3D output writes them back) and named in a note: gridpoints it
// names are not pinned.
// Refused with the file's line (InputError; a binary grid's byte offset):
// ids that are not positive, out of range or defined twice, gridpoints, zones or
// faces that nothing defines, a zone or face with the wrong number of
// gridpoints, values that are no numbers, a binary file without the
// binary grid's mark, UTF-16 text, lines that end in a carriage return
// alone, and a grid without T4 zones.
// The grid is kept in FileExtras::raw_sections: "flac3d:text" or
// "flac3d:binary" (the file as read), "flac3d:deck" ("<nodes> <tets>",
// what it describes) and "flac3d:cut-bricks" (how many B7 zones it has,
// for a note when another format drops them).
//
// Writing: a mesh read from a grid is written as that grid, line for line,
// but for the G lines of gridpoints whose coordinates changed, written
// "G id x y z" with the shortest decimals that read back exactly; a binary
// grid byte for byte, but for its gridpoints' coordinates. The mesh must
// still have the grid's gridpoint and zone counts. New grids are text.
// Any other mesh is written as a new grid: gridpoints, T4 zones, then B8,
// W6 and P5 zones for hexahedron, wedge and pyramid blocks (gridpoints
// reordered to FLAC3D's, mirrored where they would be left-handed), the
// ZGROUPs of the region tags (each tag's name in $PhysicalNames, else
// "region <tag>", read as groups in their slots by flac3d_group_names.hpp;
// a tag whose groups another tag has got is a group of its own, so that
// the regions stay apart, and where one tag alone has no name it is in no
// group), then T3 and Q4 faces for triangle and quad
// blocks with the FGROUPs of their tags, then "* TETSMOOTH PINNED" lines for
// the pinned nodes that no written zone or face pins (including the nodes of
// blocks FLAC3D has no place for: lines, points, second-order faces, which
// are not written). Ids are the file's where they are positive, distinct and
// at most 2^31 - 1, else 1, 2, ... in order. Second-order tets are refused:
// FLAC3D zones are first order.
#include <iosfwd>
#include <string>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// `source` names the grid in messages.
TetMesh read_flac3d(std::istream& in, const std::string& source);
TetMesh read_flac3d_file(const std::string& path);

void write_flac3d(const TetMesh& mesh, std::ostream& out);
void write_flac3d_file(const TetMesh& mesh, const std::string& path);

// Whether a new FLAC3D grid writes the elements of a block of `kind` with
// `nodes_per_element` nodes (as zones or faces); the others are dropped,
// their nodes listed as pins.
bool flac3d_writes_kind(const std::string& kind, int nodes_per_element);

// The file's own numbers that a new grid for `mesh` cannot keep (see
// file_numbers.hpp): "node", "element", "node and element", or "".
std::string flac3d_numbers_lost(const TetMesh& mesh);

}  // namespace tetsmooth
