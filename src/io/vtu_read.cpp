// VTU reader; see vtu.hpp for what is read and the conventions, vtu_arrays.hpp for the
// decoding of one DataArray.
#include <bit>
#include <optional>
#include <string>

#include "io/file_bytes.hpp"
#include "io/mesh_assembly.hpp"
#include "io/text_scanner.hpp"
#include "io/vtu.hpp"
#include "io/vtu_arrays.hpp"
#include "io/vtu_zlib.hpp"

namespace pdr::io {

namespace {

struct Piece {
  std::size_t npoints = 0, ncells = 0, tag_at = 0;
  std::optional<DataArray> points, connectivity, offsets, types;
  std::optional<DataArray> point_marker, region, face_marker;
};

std::size_t size_attr(const XmlScanner& xml, const XmlTag& tag, std::string_view key) {
  std::size_t v = 0;
  if (!parse_number(tag.attr(key), v) || v > xml.text().size())
    xml.fail_at(tag.begin, "<Piece> needs a valid " + std::string(key) + " attribute, found '" +
                               std::string(tag.attr(key).substr(0, 40)) + "'");
  return v;
}

// Reads the XML structure up to <AppendedData>; fills the context and the pieces.
std::vector<Piece> scan(XmlScanner& xml, VtuContext& ctx) {
  XmlTag tag;
  if (!xml.next(tag) || tag.name != "VTKFile" || tag.closing)
    xml.fail_at(tag.begin, "not a VTK XML file: expected <VTKFile>; give a .vtu file");
  if (tag.attr("type") != "UnstructuredGrid")
    xml.fail_at(tag.begin, "VTKFile type '" + std::string(tag.attr("type").substr(0, 40)) +
                               "' is not supported; pdr reads UnstructuredGrid (.vtu) files");
  const std::string_view order = tag.attr("byte_order", "LittleEndian");
  if (order != (std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian"))
    xml.fail_at(tag.begin, "byte_order " + std::string(order.substr(0, 20)) + " is not this "
                           "machine's; re-export the file with the other byte order");
  const std::string_view header = tag.attr("header_type", "UInt32");
  if (header != "UInt32" && header != "UInt64")
    xml.fail_at(tag.begin, "header_type " + std::string(header.substr(0, 20)) +
                               " is not supported; use UInt32 or UInt64");
  ctx.header64 = header == "UInt64";
  const std::string_view compressor = tag.attr("compressor");
  ctx.zlib = compressor == "vtkZLibDataCompressor" && have_zlib();
  if (!compressor.empty() && !ctx.zlib)
    xml.fail_at(tag.begin, "compressed data (" + std::string(compressor.substr(0, 40)) +
                               ") is not supported; re-export uncompressed (ParaView: Save Data "
                               "with Compressor Type None; VTK: SetCompressorTypeToNone())");

  enum class In { Other, Points, Cells, PointData, CellData } in = In::Other;
  std::vector<Piece> pieces;
  while (xml.next(tag)) {
    const std::string_view name = tag.name;
    if (name == "Piece" && !tag.closing) {
      Piece p;
      p.tag_at = tag.begin;
      p.npoints = size_attr(xml, tag, "NumberOfPoints");
      p.ncells = size_attr(xml, tag, "NumberOfCells");
      pieces.push_back(p);
    } else if (name == "Points" || name == "Cells" || name == "PointData" || name == "CellData") {
      in = (tag.closing || tag.self_closing) ? In::Other
           : name == "Points"                ? In::Points
           : name == "Cells"                 ? In::Cells
           : name == "PointData"             ? In::PointData
                                             : In::CellData;
    } else if (name == "DataArray" && !tag.closing) {
      DataArray a = describe_array(xml, tag);
      if (!tag.self_closing) {
        const std::size_t close = xml.find_closing("DataArray", tag.end);
        if (close == std::string_view::npos)
          xml.fail_at(tag.begin, "DataArray '" + std::string(a.name) + "' is not closed; the "
                                 "file is truncated");
        a.content_begin = tag.end;
        a.content_end = close;
        xml.seek(close);
      }
      if (pieces.empty()) xml.fail_at(tag.begin, "DataArray outside a <Piece>");
      Piece& p = pieces.back();
      if (in == In::Points && !p.points) p.points = a;
      else if (in == In::Cells && a.name == "connectivity") p.connectivity = a;
      else if (in == In::Cells && a.name == "offsets") p.offsets = a;
      else if (in == In::Cells && a.name == "types") p.types = a;
      else if (in == In::PointData && a.name == "pdr_point_marker") p.point_marker = a;
      else if (in == In::CellData && a.name == "pdr_region") p.region = a;
      else if (in == In::CellData && a.name == "pdr_face_marker") p.face_marker = a;
    } else if (name == "AppendedData" && !tag.closing) {
      const std::string_view enc = tag.attr("encoding", "raw");
      if (enc != "raw" && enc != "base64")
        xml.fail_at(tag.begin, "AppendedData encoding '" + std::string(enc.substr(0, 20)) +
                                   "' is not raw or base64");
      ctx.appended_raw = enc == "raw";
      const std::string_view text = xml.text();
      std::size_t p = tag.end;
      while (p < text.size() && (is_blank(text[p]) || text[p] == '\n')) ++p;
      if (p >= text.size() || text[p] != '_')
        xml.fail_at(p, "AppendedData must start with '_'; the file is corrupt");
      ctx.appended_begin = p + 1;
      break;  // raw data follows; nothing after it is needed
    }
  }
  if (pieces.empty()) xml.fail_at(0, "no <Piece> in the file; it holds no mesh");
  return pieces;
}

}  // namespace

MeshData read_vtu(const std::string& path, ReadInfo* info) {
  const std::string bytes = read_file_bytes(path);
  XmlScanner xml(bytes, path);
  VtuContext ctx;
  ctx.xml = &xml;
  const std::vector<Piece> pieces = scan(xml, ctx);

  MeshData mesh;
  std::vector<std::uint32_t> high_order;
  std::size_t skipped = 0;
  bool any_point_marker = false, any_region = false, any_face_marker = false;
  for (const Piece& pc : pieces) {
    auto fail = [&](const std::string& m) { xml.fail_at(pc.tag_at, m); };
    const std::size_t base = mesh.points.size();
    if (pc.npoints > 0) {
      if (!pc.points) fail("the piece has points but no <Points> DataArray");
      if (pc.points->components != 3)
        xml.fail_at(pc.points->tag_at, "Points must have NumberOfComponents=\"3\"");
      const std::vector<double> xyz = decode_doubles(ctx, *pc.points, 3 * pc.npoints);
      for (std::size_t i = 0; i < pc.npoints; ++i) {
        const Point p{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
        if (!(p[0] - p[0] == 0 && p[1] - p[1] == 0 && p[2] - p[2] == 0))
          xml.fail_at(pc.points->tag_at, "point " + std::to_string(i) + " has a coordinate "
                                         "that is not finite; fix the mesh");
        mesh.points.push_back(p);
      }
    }
    std::vector<std::int64_t> pmark(pc.npoints, 0);
    if (pc.point_marker) {
      pmark = decode_ints(ctx, *pc.point_marker, pc.npoints);
      any_point_marker = true;
    }
    mesh.point_markers.insert(mesh.point_markers.end(), pmark.begin(), pmark.end());
    if (pc.ncells == 0) continue;
    if (!pc.connectivity || !pc.offsets || !pc.types)
      fail("the piece has cells but lacks the connectivity, offsets or types DataArray");
    const std::vector<std::int64_t> types = decode_ints(ctx, *pc.types, pc.ncells);
    const std::vector<std::int64_t> offsets = decode_ints(ctx, *pc.offsets, pc.ncells);
    const std::int64_t nconn = offsets.back();
    if (nconn < 0) xml.fail_at(pc.offsets->tag_at, "the last offset is negative");
    const std::vector<std::int64_t> conn =
        decode_ints(ctx, *pc.connectivity, static_cast<std::size_t>(nconn));
    std::vector<std::int64_t> region(pc.ncells, 0), fmark(pc.ncells, 0);
    if (pc.region) { region = decode_ints(ctx, *pc.region, pc.ncells); any_region = true; }
    if (pc.face_marker) { fmark = decode_ints(ctx, *pc.face_marker, pc.ncells); any_face_marker = true; }

    std::int64_t prev = 0;
    std::uint32_t idx[10];
    for (std::size_t c = 0; c < pc.ncells; ++c) {
      const std::int64_t end = offsets[c];
      if (end < prev || end > nconn)
        xml.fail_at(pc.offsets->tag_at, "offsets must increase: cell " + std::to_string(c) +
                                            " ends at " + std::to_string(end) + " after " +
                                            std::to_string(prev) + "; the file is corrupt");
      const std::int64_t n = end - prev;
      const std::int64_t type = types[c];
      const int want = type == 10 ? 4 : type == 24 ? 10 : type == 5 ? 3 : type == 22 ? 6 : 0;
      if (want == 0) {
        ++skipped;
        prev = end;
        continue;
      }
      if (n != want)
        xml.fail_at(pc.offsets->tag_at, "cell " + std::to_string(c) + " of type " +
                                            std::to_string(type) + " has " + std::to_string(n) +
                                            " points, expected " + std::to_string(want));
      for (int k = 0; k < want; ++k) {
        const std::int64_t v = conn[static_cast<std::size_t>(prev + k)];
        if (v < 0 || static_cast<std::uint64_t>(v) >= pc.npoints)
          xml.fail_at(pc.connectivity->tag_at, "cell " + std::to_string(c) + " uses point " +
                                                   std::to_string(v) + " but the piece has " +
                                                   std::to_string(pc.npoints) + " points");
        idx[k] = static_cast<std::uint32_t>(base + static_cast<std::size_t>(v));
      }
      const int corners = (type == 10 || type == 24) ? 4 : 3;
      high_order.insert(high_order.end(), idx + corners, idx + want);
      if (corners == 4) {
        mesh.tets.push_back({idx[0], idx[1], idx[2], idx[3]});
        mesh.tet_regions.push_back(static_cast<int>(region[c]));
      } else {
        mesh.faces.push_back({idx[0], idx[1], idx[2]});
        mesh.face_markers.push_back(static_cast<int>(fmark[c]));
      }
      prev = end;
    }
  }
  if (mesh.tets.empty() && (skipped > 0 || !mesh.faces.empty()))
    xml.fail_at(0, "the file has no tetrahedra (cell type 10 or 24) among its " +
                       std::to_string(skipped + mesh.faces.size()) +
                       " cells; pdr reads tetrahedral meshes");
  if (!any_point_marker) mesh.point_markers.clear();
  if (!any_region) mesh.tet_regions.clear();
  if (!any_face_marker) mesh.face_markers.clear();
  PointRoles roles(mesh.points.size());
  for (const Tet& t : mesh.tets)
    for (std::uint32_t v : t) roles.corner(v);
  for (const Tri& f : mesh.faces)
    for (std::uint32_t v : f) roles.corner(v);
  for (std::uint32_t v : high_order) roles.high_order(v);
  const std::size_t dropped = roles.drop_high_order_only(mesh);
  if (info) *info = ReadInfo{skipped, dropped};
  return mesh;
}

}  // namespace pdr::io
