// Python <-> plain arrays (arrays.hpp). Every array is copied: the C++ side never holds a
// pointer into Python memory, so the GIL can be released while it works.
#include "arrays.hpp"

#include <limits>
#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>

#include "io/error.hpp"
#include "io/mesh_io.hpp"

namespace pdr::python {

namespace {

std::string shape_of(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// obj as an array; an empty sequence is an empty array of any shape.
py::array as_array(const py::handle& obj, const char* what) {
  py::array a = py::array::ensure(obj);
  if (!a) throw py::type_error(std::string(what) + ": not convertible to a numpy array");
  return a;
}

// Rows of K non-negative 32-bit indices.
template <std::size_t K>
std::vector<std::array<std::uint32_t, K>> to_rows(const py::handle& obj, const char* what) {
  std::vector<std::array<std::uint32_t, K>> rows;
  if (obj.is_none()) return rows;
  const py::array a = as_array(obj, what);
  if (a.size() == 0) return rows;
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw py::value_error(std::string(what) + ": expected integer vertex indices, got dtype " +
                          std::string(py::str(a.dtype())));
  if (a.ndim() != 2 || a.shape(1) != static_cast<py::ssize_t>(K))
    throw py::value_error(std::string(what) + ": expected an array of shape (M, " +
                          std::to_string(K) + "), got shape " + shape_of(a));
  const auto ix = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  const auto r = ix.unchecked<2>();
  rows.resize(static_cast<std::size_t>(r.shape(0)));
  for (py::ssize_t i = 0; i < r.shape(0); ++i)
    for (py::ssize_t k = 0; k < static_cast<py::ssize_t>(K); ++k) {
      const std::int64_t v = r(i, k);
      if (v < 0 || v > std::numeric_limits<std::uint32_t>::max())
        throw py::value_error(std::string(what) + "[" + std::to_string(i) + "] has vertex index " +
                              std::to_string(v) + ", not in [0, 2^32)");
      rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] =
          static_cast<std::uint32_t>(v);
    }
  return rows;
}

template <std::size_t K>
py::array_t<std::int64_t> from_rows(const std::vector<std::array<std::uint32_t, K>>& rows) {
  py::array_t<std::int64_t> a({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(K)});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t k = 0; k < K; ++k)
      w(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(k)) = rows[i][k];
  return a;
}

bool is_sequence(const py::handle& obj) {
  return py::isinstance<py::sequence>(obj) && !py::isinstance<py::str>(obj) &&
         !py::isinstance<py::bytes>(obj);
}

// An integer (int, numpy integer, bool: anything with __index__, never a float).
bool is_index(const py::handle& obj) { return PyIndex_Check(obj.ptr()) != 0; }

// One polygon of facet f (0-based f; the message names it as the PLC's line f + 1).
std::vector<std::uint32_t> to_polygon(const py::handle& obj, std::size_t f, std::size_t k) {
  const std::string where = "facets[" + std::to_string(f) + "]";
  if (!is_sequence(obj) && !py::isinstance<py::array>(obj))
    throw py::type_error(where + ": polygon " + std::to_string(k + 1) +
                         " is not a sequence of vertex indices");
  std::vector<std::uint32_t> poly;
  for (const py::handle item : py::iter(obj)) {
    if (!is_index(item))
      throw py::type_error(where + ": polygon " + std::to_string(k + 1) + " has " +
                           std::string(py::repr(item)) + ", not an integer vertex index");
    const auto v = py::int_(py::reinterpret_borrow<py::object>(item)).cast<long long>();
    if (v < 0 || v > std::numeric_limits<std::uint32_t>::max())
      throw InputError(kArraySource, f + 1,
                       "index in range: polygon " + std::to_string(k + 1) +
                           " of this facet uses vertex index " + std::to_string(v) +
                           " (0-based); fix the index");
    poly.push_back(static_cast<std::uint32_t>(v));
  }
  return poly;
}

PlcFacet to_facet(const py::handle& obj, std::size_t f) {
  PlcFacet facet;
  facet.line = f + 1;
  const std::string where = "facets[" + std::to_string(f) + "]";
  py::object polygons = py::reinterpret_borrow<py::object>(obj);
  if (py::isinstance<py::dict>(obj)) {
    const py::dict d = py::reinterpret_borrow<py::dict>(obj);
    for (const auto& kv : d) {
      const std::string key = py::str(kv.first);
      if (key != "polygons" && key != "holes" && key != "marker")
        throw py::value_error(where + ": unknown key '" + key +
                              "' (a facet dict has polygons, holes, marker)");
    }
    if (!d.contains("polygons")) throw py::value_error(where + ": a facet dict needs 'polygons'");
    polygons = d["polygons"];
    if (d.contains("holes"))
      facet.holes = to_points(d["holes"], (where + "['holes']").c_str());
    if (d.contains("marker")) facet.marker = d["marker"].cast<int>();
  }
  if (!is_sequence(polygons) && !py::isinstance<py::array>(polygons))
    throw py::type_error(where + ": a facet is a polygon (a sequence of vertex indices), a "
                                 "list of polygons, or a dict with 'polygons'");
  const py::sequence seq = py::reinterpret_borrow<py::sequence>(polygons);
  // A polygon's items are indices; a list of polygons' items are sequences.
  const bool one_polygon = py::len(seq) > 0 && is_index(seq[0]);
  if (one_polygon) {
    facet.polygons.push_back(to_polygon(polygons, f, 0));
  } else {
    std::size_t k = 0;
    for (const py::handle p : py::iter(polygons)) facet.polygons.push_back(to_polygon(p, f, k++));
  }
  return facet;
}

}  // namespace

