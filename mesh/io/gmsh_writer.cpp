// Gmsh MSH writing: MSH 4.1 through one body for both encodings, MSH 2.2
// ASCII. Everything the file needs is planned first (gmsh_write_plan.hpp).
#include <algorithm>
#include <limits>
#include <ostream>
#include <stdexcept>

#include "mesh/errors.hpp"
#include "mesh/io/atomic_file.hpp"
#include "mesh/io/gmsh_io.hpp"
#include "mesh/io/gmsh_write_plan.hpp"
#include "mesh/io/number_text.hpp"

namespace tetsmooth {
namespace {

using gmsh::ElementGroup;
using gmsh::WritePlan;

// Values of a section body as text, separated by spaces, one record a line.
class AsciiSink {
 public:
  static constexpr bool kBinary = false;
  explicit AsciiSink(std::ostream& out) : out_(out) {}
  void size(std::uint64_t v) { integer(static_cast<long long>(v)); }
  void integer(long long v) {
    gap();
    put_integer(out_, v);
  }
  void real(double v) {
    gap();
    put_real(out_, v);
  }
  void end_record() {
    out_ << '\n';
    first_ = true;
  }
  void end_body() {}

 private:
  void gap() {
    if (!first_) out_ << ' ';
    first_ = false;
  }
  std::ostream& out_;
  bool first_ = true;
};

// The same values as raw native-order bytes: size_t counts and tags as 8
// bytes, entity tags and types as 4 (the MSH 4.1 binary layout). A newline
// closes the binary body before its "$End" line.
class BinarySink {
 public:
  static constexpr bool kBinary = true;
  explicit BinarySink(std::ostream& out) : out_(out) {}
  void size(std::uint64_t v) { raw(v); }
  void integer(long long v) { raw(static_cast<std::int32_t>(v)); }
  void real(double v) { raw(v); }
  void end_record() {}
  void end_body() { out_ << '\n'; }

