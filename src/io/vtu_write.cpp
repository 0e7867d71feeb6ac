// VTU writer; see vtu.hpp. Every array is first built as its raw little-endian bytes, then
// emitted as ASCII text, inline base64 (UInt64 byte count + data, one stream) or appended
// data (raw or base64, offsets computed from the sizes before anything is written).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/base64.hpp"
#include "io/mesh_assembly.hpp"
#include "io/text_sink.hpp"
#include "io/vtu.hpp"

namespace pdr::io {

namespace {

enum class Kind { F64, I32, I64, U8 };

struct Array {
  std::string name;
  Kind kind;
  std::size_t components = 1;
  std::string bytes;  // host order == little-endian (checked in write_vtu)
};

const char* type_name(Kind k) {
  switch (k) {
    case Kind::F64: return "Float64";
    case Kind::I32: return "Int32";
    case Kind::I64: return "Int64";
    case Kind::U8: return "UInt8";
  }
  return "";
}

template <class T>
Array make(std::string name, Kind kind, std::size_t components, const std::vector<T>& v) {
  Array a{std::move(name), kind, components, {}};
  a.bytes.resize(v.size() * sizeof(T));
  if (!v.empty()) std::memcpy(a.bytes.data(), v.data(), a.bytes.size());
  return a;
}

// An integer array as Int32 when every value fits, else Int64.
Array make_index(std::string name, const std::vector<std::int64_t>& v, std::int64_t max) {
  if (max <= std::numeric_limits<std::int32_t>::max())
    return make(std::move(name), Kind::I32, 1, std::vector<std::int32_t>(v.begin(), v.end()));
  return make(std::move(name), Kind::I64, 1, v);
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

template <class T>
void put_values(TextSink& out, const std::string& bytes) {
  const std::size_t n = bytes.size() / sizeof(T);
  for (std::size_t i = 0; i < n; ++i) {
    T v;
    std::memcpy(&v, bytes.data() + i * sizeof(T), sizeof(T));
    if constexpr (std::is_floating_point_v<T>) {
      if (std::isnan(v)) out.put("nan");
      else out.put_double(v);
    } else {
      out.put_int(static_cast<std::int64_t>(v));
    }
    out.put((i + 1) % 12 == 0 || i + 1 == n ? '\n' : ' ');
  }
}

class Emitter {
 public:
  Emitter(TextSink& out, VtuEncoding enc) : out_(out), enc_(enc) {}

  void array(const Array& a) {
    out_.put("        <DataArray type=\"").put(type_name(a.kind)).put("\" Name=\"");
    out_.put(escape(a.name)).put('"');
    if (a.components != 1) out_.put(" NumberOfComponents=\"").put_uint(a.components).put('"');
    if (enc_ == VtuEncoding::Ascii) {
      out_.put(" format=\"ascii\">\n");
      switch (a.kind) {
        case Kind::F64: put_values<double>(out_, a.bytes); break;
        case Kind::I32: put_values<std::int32_t>(out_, a.bytes); break;
        case Kind::I64: put_values<std::int64_t>(out_, a.bytes); break;
        case Kind::U8: put_values<std::uint8_t>(out_, a.bytes); break;
      }
      out_.put("        </DataArray>\n");
    } else if (enc_ == VtuEncoding::InlineBase64) {
      out_.put(" format=\"binary\">\n");
      std::string text;
      base64_encode(framed(a), text);
      out_.put(text).put("\n        </DataArray>\n");
    } else {
      out_.put(" format=\"appended\" offset=\"").put_uint(offset_).put("\"/>\n");
      const std::size_t framed_size = 8 + a.bytes.size();
      offset_ += enc_ == VtuEncoding::AppendedRaw ? framed_size : base64_length(framed_size);
      appended_.push_back(&a);
    }
  }

  void appended_data() {
    if (appended_.empty()) return;
    const bool raw = enc_ == VtuEncoding::AppendedRaw;
    out_.put("  <AppendedData encoding=\"").put(raw ? "raw" : "base64").put("\">\n   _");
    for (const Array* a : appended_) {
      const std::uint64_t n = a->bytes.size();
      if (raw) {
        out_.put_bytes(&n, sizeof n).put(a->bytes);
      } else {
        std::string text;
        base64_encode(framed(*a), text);
        out_.put(text);
      }
    }
    out_.put("\n  </AppendedData>\n");
  }

 private:
  static std::string framed(const Array& a) {
    const std::uint64_t n = a.bytes.size();
    std::string f(reinterpret_cast<const char*>(&n), sizeof n);
    f += a.bytes;
    return f;
  }

  TextSink& out_;
  VtuEncoding enc_;
  std::uint64_t offset_ = 0;
  std::vector<const Array*> appended_;
};

}  // namespace

void write_vtu(const MeshData& mesh, const std::string& path,
               const std::vector<CellField>& cell_fields,
               const std::vector<PointField>& point_fields, const VtuOptions& options) {
  static_assert(std::endian::native == std::endian::little, "the VTU writer is little-endian");
  check_writable(mesh, path);
  for (const CellField& f : cell_fields)
    if (f.values.size() != mesh.tets.size() || f.name.empty())
      throw std::invalid_argument("cannot write '" + path + "': cell field '" + f.name +
                                  "' has " + std::to_string(f.values.size()) + " values for " +
                                  std::to_string(mesh.tets.size()) + " tets");
  for (const PointField& f : point_fields)
    if (f.values.size() != mesh.points.size() || f.name.empty())
      throw std::invalid_argument("cannot write '" + path + "': point field '" + f.name +
                                  "' has " + std::to_string(f.values.size()) + " values for " +
                                  std::to_string(mesh.points.size()) + " points");

  const std::size_t nt = mesh.tets.size();
  const std::size_t nf = options.write_faces ? mesh.faces.size() : 0;
  const std::size_t nc = nt + nf;
  std::vector<Array> point_data, cell_data;
  if (!mesh.point_markers.empty())
    point_data.push_back(make("pdr_point_marker", Kind::I32, 1,
                              std::vector<std::int32_t>(mesh.point_markers.begin(),
                                                        mesh.point_markers.end())));
  for (const PointField& f : point_fields)
    point_data.push_back(make(f.name, Kind::F64, 1, f.values));
  auto per_cell = [&](const std::vector<int>& tet_part, const std::vector<int>& face_part) {
    std::vector<std::int32_t> v(nc, 0);
    for (std::size_t i = 0; i < nt && !tet_part.empty(); ++i) v[i] = tet_part[i];
    for (std::size_t i = 0; i < nf && !face_part.empty(); ++i) v[nt + i] = face_part[i];
    return v;
  };
  if (!mesh.tet_regions.empty())
    cell_data.push_back(make("pdr_region", Kind::I32, 1, per_cell(mesh.tet_regions, {})));
  if (!mesh.face_markers.empty() && nf > 0)
    cell_data.push_back(make("pdr_face_marker", Kind::I32, 1, per_cell({}, mesh.face_markers)));
  for (const CellField& f : cell_fields) {
    std::vector<double> v(f.values);
    v.resize(nc, std::numeric_limits<double>::quiet_NaN());
    cell_data.push_back(make(f.name, Kind::F64, 1, v));
  }

  std::vector<double> xyz;
  xyz.reserve(3 * mesh.points.size());
  for (const Point& p : mesh.points) xyz.insert(xyz.end(), p.begin(), p.end());
  const Array points = make("Points", Kind::F64, 3, xyz);
  std::vector<std::int64_t> conn, offsets;
  conn.reserve(4 * nt + 3 * nf);
  offsets.reserve(nc);
  for (const Tet& t : mesh.tets) {
    conn.insert(conn.end(), t.begin(), t.end());
    offsets.push_back(static_cast<std::int64_t>(conn.size()));
  }
  for (std::size_t i = 0; i < nf; ++i) {
    conn.insert(conn.end(), mesh.faces[i].begin(), mesh.faces[i].end());
    offsets.push_back(static_cast<std::int64_t>(conn.size()));
  }
  std::vector<std::uint8_t> types(nc, 10);
  std::fill(types.begin() + static_cast<std::ptrdiff_t>(nt), types.end(), std::uint8_t{5});
  const Array conn_a =
      make_index("connectivity", conn, static_cast<std::int64_t>(mesh.points.size()));
  const Array offsets_a = make_index("offsets", offsets, static_cast<std::int64_t>(conn.size()));
  const Array types_a = make("types", Kind::U8, 1, types);

  AtomicFile file(path);
  TextSink out(file);
  Emitter emit(out, options.encoding);
  out.put("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
          "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n");
  out.put("    <Piece NumberOfPoints=\"").put_uint(mesh.points.size());
  out.put("\" NumberOfCells=\"").put_uint(nc).put("\">\n");
  out.put("      <PointData>\n");
  for (const Array& a : point_data) emit.array(a);
  out.put("      </PointData>\n      <CellData>\n");
  for (const Array& a : cell_data) emit.array(a);
  out.put("      </CellData>\n      <Points>\n");
  emit.array(points);
  out.put("      </Points>\n      <Cells>\n");
  emit.array(conn_a);
  emit.array(offsets_a);
  emit.array(types_a);
  out.put("      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n");
  emit.appended_data();
  out.put("</VTKFile>\n");
  out.flush();
  file.commit();
}

}  // namespace pdr::io
