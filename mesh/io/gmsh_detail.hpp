#pragma once
// Internals shared by the Gmsh MSH reader and writer (not a public API):
// the element types this library handles and the model entities of an MSH 4
// $Entities section.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/second_order.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::gmsh {

// An element type read and written. `kind` is the PassThroughBlock::kind
// used for it (meshio's cell type names), `dim` the dimension of the entity
// it lives on.
struct ElementType {
  int id;
  const char* kind;
  int nodes;
  int dim;
};

inline constexpr int kTetType = 4;
inline constexpr int kTet10Type = 11;
inline bool is_tet_type(int id) { return id == kTetType || id == kTet10Type; }

// Where Gmsh's 10-node tetrahedron puts the midside node of each edge of
// kTetEdges: its last two midside nodes are VTK's the other way round.
inline constexpr MidsidePlaces kGmshMidsidePlaces = {4, 5, 6, 7, 9, 8};

const ElementType* element_type(int id);                           // nullptr if not handled
const ElementType* element_type_of_kind(const std::string& kind);  // nullptr if none
// "unsupported element type 17 (20-node hexahedron)"; the name is left out
// for ids Gmsh does not define either.
std::string unsupported_element_type(int id);

// A model entity. Points (dim 0) carry their coordinates in box[0..2]; the
// others a bounding box min x,y,z then max x,y,z. `bounding` lists the tags
// of the entities of dimension dim-1 on its boundary, signed by orientation.
// An entity of $PartitionedEntities is the part of a model entity, its
// parent, in some partitions; the parent's dimension is dim or higher (a
// surface between two partitions of a volume has the volume as parent).
// parent_tag is 0 for the other entities and where the file names no parent.
struct Entity {
  int dim = 0;
  int tag = 0;
  double box[6] = {0, 0, 0, 0, 0, 0};
  std::vector<int> physicals;
  std::vector<int> bounding;
  int parent_dim = 0;
  int parent_tag = 0;
};

// The entities of a file, in file order (points, curves, surfaces, volumes).
class Entities {
 public:
  // False if (dim, tag) is already present: the file declares it twice.
  bool add(Entity entity);
  const Entity* find(int dim, int tag) const;
  const std::vector<Entity>& list() const { return list_; }
  std::size_t count(int dim) const;

 private:
  std::vector<Entity> list_;
  std::map<std::pair<int, int>, std::size_t> index_;
};

// The first physical tag of entity (dim, tag), 0 when it has none or the
// entity is unknown: the one physical tag an element carries in MSH 2.
int first_physical(const Entities& entities, int dim, int tag);

// Entities made up from the elements on them, for a file that declares none:
// each (dim, tag) in order of first use, with the bounding box of its
// elements' nodes (a point entity: its node's coordinates).
class EntityBuilder {
 public:
  // Adds an element on entity (dim, tag) over `count` 0-based node indices
  // into `xyz` (3 coordinates a node); returns the entity, whose physicals
  // the caller fills.
  Entity& add(int dim, int tag, const double* xyz, const std::int32_t* nodes, int count);
  Entities take();

 private:
  std::vector<Entity> made_;
  std::map<std::pair<int, int>, std::size_t> at_;
};

// How many elements lie on an entity of several physical groups, per the
// file's $Entities (none without them): the tets, and with `blocks` the
// other elements too. Formats with one tag per element keep only the first
// group of those.
std::size_t elements_in_several_groups(const FileExtras& extras, bool blocks);

// Tags a written file can carry are positive, distinct and at most
// `largest`: a tag of `tags` that is not, or nullopt when all are.
std::optional<long long> unusable_tag(std::vector<long long> tags, long long largest = INT64_MAX);

// The largest tag written where MSH holds tags as 32-bit ints (element tags
// in $ElementData, node tags in $NodeData and in MSH 2.2's $Nodes), with a
// margin: Gmsh 4.8 crashes reading $ElementData whose tags come within 100
// of INT32_MAX. Element tags are kept only up to it; node tags above it are
// kept in MSH 4.1's $Nodes (size_t), where they cost the file its node
// field data instead.
inline constexpr long long kLargestIntTag = INT32_MAX - 1024;

// Whether field data can name every one of these node tags (empty: the
// nodes are numbered 1, 2, ...).
bool node_tags_fit_int(const std::vector<long long>& node_tags);

// MSH physical tags are positive (0 is "none"). Negative region tags (a
// TetGen or VTU mesh's) are written as the next free positive tags, -1 the
// first, so that the regions stay apart: old tag -> written tag, empty when
// no tag of the tets or the pass-through blocks is negative.
std::map<int, int> negative_tag_renumbering(const FileExtras& extras);

// Every element's tag from the file, tets first and then each pass-through
// block, or empty when any element has none.
std::vector<long long> file_element_tags(const FileExtras& extras, std::size_t tets);

// The body of an ASCII $Entities section, parsed (throws InputError naming
// `source` and the line) and written back.
Entities parse_entities_text(const std::string& body, const std::string& source);
std::string format_entities_text(const Entities& entities);

}  // namespace tetsmooth::gmsh
