// Gmsh reader: $MeshFormat, the section loop, and the version 2.2 sections ($Nodes and
// $Elements, ASCII and binary). See gmsh.hpp for what is read and the conventions; the
// same sections give a surface domain (read_gmsh_surface, surface.hpp).
//
// MSH 2.2 layout: $Nodes "<n>" then n x "<tag> <x> <y> <z>" (binary: int tag, 3 doubles);
// $Elements "<m>" then m x "<id> <type> <ntags> <tags...> <nodes...>" (binary: blocks of
// int <type> <count> <ntags>, then count x int <id> <tags...> <nodes...>).
#include <optional>
#include <string>

#include "io/byte_reader.hpp"
#include "io/file_bytes.hpp"
#include "io/gmsh.hpp"
#include "io/gmsh_sections.hpp"

namespace pdr::io {

void expect_section_end(TextScanner& s, std::string_view name) {
  const std::string end = "$End" + std::string(name.substr(1));
  s.require_line(end);
  const std::string_view tok = s.token("the section end");
  if (tok != end)
    s.fail("expected " + end + ", found '" + std::string(tok.substr(0, 40)) +
           "'; a count in the " + std::string(name) + " section is wrong");
}

void read_nodes_v2(TextScanner& s, const GmshFormat& f, GmshNodes& nodes) {
  s.require_line("the number of nodes");
  const std::size_t n = s.count("the number of nodes", f.binary ? 28 : 8);
  s.end_line("the number of nodes");
  nodes.reserve(n);
  if (f.binary) {
    ByteReader b(s.text(), s.after_line(), s.file());
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t where = b.offset();
      const auto tag = b.get<std::int32_t>("a node tag");
      Point p;
      for (double& c : p) c = b.get<double>("a node coordinate");
      if (tag <= 0) b.fail_at(where, "node tag " + std::to_string(tag) + " is not positive");
      if (!(p[0] - p[0] == 0 && p[1] - p[1] == 0 && p[2] - p[2] == 0))
        b.fail_at(where, "node " + std::to_string(tag) + " has a coordinate that is not "
                         "finite; fix the mesh");
      nodes.add(static_cast<std::uint64_t>(tag), p, where);
    }
    s.resume_at(b.offset());
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      s.require_line("node " + std::to_string(i + 1) + " of " + std::to_string(n));
      const auto tag = s.number<std::uint64_t>("the node tag");
      Point p;
      p[0] = s.number<double>("the x coordinate");
      p[1] = s.number<double>("the y coordinate");
      p[2] = s.number<double>("the z coordinate");
      s.end_line("the node's coordinates");
      nodes.add(tag, p, s.line());
    }
  }
  expect_section_end(s, "$Nodes");
}