bool is_path(const py::handle& obj) {
  return py::isinstance<py::str>(obj) || PyObject_HasAttrString(obj.ptr(), "__fspath__") == 1;
}

std::string to_path(const py::handle& obj) {
  return py::str(py::module_::import("os").attr("fspath")(obj));
}

std::vector<Point> to_points(const py::handle& obj, const char* what) {
  std::vector<Point> points;
  if (obj.is_none()) return points;
  const py::array a = as_array(obj, what);
  if (a.size() == 0) return points;
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::value_error(std::string(what) + ": expected real coordinates, got dtype " +
                          std::string(py::str(a.dtype())));
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error(std::string(what) + ": expected an array of shape (N, 3), got shape " +
                          shape_of(a));
  const auto xyz = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  const auto r = xyz.unchecked<2>();
  points.resize(static_cast<std::size_t>(r.shape(0)));
  for (py::ssize_t i = 0; i < r.shape(0); ++i)
    points[static_cast<std::size_t>(i)] = {r(i, 0), r(i, 1), r(i, 2)};
  return points;
}

std::vector<Tet> to_tets(const py::handle& obj, const char* what) { return to_rows<4>(obj, what); }
std::vector<Tri> to_tris(const py::handle& obj, const char* what) { return to_rows<3>(obj, what); }

