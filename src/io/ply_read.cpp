// PLY surface reader (Stanford polygon file format), ASCII and binary in either byte order,
// as written by meshio, MeshLab, Blender and 3-D scanners.
//
// Header: "ply", "format <ascii|binary_little_endian|binary_big_endian> 1.0", "comment ..."
// and "obj_info ..." lines, elements "element <name> <count>" each followed by its
// properties "property <type> <name>" or "property list <count type> <item type> <name>",
// then "end_header". Types: char/int8, uchar/uint8, short/int16, ushort/uint16, int/int32,
// uint/uint32, float/float32, double/float64.
// Read: the x, y, z properties of element "vertex" and the list "vertex_indices" (or
// "vertex_index") of element "face", 0-based; every other property and element is skipped
// (in binary files by its size). ASCII files hold one element instance per line. Faces
// carry no markers. Messages name file:line in ASCII files, the byte offset or the face's
// number in binary ones.
#include <bit>
#include <string>
#include <vector>

#include "io/byte_reader.hpp"
#include "io/file_bytes.hpp"
#include "io/surface.hpp"
#include "io/text_scanner.hpp"

namespace pdr::io {

namespace {

enum class PlyType : std::uint8_t { I8, U8, I16, U16, I32, U32, F32, F64 };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::F64;   // the item type of a list
  PlyType count = PlyType::U8;   // the count type of a list
  bool list = false;
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
};

PlyType parse_type(TextScanner& s, std::string_view t) {
  struct Name {
    const char* a;
    const char* b;
    PlyType type;
  };
  static constexpr Name kNames[] = {
      {"char", "int8", PlyType::I8},     {"uchar", "uint8", PlyType::U8},
      {"short", "int16", PlyType::I16},  {"ushort", "uint16", PlyType::U16},
      {"int", "int32", PlyType::I32},    {"uint", "uint32", PlyType::U32},
      {"float", "float32", PlyType::F32}, {"double", "float64", PlyType::F64}};
  for (const Name& n : kNames)
    if (t == n.a || t == n.b) return n.type;
  s.fail("unknown PLY property type '" + std::string(t.substr(0, 40)) + "'; the types are "
         "char, uchar, short, ushort, int, uint, float, double (or int8 ... float64)");
}

bool is_integer(PlyType t) { return t != PlyType::F32 && t != PlyType::F64; }

std::size_t type_size(PlyType t) {
  switch (t) {
    case PlyType::I8: case PlyType::U8: return 1;
    case PlyType::I16: case PlyType::U16: return 2;
    case PlyType::I32: case PlyType::U32: case PlyType::F32: return 4;
    case PlyType::F64: return 8;
  }
  return 8;
}

// A binary value of type t as a double (exact: every PLY type fits in a double).
double get_value(ByteReader& b, PlyType t, std::endian order, std::string_view what) {
  switch (t) {
    case PlyType::I8: return b.get_in<std::int8_t>(order, what);
    case PlyType::U8: return b.get_in<std::uint8_t>(order, what);
    case PlyType::I16: return b.get_in<std::int16_t>(order, what);
    case PlyType::U16: return b.get_in<std::uint16_t>(order, what);
    case PlyType::I32: return b.get_in<std::int32_t>(order, what);
    case PlyType::U32: return b.get_in<std::uint32_t>(order, what);
    case PlyType::F32: return b.get_in<float>(order, what);
    case PlyType::F64: return b.get_in<double>(order, what);
  }
  return 0;
}

// An ASCII value of type t as a double; integers must be integers.
double get_value(TextScanner& s, PlyType t, std::string_view what) {
  if (is_integer(t)) return static_cast<double>(s.number<std::int64_t>(what));
  return s.number<double>(what);
}

struct Header {
  std::endian order = std::endian::native;
  bool ascii = true;
  std::vector<PlyElement> elements;
};

Header read_header(TextScanner& s) {
  if (!s.next_line() || s.token("the magic word") != "ply" || s.has_token())
    s.fail("a PLY file starts with the line 'ply'; this is not a PLY file");
  Header h;
  s.require_line("the format line");
  if (s.token("the format keyword") != "format") s.fail("expected 'format <type> 1.0'");
  const std::string_view f = s.token("the format");
  if (f == "binary_little_endian") h.order = std::endian::little;
  else if (f == "binary_big_endian") h.order = std::endian::big;
  else if (f != "ascii")
    s.fail("unknown PLY format '" + std::string(f.substr(0, 40)) + "'; use ascii, "
           "binary_little_endian or binary_big_endian");
  h.ascii = f == "ascii";
  (void)s.rest_of_line();  // the version
  for (;;) {
    s.require_line("the header's 'end_header'");
    const std::string_view kw = s.token("a header keyword");
    if (kw == "end_header") break;
    if (kw == "comment" || kw == "obj_info") {
      (void)s.rest_of_line();
    } else if (kw == "element") {
      PlyElement e;
      e.name = s.token("the element name");
      e.count = s.count("the element count", h.ascii ? 2 : 1);
      s.end_line("the element line");
      h.elements.push_back(std::move(e));
    } else if (kw == "property") {
      if (h.elements.empty()) s.fail("a property before any element; put 'element' first");
      PlyProperty p;
      std::string_view t = s.token("the property type");
      if (t == "list") {
        p.list = true;
        p.count = parse_type(s, s.token("the list's count type"));
        if (!is_integer(p.count)) s.fail("a list's count type must be an integer type");
        t = s.token("the list's item type");
      }
      p.type = parse_type(s, t);
      p.name = s.token("the property name");
      s.end_line("the property line");
      h.elements.back().properties.push_back(std::move(p));
    } else {
      s.fail("unknown PLY header keyword '" + std::string(kw.substr(0, 40)) + "'; expected "
             "element, property, comment, obj_info or end_header");
    }
  }
  return h;
}

// Which property of the element is what we read: -1 none.
struct Roles {
  int coord[3] = {-1, -1, -1};
  int indices = -1;
};

Roles find_roles(TextScanner& s, const PlyElement& e) {
  Roles r;
  for (std::size_t k = 0; k < e.properties.size(); ++k) {
    const PlyProperty& p = e.properties[k];
    if (e.name == "vertex" && !p.list && p.name.size() == 1 && p.name[0] >= 'x' &&
        p.name[0] <= 'z')
      r.coord[p.name[0] - 'x'] = static_cast<int>(k);
    if (e.name == "face" && p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) {
      if (!is_integer(p.type)) s.fail("the face's vertex_indices must have an integer type");
      r.indices = static_cast<int>(k);
    }
  }
  if (e.name == "vertex" && (r.coord[0] < 0 || r.coord[1] < 0 || r.coord[2] < 0))
    s.fail("the vertex element needs the properties x, y and z; add them");
  if (e.name == "face" && r.indices < 0)
    s.fail("the face element needs a list property vertex_indices; add it");
  return r;
}

}  // namespace

