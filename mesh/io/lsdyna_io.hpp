#pragma once
// LS-DYNA keyword decks (.k, .key, .dyn), as LS-PrePost, HyperMesh, ANSA
// and Ansys's pre-processors write them. The mesh of a deck is read with the
// rest of the deck kept, so that a smoothed deck is the input with only the
// *NODE cards of moved nodes changed.
//
// Lines (lsdyna_cards.hpp): '*' in column 1 starts a keyword (case ignored),
// '$' a comment. A data card is read in fixed columns, or split at commas
// where it holds one (free format). Keywords take the standard layout, the
// I10 one (ids 10 columns wide) where "*KEYWORD I10=Y" or a '%' after the
// keyword ("*NODE %") asks for it, or the long one (every field narrower
// than 20 columns 20 wide, a card on one line; lsdyna_cards.hpp) where
// "*KEYWORD LONG=Y" or a '+' asks for it; a '-' asks for the standard
// layout. LONG=S and LONG=K are refused. *INCLUDE reads the file its next
// card names in place (a relative path from the deck's directory;
// included_lines.hpp), in the parent's layout or, after "*INCLUDE %",
// "*INCLUDE +" or "*INCLUDE -", in the layout that mark names (an included
// file's own *KEYWORD sets no layout in LS-DYNA: one that asks for another
// is refused). Nothing
// after *END is read: it is kept in the deck itself, and left out (with the
// *END) in an included file, which *END ends alone.
//
// Reading (node and element ids are the deck's, kept as
// FileExtras::node_tags and tet_element_tags):
//  * *NODE: NID X Y Z TC RC, in columns of 8, 16, 16, 16, 8, 8 (10, 16,
//    16, 16, 10, 10 in I10, 20 each in the long layout); a blank coordinate
//    is 0. A node whose TC or RC is not 0 (a constraint) is pinned.
//  * *ELEMENT_SOLID (and its options TET4TOTET10, ORTHO and DOF, whose extra
//    cards are skipped): EID PID N1..N8 on one card, or EID PID alone with
//    N1..N10 on the next. The PID (part) is the region tag. Tets are N1 N2
//    N3 N4 N4 N4 N4 N4 (LS-DYNA's form), N1 N2 N3 N3 N4 N4 N4 N4, or N1..N4
//    with N5..N8 0 or blank; 10-node tets list N1..N10 on the second card,
//    the midside nodes in kTetEdges order (LS-DYNA's, as VTK's). A tet
//    listed left-handed is inverted (LS-DYNA takes one order), not turned
//    round. A blank line is a card of defaults (an option's card), but
//    where an element's first card would come. Bricks (8 distinct nodes), wedges (N1 N2 N3 N4
//    N5 N5 N6 N6) and pyramids (N1 N2 N3 N4 N5 N5 N5 N5) pass through and
//    pin their nodes; other solids pin their nodes and stay in the deck.
//    Other options of *ELEMENT_SOLID are refused.
//  * Other elements pin their nodes: *ELEMENT_SHELL (passing through as
//    triangles, N3 = N4, and quads; with its THICKNESS, BETA, MCID and
//    OFFSET cards skipped), *ELEMENT_BEAM (lines N1 N2; its orientation
//    node N3 pinned too; with the cards of its options skipped), and
//    *ELEMENT_TSHELL, *ELEMENT_DISCRETE and *ELEMENT_MASS, which stay in the
//    deck alone.
//  * *PART: the heading card names the part's PID (RegionNames); a *PART
//    with options is read for its first part alone.
//  * Pins: every node set (*SET_NODE, *SET_NODE_LIST, with _TITLE; ranges of
//    *SET_NODE_LIST_GENERATE), the nodes of segment sets (*SET_SEGMENT),
//    and the nodes that *BOUNDARY_SPC_NODE,
//    *BOUNDARY_PRESCRIBED_MOTION_NODE, *LOAD_NODE_POINT,
//    *INITIAL_VELOCITY_NODE, *CONSTRAINED_EXTRA_NODES_NODE,
//    *CONSTRAINED_SPOTWELD and *DATABASE_HISTORY_NODE name. Other keywords
//    that name nodes (the other *ELEMENT_, *CONSTRAINED_ and *SET_NODE_
//    keywords, and those with _NODE in their name) are kept with a note
//    that their nodes are not pinned.
//  * Refused with the file's line: keywords that move, merge or renumber
//    nodes (*NODE_TRANSFORM, *NODE_MERGE..., *INCLUDE_TRANSFORM,
//    *PART_MOVE) or read files in ways not followed (the other *INCLUDE_
//    keywords), LONG=S and LONG=K, ids that are not positive, fields that
//    are not numbers (parameters such as &x are not evaluated), nodes and
//    solids defined twice, part ids past 2,147,483,647, undefined nodes,
//    4- and 10-node tets mixed, and decks without nodes or tets.
//  * The deck is kept in FileExtras::raw_sections, in order: "lsdyna:text"
//    (lines as read, each ended by '\n') and "lsdyna:nodes",
//    "lsdyna:nodes-i10" or "lsdyna:nodes-long" (the lines of a *NODE
//    keyword's data, its layout in the name); then "lsdyna:deck" (kept_deck.hpp), "lsdyna:keywords" (the
//    other keywords, for a note when another format drops them),
//    "lsdyna:uncarried" (element keywords only LS-DYNA output keeps) and
//    "lsdyna:includes" (the files *INCLUDE read).
//
// Writing: a mesh read from a deck is written as that deck, line for line,
// but for the *NODE cards of nodes whose coordinates changed: the X, Y and
// Z that changed in the card's own layout (16 columns each, 20 in the long
// layout, lsdyna_cards.hpp: coordinate_field; free-format cards in as many
// characters), their NID, TC,
// RC, anything after them and the coordinates that did not change as
// read. Line ends become '\n', and included files are written in place of
// their *INCLUDE, their *KEYWORD as a comment and their keywords marked
// with the file's layout where it is not the deck's. The mesh must still have
// the deck's node and tet counts.
// Any other mesh is written as a new deck in the standard layout: *PART
// cards for its region tags (headed by their names; no section or
// material, which the user adds), *NODE, *ELEMENT_SOLID (tets as N1 N2 N3
// N4 N4 N4 N4 N4, 10-node tets on two cards, bricks, wedges and pyramids
// in the forms above), *ELEMENT_SHELL for triangles and quads,
// *ELEMENT_BEAM for lines, a node set "TETSMOOTH_PINNED" of the pinned
// nodes that no written element pins, and *END. PIDs are the region tags
// where positive and at most 99,999,999 (else new ids: lsdyna_region_ids,
// which also parts shells and beams from solids of the same tag);
// node and element ids the file's where they are positive, distinct and at
// most 99,999,999, else 1, 2, ... in order.
#include <iosfwd>
#include <map>
#include <string>

#include "mesh/io/file_numbers.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// `source` names the deck in messages; relative *INCLUDE paths start from
// its directory.
TetMesh read_lsdyna(std::istream& in, const std::string& source);
TetMesh read_lsdyna_file(const std::string& path);

void write_lsdyna(const TetMesh& mesh, std::ostream& out);
void write_lsdyna_file(const TetMesh& mesh, const std::string& path);

// The PIDs of a new deck (RegionIds): new ones for region tags that cannot
// be PIDs (0 and below, past 99,999,999) and elements without one, and for
// shells and beams whose tag solids (or, for beams, shells) have too: a
// part takes one section.
RegionIds lsdyna_region_ids(const TetMesh& mesh);

// Whether a new deck writes the elements of `block` (solids, triangles,
// quads and lines; their nodes are pinned in any case).
bool lsdyna_writes_block(const PassThroughBlock& block);

// The file's own numbers that a new deck for `mesh` cannot keep (see
// file_numbers.hpp): "node", "element", "node and element", or "".
std::string lsdyna_numbers_lost(const TetMesh& mesh);

}  // namespace tetsmooth
