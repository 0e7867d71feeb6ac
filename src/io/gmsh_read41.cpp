// Gmsh reader, version 4.1 sections: $Entities, $Nodes, $Elements, ASCII and binary.
// See gmsh.hpp for what is read.
//
// MSH 4.1 layout (manual §10.1): $Entities "<#points> <#curves> <#surfaces> <#volumes>",
// then per point "<tag> <x> <y> <z> <#phys> <phys...>", per curve/surface/volume
// "<tag> <6 bounds> <#phys> <phys...> <#bounding> <bounding...>". $Nodes "<#blocks> <#nodes>
// <min> <max>", per block "<dim> <entity> <parametric> <n>", n tags, n coordinate lines
// (x y z, plus dim parametric coordinates when parametric). $Elements "<#blocks> <#elements>
// <min> <max>", per block "<dim> <entity> <type> <n>", n lines "<tag> <nodes...>". In binary
// the counts are size_t of the data size, dims/tags/types int, coordinates double.
#include <string>

#include "io/byte_reader.hpp"
#include "io/gmsh_sections.hpp"

namespace pdr::io {

namespace {

bool finite(const Point& p) { return p[0] - p[0] == 0 && p[1] - p[1] == 0 && p[2] - p[2] == 0; }

// The four size_t counts that open $Nodes and $Elements (ASCII).
void read_counts(TextScanner& s, std::size_t out[4], std::size_t min_bytes, const char* what) {
  s.require_line(what);
  out[0] = s.count("the number of entity blocks", 8);
  out[1] = s.count(what, min_bytes);
  out[2] = s.count("the minimum tag", 0);
  out[3] = s.count("the maximum tag", 0);
  s.end_line(what);
}

}  // namespace

void read_entities_v4(TextScanner& s, const GmshFormat& f, GmshPhysicals& physicals) {
  if (f.binary) {
    ByteReader b(s.text(), s.after_line(), s.file());
    std::uint64_t count[4];
    for (auto& c : count) c = b.get_uint(f.data_size, "an entity count");
    for (int dim = 0; dim < 4; ++dim) {
      b.need_items(count[dim], 4 + 24 + f.data_size, "the entities");
      for (std::uint64_t e = 0; e < count[dim]; ++e) {
        const auto tag = b.get<std::int32_t>("an entity tag");
        b.skip(dim == 0 ? 24 : 48, "the entity's coordinates");
        const std::uint64_t nphys = b.get_uint(f.data_size, "a physical tag count");
        b.need_items(nphys, 4, "the physical tags");
        for (std::uint64_t k = 0; k < nphys; ++k) {
          const auto phys = b.get<std::int32_t>("a physical tag");
          if (k == 0) physicals[{dim, tag}] = phys;
        }
        if (dim > 0) {
          const std::uint64_t nb = b.get_uint(f.data_size, "a bounding entity count");
          b.need_items(nb, 4, "the bounding entities");
          b.skip(static_cast<std::size_t>(nb) * 4, "the bounding entities");
        }
      }
    }
    s.resume_at(b.offset());
  } else {
    s.require_line("the entity counts");
    std::size_t count[4];
    for (auto& c : count) c = s.count("an entity count", 8);
    s.end_line("the entity counts");
    for (int dim = 0; dim < 4; ++dim) {
      for (std::size_t e = 0; e < count[dim]; ++e) {
        s.require_line("an entity of dimension " + std::to_string(dim));
        const int tag = s.number<int>("the entity tag");
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) (void)s.number<double>("an entity bound");
        const std::size_t nphys = s.count("the number of physical tags", 2);
        for (std::size_t k = 0; k < nphys; ++k) {
          const int phys = s.number<int>("a physical tag");
          if (k == 0) physicals[{dim, tag}] = phys;
        }
        if (dim > 0) {
          const std::size_t nb = s.count("the number of bounding entities", 2);
          for (std::size_t k = 0; k < nb; ++k) (void)s.number<int>("a bounding entity");
        }
        s.end_line("the entity");
      }
    }
  }
  expect_section_end(s, "$Entities");
}

