#pragma once
// What the VTK readers (VTU and legacy VTK) take from a file's point and cell
// data arrays: the region tags, the fixed nodes, and a note on the other
// arrays, which are not carried over to the output. One place, so that both
// readers accept the same arrays and say the same about the rest.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/io/vtk_cells.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// Cell-data arrays read as region tags, in order of preference: tetsmooth's
// own, then the names that meshio (Gmsh physical groups, Medit references)
// and VTK/ParaView (CellEntityIds) give them. Only one is used: the most
// preferred one present, the first of that name if several are; the others
// are noted like any other array. It must hold one whole number per cell.
inline constexpr const char* kVtkTagArrays[] = {kVtkTagArray, "gmsh:physical", "medit:ref", "CellEntityIds"};

// One point or cell data array as a file declares it.
struct VtkArrayDecl {
  bool on_cells = false;  // cell data, else point data
  std::string name;
  std::size_t components = 1;
};

inline constexpr std::size_t kNoVtkArray = SIZE_MAX;

// The arrays a reader carries over, as indices into the list it gave.
struct VtkArrayPick {
  std::size_t tags = kNoVtkArray;
  std::size_t entities = kNoVtkArray;       // the first kVtkEntityArray on cells
  std::size_t node_entities = kNoVtkArray;  // the first kVtkNodeEntityArray on points
  std::size_t fixed = kNoVtkArray;
};

// Whether the reader may need the values of `a` (a one-component array of a
// tag name or kVtkEntityArray on cells, kVtkFixedArray on points, or
// kVtkNodeEntityArray on points with 2 components, or 3 as meshio pads it in
// legacy VTK): a streaming reader keeps those until it has seen every array.
bool vtk_array_wanted(const VtkArrayDecl& a);

// Picks the tag, entity, node entity and fixed-node arrays from every point and cell data array
// of a file, in file order, and adds to `notes` one sentence per kind (point
// data, cell data) naming the arrays that are not carried over, leaving out
// the "quality" and "boundary" fields that tetsmooth itself writes (the
// command line computes them afresh on every write).
VtkArrayPick pick_vtk_arrays(const std::vector<VtkArrayDecl>& arrays, std::vector<std::string>& notes);

// Adds to `notes` a sentence naming the field data arrays (data of the
// whole dataset, such as ParaView's TimeValue), which no output carries;
// nothing when there are none.
void note_vtk_field_data(const std::vector<std::string>& names, std::vector<std::string>& notes);

// The values of the region (or entity) tag array `name`, one per cell, as ints.
// InputError at `where` (the file and the array's line) for a count other
// than `cells`, or naming the cell whose value is not a whole number in the
// range of int.
std::vector<int> vtk_region_tags(const std::vector<double>& values, std::size_t cells, const std::string& name,
                                 const std::string& where);

// Sets the Gmsh entity each node is classified on (FileExtras::
// node_entity_dims and node_entity_tags) from the kVtkNodeEntityArray
// `name`, `components` values a node: its dimension and tag, and with 3 a
// padding 0. InputError at `where` for a count other than components times
// mesh.num_nodes(), or naming the point whose dimension is not 0 to 3, whose
// tag is not a whole number in int range, or whose padding is not 0.
void classify_vtk_nodes(TetMesh& mesh, const std::vector<double>& values, std::size_t components,
                        const std::string& name, const std::string& where);

// Fixes the nodes whose value in the fixed-node array `name` is not 0, on
// top of those the reader fixed already. InputError at `where` for a count
// other than mesh.num_nodes() or a value that is not a whole number.
void fix_vtk_nodes(TetMesh& mesh, const std::vector<double>& values, const std::string& name, const std::string& where);

}  // namespace tetsmooth
