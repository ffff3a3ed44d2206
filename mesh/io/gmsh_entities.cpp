#include <algorithm>
#include <limits>
#include <sstream>

#include "mesh/errors.hpp"
#include "mesh/file_extras.hpp"
#include "mesh/io/gmsh_detail.hpp"
#include "mesh/io/gmsh_source.hpp"
#include "mesh/io/number_text.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::gmsh {

bool Entities::add(Entity entity) {
  const auto key = std::make_pair(entity.dim, entity.tag);
  if (!index_.emplace(key, list_.size()).second) return false;
  list_.push_back(std::move(entity));
  return true;
}

const Entity* Entities::find(int dim, int tag) const {
  const auto it = index_.find({dim, tag});
  return it == index_.end() ? nullptr : &list_[it->second];
}

std::size_t Entities::count(int dim) const {
  std::size_t n = 0;
  for (const Entity& e : list_) n += e.dim == dim;
  return n;
}

int first_physical(const Entities& entities, int dim, int tag) {
  const Entity* e = entities.find(dim, tag);
  return e == nullptr || e->physicals.empty() ? 0 : e->physicals.front();
}

Entity& EntityBuilder::add(int dim, int tag, const double* xyz, const std::int32_t* nodes, int count) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const auto [it, fresh] = at_.emplace(std::make_pair(dim, tag), made_.size());
  if (fresh) {
    Entity& x = made_.emplace_back();
    x.dim = dim;
    x.tag = tag;
    std::fill(x.box, x.box + 3, kInf);
    std::fill(x.box + 3, x.box + 6, -kInf);
  }
  Entity& x = made_[it->second];
  for (int k = 0; k < count; ++k) {
    const double* p = &xyz[3 * static_cast<std::size_t>(nodes[k])];
    for (int c = 0; c < 3; ++c) {
      x.box[c] = std::min(x.box[c], p[c]);
      x.box[c + 3] = std::max(x.box[c + 3], p[c]);
    }
  }
  return x;
}

Entities EntityBuilder::take() {
  Entities entities;
  for (Entity& x : made_) entities.add(std::move(x));
  made_.clear();
  at_.clear();
  return entities;
}

std::size_t elements_in_several_groups(const FileExtras& extras, bool blocks) {
  const std::string* raw = raw_section(extras, "$Entities");
  if (raw == nullptr) return 0;
  Entities entities;
  try {
    entities = parse_entities_text(*raw, "$Entities");
  } catch (const InputError&) {
    return 0;  // not what a reader stored; the writers make entities up then
  }
  const auto count = [&](int dim, const std::vector<int>& tags) {
    std::size_t n = 0;
    for (int tag : tags) {
      const Entity* e = entities.find(dim, tag);
      n += e != nullptr && e->physicals.size() > 1;
    }
    return n;
  };
  std::size_t n = count(3, extras.tet_entity_tags);
  for (const PassThroughBlock& block : extras.blocks)
    if (const ElementType* type = element_type_of_kind(block.kind); blocks && type != nullptr)
      n += count(type->dim, block.entity_tags);
  return n;
}

