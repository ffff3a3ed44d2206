#pragma once
// What every MSH flavour writes, worked out once from a TetMesh: node tags,
// the model entities and each element's entity and physical tag. Internal
// to the Gmsh writer.
//
// A mesh read from MSH 4.1 keeps its $Entities (verbatim) and its element
// classification, as long as every entity an element refers to is still
// declared. (A partitioned file qualifies: the reader moves its elements and
// nodes to the model entities of $Entities, so what is written is not
// partitioned.) Any other mesh gets entities made up from what it carries:
// each element's entity tag, else its physical tag (region attribute, Medit
// reference), else 1; each entity lists the positive physical tags of its
// elements. To those come the points, curves and surfaces that the nodes'
// classification (meshio's gmsh:dim_tags in VTU and VTK) names and no
// element is on, an embedded surface say (add_classification_entities in
// the .cpp tells which are left out and why). A node keeps its
// classification where the entity is declared; the others are classified
// on the lowest-dimensional entity of an element that uses them, as Gmsh
// does.
// Node and element tags are the file's where it gave usable ones (see
// WritePlan), so ids that a simulation deck refers to survive.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mesh/io/gmsh_detail.hpp"
#include "mesh/io/gmsh_io.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::gmsh {

// The tets, or one pass-through block: `count` elements of `type` with
// `type->nodes` 0-based indices each from nodes(): `connectivity` in the
// mesh, or `owned` where the group builds its own (second-order tets, whose
// corners and midside nodes the mesh keeps apart).
struct ElementGroup {
  const ElementType* type = nullptr;
  const index_t* connectivity = nullptr;
  std::vector<index_t> owned;
  std::size_t count = 0;
  std::vector<int> entity;    // per element
  std::vector<int> physical;  // per element, 0 for none

  const index_t* nodes() const { return owned.empty() ? connectivity : owned.data(); }
};

struct WritePlan {
  // Per node: the file's node tags when every node has one and they are
  // positive, distinct and (in MSH 2.2, which numbers nodes by int) at most
  // kLargestIntTag, else 1, 2, ...
  std::vector<long long> node_tags;
  std::vector<int> node_dims;        // per node: the entity it is classified on
  std::vector<int> node_entities;
  Entities entities;
  std::string entities_text;         // $Entities body as written in ASCII
  std::string physical_names;        // $PhysicalNames body, or empty
  // The tets and the pass-through blocks, in the order of their first
  // element tags (tets first when the elements are numbered 1, 2, ...).
  std::vector<ElementGroup> groups;
  // Per element, in the order of `groups`: the file's element tags when
  // every element has one and they are positive, distinct and at most
  // kLargestIntTag, else 1, 2, ...
  std::vector<long long> element_tags;
  std::size_t element_count = 0;
  // Whether the file's $Entities were kept, so that an element is in every
  // physical group of its entity (MSH 2.2 repeats it for each, see
  // v22_physicals), not only in `physical`, the first.
  bool groups_of_entities = false;
};

// Throws OutputError for pass-through blocks that MSH cannot hold.
WritePlan plan_gmsh_output(const TetMesh& mesh, MshFlavour flavour);

// Per node, 1 where MSH 4.1 output classifies it on a point, curve or
// surface, which is what pins it in a run on the output (as the mesh's own
// node_entity_dims pin it); empty where the mesh has no classification or
// cannot be written at all.
std::vector<std::uint8_t> msh41_feature_nodes(const TetMesh& mesh);

// The physical tags element e of `g` is written with in MSH 2.2, which gives
// an element one physical tag a line: as Gmsh does, an element of several
// groups is written once per group, every line with the same element tag
// (Gmsh 4.8 reads such lines as one element in all the groups; its own
// writer numbers them apart, and reading that back, Gmsh and tetsmooth both
// find the element once per group). Every group of its entity where the
// plan kept the file's entities, else its one tag (0 for none).
std::pair<const int*, std::size_t> v22_physicals(const WritePlan& plan, const ElementGroup& g, std::size_t e);
// The number of MSH 2.2 element lines: every element once per group.
std::size_t v22_lines(const WritePlan& plan);

}  // namespace tetsmooth::gmsh
