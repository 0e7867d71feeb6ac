// The Python module `pdr` (issue #12): its functions (api.hpp) with their signatures and
// docstrings, and the translation of pdr's exceptions into Python's.
//
// Exceptions, each carrying the message the command line prints after "pdr: ":
//   pdr.InputError (a ValueError; attributes file, line)  InputError: bad input, exit 2
//   OSError                                               std::system_error: a file
//                                                         could not be read or written
//   pdr.CapacityError (a RuntimeError)                    CapacityError: a mesh past the
//                                                         32-bit tet ids, exit 3
//   pdr.InternalError (a RuntimeError)                    RefineError, SurfaceError: exit 4
// pybind11's own rules cover the rest (std::invalid_argument: ValueError, e.g. a mesh that
// a writer rejects; std::bad_alloc: MemoryError; other std::exception: RuntimeError).
#include <system_error>

#include <pybind11/stl.h>

#include "api.hpp"
#include "io/error.hpp"
#include "mesh/tet_store.hpp"

namespace py = pybind11;
using pdr::python::InternalError;

namespace {

// The exception types, owned by the module (which is never unloaded).
py::handle input_error, capacity_error, internal_error;

void translate(std::exception_ptr failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const pdr::InputError& e) {
    py::object err = input_error(e.what());
    err.attr("file") = e.file();
    err.attr("line") = e.line();
    PyErr_SetObject(input_error.ptr(), err.ptr());
  } catch (const std::system_error& e) {
    PyErr_SetString(PyExc_OSError, e.what());
  } catch (const pdr::CapacityError& e) {
    PyErr_SetString(capacity_error.ptr(), e.what());
  } catch (const InternalError& e) {
    PyErr_SetString(internal_error.ptr(), e.what());
  }
}

constexpr const char* kModuleDoc = R"(pdr: guaranteed-quality Delaunay refinement of
polyhedral domains, and an exact checker for tetrahedral meshes, on numpy arrays.

    import numpy as np, pdr
    m = pdr.mesh(points, facets, ratio=2.0, max_volume=0.05)   # N x 3, list of polygons
    r = pdr.check(m["points"], m["tets"], domain=(points, facets), ratio=2.0)
    assert r["ok"]
    pdr.write("out/cube", m["points"], m["tets"], m["faces"])  # out/cube.{node,ele,face,vtu}

Arrays: points are N x 3 float64; tets M x 4 and faces K x 3 are 0-based integer indices
(returned as int64); a tet (a, b, c, d) is positive when det[b-a, c-a, d-a] > 0, a
boundary face's normal (b-a) x (c-a) points out of the mesh.

Facets (a piecewise linear complex, as in a TetGen .poly file): facets[f] is one polygon
(a sequence of vertex indices), or a list of polygons (outer boundaries, inner polygons,
2-vertex segments, 1-vertex points), or a dict {"polygons": [...], "holes": points in the
facet's plane that mark inner polygons as holes, "marker": int}. holes are points inside
the volume holes (voids); as in a .poly, a closed surface inside another bounds a second
region unless a hole point lies in it. pdr.read(path) returns a domain as a dict of that
form (with "regions" and "enclosure": "hole_points", or "parity" for a surface file, where
an inner surface bounds a void), which pdr.mesh and pdr.check take back.

Errors carry the command line's messages: pdr.InputError (a ValueError, with attributes
file and line) for bad input; for arrays the file is "<arrays>" and a line is the 1-based
position of a facet in facets. OSError when a file cannot be read or written,
pdr.CapacityError and pdr.InternalError (RuntimeErrors) as exit 3 and 4 of `pdr mesh`.)";

// pybind11 writes each function's signature above its docstring.
constexpr const char* kMeshDoc = R"(`pdr mesh` on a domain: points (N x 3), facets and holes
(see the module's doc), or a domain file or dict (as pdr.read returns) as the only
positional argument (.poly, .smesh, .off, .stl, .ply, .obj, .mesh, .msh). Every tet gets radius-edge ratio < ratio; max_volume and
size bound tet volumes and circumradii. check runs the exact checker against the domain and
the order-independence check; audit checks Lemma 1 after every insertion.

Returns {"points", "tets", "faces", "face_markers" (the facets' markers of the faces),
"summary" (what `pdr mesh --json` prints, less "written": nothing is written),
"exit_code" (the command's: 0, 1 or 3), "status" ("ok", "violations": the checker
disagrees, a bug; or "not_guaranteed": exit 3, some tet kept ratio >= B or a bound is
unmet), "reason" (why not ok, "" when ok), "leftovers" (the tets left with ratio >= B,
each with its reason; the first 50)}. A surface mesh that reaches the vertex cap returns
no tets with status "not_guaranteed".)";

constexpr const char* kCheckDoc = R"(`pdr check --json` on a mesh: points (N x 3), tets (M x
4), optionally its boundary faces (K x 3); or a mesh file or prefix as the only positional
argument (PREFIX for PREFIX.node + PREFIX.ele, or .ele/.node/.msh/.mesh/.vtu). domain: a
path, (points, facets[, holes]), or a domain dict from pdr.read; with it the conformity and
encroachment checks run. ratio: require radius-edge ratio < ratio (None: not checked); h:
require every edge longer than h.