void read_nodes_v4(TextScanner& s, const GmshFormat& f, GmshNodes& nodes) {
  if (f.binary) {
    ByteReader b(s.text(), s.after_line(), s.file());
    std::uint64_t head[4];
    for (auto& h : head) h = b.get_uint(f.data_size, "the node counts");
    b.need_items(head[1], f.data_size + 24, "the nodes");
    nodes.reserve(static_cast<std::size_t>(head[1]));
    std::uint64_t total = 0;
    for (std::uint64_t blk = 0; blk < head[0]; ++blk) {
      const std::size_t at = b.offset();
      const auto dim = b.get<std::int32_t>("a node block dimension");
      (void)b.get<std::int32_t>("a node block entity");
      const auto parametric = b.get<std::int32_t>("a node block parametric flag");
      const std::uint64_t n = b.get_uint(f.data_size, "a node block count");
      if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1 || n > head[1] - total)
        b.fail_at(at, "node block header (dimension " + std::to_string(dim) + ", parametric " +
                          std::to_string(parametric) + ", " + std::to_string(n) +
                          " nodes) does not fit the " + std::to_string(head[1]) +
                          " nodes declared; the file is corrupt");
      const std::size_t ncoord = 3 + (parametric ? static_cast<std::size_t>(dim) : 0);
      b.need_items(n, f.data_size + 8 * ncoord, "the node block");
      ByteReader tags = b;
      b.skip(static_cast<std::size_t>(n) * f.data_size, "the node tags");
      for (std::uint64_t i = 0; i < n; ++i) {
        const std::size_t where = tags.offset();
        const std::uint64_t tag = tags.get_uint(f.data_size, "a node tag");
        Point p;
        for (double& c : p) c = b.get<double>("a node coordinate");
        b.skip(8 * (ncoord - 3), "the parametric coordinates");
        if (!finite(p))
          b.fail_at(where, "node " + std::to_string(tag) + " has a coordinate that is not "
                           "finite; fix the mesh");
        nodes.add(tag, p, where);
      }
      total += n;
    }
    if (total != head[1])
      b.fail("the node blocks hold " + std::to_string(total) + " nodes but the header "
             "declares " + std::to_string(head[1]) + "; the file is corrupt");
    s.resume_at(b.offset());
  } else {
    std::size_t head[4];
    read_counts(s, head, 8, "the number of nodes");
    nodes.reserve(head[1]);
    std::size_t total = 0;
    for (std::size_t blk = 0; blk < head[0]; ++blk) {
      s.require_line("a node block header '<dim> <entity> <parametric> <n>'");
      const int dim = s.number<int>("the block dimension");
      (void)s.number<int>("the block entity");
      const int parametric = s.number<int>("the parametric flag");
      const std::size_t n = s.count("the number of nodes in the block", 8);
      s.end_line("the node block header");
      if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1)
        s.fail("bad node block header: dimension must be 0..3 and parametric 0 or 1");
      if (n > head[1] - total)
        s.fail("the node blocks hold more than the " + std::to_string(head[1]) +
               " nodes declared; fix the node count");
      const std::size_t ncoord = 3 + (parametric ? static_cast<std::size_t>(dim) : 0);
      const std::size_t first = nodes.size();
      for (std::size_t i = 0; i < n; ++i) {
        s.require_line("a node tag");
        nodes.add(s.number<std::uint64_t>("the node tag"), Point{}, s.line());
        s.end_line("the node tag (one per line)");
      }
      for (std::size_t i = 0; i < n; ++i) {
        s.require_line("node coordinates");
        Point& p = nodes.points()[first + i];
        p[0] = s.number<double>("the x coordinate");
        p[1] = s.number<double>("the y coordinate");
        p[2] = s.number<double>("the z coordinate");
        for (std::size_t k = 3; k < ncoord; ++k) (void)s.number<double>("a parametric coordinate");
        s.end_line("the node's coordinates");
      }
      total += n;
    }
    if (total != head[1])
      s.fail("the node blocks hold " + std::to_string(total) + " nodes but the header "
             "declares " + std::to_string(head[1]) + "; fix the node count");
  }
  expect_section_end(s, "$Nodes");
}