namespace {

// Reads the tag of a partitioned entity's parent and the partitions it is
// in (not kept: the reader merges the partitions).
template <class Source>
void read_parent(Source& src, Entity& e) {
  e.parent_dim = src.int_value("parent entity dimension");
  e.parent_tag = src.int_value("parent entity tag");
  // Gmsh writes "0 0" for an entity without a parent.
  if (e.parent_tag != 0 && (e.parent_dim < e.dim || e.parent_dim > 3))
    src.fail("partitioned entity of dimension " + std::to_string(e.dim) + " with tag " + std::to_string(e.tag) +
             " has a parent of dimension " + std::to_string(e.parent_dim) + " (expected " + std::to_string(e.dim) +
             " to 3)");
  const std::uint64_t partitions = src.size_value("number of partitions");
  src.reservable(partitions, 4);
  for (std::uint64_t k = 0; k < partitions; ++k) src.int_value("partition tag");
}

// The four counts and the entity records of $Entities or, `partitioned`,
// of $PartitionedEntities, whose records add the parent and the partitions
// after the tag.
template <class Source>
Entities read_entity_records(Source& src, bool partitioned) {
  static const char* const kCountNames[4] = {"number of points", "number of curves", "number of surfaces",
                                             "number of volumes"};
  std::uint64_t counts[4];
  for (int dim = 0; dim < 4; ++dim) counts[dim] = src.size_value(kCountNames[dim]);
  Entities entities;
  for (int dim = 0; dim < 4; ++dim) {
    // Smallest binary record: tag, coordinates, and an empty physical list
    // (plus an empty boundary list above dimension 0, and the parent and an
    // empty partition list when partitioned).
    src.reservable(counts[dim], (dim == 0 ? 4 + 24 + 8 : 4 + 48 + 16) + (partitioned ? 16 : 0));
    for (std::uint64_t i = 0; i < counts[dim]; ++i) {
      Entity e;
      e.dim = dim;
      e.tag = src.int_value("entity tag");
      if (partitioned) read_parent(src, e);
      if (dim == 0) {
        for (int k = 0; k < 3; ++k) e.box[k] = e.box[k + 3] = src.real_value("point coordinate");
      } else {
        for (double& v : e.box) v = src.real_value("bounding box coordinate");
      }
      const std::uint64_t physicals = src.size_value("number of physical tags");
      src.reservable(physicals, 4);
      for (std::uint64_t k = 0; k < physicals; ++k) e.physicals.push_back(src.int_value("physical tag"));
      if (dim > 0) {
        const std::uint64_t bounding = src.size_value("number of bounding entities");
        src.reservable(bounding, 4);
        for (std::uint64_t k = 0; k < bounding; ++k) e.bounding.push_back(src.int_value("bounding entity tag"));
      }
      const int tag = e.tag;
      if (!entities.add(std::move(e)))
        src.fail(std::string(partitioned ? "partitioned " : "") + "entity of dimension " + std::to_string(dim) +
                 " with tag " + std::to_string(tag) + " is declared twice");
    }
  }
  return entities;
}

}  // namespace

template <class Source>
Entities read_entities(Source& src) {
  return read_entity_records(src, false);
}

template <class Source>
Entities read_partitioned_entities(Source& src) {
  src.size_value("number of partitions");
  const std::uint64_t ghosts = src.size_value("number of ghost entities");
  src.reservable(ghosts, 8);
  for (std::uint64_t i = 0; i < ghosts; ++i) {
    src.int_value("ghost entity tag");
    src.int_value("ghost entity partition");
  }
  return read_entity_records(src, true);
}

template Entities read_entities<AsciiSource>(AsciiSource&);
template Entities read_entities<BinarySource>(BinarySource&);
template Entities read_partitioned_entities<AsciiSource>(AsciiSource&);
template Entities read_partitioned_entities<BinarySource>(BinarySource&);

Entities parse_entities_text(const std::string& body, const std::string& source) {
  std::istringstream in(body);
  TextLines lines(in, source, '\0');
  AsciiSource src(lines);
  Entities entities = read_entities(src);
  const std::string_view rest = src.next_section();
  if (!rest.empty()) src.fail("unexpected " + quoted_token(rest) + " after the last entity");
  return entities;
}

std::string format_entities_text(const Entities& entities) {
  std::ostringstream out;
  for (int dim = 0; dim < 4; ++dim) out << entities.count(dim) << (dim < 3 ? ' ' : '\n');
  for (int dim = 0; dim < 4; ++dim) {
    for (const Entity& e : entities.list()) {
      if (e.dim != dim) continue;
      put_integer(out, e.tag);
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) {
        out << ' ';
        put_real(out, e.box[k]);
      }
      out << ' ' << e.physicals.size();
      for (int p : e.physicals) out << ' ' << p;
      if (dim > 0) {
        out << ' ' << e.bounding.size();
        for (int b : e.bounding) out << ' ' << b;
      }
      out << '\n';
    }
  }
  return out.str();
}

}  // namespace tetsmooth::gmsh