 private:
  template <class T>
  void raw(T v) {
    out_.write(reinterpret_cast<const char*>(&v), sizeof v);
  }
  std::ostream& out_;
};

void check_fields(const TetMesh& mesh, const MeshFields& fields) {
  for (const auto& [name, values] : fields.node_scalars)
    if (values.size() != mesh.num_nodes())
      throw std::invalid_argument("node field '" + name + "' has " + std::to_string(values.size()) + " values for " +
                                  std::to_string(mesh.num_nodes()) + " nodes");
  for (const auto& [name, values] : fields.tet_scalars)
    if (values.size() != mesh.num_tets())
      throw std::invalid_argument("tet field '" + name + "' has " + std::to_string(values.size()) + " values for " +
                                  std::to_string(mesh.num_tets()) + " tets");
}

// One $NodeData or $ElementData view at time 0; the header is text in
// every flavour.
void write_data_header(std::ostream& out, const char* section, const std::string& name, std::size_t count) {
  std::string title = name;
  std::replace(title.begin(), title.end(), '"', '\'');
  out << '$' << section << "\n1\n\"" << title << "\"\n1\n0\n3\n0\n1\n" << count << '\n';
}

// In MSH 2.2 (`v22`) an element written once per physical group gets its
// value once per line, so that readers that take the values in the order of
// the element lines (meshio) find one for each.
template <class Sink>
void write_fields(std::ostream& out, Sink& sink, const WritePlan& plan, const MeshFields& fields, bool v22) {
  // Field data name nodes by int; node tags past that, which only MSH 4.1's
  // $Nodes holds, cost the file its node fields (output_losses says so
  // before the work). Element tags always fit: the plan keeps no others.
  if (gmsh::node_tags_fit_int(plan.node_tags))
    for (const auto& [name, values] : fields.node_scalars) {
      write_data_header(out, "NodeData", name, values.size());
      for (std::size_t i = 0; i < values.size(); ++i) {
        sink.integer(plan.node_tags[i]);
        sink.real(values[i]);
        sink.end_record();
      }
      sink.end_body();
      out << "$EndNodeData\n";
    }
  // Every element, in the order of $Elements; the elements other than tets
  // get NaN ("no value") rather than no entry: readers such as meshio
  // expect a value for every element.
  for (const auto& [name, values] : fields.tet_scalars) {
    write_data_header(out, "ElementData", name, v22 ? gmsh::v22_lines(plan) : plan.element_count);
    std::size_t written = 0;
    for (const ElementGroup& g : plan.groups) {
      const bool tets = gmsh::is_tet_type(g.type->id);
      for (std::size_t e = 0; e < g.count; ++e, ++written) {
        const std::size_t copies = v22 ? gmsh::v22_physicals(plan, g, e).second : 1;
        for (std::size_t c = 0; c < copies; ++c) {
          sink.integer(plan.element_tags[written]);
          sink.real(tets ? values[e] : std::numeric_limits<double>::quiet_NaN());
          sink.end_record();
        }
      }
    }
    sink.end_body();
    out << "$EndElementData\n";
  }
}

void write_physical_names(std::ostream& out, const WritePlan& plan) {
  if (plan.physical_names.empty()) return;
  out << "$PhysicalNames\n" << plan.physical_names << "$EndPhysicalNames\n";
}

void write_entities_binary(BinarySink& sink, const gmsh::Entities& entities) {
  for (int dim = 0; dim < 4; ++dim) sink.size(entities.count(dim));
  for (int dim = 0; dim < 4; ++dim) {
    for (const gmsh::Entity& e : entities.list()) {
      if (e.dim != dim) continue;
      sink.integer(e.tag);
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) sink.real(e.box[k]);
      sink.size(e.physicals.size());
      for (int p : e.physicals) sink.integer(p);
      if (dim > 0) {
        sink.size(e.bounding.size());
        for (int b : e.bounding) sink.integer(b);
      }
    }
  }
  sink.end_body();
}

// Nodes and elements go out in blocks of consecutive items on the same
// entity, so that a round trip keeps their order.
template <class Sink>
void write_nodes_v41(std::ostream& out, Sink& sink, const TetMesh& mesh, const WritePlan& plan) {
  const std::size_t n = mesh.num_nodes();
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < n; ++i)
    if (i == 0 || plan.node_dims[i] != plan.node_dims[i - 1] || plan.node_entities[i] != plan.node_entities[i - 1])
      starts.push_back(i);
  starts.push_back(n);
  const auto [lo, hi] = std::minmax_element(plan.node_tags.begin(), plan.node_tags.end());
  out << "$Nodes\n";
  sink.size(starts.size() - 1);
  sink.size(n);
  sink.size(n == 0 ? 0 : static_cast<std::uint64_t>(*lo));
  sink.size(n == 0 ? 0 : static_cast<std::uint64_t>(*hi));
  sink.end_record();
  for (std::size_t b = 0; b + 1 < starts.size(); ++b) {
    const std::size_t first = starts[b], last = starts[b + 1];
    sink.integer(plan.node_dims[first]);
    sink.integer(plan.node_entities[first]);
    sink.integer(0);  // no parametric coordinates
    sink.size(last - first);
    sink.end_record();
    for (std::size_t i = first; i < last; ++i) {
      sink.size(static_cast<std::uint64_t>(plan.node_tags[i]));
      sink.end_record();
    }
    for (std::size_t i = first; i < last; ++i) {
      for (int c = 0; c < 3; ++c) sink.real(mesh.xyz[3 * i + c]);
      sink.end_record();
    }
  }
  sink.end_body();
  out << "$EndNodes\n";
}

template <class Sink>
void write_elements_v41(std::ostream& out, Sink& sink, const WritePlan& plan) {
  std::size_t blocks = 0;
  for (const ElementGroup& g : plan.groups)
    for (std::size_t e = 0; e < g.count; ++e) blocks += e == 0 || g.entity[e] != g.entity[e - 1];
  const auto [lo, hi] = std::minmax_element(plan.element_tags.begin(), plan.element_tags.end());
  out << "$Elements\n";
  sink.size(blocks);
  sink.size(plan.element_count);
  sink.size(plan.element_count == 0 ? 0 : static_cast<std::uint64_t>(*lo));
  sink.size(plan.element_count == 0 ? 0 : static_cast<std::uint64_t>(*hi));
  sink.end_record();
  std::size_t written = 0;
  for (const ElementGroup& g : plan.groups) {
    const auto nodes = static_cast<std::size_t>(g.type->nodes);
    for (std::size_t first = 0; first < g.count;) {
      std::size_t last = first + 1;
      while (last < g.count && g.entity[last] == g.entity[first]) ++last;
      sink.integer(g.type->dim);
      sink.integer(g.entity[first]);
      sink.integer(g.type->id);
      sink.size(last - first);
      sink.end_record();
      for (std::size_t e = first; e < last; ++e) {
        sink.size(static_cast<std::uint64_t>(plan.element_tags[written++]));
        for (std::size_t k = 0; k < nodes; ++k)
          sink.size(
              static_cast<std::uint64_t>(plan.node_tags[static_cast<std::size_t>(g.nodes()[e * nodes + k])]));
        sink.end_record();
      }
      first = last;
    }
  }
  sink.end_body();
  out << "$EndElements\n";
}