Surface read_ply(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  TextScanner s(bytes, path, '\0');
  const Header h = read_header(s);
  Surface surf;
  surf.source = path;
  std::vector<double> corner_values;  // face corners as read, checked once all are in
  std::vector<std::size_t> face_sizes;
  Point xyz{};
  std::vector<double> list;
  std::size_t data_at = s.after_line();
  bool have_vertices = false, have_faces = false;
  for (const PlyElement& e : h.elements) {
    const Roles r = find_roles(s, e);
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    have_vertices |= is_vertex;
    have_faces |= is_face;
    ByteReader b(bytes, data_at, path);
    for (std::size_t i = 0; i < e.count; ++i) {
      const std::string what = e.name + " " + std::to_string(i);
      if (h.ascii) s.require_line(what + " of " + std::to_string(e.count));
      const std::size_t line = h.ascii ? s.line() : 0;
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        double v;
        if (!p.list) {
          v = h.ascii ? get_value(s, p.type, p.name) : get_value(b, p.type, h.order, p.name);
          for (int c = 0; c < 3; ++c)
            if (static_cast<int>(k) == r.coord[c]) xyz[c] = v;
          continue;
        }
        const double n = h.ascii ? get_value(s, p.count, "a list count")
                                 : get_value(b, p.count, h.order, "a list count");
        if (n < 0) {
          if (h.ascii) s.fail("a list count is negative");
          b.fail("a list count is negative");
        }
        const auto count = static_cast<std::size_t>(n);
        if (!h.ascii) b.need_items(count, type_size(p.type), "a list");
        list.clear();
        for (std::size_t j = 0; j < count; ++j)
          list.push_back(h.ascii ? get_value(s, p.type, p.name)
                                 : get_value(b, p.type, h.order, p.name));
        if (static_cast<int>(k) == r.indices) {
          corner_values.insert(corner_values.end(), list.begin(), list.end());
          face_sizes.push_back(count);
          surf.face_lines.push_back(line);
        }
      }
      if (h.ascii) s.end_line("the " + e.name + "'s properties");
      if (is_vertex) surf.add_point(xyz, line, static_cast<std::int64_t>(i));
    }
    data_at = b.offset();
  }
  if (!have_vertices || !have_faces)
    s.fail_at(0, "a PLY surface needs the elements 'vertex' and 'face'; this file has " +
                     std::string(have_vertices ? "no faces" : "no vertices"));
  // The corners, now that the vertex count is known.
  const std::size_t nv = surf.points.size();
  std::size_t at = 0;
  std::vector<std::uint32_t> corners;
  const std::vector<std::size_t> lines = std::move(surf.face_lines);
  surf.face_lines.clear();
  for (std::size_t f = 0; f < face_sizes.size(); ++f) {
    corners.clear();
    for (std::size_t j = 0; j < face_sizes[f]; ++j, ++at) {
      const double v = corner_values[at];
      if (v < 0 || v >= static_cast<double>(nv))
        throw InputError(path, lines[f],
                         "face " + std::to_string(f + 1) + ": corner index " +
                             std::to_string(static_cast<std::int64_t>(v)) +
                             " is out of range: the vertices are numbered 0.." +
                             std::to_string(nv == 0 ? 0 : nv - 1) + "; fix the index");
      corners.push_back(static_cast<std::uint32_t>(v));
    }
    surf.add_face(corners, lines[f], 0);
  }
  if (h.ascii && s.next_line())
    s.fail("unexpected data after the last element; a count in the header is wrong");
  if (!h.ascii && data_at != bytes.size())
    throw InputError(path, 0, "at byte offset " + std::to_string(data_at) + ": " +
                                  std::to_string(bytes.size() - data_at) + " bytes are left "
                                  "after the last element; a count in the header is wrong");
  return surf;
}

}  // namespace pdr::io
