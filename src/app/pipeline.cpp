// triangulate_write_check (pipeline.hpp).
#include "app/pipeline.hpp"

#include <algorithm>

#include "app/exit_codes.hpp"
#include "check/check.hpp"
#include "delaunay/bulk.hpp"
#include "delaunay/export.hpp"
#include "io/error.hpp"

namespace pdr::app {

int triangulate_write_check(std::vector<Point> points, const std::string& source,
                            const std::string& prefix,
                            const std::vector<io::MeshFormat>& formats, bool check,
                            unsigned threads, PhaseTimer& timer, Summary& summary) {
  const std::size_t n = points.size();
  Delaunay dt(std::move(points));
  const BulkResult bulk = bulk_insert(dt);
  if (bulk.status != BulkStatus::Ok)
    throw InputError(source, 0, bulk.message + "; give points that span a volume");
  const double t_build = timer.lap("delaunay");
  const MeshData mesh = to_mesh_data(dt);
  summary.set("points", n);
  summary.set("duplicates", bulk.duplicates.size());
  if (!bulk.duplicates.empty()) {
    std::vector<std::string> first;
    for (std::size_t i = 0; i < std::min<std::size_t>(bulk.duplicates.size(), 5); ++i)
      first.push_back("point " + std::to_string(bulk.duplicates[i].id) + " = vertex " +
                      std::to_string(bulk.duplicates[i].kept));
    summary.set("duplicates_first", first);
  }
  summary.set("tets", mesh.tets.size());
  summary.set("boundary_faces", mesh.faces.size());
  summary.set("tets_per_second", t_build > 0 ? static_cast<double>(mesh.tets.size()) / t_build
                                             : 0.0);

  io::write_mesh(mesh, prefix, formats);
  std::vector<std::string> written;
  for (auto f : formats)
    for (auto& p : io::output_paths(prefix, f)) written.push_back(p);
  summary.set("written", written);
  timer.lap("write");

  int code = kExitOk;
  if (check) {
    check::Options opt;
    opt.threads = threads;
    const check::Report report = check::check_mesh(check::view_of(mesh), opt);
    timer.lap("check");
    nlohmann::json failed = nlohmann::json::array();
    for (const auto& c : report.checks)
      if (c.status == check::Status::Fail) failed.push_back(c.id);
    summary.set("check", report.ok() ? "pass" : "FAIL");
    if (!report.ok()) {
      summary.set("check_failed", failed);
      summary.set("check_report", check::to_text(report));
      code = kExitViolations;
    }
  } else {
    summary.set("check", "skipped (--no-check)");
  }
  summary.set("seconds", timer.phases());
  summary.set("peak_rss_bytes", peak_rss_bytes());
  return code;
}

}  // namespace pdr::app