template <class Sink>
void write_v41(std::ostream& out, const TetMesh& mesh, const WritePlan& plan, const MeshFields& fields) {
  Sink sink(out);
  out << "$MeshFormat\n4.1 " << (Sink::kBinary ? 1 : 0) << " 8\n";
  if constexpr (Sink::kBinary) {
    const std::int32_t one = 1;  // tells readers the byte order
    out.write(reinterpret_cast<const char*>(&one), sizeof one);
    out << '\n';
  }
  out << "$EndMeshFormat\n";
  write_physical_names(out, plan);
  out << "$Entities\n";
  if constexpr (Sink::kBinary)
    write_entities_binary(sink, plan.entities);
  else
    out << plan.entities_text;
  out << "$EndEntities\n";
  write_nodes_v41(out, sink, mesh, plan);
  write_elements_v41(out, sink, plan);
  write_fields(out, sink, plan, fields, false);
}

// MSH 2.2 has no entities: each element carries its physical and
// elementary tag (the entity tag of the plan), on a line per physical group.
void write_v22(std::ostream& out, const TetMesh& mesh, const WritePlan& plan, const MeshFields& fields) {
  AsciiSink sink(out);
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  write_physical_names(out, plan);
  out << "$Nodes\n" << mesh.num_nodes() << '\n';
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    sink.integer(plan.node_tags[i]);
    for (int c = 0; c < 3; ++c) sink.real(mesh.xyz[3 * i + c]);
    sink.end_record();
  }
  out << "$EndNodes\n$Elements\n" << gmsh::v22_lines(plan) << '\n';
  std::size_t written = 0;
  for (const ElementGroup& g : plan.groups) {
    const auto nodes = static_cast<std::size_t>(g.type->nodes);
    for (std::size_t e = 0; e < g.count; ++e, ++written) {
      const auto [physicals, count] = gmsh::v22_physicals(plan, g, e);
      for (std::size_t p = 0; p < count; ++p) {
        sink.integer(plan.element_tags[written]);
        sink.integer(g.type->id);
        sink.integer(2);
        sink.integer(physicals[p]);
        sink.integer(g.entity[e]);
        for (std::size_t k = 0; k < nodes; ++k)
          sink.integer(plan.node_tags[static_cast<std::size_t>(g.nodes()[e * nodes + k])]);
        sink.end_record();
      }
    }
  }
  out << "$EndElements\n";
  write_fields(out, sink, plan, fields, true);
}

void write_planned(const TetMesh& mesh, std::ostream& out, MshFlavour flavour, const WritePlan& plan,
                   const MeshFields& fields) {
  switch (flavour) {
    case MshFlavour::V41Ascii:
      write_v41<AsciiSink>(out, mesh, plan, fields);
      break;
    case MshFlavour::V41Binary:
      write_v41<BinarySink>(out, mesh, plan, fields);
      break;
    case MshFlavour::V22Ascii:
      write_v22(out, mesh, plan, fields);
      break;
  }
}

}  // namespace

void write_gmsh(const TetMesh& mesh, std::ostream& out, MshFlavour flavour, const MeshFields& fields) {
  check_fields(mesh, fields);
  const WritePlan plan = gmsh::plan_gmsh_output(mesh, flavour);
  write_planned(mesh, out, flavour, plan, fields);
  if (!out) throw OutputError("the MSH output stream failed");
}

void write_gmsh_file(const TetMesh& mesh, const std::string& path, MshFlavour flavour, const MeshFields& fields) {
  check_fields(mesh, fields);
  const WritePlan plan = checked_for(path, [&] { return gmsh::plan_gmsh_output(mesh, flavour); });
  write_atomically(
      path, [&](std::ostream& out) { write_planned(mesh, out, flavour, plan, fields); },
      flavour == MshFlavour::V41Binary);
}

}  // namespace tetsmooth
