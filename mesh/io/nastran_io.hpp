#pragma once
// Nastran bulk data (.bdf, .nas): MSC/NX Nastran, Optistruct and the
// pre-processors that write for them (Femap, HyperMesh, Gmsh, meshio). The
// mesh of a deck is read with the rest of the deck kept, so that a smoothed
// deck is the input with only the GRID entries of moved nodes changed.
//
// Entries (nastran_cards.hpp): small field (8 columns), large field (a name
// ending in '*', 16 columns, continued on a line that starts with '*') and
// free field (commas), continued on lines that start with '+', '*', ',' or a
// blank; '$' starts a comment. INCLUDE 'file' is read in place (a relative
// path from the deck's directory; included_lines.hpp). Lines before BEGIN
// BULK (executive and case control) and after ENDDATA are kept and not read;
// a file without BEGIN BULK is bulk data throughout (Gmsh writes so). Reals
// take every Nastran form ("1.5", ".5", "5.", "1.5E-3", "1.5-3", "1.5D-3"),
// and whole numbers too, as Gmsh writes some coordinates.
//
// Reading:
//  * GRID ID CP X1 X2 X3 CD PS SEID: ids any positive whole numbers, kept as
//    FileExtras::node_tags; blank coordinates are 0. CP must be 0 (blank
//    takes GRDSET's CP, which must then be 0 too: nodes in other coordinate
//    systems are refused); a node with a PS (its own, or GRDSET's where its
//    own is blank: a permanent single-point constraint) is pinned.
//  * CTETRA EID PID G1..G4, or G1..G10 with the midside nodes in kTetEdges
//    order (Nastran's, as VTK's; a 4-node one may give G5..G10 as 0);
//    meshio 5's CTETRA_ too, with a note. Ids
//    kept as tet_element_tags; the PID is the region tag
//    (FileExtras::tet_tags; a blank PID is 0). Nastran takes a tet's grid
//    points in either handedness: one listed left-handed is read with G2
//    and G3 swapped (and its midside nodes with them), with a note.
//  * Other elements pin their grid points. Those with a shape in other
//    formats pass through (PassThroughBlock, tag = PID where they have one):
//    CTRIA3/CTRIAR (triangle), CTRIA6 (triangle6), CQUAD4/CQUADR/CSHEAR
//    (quad), CROD/CTUBE/CBAR/CBEAM/CBEND/CBUSH/CBUSH1D/CBUSH2D/CGAP/CVISC/CONROD
//    (line; the orientation node G0 of a bar, beam, bush or gap is pinned
//    too, and BAROR's and BEAMOR's), CONM1/CONM2 (vertex), CHEXA, CPENTA, CPYRAM/CPYRA with corner
//    nodes only (hexahedron, wedge, pyramid). The others only pin and stay
//    in the deck: CQUAD8, CQUAD, CTRIAX6, CBEAM3, higher-order solids,
//    CELAS1/2, CDAMP1/2, CMASS1/2, PLOTEL, RBAR, RBAR1, RROD, RJOINT, RTRPLT,
//    RBE1, RBE2, RBE3 (nastran_entry_types.cpp lays out where each names
//    its grid points).
//  * Loads, constraints and the points that give them a direction pin the
//    grid points they name: SPC, SPC1 (with THRU ranges), SPCD, FORCE,
//    FORCE1/2 and MOMENT, MOMENT1/2 (with their direction's points),
//    RFORCE, RFORCE1, PLOAD, DAREA, ACCEL1, NOLIN1, DVGRID, SUPORT, SUPORT1,
//    MPC, CORD1R/C/S, BNDFIX1, SPCOFF1, the
//    analysis sets ASET, BSET, CSET, QSET, OMIT, USET and their ...1 forms,
//    TIC; and
//    the comment lines "$TETSMOOTH PINNED <id> ..." that the writer leaves
//    for pins nothing else keeps. Scalar points (SPOINT, EPOINT) that these
//    name are no grid points and pin nothing. Entries of other types are
//    kept and not read; of those, the ones known to name grid points
//    (CWELD, CFAST, RSPLINE, GENEL, ...) and those of types not known at
//    all get a note that their nodes may move (names_no_grids lists the
//    types known to name none).
//  * Refused with the file's line: superelements (BEGIN SUPER, BEGIN BULK
//    SUPER=), replicated entries ('=' lines), a carriage return inside a
//    line (mixed line ends, which would shift columns), GRID, CD and SEID
//    ids of more than 8 digits, CP other than 0, a value past
//    the last field of a GRID or CTETRA (a line laid out wrong: a
//    large-field GRID continued in small field), ids defined twice, grid
//    points that no GRID defines, CTETRA with other than 4 or 10 grid
//    points, and included files that cannot be read.
//  * The deck is kept in FileExtras::raw_sections, in order: "nastran:text"
//    bodies as read (lines end in '\n') and "nastran:grids" bodies, the
//    text of runs of GRID entries; then "nastran:deck" ("<nodes> <tets>",
//    what the deck describes), "nastran:types" (the deck's entry types other
//    than GRID and the elements, for a note when another format drops
//    them), "nastran:uncarried" (the element types that only pin, for the
//    same note) and "nastran:includes" (the files INCLUDE read).
//
// Writing: a mesh read from a deck is written as that deck, line for line,
// but for the GRID entries of nodes whose coordinates changed: those are
// written in large field (GRID* and a '*' line) with their CP, CD, PS and
// SEID as read (the reader checks them: ids, PS digits 1 to 6), after the
// entry's comments (inline ones as lines of their own; one that would read
// as a pin line marked off with another '$'), and each coordinate in 16
// characters (nastran_fields.hpp: real_field). A node that did not move
// keeps its GRID text byte for byte. Line ends become '\n', and included
// files are written in place of their INCLUDE lines. The mesh must still
// have the deck's node and tet counts.
// Any other mesh is written as a new deck: "BEGIN BULK", GRID* entries,
// CTETRA (PID = region tag; tags that cannot be PIDs, and tets without
// one, as new ids; shells and rods of a solid's tag get their own:
// nastran_region_ids), the pass-through elements (CTRIA3,
// CTRIA6, CQUAD4, CROD, CONM2, CHEXA, CPENTA, CPYRAM), "$TETSMOOTH PINNED"
// lines for pinned nodes that no element pins, and ENDDATA. Node and
// element ids are the file's where they are positive, distinct and at most
// 99,999,999, else 1, 2, ... in order.
#include <iosfwd>
#include <map>
#include <string>

#include "mesh/io/file_numbers.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// `source` names the deck in messages.
TetMesh read_nastran(std::istream& in, const std::string& source);
TetMesh read_nastran_file(const std::string& path);

void write_nastran(const TetMesh& mesh, std::ostream& out);
void write_nastran_file(const TetMesh& mesh, const std::string& path);

// The PIDs of a new deck (RegionIds): new ones for region tags that cannot
// be PIDs (0 and below, and past 99,999,999) and elements without one (as
// tag 0): ids that no tag holds, from above the largest tag kept on (then
// from 1 up), 0 first, then -1, -2, ..., then the large tags in order
// (Nastran's PIDs are positive, of at most 8 digits); and for shells and
// lines whose tag solids (or, for lines, shells) have too, since a PID
// names one property entry (a PSOLID or a PSHELL).
RegionIds nastran_region_ids(const TetMesh& mesh);

// The file's own numbers that a new deck for `mesh` cannot keep (see
// file_numbers.hpp): "node", "element", "node and element", or "".
std::string nastran_numbers_lost(const TetMesh& mesh);

}  // namespace tetsmooth
