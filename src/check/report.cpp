// Report rendering: to_text for people (failed checks named first, every diagnostic starts
// with the invariant's id) and to_json for programs (schema_version 1, described below).
//
// JSON schema 1:
//   { "schema_version": 1, "ok": bool,
//     "mesh": {"points": n, "tets": n, "boundary_faces": n}, "domain": bool,
//     "options": {"ratio_bound": x|null, "min_edge": x|null, "max_reported": n,
//                 "threads": n, "relative_tolerance": x, "inexact_facet_tolerance": x,
//                 "coordinate_uncertainty": x,
//                 "check_overlap": bool},
//     "checks": [ {"id", "invariant", "status": "pass"|"warn"|"fail"|"skipped", "reason",
//                  "checked", "violations", "counts": {name: n}, "values": {name: x},
//                  "findings": [ {"kind", "id": n|null, "vertices": [n], "points": [[x,y,z]],
//                                 "value": x|null, "message"} ] } ],
//     "seconds": {phase: s}   (only when asked: wall times are not reproducible) }
#include <nlohmann/json.hpp>

#include <sstream>

#include "check/check.hpp"

namespace pdr::check {

std::string_view to_string(Status s) {
  switch (s) {
    case Status::Pass: return "pass";
    case Status::Warn: return "warn";
    case Status::Fail: return "fail";
    case Status::Skipped: return "skipped";
  }
  return "unknown";
}

namespace {

std::string upper(std::string_view s) {
  std::string u(s);
  for (char& ch : u) ch = static_cast<char>(ch >= 'a' && ch <= 'z' ? ch - 'a' + 'A' : ch);
  return u;
}

void summary_line(std::ostringstream& out, const CheckResult& r) {
  const std::string_view tag = r.status == Status::Skipped ? "SKIP" : to_string(r.status);
  out << upper(tag) << "  " << r.id << ": ";
  switch (r.status) {
    case Status::Fail:
      out << r.violations << " of " << r.checked << " violate: " << r.invariant;
      break;
    case Status::Pass:
      out << r.checked << " checked";
      break;
    case Status::Warn:
      out << r.violations << " of " << r.checked << " flagged";
      break;
    case Status::Skipped:
      break;
  }
  if (!r.reason.empty()) out << (r.status == Status::Skipped ? "" : "; ") << r.reason;
  out << "\n";
  std::string extra;
  for (const auto& [k, v] : r.counts) extra += " " + k + "=" + std::to_string(v);
  for (const auto& [k, v] : r.values) {
    std::ostringstream x;
    x << v;
    extra += " " + k + "=" + x.str();
  }
  if (!extra.empty()) out << "      " << extra.substr(1) << "\n";
  for (const Finding& f : r.findings) {
    out << "      " << f.message;
    if (!f.vertices.empty()) {
      out << " [vertices";
      for (std::uint32_t v : f.vertices) out << " " << v;
      out << "]";
    }
    out << "\n";
  }
  if (r.violations > r.findings.size() && !r.findings.empty())
    out << "      ... " << (r.violations - r.findings.size()) << " more\n";
}

}  // namespace

std::string to_text(const Report& report) {
  std::ostringstream out;
  std::string failed;
  for (const CheckResult& r : report.checks)
    if (r.status == Status::Fail) failed += (failed.empty() ? "" : ", ") + r.id;
  out << "pdr check: " << (report.ok() ? "PASS" : "FAIL");
  if (!failed.empty()) out << " (failed: " << failed << ")";
  out << "\nmesh: " << report.points << " points, " << report.tets << " tets, "
      << report.boundary_faces << " boundary faces; domain: " << (report.has_domain ? "yes" : "no")
      << "\n";
  for (const CheckResult& r : report.checks)
    if (r.status == Status::Fail) summary_line(out, r);
  for (const CheckResult& r : report.checks)
    if (r.status != Status::Fail) summary_line(out, r);
  return out.str();
}

nlohmann::json to_json(const Report& report, bool with_timing) {
  using nlohmann::json;
  json j;
  j["schema_version"] = Report::kSchemaVersion;
  j["ok"] = report.ok();
  j["mesh"] = {{"points", report.points}, {"tets", report.tets}, {"boundary_faces", report.boundary_faces}};
  j["domain"] = report.has_domain;
  const Options& o = report.options;
  j["options"] = {{"ratio_bound", o.ratio_bound ? json(*o.ratio_bound) : json(nullptr)},
                  {"min_edge", o.min_edge ? json(*o.min_edge) : json(nullptr)},
                  {"max_reported", o.max_reported},
                  {"threads", o.threads},
                  {"relative_tolerance", o.relative_tolerance},
                  {"inexact_facet_tolerance", o.inexact_facet_tolerance},
                  {"coordinate_uncertainty", o.coordinate_uncertainty},
                  {"check_overlap", o.check_overlap}};
  json checks = json::array();
  for (const CheckResult& r : report.checks) {
    json c;
    c["id"] = r.id;
    c["invariant"] = r.invariant;
    c["status"] = std::string(to_string(r.status));
    c["reason"] = r.reason;
    c["checked"] = r.checked;
    c["violations"] = r.violations;
    c["counts"] = json::object();
    for (const auto& [k, v] : r.counts) c["counts"][k] = v;
    c["values"] = json::object();
    for (const auto& [k, v] : r.values) c["values"][k] = v;
    json findings = json::array();
    for (const Finding& f : r.findings) {
      json x;
      x["kind"] = f.kind;
      x["id"] = f.id == kNoId ? json(nullptr) : json(f.id);
      x["vertices"] = f.vertices;
      json pts = json::array();
      for (const Point& p : f.points) pts.push_back({p[0], p[1], p[2]});
      x["points"] = pts;
      x["value"] = f.value ? json(*f.value) : json(nullptr);
      x["message"] = f.message;
      findings.push_back(std::move(x));
    }
    c["findings"] = std::move(findings);
    checks.push_back(std::move(c));
  }
  j["checks"] = std::move(checks);
  if (with_timing) j["seconds"] = report.seconds;
  return j;
}

}  // namespace pdr::check
