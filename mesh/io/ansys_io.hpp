#pragma once
// ANSYS Mechanical APDL archive and input files (.cdb: CDWRITE's "coded
// database", and the blocks of Workbench's ds.dat): the mesh is read with
// the rest of the file kept, so that a smoothed file is the input with only
// the NBLOCK records of moved nodes changed.
//
// A file is APDL command lines (fields split by commas, any case, '!'
// starts a comment, '$' separates commands on one line) and the blocks the
// commands open, whose records are fixed-width fields laid out by the
// Fortran format on the line after the command (ansys_fields.hpp):
//  * NBLOCK,NUMFIELD,SOLID,NDMAX,NDSEL then "(3i9,6e21.13e3)" (or "(3i8,
//    6e20.13)", "(1i9,3e20.9e3)", ...): a node a line, its number first (the
//    other integers, the solid model's entity and place, are kept as read),
//    then X, Y, Z and the rotation angles THXY, THYZ, THZX; values left off
//    the end of a line, or blank, are 0. The block ends at "N,R5.3,LOC,-1"
//    (or "N,UNBL,LOC,-1", as recent releases write it) or at a record whose
//    number is -1.
//  * EBLOCK,NUM_NODES,SOLID,NDMAX,NDSEL then "(19i9)": an element a record,
//    its fields MAT, TYPE, REAL, SECNUM, ESYS, birth/death, solid model
//    reference, shape, node count, exclude key, element number, then the
//    nodes, eight on the first line and the rest on the next. Without SOLID
//    ("EBLOCK,10,,,n", Workbench's contact and surface elements) a record is
//    one line: element number, TYPE, REAL, MAT, SECNUM, then nodes. Either
//    ends at a record of -1.
//  * CMBLOCK,NAME,NODE|ELEM,count then "(8i10)": a component's items, a
//    negative number -n meaning the range from the number before it to n.
//  * ETBLOCK,count,NMAX then "(2i9,19a9)": element types as recent
//    releases write them, ITYPE and the element's number a record (then
//    its KEYOPTs, not read), up to a record of -1.
//
// Reading:
//  * Element types come from ET,ITYPE,ENAME (a number, 187, or a name,
//    SOLID187) and ETBLOCK. ITYPE and node numbers may be whole reals
//    ("7.0") or scalar parameters that *SET,NAME,VALUE or NAME=VALUE give
//    (Workbench's "*SET,cid,3" then "ET,cid,174"); one that another *
//    command sets (*DO, *GET, ...) is no longer known. Elements of 3-D solid types (ansys_element_types.hpp) with
//    the nodes of a tet are the tets: 4 nodes (SOLID285, or a 187 without
//    midside nodes), 10 (SOLID187, 92, ...: corners I, J, K, L then the
//    midside nodes of IJ, JK, KI, IL, JL, KL, as kTetEdges), a brick's 8 as
//    I,J,K,K,M,M,M,M (SOLID185's degenerate tet) or its 20 likewise
//    (SOLID186). 8-node solids of brick, wedge and pyramid shape pass
//    through as hexahedra, wedges and pyramids (tag = MAT); every other
//    element (20-node bricks among them) pins its nodes and stays in the
//    file alone.
//  * Numbers: node and element numbers are kept (FileExtras::node_tags,
//    tet_element_tags). The region of a solid (a tet or a pass-through
//    solid) is its MAT; element components of solids split regions further
//    (RegionSplitter), and then the regions are numbered 1, 2, ... with a
//    note. A component that holds exactly one region's solids names it
//    ($PhysicalNames).
//  * Pins: the nodes of every node component (the named selections that
//    loads and supports are put on), of elements other than tets, and the
//    nodes that D, F, BF, IC and M name by number (with the ranges NEND,
//    NINC of D, F, IC and M), CP and CE list (their NODE fields, and those
//    of CDWRITE's "CE,R5.0,NODE,..." lines), CERIG names (master and
//    slave), RBE3 names (master, and the component of its slaves) and
//    CPNGEN spans. Noted, not pinned: words where a node goes that no node
//    CMBLOCK defines (a component made by selection with CM, a parameter
//    tetsmooth cannot evaluate), ALL, P and P51X, CPINTF and CEINTF
//    (tetsmooth does not follow APDL's selection), CPSGEN and CESGEN, and
//    CDWRITE's block forms of D, F, CP, BF and IC ("D,R5.0,...").
//  * Lines that cannot be command names (a number first: the data lines of
//    blocks tetsmooth does not read, RLBLOCK's or SFE's) are kept and not
//    read, but for one right after a block's end (a -1 among the records
//    would end it early, a CMBLOCK's count be too small) and a line of 12
//    or more whole numbers after the first EBLOCK, an element record out of
//    its block: those are refused.
//  * Refused with the file's line: commands that define, move, reorder or
//    delete nodes or elements outside the blocks (N, E, EN, NGEN, NMODIF,
//    VMESH, EORIENT, ..., ansys_element_types.cpp; N and EN in CDWRITE's
//    form too, but for the marks whose fourth field is -1), change their
//    materials (MPCHG), NUMOFF after an NBLOCK, /INPUT, *USE and CDREAD of
//    other files, an element of more than 200 nodes, NBLOCK and EBLOCK
//    records that break their format, nodes or elements
//    numbered twice, nodes that no NBLOCK defines, element types that no ET
//    defines, and 4- and 10-node tets mixed.
//  * The file is kept in FileExtras::raw_sections, in order: "ansys:text"
//    bodies as read and "ansys:nblock" bodies (an NBLOCK's format line and
//    records); then "ansys:deck" ("<nodes> <tets>"), "ansys:commands" (the
//    other commands, for a note when another format drops them) and
//    "ansys:uncarried" (element types that only pin).
//
// Writing: a mesh read from a file is written as that file, byte for byte,
// but for the NBLOCK records of nodes whose coordinates changed: those of
// X, Y and Z that changed are written in the block's own format (14
// significant digits in e21.13e3, as MAPDL writes them), the record's other
// fields as read. Any
// other mesh is written as a new file: /PREP7, ET 1 = SOLID285 (or
// SOLID187 for 10-node tets), ET 2 = SOLID185 for bricks, wedges and
// pyramids (degenerate as above), an NBLOCK in (3i9,6e21.13e3), an EBLOCK in
// (19i9) with MAT = region tag (tags that cannot be MATs, and tets without
// one, as new numbers: ansys_new_materials), node components TETSMOOTH_PINNED
// (every pin that no written element keeps) and one for each named region
// of triangles, quads, lines or points (those elements are not written),
// element components for the named regions of solids, and FINISH. Node and
// element numbers are the file's where they are positive, distinct and at
// most 99,999,999, else 1, 2, ... in order.
#include <iosfwd>
#include <map>
#include <string>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// `source` names the file in messages.
TetMesh read_ansys(std::istream& in, const std::string& source);
TetMesh read_ansys_file(const std::string& path);

void write_ansys(const TetMesh& mesh, std::ostream& out);
void write_ansys_file(const TetMesh& mesh, const std::string& path);

// The material numbers a new file gives region tags that cannot be ones (0
// and below, past 99,999,999) and solids without a tag (new_positive_ids).
std::map<int, int> ansys_new_materials(const TetMesh& mesh);

// The file's own numbers that a new file for `mesh` cannot keep (see
// file_numbers.hpp): "node", "element", "node and element", or "".
std::string ansys_numbers_lost(const TetMesh& mesh);

}  // namespace tetsmooth
