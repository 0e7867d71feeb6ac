// pdr.check (api.hpp): the exact checker (check::check_mesh) on a mesh given as arrays or
// as a file, its report returned as the object `pdr check --json` prints
// (docs/check-report-schema.md): check::to_json's fields, then "input" (the mesh and the
// domain as given: a path, or kArraySource for arrays, "" for no domain; what the reader
// skipped) and "seconds" (read, check, and the checker's own phases as check.<phase>).
#include <string>

#include <nlohmann/json.hpp>

#include "api.hpp"
#include "app/order_check.hpp"
#include "app/summary.hpp"
#include "arrays.hpp"
#include "io/mesh_io.hpp"

namespace pdr::python {

py::dict check(const py::object& mesh_or_points, const py::object& tets,
               const py::object& faces, const py::object& domain, check::Options options) {
  if (options.threads < 1) throw py::value_error("threads: must be at least 1");
  if (options.ratio_bound && !(*options.ratio_bound > 0))
    throw py::value_error("ratio: must be positive (or None: not checked)");
  if (options.min_edge && !(*options.min_edge >= 0))
    throw py::value_error("h: must be non-negative (or None: not checked)");
  app::PhaseTimer timer;
  MeshData mesh;
  io::ReadInfo info;
  std::string mesh_name = kArraySource;
  if (is_path(mesh_or_points)) {
    if (!tets.is_none() || !faces.is_none())
      throw py::value_error("check: give a mesh file, or points with tets, not both");
    mesh_name = to_path(mesh_or_points);
    mesh = io::read_mesh(mesh_name, &info);
  } else {
    mesh.points = to_points(mesh_or_points, "points");
    mesh.tets = to_tets(tets, "tets");
    mesh.faces = to_tris(faces, "faces");
  }
  std::optional<Plc> plc;
  if (!domain.is_none()) plc = to_domain(domain);
  timer.lap("read");

  check::Report report;
  {
    py::gil_scoped_release unlocked;  // the arrays were copied into mesh and plc
    const check::MeshView view = check::view_of(mesh);
    report = plc ? check::check_mesh(view, *plc, options) : check::check_mesh(view, options);
    app::add_order_check(report, mesh, app::kOrderCheckSeed);
  }
  timer.lap("check");

  nlohmann::json j = check::to_json(report);
  j["input"] = {{"mesh", mesh_name},
                {"domain", plc ? (is_path(domain) ? to_path(domain) : kArraySource) : ""},
                {"skipped_elements", info.skipped_elements},
                {"dropped_high_order_nodes", info.dropped_high_order_nodes}};
  j["seconds"] = timer.phases();
  for (const auto& [phase, s] : report.seconds) j["seconds"]["check." + phase] = s;
  return from_json(j);
}

}  // namespace pdr::python
