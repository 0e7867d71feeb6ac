// explain_tet (explain.hpp): one tet in full. Verdicts are exact signs (the checker's own,
// check/signs.hpp, exact for any finite coordinates; GMP for the ratio); the printed
// measures are floating-point constructions, or exact values rounded where the coordinate
// differences leave the filters' range (tet_measures, check/fields.hpp).
#include "check/explain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include "check/fields.hpp"
#include "check/signs.hpp"
#include "geom/exact.hpp"
#include "geom/point_text.hpp"

namespace pdr::check {

TetExplanation explain_tet(const MeshView& mesh, const Report& report, std::uint64_t tet,
                           std::size_t max_listed) {
  if (tet >= mesh.tets.size()) {
    std::ostringstream msg;
    msg << "explain: tet " << tet << " does not exist (the mesh has " << mesh.tets.size()
        << " tets, numbered from 0)";
    throw std::out_of_range(msg.str());
  }
  TetExplanation e;
  e.tet = tet;
  e.vertices = mesh.tets[tet];

  // The findings naming T come first: they are all there is for a tet with bad indices.
  const auto incident = vertex_tets(mesh);
  for (const CheckResult& r : report.checks)
    for (const Finding& f : r.findings) {
      const auto named = tets_named_by(f, incident, mesh);
      if (std::binary_search(named.begin(), named.end(), tet)) e.findings.emplace_back(r.id, f);
    }

  e.indices_valid = std::all_of(e.vertices.begin(), e.vertices.end(),
                                [&](std::uint32_t v) { return v < mesh.points.size(); });
  if (!e.indices_valid) return e;
  for (int i = 0; i < 4; ++i) e.points[i] = mesh.points[e.vertices[i]];
  const auto& [a, b, c, d] = e.points;
  e.orientation = signs::orient3d(a, b, c, d);

  mpq_class l2_exact;
  bool first = true;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const mpq_class q = exact::squared_distance(e.points[i], e.points[j]);
      if (first || q < l2_exact) l2_exact = q;
      first = false;
    }
  e.shortest_edge = std::sqrt(l2_exact.get_d());
  if (e.orientation == Sign::Zero) return e;

  const TetMeasures m = tet_measures(a, b, c, d);
  e.circumcenter = m.circumcenter;
  e.circumradius = m.circumradius;
  e.ratio = m.ratio;
  const std::optional<double> B = report.options.ratio_bound;
  if (B && std::isfinite(*B) && *B > 0) {
    const mpq_class b2 = mpq_class(*B) * mpq_class(*B);
    e.ratio_below_bound = exact::circumradius2(a, b, c, d) < b2 * l2_exact;
  }

  for (std::uint32_t p = 0; p < mesh.points.size(); ++p) {
    if (std::find(e.vertices.begin(), e.vertices.end(), p) != e.vertices.end()) continue;
    const Sign s = signs::insphere(a, b, c, d, mesh.points[p]) * e.orientation;
    if (s == Sign::Positive) {
      if (e.inside.size() < max_listed) e.inside.push_back(p);
      ++e.inside_total;
    } else if (s == Sign::Zero) {
      if (e.cospherical.size() < max_listed) e.cospherical.push_back(p);
      ++e.cospherical_total;
    }
  }
  return e;
}

namespace {

std::string list_text(const std::vector<std::uint32_t>& v, std::uint64_t total) {
  std::ostringstream s;
  for (std::uint32_t x : v) s << " " << x;
  if (total > v.size()) s << " ... (" << (total - v.size()) << " more)";
  return s.str();
}

std::string sign_word(Sign s) {
  if (s == Sign::Positive) return "positive";
  return s == Sign::Negative ? "negative (inverted)" : "zero (flat)";
}

}  // namespace

std::string to_text(const TetExplanation& e) {
  std::ostringstream o;
  o.precision(17);
  o << "tet " << e.tet << ": vertices " << e.vertices[0] << " " << e.vertices[1] << " "
    << e.vertices[2] << " " << e.vertices[3] << "\n";
  if (!e.indices_valid) {
    o << "  validity.indices: a vertex index is out of range; nothing more can be said\n";
  } else {
    for (int i = 0; i < 4; ++i)
      o << "  v" << i << " = " << e.vertices[i] << " " << point_text(e.points[i]) << "\n";
    o << "  orientation (exact): " << sign_word(e.orientation) << "\n";
    o << "  shortest edge: " << e.shortest_edge << "\n";
    if (e.circumcenter) {
      o << "  circumcenter: " << point_text(*e.circumcenter) << ", radius " << *e.circumradius
        << "\n  radius-edge ratio: " << *e.ratio;
      if (e.ratio_below_bound)
        o << " (exactly " << (*e.ratio_below_bound ? "below" : "not below") << " the bound)";
      o << "\n  vertices strictly inside the circumsphere (exact): " << e.inside_total
        << list_text(e.inside, e.inside_total) << "\n  other vertices on the circumsphere: "
        << e.cospherical_total << list_text(e.cospherical, e.cospherical_total) << "\n";
    }
  }
  o << "  findings naming this tet: " << e.findings.size() << "\n";
  for (const auto& [id, f] : e.findings) o << "    " << f.message << "\n";
  return o.str();
}

nlohmann::json to_json(const TetExplanation& e) {
  using nlohmann::json;
  json j;
  j["tet"] = e.tet;
  j["vertices"] = e.vertices;
  j["indices_valid"] = e.indices_valid;
  json pts = json::array();
  if (e.indices_valid)
    for (const Point& p : e.points) pts.push_back({p[0], p[1], p[2]});
  j["points"] = pts;
  j["orientation"] = to_int(e.orientation);
  j["shortest_edge"] = e.shortest_edge;
  j["circumcenter"] = e.circumcenter ? json({(*e.circumcenter)[0], (*e.circumcenter)[1],
                                             (*e.circumcenter)[2]})
                                     : json(nullptr);
  j["circumradius"] = e.circumradius ? json(*e.circumradius) : json(nullptr);
  j["ratio"] = e.ratio ? json(*e.ratio) : json(nullptr);
  j["ratio_below_bound"] = e.ratio_below_bound ? json(*e.ratio_below_bound) : json(nullptr);
  j["inside"] = e.inside;
  j["inside_total"] = e.inside_total;
  j["cospherical"] = e.cospherical;
  j["cospherical_total"] = e.cospherical_total;
  json fs = json::array();
  for (const auto& [id, f] : e.findings) fs.push_back({{"check", id}, {"message", f.message}});
  j["findings"] = fs;
  return j;
}

}  // namespace pdr::check
