// The domain analysis in one call (paper §1.1, §2.1), and its report as text and JSON; see
// domain/analysis.hpp.

#include "domain/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "domain/steps.hpp"
#include "domain/validate.hpp"

namespace pdr::domain {

namespace {

std::string num(double x, const char* fmt = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

std::string at_line(std::size_t line) { return line ? " (line " + std::to_string(line) + ")" : ""; }

std::string describe(const PlcDomain& dom, ComponentKind k, std::uint32_t id) {
  const auto& lines = dom.plc.point_lines;
  auto vline = [&](std::uint32_t v) { return at_line(v < lines.size() ? lines[v] : 0); };
  switch (k) {
    case ComponentKind::Vertex: return "vertex " + std::to_string(id) + vline(id);
    case ComponentKind::Segment: {
      const DomainSegment& s = dom.segments[id];
      return "segment " + std::to_string(s.a) + vline(s.a) + " - " + std::to_string(s.b) + vline(s.b);
    }
    case ComponentKind::Facet: return "facet " + std::to_string(id) + at_line(dom.plc.facets[id].line);
  }
  return "?";
}

std::string describe(const AngleRecord& r) {
  std::ostringstream o;
  o << angle_kind_name(r.kind) << " " << num(r.degrees, "%.4f") << " deg";
  if (r.in_facet) o << " (inside facet)";
  o << ":";
  if (r.vertex >= 0) o << " at vertex " << r.vertex << at_line(r.vertex_line) << ";";
  for (std::size_t i = 0; i < r.segments.size(); ++i)
    o << " segment " << r.segments[i][0] << at_line(r.segment_lines[i][0]) << " - "
      << r.segments[i][1] << at_line(r.segment_lines[i][1]) << ";";
  for (std::size_t i = 0; i < r.facets.size(); ++i)
    o << " facet " << r.facets[i] << at_line(r.facet_lines[i]) << ";";
  std::string s = o.str();
  if (!s.empty() && s.back() == ';') s.pop_back();
  return s;
}

// Unrelated components (sharing no vertex) must lie apart by more than double coordinates
// resolve: closer than 2^-40 (about 1e-12) times the largest coordinate magnitude (a few
// thousand units in the last place) no vertex can be placed between them, and they touch
// or cross to within rounding (rotated boxes stacked face on face, a few ulps apart). This
// classifies the input; it decides nothing in the mesher.
void check_apart(const PlcDomain& dom, const FeatureSize& fs) {
  if (!std::isfinite(fs.min_distance)) return;
  const Plc& plc = dom.plc;
  double scale = 0;
  for (const Point& p : plc.points)
    for (const double c : p) scale = std::max(scale, std::fabs(c));
  if (fs.min_distance > std::ldexp(scale, -40)) return;
  const auto line = [&](ComponentKind k, std::uint32_t id) -> std::size_t {
    if (k == ComponentKind::Facet) return plc.facets[id].line;
    const std::uint32_t v = k == ComponentKind::Vertex ? id : dom.segments[id].a;
    return v < plc.point_lines.size() ? plc.point_lines[v] : 0;
  };
  const bool points = fs.first_kind == ComponentKind::Vertex && fs.second_kind == ComponentKind::Vertex;
  detail::fail(plc, line(fs.first_kind, fs.first),
               "components apart: " + describe(dom, fs.first_kind, fs.first) + " and " +
                   describe(dom, fs.second_kind, fs.second) + " are " +
                   num(fs.min_distance, "%.3g") +
                   " apart, closer than double coordinates of this magnitude resolve (2^-40 "
                   "of the largest, " + num(scale, "%.3g") + ")" +
                   (points ? ": merge the two vertices"
                           : ", and share no vertex: they touch or cross. Join them at "
                             "common vertices and segments, or move them apart"));
}

}  // namespace

DomainReport make_report(const PlcDomain& dom, const Admissibility& adm, const FeatureSize& fs) {
  DomainReport r;
  const Plc& plc = dom.plc;
  r.source = plc.source;
  r.input_vertices = plc.points.size();
  r.vertices = dom.vertex_count();
  r.segments = dom.segments.size();
  for (const DomainSegment& s : dom.segments) r.standalone_segments += s.sides.empty();
  r.facets = dom.face_count();
  for (const DomainFacet& f : dom.facets) r.triangles += f.tris.size();
  r.shells = dom.shells;
  std::vector<std::uint8_t> reported(dom.cells, 0);
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f)
    for (const int c : dom.facets[f].cells) {
      if (c < 0 || reported[c] || dom.cell_inside[c]) continue;
      reported[c] = 1;
      ++r.voids;
      if (dom.cell_holes[c] == 0) r.unmarked_voids.emplace_back(f, plc.facets[f].line);
    }
  for (const PlcDomain::Dropped& d : dom.dropped)
    if (r.dropped_facets.empty() || r.dropped_facets.back().first != d.facet)
      r.dropped_facets.emplace_back(d.facet, plc.facets[d.facet].line);
  std::sort(r.dropped_facets.begin(), r.dropped_facets.end());
  r.dropped_facets.erase(std::unique(r.dropped_facets.begin(), r.dropped_facets.end()),
                         r.dropped_facets.end());
  r.surface_walls = dom.surface_walls;
  r.volume_holes = plc.holes.size();
  for (const PlcFacet& f : plc.facets) r.facet_holes += f.holes.size();
  r.regions = plc.regions.size();
  bool first = true;
  for (std::uint32_t v = 0; v < plc.points.size(); ++v) {
    for (int k = 0; k < 3; ++k) {
      r.bbox_lo[k] = first ? plc.points[v][k] : std::min(r.bbox_lo[k], plc.points[v][k]);
      r.bbox_hi[k] = first ? plc.points[v][k] : std::max(r.bbox_hi[k], plc.points[v][k]);
    }
    first = false;
  }
  r.planarity_tolerance = dom.options.planarity_tolerance;
  r.tolerance = dom.tolerance;
  for (std::uint32_t f : dom.tolerance_facets)
    r.tolerance_facets.push_back({f, plc.facets[f].line, dom.facets[f].plane.max_deviation});
  r.admissible = adm.admissible;
  r.right_within_tolerance = adm.tolerated;
  r.violations = adm.violations;
  r.angle_stats = adm.stats;
  r.feature = fs;
  if (std::isfinite(fs.min_distance))
    r.closest = describe(dom, fs.first_kind, fs.first) + " and " + describe(dom, fs.second_kind, fs.second);
  return r;
}

std::string bent_right_angles_hint(const DomainReport& r) {
  const bool near_right =
      std::all_of(r.violations.begin(), r.violations.end(), [](const AngleRecord& v) {
        return std::fabs(v.degrees - 90) < 1e-4 || std::fabs(v.degrees - 270) < 1e-4;
      });
  if (r.violations.empty() || !near_right) return {};
  return "every violation is within 1e-4 deg of a right angle: if the input means right "
         "angles, its coordinates are less precise than the planarity tolerance and the "
         "digits they are written with admit (planarity.coordinate_uncertainty); raise the "
         "tolerance (--planarity-tolerance) to read them as right";
}

std::vector<const AngleRecord*> listed_violations(const DomainReport& r) {
  const auto beyond = [](const AngleRecord& v) {
    return v.degrees < 90 ? 90 - v.degrees : std::max(0.0, v.degrees - 270);
  };
  std::vector<const AngleRecord*> out;
  for (const AngleRecord& v : r.violations) out.push_back(&v);
  const std::size_t n = std::min(out.size(), kListedViolations);
  std::partial_sort(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n), out.end(),
                    [&](const AngleRecord* a, const AngleRecord* b) {
                      const double x = beyond(*a), y = beyond(*b);
                      return x != y ? x > y : a < b;  // ties: in the order found
                    });
  out.resize(n);
  return out;
}