void read_elements_v2(TextScanner& s, const GmshFormat& f, const GmshNodes& nodes,
                      GmshSink& sink) {
  s.require_line("the number of elements");
  const std::size_t m = s.count("the number of elements", f.binary ? 12 : 8);
  s.end_line("the number of elements");
  std::uint32_t idx[128];
  if (f.binary) {
    ByteReader b(s.text(), s.after_line(), s.file());
    auto fail = [&](const std::string& msg) { b.fail(msg); };
    for (std::size_t done = 0; done < m;) {
      const std::size_t header_at = b.offset();
      const auto type_id = b.get<std::int32_t>("an element block type");
      const auto count = b.get<std::int32_t>("an element block count");
      const auto ntags = b.get<std::int32_t>("an element block tag count");
      const GmshType type = gmsh_type(type_id);
      if (type.nodes == 0)
        b.fail_at(header_at, "unknown element type " + std::to_string(type_id) +
                                 "; binary data of unknown types cannot be skipped, export "
                                 "the mesh in ASCII or without such elements");
      if (count <= 0 || static_cast<std::size_t>(count) > m - done || ntags < 0)
        b.fail_at(header_at, "element block of " + std::to_string(count) + " elements with " +
                                 std::to_string(ntags) + " tags does not fit the " +
                                 std::to_string(m) + " elements declared");
      const std::size_t ints = 1 + static_cast<std::size_t>(ntags) + type.nodes;
      b.need_items(static_cast<std::uint64_t>(count), 4 * ints, "the element block");
      for (std::int32_t e = 0; e < count; ++e) {
        const auto id = b.get<std::int32_t>("an element id");
        int physical = 0;
        for (std::int32_t t = 0; t < ntags; ++t) {
          const auto tag = b.get<std::int32_t>("an element tag");
          if (t == 0) physical = tag;
        }
        for (int k = 0; k < type.nodes; ++k) {
          const auto tag = b.get<std::int32_t>("an element node");
          idx[k] = map_node(nodes, static_cast<std::uint64_t>(tag < 0 ? 0 : tag), id, fail);
        }
        sink.add(type, idx, physical, 0, id);
      }
      done += static_cast<std::size_t>(count);
    }
    s.resume_at(b.offset());
  } else {
    auto fail = [&](const std::string& msg) { s.fail(msg); };
    for (std::size_t e = 0; e < m; ++e) {
      s.require_line("element " + std::to_string(e + 1) + " of " + std::to_string(m));
      const auto id = s.number<std::int64_t>("the element id");
      const GmshType type = gmsh_type(s.number<std::int64_t>("the element type"));
      if (!sink.wants(type.kind)) {
        (void)s.rest_of_line();
        sink.skip();
        continue;
      }
      const std::size_t ntags = s.count("the number of element tags", 0);
      int physical = 0;
      for (std::size_t t = 0; t < ntags; ++t) {
        const int tag = s.number<int>("an element tag");
        if (t == 0) physical = tag;
      }
      for (int k = 0; k < type.nodes; ++k)
        idx[k] = map_node(nodes, s.number<std::uint64_t>("an element node"), id, fail);
      s.end_line("the element's nodes");
      sink.add(type, idx, physical, s.line(), id);
    }
  }
  expect_section_end(s, "$Elements");
}

namespace {

GmshFormat read_mesh_format(TextScanner& s) {
  if (!s.next_line() || s.token("the first section") != "$MeshFormat")
    s.fail("a Gmsh file starts with $MeshFormat; this is not an MSH file");
  s.require_line("the version line '<version> <file-type> <data-size>'");
  GmshFormat f;
  const std::string_view version = s.token("the version");
  if (version == "4.1") f.major = 4;
  else if (version == "2.2" || version == "2.1" || version == "2" || version == "2.0") f.major = 2;
  else
    s.fail("MSH version " + std::string(version.substr(0, 20)) + " is not supported; export "
           "with -format msh41 or msh22");
  const int file_type = s.number<int>("the file type");
  if (file_type != 0 && file_type != 1) s.fail("the file type must be 0 (ASCII) or 1 (binary)");
  f.binary = file_type == 1;
  const int data_size = s.number<int>("the data size");
  if (f.binary && (f.major == 2 ? data_size != 8 : (data_size != 8 && data_size != 4)))
    s.fail("binary data size " + std::to_string(data_size) + " is not supported; export on a "
           "64-bit machine");
  f.data_size = static_cast<std::size_t>(data_size);
  s.end_line("the data size");
  if (f.binary) {
    ByteReader b(s.text(), s.after_line(), s.file());
    const auto one = b.get<std::int32_t>("the byte order marker");
    if (one != 1)
      b.fail("the byte order marker is " + std::to_string(one) + ", not 1: the file was "
             "written on a machine of the other byte order; export it in ASCII");
    s.resume_at(b.offset());
  }
  expect_section_end(s, "$MeshFormat");
  return f;
}

void skip_section(TextScanner& s, std::string_view name) {
  const std::string end = "$End" + std::string(name.substr(1));
  const std::size_t start = s.line();
  while (s.next_line())
    if (s.token("a token") == end) return;
  s.fail_at(start, "section " + std::string(name) + " is not closed by " + end +
                       "; the file is truncated");
}

}  // namespace

