#pragma once
// Exodus II files (.exo, .e, .ex2, and Cubit's .g and .gen), the meshes of
// Cubit, MOOSE, Sierra and SEACAS. An Exodus file is a netCDF dataset
// (classic, 64-bit offset, 64-bit data or netCDF-4); tetsmooth reads and
// writes it through the netCDF library, and is built without Exodus
// support where that library is missing (exodus_available()).
//
// Reading (the variables of the Exodus II data model; indices in the file
// are 1-based):
//  * num_dim must be 3. Coordinates come from coordx, coordy, coordz (or the
//    older coord, num_dim × num_nodes), doubles or floats.
//  * Element blocks: connect1, connect2, ... with their elem_type
//    (exodus_element_types.hpp). Tet blocks (TETRA, TET4, TETRA10, ...) are
//    the tets, 4-node or 10-node (not both), in block order. Bricks,
//    wedges, pyramids, triangles, quads, bars and spheres pass through as
//    blocks of those kinds and pin their nodes. Blocks of other types
//    (HEX20, TETRA14, NSIDED polygons, ...) pin their nodes and stay in
//    Exodus output alone; polyhedra (NFACED) are refused.
//  * An element's region tag is its block's id (eb_prop1), named by
//    eb_names in $PhysicalNames (dimension 3 for solids, 2 for faces, 1 for
//    bars, 0 for spheres). Ids past int range, or ids that two blocks
//    share, are renumbered 1, 2, ... in block order, with a note, so that
//    the blocks stay apart.
//  * node_num_map and elem_num_map are kept as the node and element ids.
//  * Every node set pins its nodes, and every side set the nodes of its
//    sides (a tet's corners on that side, with their midside nodes), since
//    a simulation applies its loads and conditions to them; the other
//    elements of a side set pin all their nodes anyway.
// Refused with the file's name and the variable at fault (InputError): a
// file that is not netCDF, a classic file whose header is corrupt, that is
// cut short or still being written (netcdf_classic_header.hpp, with the
// byte), a netCDF-4 file whose header crashes HDF5 or sets it looping
// (opened in a child process first, netcdf_dataset.cpp), netCDF without
// Exodus's dimensions and variables, variables over other dimensions than
// the data model gives them (a transposed coord or connect), variables
// larger than the file could hold, num_dim other than 3, node indices out
// of range, side numbers out of range, and a file without 4- or 10-node
// tets.
// Kept in FileExtras::raw_sections: "exodus:file" (the file's bytes),
// "exodus:deck" (kept_deck.hpp: what it describes), "exodus:coordinates"
// (the coordinate variables, "coordx coordy coordz" or "coord"),
// "exodus:rest" (what else it holds: sets, results, element attributes,
// QA records; for the note when another format drops it) and
// "exodus:uncarried" (the types only Exodus output keeps).
//
// Writing: a mesh read from an Exodus file is written as that file, with
// only the coordinate variables rewritten (in the file's precision: a file
// of floats gets moved nodes rounded to float), so that its blocks, sets,
// names, maps, attributes, QA records and results stay as they were. The
// mesh must still have the file's node and tet counts. Any other mesh is
// written as a new file (64-bit offset format, or 64-bit data where a
// variable passes 4 GiB): double coordinates, a TETRA or TETRA10 block for
// each region tag, then a block for each tag of each pass-through block's
// elements (types as exodus_element_types.hpp writes them), each block
// named by its tag's name and numbered by its tag where that is not
// negative and free (MOOSE and meshio number blocks from 0), else by the
// next free positive id, names repeated (a volume and a surface of one
// name) made unique with the block's type, then its id, as SEACAS requires;
// node_num_map and elem_num_map where the file's ids are positive, distinct
// and in int range; and a node set "tetsmooth_pinned" of the pinned nodes
// that no written element pins.
#include <string>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// Whether this build reads and writes Exodus files (it has netCDF).
bool exodus_available();

// `source` names the file in messages.
TetMesh read_exodus(std::string bytes, const std::string& source);
TetMesh read_exodus_file(const std::string& path);

// The bytes of the file write_exodus_file writes (OutputError for a mesh it
// cannot write).
std::string write_exodus(const TetMesh& mesh);
void write_exodus_file(const TetMesh& mesh, const std::string& path);
// The checks write_exodus_file makes before it writes: OutputError for a
// mesh it cannot write.
void check_exodus_writable(const TetMesh& mesh);

// The file's own numbers that a new Exodus file cannot keep (see
// file_numbers.hpp): "node", "element", "node and element", or "".
std::string exodus_numbers_lost(const TetMesh& mesh);

}  // namespace tetsmooth