std::string render_text(const DomainReport& r) {
  std::ostringstream o;
  o << "domain " << (r.source.empty() ? "(unnamed)" : r.source) << "\n";
  o << "  components: " << r.vertices << " vertices (" << r.input_vertices << " in the input), "
    << r.segments << " segments (" << r.standalone_segments << " standalone), " << r.facets
    << " facets (" << r.triangles << " triangles), " << r.shells << " closed shells\n";
  o << "  holes: " << r.volume_holes << " volume, " << r.facet_holes << " facet; regions: "
    << r.regions << "; voids: " << r.voids << "\n";
  for (const auto& [f, line] : r.unmarked_voids)
    o << "    the void bounded by facet " << f << at_line(line)
      << " holds no volume hole point (TetGen would mesh it as a region)\n";
  if (r.surface_walls)
    o << "    the surface has walls (edges of three or more faces), which parity misreads: "
         "every bounded cell is a region, as TetGen reads a surface (a void needs a .poly "
         "with a volume hole point)\n";
  for (const auto& [f, line] : r.dropped_facets)
    o << "    facet " << f << at_line(line)
      << " bounds no region (voids or the outside on both sides) and is dropped, all or in "
         "part, as TetGen drops it\n";
  o << "  bounding box: [" << num(r.bbox_lo[0]) << ", " << num(r.bbox_lo[1]) << ", "
    << num(r.bbox_lo[2]) << "] .. [" << num(r.bbox_hi[0]) << ", " << num(r.bbox_hi[1]) << ", "
    << num(r.bbox_hi[2]) << "]\n";
  if (r.tolerance_facets.empty()) {
    o << "  planarity: every facet exactly planar\n";
  } else {
    o << "  planarity: " << r.tolerance_facets.size()
      << " facet(s) planar only within the relative tolerance " << num(r.planarity_tolerance)
      << (r.tolerance.uncertainty() > 0
              ? " or the coordinates' rounding (" + num(r.tolerance.uncertainty(), "%.3g") + ")"
              : std::string())
      << ":\n";
    for (const ToleranceFacet& t : r.tolerance_facets)
      o << "    facet " << t.facet << at_line(t.line) << ": deviation " << num(t.deviation, "%.3g")
        << "\n";
  }
  o << "  admissible (paper 1.1, related components at 90..270 deg): "
    << (r.admissible ? "yes" : "no") << "\n";
  if (r.right_within_tolerance > 0)
    o << "    " << r.right_within_tolerance
      << " angle test(s) a hair off 90 or 270 deg, read as right angles (within the planarity "
         "tolerance)\n";
  for (int k = 0; k < angle_kinds; ++k) {
    const AngleStats& s = r.angle_stats[k];
    o << "    " << angle_kind_name(static_cast<AngleKind>(k)) << ": " << s.pairs << " pairs";
    if (s.pairs) o << ", " << num(s.min_degrees, "%.4f") << " .. " << num(s.max_degrees, "%.4f") << " deg";
    o << "\n";
  }
  if (!r.violations.empty()) {
    o << "  violations (" << r.violations.size() << "):\n";
    for (const AngleRecord* v : listed_violations(r)) o << "    " << describe(*v) << "\n";
    if (r.violations.size() > kListedViolations)
      o << "    ... and " << r.violations.size() - kListedViolations
        << " more (the listed ones are the farthest from 90..270 deg)\n";
    if (const std::string hint = bent_right_angles_hint(r); !hint.empty()) o << "    " << hint << "\n";
  }
  if (std::isfinite(r.feature.d))
    o << "  d (paper 2.1) = " << num(r.feature.d, "%.10g") << " = min distance "
      << num(r.feature.min_distance, "%.10g") << " / sqrt 2, between " << r.closest << "\n";
  else
    o << "  d (paper 2.1): no two unrelated components\n";
  return o.str();
}

