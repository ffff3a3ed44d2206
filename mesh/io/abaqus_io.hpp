#pragma once
// Abaqus and CalculiX input decks (.inp): the mesh of a flat deck or of one
// with parts and an assembly, read with the rest of the deck kept so that a
// smoothed deck is the input with only its node coordinates changed.
//
// Reading:
//  * *NODE lines "id, x, y, z" (ids any positive whole numbers, kept as
//    FileExtras::node_tags; omitted coordinates are 0, as Abaqus reads
//    them); *ELEMENT blocks of tets (C3D4..., C3D10..., one kind a deck;
//    ids kept as tet_element_tags) and of other elements, which pass through
//    with their nodes pinned (element_types: shells, membranes, surface
//    elements, trusses, beams, first-order solids, one-node elements).
//  * Regions (FileExtras::tet_tags): the ordinal of the *SOLID SECTION whose
//    element set holds a tet, where the deck has sections; otherwise from
//    the ELSET= of the tet's *ELEMENT line, each name's trailing number
//    where every name has a different one (Gmsh's Volume1, Volume2, ...;
//    negative after "_M", as the writer names negative tags: REGION_M2 is
//    -2), else the names numbered 1, 2, ... in the order met. Other
//    elements get their tags from their ELSET= names the same way.
//    A deck with neither: the tets that the same *ELSET sets hold form a
//    region (meshio writes Gmsh's physical groups so), named after the first
//    set that holds its tets and no others.
//  * Pinned nodes, besides those of non-tet elements: nodes that loads and
//    constraints name (by number or node set): *BOUNDARY, *CLOAD, *CFLUX,
//    *CFLOW, *EQUATION and *MPC; and the node set TETSMOOTH_PINNED that the
//    writer leaves for pins nothing else keeps. Node sets that only output
//    or monitoring name (*NODE PRINT, *MONITOR) pin nothing.
//  * Parts and an assembly (abaqus_assembly.cpp): *PART, NAME= ... *END
//    PART holds nodes, elements, sets and sections numbered and named within
//    the part; *ASSEMBLY ... *END ASSEMBLY places each part by one *INSTANCE,
//    NAME=, PART= ... *END INSTANCE, whose optional data lines translate and
//    then rotate it (abaqus_placement.hpp). The mesh is the instances' union
//    in assembly coordinates, in read order, each instance's nodes its own
//    (bodies are never merged); node_tags and tet_element_tags are the
//    parts' numbers, so they repeat across parts. Regions: each (part,
//    section), named "Part.Set". Outside parts, "Instance.number" and
//    "Instance.Set" name a part's node and set, *NSET/*ELSET, INSTANCE= list
//    a part's numbers and sets, a plain number names a node of the assembly
//    itself (*NODE inside *ASSEMBLY: reference points, which no element
//    holds). A part that no instance places is left out of the mesh, its
//    lines kept as text. Refused with the line: a part instanced twice,
//    keywords inside *INSTANCE, *ELEMENT inside *ASSEMBLY, nested or
//    unclosed structure, *INSTANCE of an unknown part or without PART=,
//    nodes or elements outside parts in a deck with parts.
//  * *INCLUDE files are read in place (abaqus_deck_lines.hpp). Node and
//    element generation (*NGEN, *ELGEN, ...), and nodes in other coordinate
//    systems (*SYSTEM, SYSTEM=C|S) are refused with a message.
//  * The deck is kept in FileExtras::raw_sections, in order: "abaqus:text"
//    bodies as read (lines end in '\n'; included files inline) and
//    "abaqus:nodes" counts of the *NODE lines between them, or for a run in
//    a part that its instance moves, "abaqus:placed": the count, the
//    placement (Placement::to_text) and the part coordinates as read, a line
//    each; then
//    "abaqus:deck" ("<nodes> <tets>", what the deck describes) and
//    "abaqus:keywords" (the deck's keywords other than *HEADING, *NODE and
//    *ELEMENT, as written, for a note when another format drops them) and
//    "abaqus:includes" (the files *INCLUDE read); and "$PhysicalNames",
//    Gmsh's names for the region tags (the sections' and *ELEMENT lines'
//    element set names, or those of the *ELSET lists that name regions, as
//    written), which MSH output keeps.
//
// Writing: a mesh read from a deck is written as that deck, each *NODE line
// "id, x, y, z" with the new coordinates in shortest round-trip form (in a
// placed part: the part coordinates as read where the placed position is
// still the node's, to the bit; else the inverse placement of its position,
// rounded in doubles, so a rotated part's moved node reads back within a few
// ulps) and
// every other line as read, but for the line ends (each line ends in '\n',
// the last too: CRLF becomes LF), a UTF-8 byte order mark (dropped) and
// *INCLUDE lines (the included lines in their place); the mesh must still
// have the deck's node and tet counts. Any other mesh is written as a new deck: *HEADING, *NODE, then
// *ELEMENT blocks in file order (C3D4 or C3D10; other elements under the
// type_name_of() types), one block per run of one region tag, with
// ELSET= the region's name (Gmsh's physical name, for its dimension) where
// it is a plain Abaqus set name (1 to 80 letters, digits and '_', the first
// a letter) that no other region's set has in any case, else
// ELSET=REGION_<tag> (negative tags as REGION_M<|tag|>) and, for other
// elements, ELSET=<KIND>_<tag> (abaqus_set_names.hpp); then *NSET,
// NSET=TETSMOOTH_PINNED for pinned nodes that no element pins. Node and element ids are the file's where
// they are positive and distinct, else 1, 2, ... in order.
#include <iosfwd>
#include <string>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// `source` names the deck in messages and is the place *INCLUDE paths are
// relative to.
TetMesh read_abaqus(std::istream& in, const std::string& source);
TetMesh read_abaqus_file(const std::string& path);

void write_abaqus(const TetMesh& mesh, std::ostream& out);

// The file's own numbers that a new deck for `mesh` cannot keep, and
// numbers 1, 2, ... instead (some missing, not positive or not distinct):
// "node", "element", "node and element", or "" when it keeps them all.
std::string abaqus_numbers_lost(const TetMesh& mesh);
// The names of regions that a new deck for `mesh` names by tag instead
// (REGION_<tag>: the name is no plain Abaqus set name, or is another's);
// empty where the mesh's own deck is written back.
std::vector<std::string> abaqus_names_lost(const TetMesh& mesh);
// Whether tetsmooth, reading a new deck for `mesh` back, gives its regions
// their tags again (true where the mesh's own deck is written back).
bool abaqus_tags_read_back(const TetMesh& mesh);
void write_abaqus_file(const TetMesh& mesh, const std::string& path);

}  // namespace tetsmooth
