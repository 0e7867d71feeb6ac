// triangulate_write_check (pipeline.hpp).
#include "app/pipeline.hpp"

#include <filesystem>

#include "app/exit_codes.hpp"
#include "check/check.hpp"
#include "delaunay/bulk.hpp"
#include "delaunay/export.hpp"
#include "geom/input_range.hpp"
#include "io/error.hpp"

namespace pdr::app {
namespace {

// Drops the duplicate points (never inserted, so in no tet; input ids, so `mesh` must be
// in the input's order) and renumbers the rest: the output lists each vertex once, as a
// mesh must (validity.duplicate_vertices).
void drop_duplicates(MeshData& mesh, const std::vector<Duplicate>& duplicates) {
  if (duplicates.empty()) return;
  std::vector<std::uint8_t> drop(mesh.points.size(), 0);
  for (const auto& d : duplicates) drop[d.id] = 1;
  std::vector<std::uint32_t> renumber(mesh.points.size());
  std::size_t kept = 0;
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    renumber[i] = static_cast<std::uint32_t>(kept);
    if (!drop[i]) mesh.points[kept++] = mesh.points[i];
  }
  mesh.points.resize(kept);
  if (!mesh.point_markers.empty()) mesh.point_markers.clear();
  for (auto& t : mesh.tets)
    for (auto& v : t) v = renumber[v];
  for (auto& f : mesh.faces)
    for (auto& v : f) v = renumber[v];
}

}  // namespace

int triangulate_write_check(std::vector<Point> points, const std::string& source,
                            const std::string& prefix,
                            const std::vector<io::MeshFormat>& formats, bool check,
                            unsigned threads, PhaseTimer& timer, Summary& summary) {
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i)
    if (!in_input_range(points[i]))
      throw InputError(source, 0,
                       "point " + std::to_string(i) +
                           " has a coordinate that is not 0 and not of magnitude in "
                           "[2^-100, 2^100] (about 1e-30 .. 1e30); rescale the input");
  Delaunay dt(std::move(points));
  const BulkResult bulk = bulk_insert(dt);
  if (bulk.status != BulkStatus::Ok)
    throw InputError(source, 0, bulk.message + "; give points that span a volume");
  const double t_build = timer.lap("delaunay");
  // The vertices in the input's order (the insertion stored them in its own), so that the
  // duplicates' input ids name them, and vertex i of the output is point i of the input.
  MeshData mesh = to_mesh_data(dt);
  restore_input_order(mesh, bulk.input_index);
  drop_duplicates(mesh, bulk.duplicates);
  summary.set("points", n);
  summary.set("vertices", mesh.points.size());
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

  write_outputs(mesh, prefix, formats, timer, summary);

  int code = kExitOk;
  if (check) {
    check::Options opt;
    opt.threads = threads;
    const check::Report report = check::check_mesh(check::view_of(mesh), opt);
    timer.lap("check");
    record_check(report, true, summary);
    if (!report.ok()) code = kExitViolations;
  } else {
    summary.set("check", "skipped (--no-check)");
  }
  finish_summary(timer, summary);
  return code;
}

void skip_dropped(const domain::PlcDomain& dom, check::Options& options) {
  for (const domain::PlcDomain::Dropped& d : dom.dropped)
    for (const auto& t : d.tris) options.dropped_tris.push_back({d.facet, t});
  options.dropped_segments.insert(options.dropped_segments.end(), dom.dropped_segments.begin(),
                                  dom.dropped_segments.end());
  // Their vertices that no kept triangle or segment holds: a mesher may leave them out.
  std::vector<std::uint8_t> state(dom.vertex_count(), 0);  // 1: on a dropped piece, 2: kept
  for (const domain::PlcDomain::Dropped& d : dom.dropped)
    for (const auto& t : d.tris)
      for (const std::uint32_t v : t) state[v] = 1;
  for (const auto& s : dom.dropped_segments) state[s[0]] = state[s[1]] = 1;
  for (const domain::DomainFacet& f : dom.facets)
    for (const domain::FacetTri& t : f.tris)
      for (const std::uint32_t v : t.v) state[v] = 2;
  for (const domain::DomainSegment& s : dom.segments) state[s.a] = state[s.b] = 2;
  for (std::uint32_t v = 0; v < state.size(); ++v)
    if (state[v] == 1) options.dropped_vertices.push_back(v);
  // So may it the isolated vertices outside Ω (TetGen does).
  options.dropped_vertices.insert(options.dropped_vertices.end(), dom.outside_vertices.begin(),
                                  dom.outside_vertices.end());
}

void write_outputs(const MeshData& mesh, const std::string& prefix,
                   const std::vector<io::MeshFormat>& formats, PhaseTimer& timer,
                   Summary& summary) {
  const auto parent = std::filesystem::path(prefix).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  io::write_mesh(mesh, prefix, formats);
  std::vector<std::string> written;
  for (auto f : formats)
    for (auto& p : io::output_paths(prefix, f)) written.push_back(p);
  summary.set("written", written);
  timer.lap("write");
}

std::vector<std::string> record_check(const check::Report& report, bool with_report,
                                      Summary& summary) {
  std::vector<std::string> failed;
  for (const auto& c : report.checks)
    if (c.status == check::Status::Fail) failed.push_back(c.id);
  summary.set("check", report.ok() ? "pass" : "FAIL");
  if (!report.ok()) {
    summary.set("check_failed", failed);
    if (with_report) summary.set("check_report", check::to_text(report));
  }
  return failed;
}

void finish_summary(const PhaseTimer& timer, Summary& summary) {
  summary.set("seconds", timer.phases());
  summary.set("peak_rss_bytes", peak_rss_bytes());
}

}  // namespace pdr::app