GmshMarkerNames read_physical_names(TextScanner& s) {
  s.require_line("the number of physical names");
  const std::size_t n = s.count("the number of physical names", 6);
  s.end_line("the number of physical names");
  GmshMarkerNames out;
  constexpr std::string_view kPrefix = "\"pdr marker ";
  for (std::size_t i = 0; i < n; ++i) {
    s.require_line("a physical name '<dim> <tag> \"<name>\"'");
    const int dim = s.number<int>("the physical group's dimension");
    const int tag = s.number<int>("the physical tag");
    const std::string_view name = s.rest_of_line();
    int marker = 0;
    if (name.size() > kPrefix.size() + 1 && name.substr(0, kPrefix.size()) == kPrefix &&
        name.back() == '"' &&
        parse_number(name.substr(kPrefix.size(), name.size() - kPrefix.size() - 1), marker))
      out[{dim, tag}] = marker;
  }
  expect_section_end(s, "$PhysicalNames");
  return out;
}

namespace {

// The sections of a whole file; `sink` holds its elements.
struct GmshFile {
  GmshFormat format;
  GmshNodes nodes;
  std::optional<GmshSink> sink;
};

GmshFile read_sections(const std::string& path, const std::string& bytes, bool surface) {
  TextScanner s(bytes, path, '\0');
  GmshFile file;
  file.format = read_mesh_format(s);
  const GmshFormat& f = file.format;
  GmshNodes& nodes = file.nodes;
  GmshPhysicals physicals;
  GmshMarkerNames names;
  bool have_nodes = false;
  while (s.next_line()) {
    const std::string_view name = s.token("a section name");
    if (name.empty() || name[0] != '$')
      s.fail("expected a section name such as $Nodes, found '" +
             std::string(name.substr(0, 40)) + "'; a count in the previous section is wrong");
    if (name == "$Nodes") {
      if (have_nodes) s.fail("a second $Nodes section is not supported; merge the sections");
      if (f.major == 2) read_nodes_v2(s, f, nodes);
      else read_nodes_v4(s, f, nodes);
      const std::size_t dup = nodes.finish();
      if (dup != nodes.size()) {
        const std::string msg = "node tag " + std::to_string(nodes.tag(dup)) +
                                " is defined twice; give every node its own tag";
        if (f.binary) ByteReader(bytes, 0, path).fail_at(nodes.where(dup), msg);
        s.fail_at(nodes.where(dup), msg);
      }
      have_nodes = true;
    } else if (name == "$Elements") {
      if (!have_nodes) s.fail("$Elements comes before $Nodes; Gmsh writes $Nodes first");
      if (file.sink) s.fail("a second $Elements section is not supported");
      file.sink.emplace(std::move(nodes.points()), surface);
      file.sink->set_marker_names(names);
      if (f.major == 2) read_elements_v2(s, f, nodes, *file.sink);
      else read_elements_v4(s, f, nodes, physicals, *file.sink);
    } else if (name == "$PhysicalNames") {
      names = read_physical_names(s);
    } else if (name == "$Entities" && f.major == 4) {
      read_entities_v4(s, f, physicals);
    } else {
      skip_section(s, name);
    }
  }
  if (!file.sink)
    s.fail_at(0, "no $Elements section; the file holds no mesh, mesh the volume (gmsh -3)");
  return file;
}

}  // namespace

MeshData read_gmsh(const std::string& path, ReadInfo* info) {
  const std::string bytes = read_file_bytes(path);
  GmshFile file = read_sections(path, bytes, false);
  std::string problem;
  MeshData mesh = file.sink->finish(info, problem);
  if (!problem.empty()) throw InputError(path, 0, problem);
  return mesh;
}

Surface read_gmsh_surface(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  GmshFile file = read_sections(path, bytes, true);
  return file.sink->finish_surface(path, file.nodes, file.format.binary);
}

}  // namespace pdr::io
