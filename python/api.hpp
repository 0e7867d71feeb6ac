// The functions of the Python module `pdr` (module.cpp binds them, with their docstrings).
// Each one is the library path of a command-line command, not a copy of it:
//   mesh   app::mesh_plc_reported (src/app/cmd_mesh.cpp), the mesh returned instead of
//          written;
//   check  check::check_mesh and check::to_json, the report as `pdr check --json` prints it;
//   read   io::read_mesh / io::read_domain;
//   write  app::write_outputs (atomic files, the prefix's folder created).
// Errors: InputError (a file:line message, as the command line prints it after "pdr: ")
// becomes pdr.InputError, a ValueError; module.cpp registers the translations.
#pragma once

#include <stdexcept>
#include <string>

#include <pybind11/pybind11.h>

#include "app/commands.hpp"
#include "check/check.hpp"

namespace pdr::python {

namespace py = pybind11;

// An internal invariant failed (a bug, or a domain the guards did not catch): exit 4 of
// `pdr mesh`. Its message is the one the command prints.
class InternalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `domain_or_points` is a domain file (then facets and holes are None) or the PLC's points;
// `args` holds the command's options (its domain, prefix, formats and json are unused).
py::dict mesh(const py::object& domain_or_points, const py::object& facets,
              const py::object& holes, app::MeshArgs args);

// `mesh_or_points` is a mesh file or prefix (then tets and faces are None) or the points;
// `domain` None, or what to_domain takes (arrays.hpp).
py::dict check(const py::object& mesh_or_points, const py::object& tets,
               const py::object& faces, const py::object& domain, check::Options options);

// kind: "auto", "mesh" or "domain".
py::dict read(const py::object& path, const std::string& kind);

// Returns the paths written.
py::list write(const py::object& path_or_prefix, const py::object& points,
               const py::object& tets, const py::object& faces, const py::object& formats,
               const py::object& face_markers);

}  // namespace pdr::python