nlohmann::json to_json(const DomainReport& r) {
  using nlohmann::json;
  json j;
  j["source"] = r.source;
  j["counts"] = {{"input_vertices", r.input_vertices}, {"vertices", r.vertices},
                 {"segments", r.segments},             {"standalone_segments", r.standalone_segments},
                 {"facets", r.facets},                 {"triangles", r.triangles},
                 {"shells", r.shells},                 {"volume_holes", r.volume_holes},
                 {"facet_holes", r.facet_holes},       {"regions", r.regions},
                 {"voids", r.voids}};
  json unmarked = json::array();
  for (const auto& [f, line] : r.unmarked_voids) unmarked.push_back({{"facet", f}, {"line", line}});
  j["unmarked_voids"] = unmarked;
  json dropped = json::array();
  for (const auto& [f, line] : r.dropped_facets) dropped.push_back({{"facet", f}, {"line", line}});
  j["dropped_facets"] = dropped;
  j["surface_walls"] = r.surface_walls;
  j["bounding_box"] = {{"min", r.bbox_lo}, {"max", r.bbox_hi}};
  json tol = json::array();
  for (const ToleranceFacet& t : r.tolerance_facets)
    tol.push_back({{"facet", t.facet}, {"line", t.line}, {"deviation", t.deviation}});
  // The coordinates' precision as inferred (io/precision.hpp): their most significant
  // digits, whether they are all floats, and how far rounding may have moved a vertex
  // (0: exact, or full double precision).
  j["planarity"] = {{"tolerance", r.planarity_tolerance},
                    {"coordinate_digits", r.tolerance.precision.digits},
                    {"coordinate_float32", r.tolerance.precision.float32},
                    {"coordinate_uncertainty", r.tolerance.uncertainty()},
                    {"tolerance_facets", tol}};
  json stats = json::object();
  for (int k = 0; k < angle_kinds; ++k) {
    const AngleStats& s = r.angle_stats[k];
    json e = {{"pairs", s.pairs}};
    if (s.pairs) {
      e["min_degrees"] = s.min_degrees;
      e["max_degrees"] = s.max_degrees;
    }
    stats[angle_kind_name(static_cast<AngleKind>(k))] = e;
  }
  json viol = json::array();
  for (const AngleRecord* p : listed_violations(r)) {
    const AngleRecord& v = *p;
    json e = {{"kind", angle_kind_name(v.kind)}, {"degrees", v.degrees}, {"in_facet", v.in_facet}};
    if (v.vertex >= 0) e["vertex"] = {{"id", v.vertex}, {"line", v.vertex_line}};
    json segs = json::array();
    for (std::size_t i = 0; i < v.segments.size(); ++i)
      segs.push_back({{"ends", v.segments[i]}, {"lines", v.segment_lines[i]}});
    e["segments"] = segs;
    json facs = json::array();
    for (std::size_t i = 0; i < v.facets.size(); ++i)
      facs.push_back({{"facet", v.facets[i]}, {"line", v.facet_lines[i]}});
    e["facets"] = facs;
    viol.push_back(e);
  }
  j["admissibility"] = {{"admissible", r.admissible},
                        {"right_within_tolerance", r.right_within_tolerance},
                        {"angles", stats},
                        {"violations", viol},
                        {"violation_count", r.violations.size()}};
  json d = {{"d", nullptr}, {"min_distance", nullptr}};
  if (std::isfinite(r.feature.d)) {
    d["d"] = r.feature.d;
    d["min_distance"] = r.feature.min_distance;
    d["closest"] = {{"first", {{"kind", component_kind_name(r.feature.first_kind)}, {"id", r.feature.first}}},
                    {"second", {{"kind", component_kind_name(r.feature.second_kind)}, {"id", r.feature.second}}},
                    {"description", r.closest}};
  }
  j["feature_size"] = d;
  return j;
}

DomainAnalysis analyze(const Plc& plc, const PlcOptions& options) {
  DomainAnalysis a{build_domain(plc, options), {}};
  const FeatureSize fs = feature_size(a.domain);
  check_apart(a.domain, fs);
  a.report = make_report(a.domain, check_admissibility(a.domain), fs);
  return a;
}

DomainReport analyze_domain(const Plc& plc, const PlcOptions& options) {
  return analyze(plc, options).report;
}

}  // namespace pdr::domain
