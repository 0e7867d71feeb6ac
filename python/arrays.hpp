// Conversions between Python objects and pdr's plain arrays (MeshData, Plc) for the module
// `pdr` (module.cpp): numpy arrays in and out, lists accepted wherever numpy converts them.
//
// Conventions (the module's docstring repeats them for Python users):
//   - points: an N×3 array of float64 (anything numpy converts to one);
//   - tets M×4, faces K×3: integer arrays of 0-based indices, returned as int64; an index
//     must be >= 0 and < 2^32 (ValueError), its range against the points is the checker's
//     business (validity.indices), as for a file;
//   - facets: a list; facets[f] is one polygon (a sequence of vertex indices), or a list of
//     polygons (outer boundaries, inner polygons, segments, isolated points: mesh/plc.hpp),
//     or a dict {"polygons": [...], "holes": H×3 points in the facet's plane, "marker": int};
//     an F×k integer array is F facets of one polygon each;
//   - a PLC built from arrays is named kArraySource in messages, and a line number there is
//     the 1-based position of the facet in `facets` (points are named by their 0-based index).
// Type errors (a facet that is not a sequence, a float as an index) raise TypeError; shape
// and index errors ValueError; what the domain validation rejects raises pdr.InputError
// later, with the message `pdr mesh` prints.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "io/read_info.hpp"
#include "mesh/mesh_data.hpp"
#include "mesh/plc.hpp"

namespace pdr::python {

namespace py = pybind11;

inline constexpr const char* kArraySource = "<arrays>";

// A str or an os.PathLike: the path it names (as the command line would take it).
bool is_path(const py::handle& obj);
std::string to_path(const py::handle& obj);

// N×3 float64 coordinates; `what` names the argument in messages. None: no points.
std::vector<Point> to_points(const py::handle& obj, const char* what);

// M×K non-negative integer indices (K = 4: tets, K = 3: faces). None: no rows.
std::vector<Tet> to_tets(const py::handle& obj, const char* what);
std::vector<Tri> to_tris(const py::handle& obj, const char* what);

// One int per row (markers); None: none.
std::vector<int> to_ints(const py::handle& obj, const char* what);

// The PLC of points, facets and volume holes (None: no holes), read as a .poly is (every
// bounded cell in which no hole point lies is meshed: Enclosure::HolePoints).
Plc to_plc(const py::handle& points, const py::handle& facets, const py::handle& holes);

// A domain argument: a path (io::read_domain), a (points, facets[, holes]) sequence, or a
// dict with "points", "facets" and optionally "holes", "regions" and "enclosure" (as
// pdr.read returns a domain).
Plc to_domain(const py::handle& obj);

py::array_t<double> from_points(const std::vector<Point>& points);
py::array_t<std::int64_t> from_tets(const std::vector<Tet>& tets);
py::array_t<std::int64_t> from_tris(const std::vector<Tri>& tris);
// None when `values` is empty (MeshData's "no markers").
py::object from_ints(const std::vector<int>& values);

// {"points", "tets", "faces", "face_markers", "point_markers", "tet_regions"} (markers and
// regions None when the mesh has none).
py::dict from_mesh(const MeshData& mesh);

// {"kind": "domain", "source", "points", "facets" (dicts as above), "holes", "regions",
// "enclosure" ("hole_points": TetGen's reading, "parity": a surface file's), "point_markers"}:
// the form to_domain takes back.
py::dict from_plc(const Plc& plc);

// A JSON value as Python objects (dict, list, str, int, float, bool, None).
py::object from_json(const nlohmann::json& j);

}  // namespace pdr::python
