// pdr.mesh (api.hpp): `pdr mesh` on a PLC given as arrays or as a file, the mesh returned
// as arrays instead of written. The mesher, the checker against the domain and the
// order-independence check are app::mesh_plc_reported's, so the summary is the one
// `pdr mesh --json` prints (less "written": nothing is written) and the exit code is the
// command's: 0 ok, 1 the checker found violations, 3 meshed but not guaranteed (what is
// left is in the summary: "quality", "leftovers", "stop_reason", "unsplit",
// "conformity"). Exit 4 raises pdr.InternalError; bad input raises before meshing.
#include <string>

#include "api.hpp"
#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "arrays.hpp"
#include "io/mesh_io.hpp"

namespace pdr::python {

namespace {

// The option checks of `pdr mesh` (its CLI11 validators), as ValueError.
void check_options(const refine::RefineOptions& o) {
  if (!(o.ratio >= 1.0 && o.ratio <= 1e6))
    throw py::value_error("ratio: " + std::to_string(o.ratio) + " is not in [1, 1e6]");
  if (o.max_volume && !(*o.max_volume > 0)) throw py::value_error("max_volume: must be positive");
  if (o.size && !(*o.size > 0)) throw py::value_error("size: must be positive");
}

std::string status_of(int code) {
  switch (code) {
    case app::kExitOk: return "ok";
    case app::kExitViolations: return "violations";
    default: return "not_guaranteed";
  }
}

// Why a run did not end ok, from the summary's own entries.
std::string reason_of(int code, const py::dict& summary, const std::string& failure) {
  if (code == app::kExitOk) return "";
  if (code == app::kExitViolations) {
    const py::object ids = summary.contains("check_failed") ? py::object(summary["check_failed"])
                                                            : py::object(py::list());
    return "the checker found violations: " + std::string(py::str(ids));
  }
  std::string reason;
  for (const char* key : {"quality", "conformity"})
    if (summary.contains(key))
      reason += (reason.empty() ? "" : "; ") + std::string(py::str(summary[key]));
  return reason.empty() ? failure : reason;
}

}  // namespace

py::dict mesh(const py::object& domain_or_points, const py::object& facets,
              const py::object& holes, app::MeshArgs args) {
  check_options(args.options);
  Plc plc;
  if (is_path(domain_or_points) || py::isinstance<py::dict>(domain_or_points)) {
    if (!facets.is_none() || !holes.is_none())
      throw py::value_error("mesh: give a domain (a file or a dict), or points with facets, not both");
    plc = to_domain(domain_or_points);
  } else {
    plc = to_plc(domain_or_points, facets, holes);
  }
  args.prefix.clear();  // written nowhere: returned

  app::Summary summary;
  summary.set("command", "mesh");
  std::string failure;
  MeshData out;
  int code;
  {
    py::gil_scoped_release unlocked;  // the arrays were copied into plc
    code = app::mesh_plc_reported(plc, args, summary, failure, &out);
  }
  if (code == app::kExitInternal) throw InternalError(failure);

  py::dict result = from_mesh(out);
  const py::dict s = from_json(summary.to_json());
  result["summary"] = s;
  result["exit_code"] = code;
  result["status"] = status_of(code);
  result["reason"] = reason_of(code, s, failure);
  result["leftovers"] = s.contains("leftovers") ? s["leftovers"] : py::list();
  return result;
}

}  // namespace pdr::python
