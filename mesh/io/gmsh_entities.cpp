#include <sstream>

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

template <class Source>
Entities read_entities(Source& src) {
  static const char* const kCountNames[4] = {"number of points", "number of curves", "number of surfaces",
                                             "number of volumes"};
  std::uint64_t counts[4];
  for (int dim = 0; dim < 4; ++dim) counts[dim] = src.size_value(kCountNames[dim]);
  Entities entities;
  for (int dim = 0; dim < 4; ++dim) {
    // Smallest binary record: tag, coordinates, and an empty physical list
    // (plus an empty boundary list above dimension 0).
    src.reservable(counts[dim], dim == 0 ? 4 + 24 + 8 : 4 + 48 + 16);
    for (std::uint64_t i = 0; i < counts[dim]; ++i) {
      Entity e;
      e.dim = dim;
      e.tag = src.int_value("entity tag");
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
        src.fail("entity of dimension " + std::to_string(dim) + " with tag " + std::to_string(tag) +
                 " is declared twice");
    }
  }
  return entities;
}

template Entities read_entities<AsciiSource>(AsciiSource&);
template Entities read_entities<BinarySource>(BinarySource&);

Entities parse_entities_text(const std::string& body, const std::string& source) {
  std::istringstream in(body);
  TextLines lines(in, source, '\0');
  AsciiSource src(lines);
  Entities entities = read_entities(src);
  const std::string_view rest = src.next_section();
  if (!rest.empty()) src.fail("unexpected '" + std::string(rest.substr(0, 40)) + "' after the last entity");
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