std::vector<int> to_ints(const py::handle& obj, const char* what) {
  std::vector<int> v;
  if (obj.is_none()) return v;
  const py::array a = as_array(obj, what);
  if (a.size() == 0) return v;
  if (a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
    throw py::value_error(std::string(what) + ": expected integers, got dtype " +
                          std::string(py::str(a.dtype())));
  if (a.ndim() != 1)
    throw py::value_error(std::string(what) + ": expected a 1-d array, got shape " + shape_of(a));
  const auto ix = py::array_t<int, py::array::c_style | py::array::forcecast>::ensure(a);
  v.assign(ix.data(), ix.data() + ix.size());
  return v;
}

Plc to_plc(const py::handle& points, const py::handle& facets, const py::handle& holes) {
  Plc plc;
  plc.source = kArraySource;
  plc.enclosure = Enclosure::HolePoints;  // as a .poly reads
  plc.points = to_points(points, "points");
  if (!facets.is_none()) {
    if (!is_sequence(facets) && !py::isinstance<py::array>(facets))
      throw py::type_error("facets: expected a list of facets");
    std::size_t f = 0;
    for (const py::handle facet : py::iter(facets)) plc.facets.push_back(to_facet(facet, f++));
  }
  plc.holes = to_points(holes, "holes");
  return plc;
}

Plc to_domain(const py::handle& obj) {
  if (is_path(obj)) return io::read_domain(to_path(obj));
  if (py::isinstance<py::dict>(obj)) {
    const py::dict d = py::reinterpret_borrow<py::dict>(obj);
    if (!d.contains("points") || !d.contains("facets"))
      throw py::value_error("domain: a dict needs 'points' and 'facets' (as pdr.read returns)");
    const py::object holes = d.contains("holes") ? py::object(d["holes"]) : py::object(py::none());
    Plc plc = to_plc(d["points"], d["facets"], holes);
    if (d.contains("enclosure")) {
      const std::string e = py::str(d["enclosure"]);
      if (e != "hole_points" && e != "parity")
        throw py::value_error("domain['enclosure']: expected 'hole_points' or 'parity'");
      plc.enclosure = e == "parity" ? Enclosure::Parity : Enclosure::HolePoints;
    }
    if (d.contains("regions") && !d["regions"].is_none())
      for (const py::handle r : py::iter(d["regions"])) {
        const py::dict rd = py::reinterpret_borrow<py::dict>(r);
        PlcRegion region;
        const py::sequence at = py::reinterpret_borrow<py::sequence>(rd["point"]);
        if (py::len(at) != 3) throw py::value_error("domain['regions'][i]['point']: expected (x, y, z)");
        for (int k = 0; k < 3; ++k) region.point[k] = py::float_(at[k]).cast<double>();
        region.attribute = rd.contains("attribute") ? py::float_(rd["attribute"]).cast<double>() : 0.0;
        if (rd.contains("max_volume") && !rd["max_volume"].is_none())
          region.max_volume = py::float_(rd["max_volume"]).cast<double>();
        plc.regions.push_back(region);
      }
    return plc;
  }
  if (is_sequence(obj)) {
    const py::sequence s = py::reinterpret_borrow<py::sequence>(obj);
    if (py::len(s) == 2) return to_plc(s[0], s[1], py::none());
    if (py::len(s) == 3) return to_plc(s[0], s[1], s[2]);
  }
  throw py::type_error("domain: expected a path, (points, facets[, holes]) or a dict");
}

py::array_t<double> from_points(const std::vector<Point>& points) {
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) w(static_cast<py::ssize_t>(i), k) = points[i][k];
  return a;
}

py::array_t<std::int64_t> from_tets(const std::vector<Tet>& tets) { return from_rows<4>(tets); }
py::array_t<std::int64_t> from_tris(const std::vector<Tri>& tris) { return from_rows<3>(tris); }

py::object from_ints(const std::vector<int>& values) {
  if (values.empty()) return py::none();
  return py::array_t<int>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::dict from_mesh(const MeshData& mesh) {
  py::dict d;
  d["points"] = from_points(mesh.points);
  d["tets"] = from_tets(mesh.tets);
  d["faces"] = from_tris(mesh.faces);
  d["face_markers"] = from_ints(mesh.face_markers);
  d["point_markers"] = from_ints(mesh.point_markers);
  d["tet_regions"] = from_ints(mesh.tet_regions);
  return d;
}

py::dict from_plc(const Plc& plc) {
  py::dict d;
  d["kind"] = "domain";
  d["source"] = plc.source;
  d["points"] = from_points(plc.points);
  py::list facets;
  for (const PlcFacet& f : plc.facets) {
    py::list polygons;
    for (const auto& p : f.polygons) polygons.append(py::cast(p));
    py::dict facet;
    facet["polygons"] = polygons;
    facet["holes"] = from_points(f.holes);
    facet["marker"] = f.marker;
    facets.append(facet);
  }
  d["facets"] = facets;
  d["holes"] = from_points(plc.holes);
  py::list regions;
  for (const PlcRegion& r : plc.regions) {
    py::dict region;
    region["point"] = py::make_tuple(r.point[0], r.point[1], r.point[2]);
    region["attribute"] = r.attribute;
    region["max_volume"] = r.max_volume < 0 ? py::object(py::none()) : py::float_(r.max_volume);
    regions.append(region);
  }
  d["regions"] = regions;
  d["enclosure"] = plc.enclosure == Enclosure::Parity ? "parity" : "hole_points";
  d["point_markers"] = from_ints(plc.point_markers);
  return d;
}

py::object from_json(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

}  // namespace pdr::python