Returns the report (docs/check-report-schema.md): "ok", "schema_version", "mesh",
"options", "checks" (each with "id", "status", "violations", "findings"), "input",
"seconds". Indices out of range, flipped tets and the like are failed checks, not
exceptions.)";

constexpr const char* kReadDoc = R"(Reads a mesh (kind "mesh": {"kind", "source", "points",
"tets", "faces", "face_markers", "point_markers", "tet_regions", "skipped_elements",
"dropped_high_order_nodes"}) or a domain (kind "domain": {"kind", "source", "points",
"facets", "holes", "regions", "point_markers"}). "auto" decides by the name: .poly, .smesh,
.off, .stl, .ply are domains; .node is a mesh when PREFIX.ele exists, else a point set
domain; .msh and .mesh are meshes unless they hold no tet; else a mesh (.ele, .vtu, PREFIX).)";

constexpr const char* kWriteDoc = R"(Writes a mesh as `pdr mesh` does: each file atomically,
the folder created. formats: a list (or a comma-separated string) of "node", "vtu", "msh",
"mesh"; then path_or_prefix is a prefix. Without formats, a path ending in .node/.ele, .vtu,
.msh or .mesh writes that format, and a bare prefix gets PREFIX.{node,ele,face} and
PREFIX.vtu. Returns the paths written.)";

}  // namespace

PYBIND11_MODULE(pdr, m) {
  m.doc() = kModuleDoc;
  m.attr("__version__") = PDR_VERSION;
  input_error = py::exception<pdr::InputError>(m, "InputError", PyExc_ValueError);
  capacity_error = py::exception<pdr::CapacityError>(m, "CapacityError", PyExc_RuntimeError);
  internal_error = py::exception<InternalError>(m, "InternalError", PyExc_RuntimeError);
  py::register_exception_translator(&translate);

  const pdr::app::MeshArgs mesh_defaults;
  m.def(
      "mesh",
      [](const py::object& points, const py::object& facets, const py::object& holes,
         double ratio, std::optional<double> max_volume, std::optional<double> size,
         bool check, bool audit, std::uint64_t seed, std::size_t max_vertices) {
        pdr::app::MeshArgs args;
        args.options.ratio = ratio;
        args.options.max_volume = max_volume;
        args.options.size = size;
        args.options.audit = audit;
        args.options.max_vertices = max_vertices;
        args.check = check;
        args.seed = seed;
        return pdr::python::mesh(points, facets, holes, std::move(args));
      },
      kMeshDoc, py::arg("points"), py::arg("facets") = py::none(),
      py::arg("holes") = py::none(), py::kw_only(),
      py::arg("ratio") = mesh_defaults.options.ratio, py::arg("max_volume") = py::none(),
      py::arg("size") = py::none(), py::arg("check") = mesh_defaults.check,
      py::arg("audit") = mesh_defaults.options.audit, py::arg("seed") = mesh_defaults.seed,
      py::arg("max_vertices") = mesh_defaults.options.max_vertices);

  const pdr::check::Options check_defaults;
  m.def(
      "check",
      [](const py::object& points, const py::object& tets, const py::object& faces,
         const py::object& domain, std::optional<double> ratio, std::optional<double> h,
         std::size_t max_reported, unsigned threads) {
        pdr::check::Options options;
        options.ratio_bound = ratio;
        options.min_edge = h;
        options.max_reported = max_reported;
        options.threads = threads;
        return pdr::python::check(points, tets, faces, domain, options);
      },
      kCheckDoc, py::arg("points"), py::arg("tets") = py::none(),
      py::arg("faces") = py::none(), py::kw_only(), py::arg("domain") = py::none(),
      py::arg("ratio") = mesh_defaults.options.ratio, py::arg("h") = py::none(),
      py::arg("max_reported") = check_defaults.max_reported,
      py::arg("threads") = check_defaults.threads);

  m.def("read", &pdr::python::read, kReadDoc, py::arg("path"), py::arg("kind") = "auto");
  m.def("write", &pdr::python::write, kWriteDoc, py::arg("path_or_prefix"), py::arg("points"),
        py::arg("tets"), py::arg("faces") = py::none(), py::kw_only(),
        py::arg("formats") = py::none(), py::arg("face_markers") = py::none());
}