void read_elements_v4(TextScanner& s, const GmshFormat& f, const GmshNodes& nodes,
                      const GmshPhysicals& physicals, GmshSink& sink) {
  auto physical_of = [&](int dim, int entity) {
    const auto it = physicals.find({dim, entity});
    return it == physicals.end() ? 0 : it->second;
  };
  std::uint32_t idx[128];
  if (f.binary) {
    ByteReader b(s.text(), s.after_line(), s.file());
    auto fail = [&](const std::string& msg) { b.fail(msg); };
    std::uint64_t head[4];
    for (auto& h : head) h = b.get_uint(f.data_size, "the element counts");
    std::uint64_t total = 0;
    for (std::uint64_t blk = 0; blk < head[0]; ++blk) {
      const std::size_t at = b.offset();
      const auto dim = b.get<std::int32_t>("an element block dimension");
      const auto entity = b.get<std::int32_t>("an element block entity");
      const auto type_id = b.get<std::int32_t>("an element block type");
      const std::uint64_t n = b.get_uint(f.data_size, "an element block count");
      const GmshType type = gmsh_type(type_id);
      if (type.nodes == 0)
        b.fail_at(at, "unknown element type " + std::to_string(type_id) + "; binary data of "
                      "unknown types cannot be skipped, export in ASCII");
      if (n > head[1] - total)
        b.fail_at(at, "the element blocks hold more than the " + std::to_string(head[1]) +
                          " elements declared; the file is corrupt");
      const std::size_t per = f.data_size * (1 + static_cast<std::size_t>(type.nodes));
      b.need_items(n, per, "the element block");
      const int marker = physical_of(dim, entity);
      for (std::uint64_t e = 0; e < n; ++e) {
        const auto id = static_cast<std::int64_t>(b.get_uint(f.data_size, "an element tag"));
        if (!sink.wants(type.kind)) {
          b.skip(per - f.data_size, "the element's nodes");
          sink.skip();
          continue;
        }
        for (int k = 0; k < type.nodes; ++k)
          idx[k] = map_node(nodes, b.get_uint(f.data_size, "an element node"), id, fail);
        sink.add(type, idx, marker, 0, id);
      }
      total += n;
    }
    if (total != head[1])
      b.fail("the element blocks hold " + std::to_string(total) + " elements but the header "
             "declares " + std::to_string(head[1]) + "; the file is corrupt");
    s.resume_at(b.offset());
  } else {
    auto fail = [&](const std::string& msg) { s.fail(msg); };
    std::size_t head[4];
    read_counts(s, head, 4, "the number of elements");
    std::size_t total = 0;
    for (std::size_t blk = 0; blk < head[0]; ++blk) {
      s.require_line("an element block header '<dim> <entity> <type> <n>'");
      const int dim = s.number<int>("the block dimension");
      const int entity = s.number<int>("the block entity");
      const GmshType type = gmsh_type(s.number<std::int64_t>("the element type"));
      const std::size_t n = s.count("the number of elements in the block", 4);
      s.end_line("the element block header");
      if (n > head[1] - total)
        s.fail("the element blocks hold more than the " + std::to_string(head[1]) +
               " elements declared; fix the element count");
      const int marker = physical_of(dim, entity);
      const bool wanted = sink.wants(type.kind);
      for (std::size_t e = 0; e < n; ++e) {
        s.require_line("an element line '<tag> <nodes...>'");
        if (!wanted) {
          (void)s.rest_of_line();
          sink.skip();
          continue;
        }
        const auto id = s.number<std::int64_t>("the element tag");
        for (int k = 0; k < type.nodes; ++k)
          idx[k] = map_node(nodes, s.number<std::uint64_t>("an element node"), id, fail);
        s.end_line("the element's nodes");
        sink.add(type, idx, marker, s.line(), id);
      }
      total += n;
    }
    if (total != head[1])
      s.fail("the element blocks hold " + std::to_string(total) + " elements but the header "
             "declares " + std::to_string(head[1]) + "; fix the element count");
  }
  expect_section_end(s, "$Elements");
}

}  // namespace pdr::io
