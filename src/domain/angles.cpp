// Admissibility: the angles between related components (paper §1.1); definitions and the
// exact classification are documented in domain/angles.hpp.
#include "domain/angles.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "domain/exact.hpp"

namespace pdr::domain {

const char* angle_kind_name(AngleKind k) {
  switch (k) {
    case AngleKind::SegmentSegment: return "segment-segment";
    case AngleKind::FacetFacet: return "facet-facet";
    case AngleKind::FacetSegment: return "facet-segment";
    case AngleKind::FacetFacetVertex: return "facet-facet-at-vertex";
  }
  return "?";
}

namespace {

using Vec = std::array<double, 3>;
constexpr double kDeg = 180.0 / 3.14159265358979323846;

Vec sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }
double angle_deg(const Vec& a, const Vec& b) { return std::atan2(norm(cross(a, b)), dot(a, b)) * kDeg; }

// Smallest angle between direction s and the planar convex cone spanned by r1, r2.
double ray_cone_deg(const Vec& s, const Vec& r1, const Vec& r2) {
  const Vec n = cross(r1, r2);
  const double nn = dot(n, n), sn = dot(s, n);
  const Vec par{s[0] - sn / nn * n[0], s[1] - sn / nn * n[1], s[2] - sn / nn * n[2]};
  const double lp = norm(par);
  if (lp <= 1e-15 * norm(s)) return 90.0;
  if (dot(cross(r1, par), n) >= 0 && dot(cross(par, r2), n) >= 0)
    return std::atan2(std::fabs(sn) / std::sqrt(nn), lp) * kDeg;
  return std::min(angle_deg(s, r1), angle_deg(s, r2));
}

// No angle more than this (radians, 0.057 degrees) from a right angle is read as one,
// whatever the uncertainty and however short the edges (a tolerance classifies rounding,
// not shapes).
constexpr double kMaxOpening = 1e-3;

// Whether the angle at o between a and b is acute as the input means it: the exact sign
// of the cosine is positive, and moving o, a and b by at most `delta` each (the positional
// uncertainty the planarity tolerance admits, uncertainty() below) cannot be shown to make
// it a right angle. The angle's gradient with respect to a is perpendicular to x = a - o
// with length 1 / |x|, with respect to b likewise, and with respect to o minus their sum,
// of length sqrt(1 / |x|^2 + 1 / |y|^2) at 90°; so to first order such moves open it by
// delta (1 / |x| + 1 / |y| + sqrt(1 / |x|^2 + 1 / |y|^2)), and an angle whose complement
// asin(cos) is at most that is the right angle rounding bent, counted in `tolerated`.
// The decision is floating point on purpose: it classifies the input, the mesher never
// sees it, and the cosine's error (a few ulps) is far below delta / |x|.
bool acute(const Point& o, const Point& a, const Point& b, double delta, std::size_t& tolerated) {
  if (dot_sign(o, a, b) != Sign::Positive) return false;
  const Vec x = sub(a, o), y = sub(b, o);
  const double lx = norm(x), ly = norm(y);
  const double cosine = std::min(1.0, dot(x, y) / (lx * ly));
  if (std::asin(cosine) > right_angle_opening(lx, ly, delta)) return true;
  ++tolerated;
  return false;
}

// The same for the dihedral angle along p-q between the half-planes through a and b. Its
// gradient with respect to a is normal to the half-plane of a, of length 1 / h_a (h_a: the
// distance from a to the line pq), with respect to b likewise; with respect to p it is
// -(1 - t_a) times a's minus (1 - t_b) times b's, and with respect to q -t_a times a's
// minus t_b times b's (t_a: the parameter of a's projection on p + t (q - p)), the four
// summing to zero as a rigid translation changes nothing; at 90° a's and b's are
// orthogonal, which gives the lengths below.
bool acute_dihedral(const Point& p, const Point& q, const Point& a, const Point& b,
                    double delta, std::size_t& tolerated) {
  if (dihedral_cos_sign(p, q, a, b) != Sign::Positive) return false;
  const Vec u = sub(q, p), wa = sub(a, p), wb = sub(b, p);
  const Vec x = cross(u, wa), y = cross(u, wb);
  const double uu = dot(u, u), lu = std::sqrt(uu), lx = norm(x), ly = norm(y);
  const double cosine = std::min(1.0, dot(x, y) / (lx * ly));
  const double ga = lu / lx, gb = lu / ly;  // 1 / h_a, 1 / h_b
  const double ta = dot(wa, u) / uu, tb = dot(wb, u) / uu;
  const double opening =
      std::min(kMaxOpening, delta * (ga + gb + std::hypot((1 - ta) * ga, (1 - tb) * gb) +
                                     std::hypot(ta * ga, tb * gb)));
  if (std::asin(cosine) > opening) return true;
  ++tolerated;
  return false;
}

// The positional uncertainty of the input the planarity tolerance admits: a facet is
// planar within tolerance when its vertices lie within tol times its diameter of a plane,
// so a vertex of the domain is known to about tol times the domain's diameter (its
// bounding box's diagonal), or to the uncertainty of coordinates written with fewer
// digits (io/precision.hpp), whichever is more.
double uncertainty(const std::vector<Point>& pts, const io::PlanarityTolerance& t) {
  if (pts.empty()) return 0;
  Point lo = pts[0], hi = pts[0];
  for (const Point& q : pts)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], q[i]);
      hi[i] = std::max(hi[i], q[i]);
    }
  return std::max(t.relative * norm(sub(hi, lo)), t.uncertainty());
}

struct Corner {
  std::uint32_t x, y;  // the triangle's other corners, counter-clockwise after v
};

class Checker {
 public:
  explicit Checker(const PlcDomain& dom)
      : dom_(dom), pts_(dom.plc.points), delta_(uncertainty(dom.plc.points, dom.tolerance)) {
    corners_.resize(dom.facets.size());
    for (std::size_t f = 0; f < dom.facets.size(); ++f) {
      for (const FacetTri& t : dom.facets[f].tris)
        for (int i = 0; i < 3; ++i) corners_[f].push_back({t.v[i], {t.v[(i + 1) % 3], t.v[(i + 2) % 3]}});
      std::sort(corners_[f].begin(), corners_[f].end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
    }
  }

  Admissibility run() {
    for (std::size_t f = 0; f < dom_.facets.size(); ++f) facet_sectors(f);
    for (std::uint32_t v = 0; v < pts_.size(); ++v) {
      segment_pairs(v);
      facet_segment_pairs(v);
      facet_facet_vertex_pairs(v);
    }
    for (std::uint32_t s = 0; s < dom_.segments.size(); ++s) dihedrals(s);
    return std::move(out_);
  }

 private:
  std::vector<Corner> corners_at(std::size_t f, std::uint32_t v) const {
    std::vector<Corner> r;
    auto range = std::equal_range(corners_[f].begin(), corners_[f].end(),
                                  std::pair<std::uint32_t, Corner>{v, {}},
                                  [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto it = range.first; it != range.second; ++it) r.push_back(it->second);
    return r;
  }

  std::array<std::uint32_t, 2> ends(std::uint32_t s) const { return {dom_.segments[s].a, dom_.segments[s].b}; }
  std::size_t line(std::uint32_t v) const {
    return v < dom_.plc.point_lines.size() ? dom_.plc.point_lines[v] : 0;
  }

  void record(AngleRecord r, bool violation) {
    AngleStats& st = out_.stats[static_cast<int>(r.kind)];
    ++st.pairs;
    st.min_degrees = std::min(st.min_degrees, r.degrees);
    st.max_degrees = std::max(st.max_degrees, r.degrees);
    if (!violation) return;
    out_.admissible = false;
    if (r.vertex >= 0) r.vertex_line = line(static_cast<std::uint32_t>(r.vertex));
    for (const auto& s : r.segments) r.segment_lines.push_back({line(s[0]), line(s[1])});
    for (std::uint32_t f : r.facets) r.facet_lines.push_back(dom_.plc.facets[f].line);
    out_.violations.push_back(std::move(r));
  }

  // Sectors of facet f between consecutive segments around each vertex: start at a
  // triangle whose edge (v, next corner) is a segment, turn counter-clockwise about v
  // across non-segment edges until an edge (v, y) that is a segment.
  void facet_sectors(std::size_t f) {
    const DomainFacet& F = dom_.facets[f];
    for (std::size_t t0 = 0; t0 < F.tris.size(); ++t0)
      for (int i = 0; i < 3; ++i) {
        if (!F.tris[t0].on_segment[(i + 2) % 3]) continue;
        const std::uint32_t v = F.tris[t0].v[i];
        const std::uint32_t sx = *dom_.find_segment(v, F.tris[t0].v[(i + 1) % 3]);
        double angle = 0;
        std::int32_t cur = static_cast<std::int32_t>(t0);
        for (std::size_t guard = 0; cur >= 0 && guard <= F.tris.size(); ++guard) {
          const FacetTri& T = F.tris[cur];
          const int j = T.v[0] == v ? 0 : (T.v[1] == v ? 1 : 2);
          const std::uint32_t x = T.v[(j + 1) % 3], y = T.v[(j + 2) % 3];
          angle += angle_deg(sub(pts_[x], pts_[v]), sub(pts_[y], pts_[v]));
          if (T.on_segment[(j + 1) % 3]) {
            const std::uint32_t sy = *dom_.find_segment(v, y);
            if (sy != sx) sectors_.emplace(std::pair{std::min(sx, sy), std::max(sx, sy)},
                                           std::pair{angle, static_cast<std::uint32_t>(f)});
            break;
          }
          cur = T.nbr[(j + 1) % 3];
        }
      }
  }

  void segment_pairs(std::uint32_t v) {
    const auto& segs = dom_.vertex_segments[v];
    for (std::size_t i = 0; i < segs.size(); ++i)
      for (std::size_t j = i + 1; j < segs.size(); ++j) {
        const DomainSegment &s = dom_.segments[segs[i]], &t = dom_.segments[segs[j]];
        const std::uint32_t a = s.a == v ? s.b : s.a, b = t.a == v ? t.b : t.a;
        AngleRecord r;
        r.kind = AngleKind::SegmentSegment;
        r.vertex = v;
        r.segments = {ends(segs[i]), ends(segs[j])};
        auto it = sectors_.find({std::min(segs[i], segs[j]), std::max(segs[i], segs[j])});
        if (it != sectors_.end()) {
          r.degrees = it->second.first;
          r.in_facet = true;
          r.facets = {it->second.second};
        } else {
          r.degrees = angle_deg(sub(pts_[a], pts_[v]), sub(pts_[b], pts_[v]));
        }
        record(std::move(r), acute(pts_[v], pts_[a], pts_[b], delta_, out_.tolerated));
      }
  }

  void facet_segment_pairs(std::uint32_t v) {
    for (std::uint32_t f : dom_.vertex_facets[v]) {
      const std::vector<Corner> cs = corners_at(f, v);
      const auto& fsegs = dom_.facets[f].segments;
      for (std::uint32_t s : dom_.vertex_segments[v]) {
        if (std::binary_search(fsegs.begin(), fsegs.end(), s)) continue;
        const std::uint32_t w = dom_.segments[s].a == v ? dom_.segments[s].b : dom_.segments[s].a;
        const Vec sv = sub(pts_[w], pts_[v]);
        bool violation = false;
        double deg = 180;
        for (const Corner& c : cs) {
          deg = std::min(deg, ray_cone_deg(sv, sub(pts_[c.x], pts_[v]), sub(pts_[c.y], pts_[v])));
          violation = violation || acute(pts_[v], pts_[w], pts_[c.x], delta_, out_.tolerated) ||
                      acute(pts_[v], pts_[w], pts_[c.y], delta_, out_.tolerated);
        }
        AngleRecord r;
        r.kind = AngleKind::FacetSegment;
        r.degrees = deg;
        r.vertex = v;
        r.segments = {ends(s)};
        r.facets = {f};
        record(std::move(r), violation);
      }
    }
  }

  void facet_facet_vertex_pairs(std::uint32_t v) {
    const auto& fs = dom_.vertex_facets[v];
    if (fs.size() < 2) return;
    // Each facet's corners at v and its segments at v (few, so pair tests stay cheap even
    // where many facets meet).
    std::vector<std::vector<Corner>> corners(fs.size());
    std::vector<std::vector<std::uint32_t>> segs(fs.size());
    for (std::size_t i = 0; i < fs.size(); ++i) {
      corners[i] = corners_at(fs[i], v);
      const auto& own = dom_.facets[fs[i]].segments;
      for (const Corner& c : corners[i])
        for (std::uint32_t u : {c.x, c.y})
          if (const auto s = dom_.find_segment(v, u); s && std::binary_search(own.begin(), own.end(), *s))
            segs[i].push_back(*s);
      std::sort(segs[i].begin(), segs[i].end());
      segs[i].erase(std::unique(segs[i].begin(), segs[i].end()), segs[i].end());
    }
    for (std::size_t i = 0; i < fs.size(); ++i)
      for (std::size_t j = i + 1; j < fs.size(); ++j) {
        bool share = false;
        for (std::uint32_t s : segs[i])
          share = share || std::binary_search(segs[j].begin(), segs[j].end(), s);
        if (share) continue;
        const std::vector<Corner>&ci = corners[i];
        const std::vector<Corner>&cj = corners[j];
        bool violation = false;
        double deg = 180;
        for (const Corner& a : ci)
          for (const Corner& b : cj) {
            const Vec a1 = sub(pts_[a.x], pts_[v]), a2 = sub(pts_[a.y], pts_[v]);
            const Vec b1 = sub(pts_[b.x], pts_[v]), b2 = sub(pts_[b.y], pts_[v]);
            deg = std::min({deg, ray_cone_deg(a1, b1, b2), ray_cone_deg(a2, b1, b2),
                            ray_cone_deg(b1, a1, a2), ray_cone_deg(b2, a1, a2)});
            for (std::uint32_t g : {a.x, a.y})
              for (std::uint32_t h : {b.x, b.y})
                violation = violation || acute(pts_[v], pts_[g], pts_[h], delta_, out_.tolerated);
          }
        AngleRecord r;
        r.kind = AngleKind::FacetFacetVertex;
        r.degrees = deg;
        r.vertex = v;
        r.facets = {fs[i], fs[j]};
        record(std::move(r), violation);
      }
  }

  void dihedrals(std::uint32_t s) {
    const DomainSegment& S = dom_.segments[s];
    const std::size_t k = S.sides.size();
    if (k == 1 && S.sides[0].inside_after > 0) {
      // A free edge of a facet inside Ω (a baffle, a wall's window): the domain turns all
      // the way round it, 360 degrees.
      AngleRecord r;
      r.kind = AngleKind::FacetFacet;
      r.degrees = 360;
      r.segments = {ends(s)};
      r.facets = {S.sides[0].facet, S.sides[0].facet};
      record(std::move(r), true);
    }
    if (k < 2) return;
    const Point &p = pts_[S.a], &q = pts_[S.b];
    const Vec u = sub(q, p);
    const double lu = norm(u);
    const Vec uh{u[0] / lu, u[1] / lu, u[2] / lu};
    for (std::size_t i = 0; i < k; ++i) {
      const HalfFacet &x = S.sides[i], &y = S.sides[(i + 1) % k];
      if (x.inside_after <= 0 || x.facet == y.facet) continue;
      // Rotation angle from x's half-plane to y's, positive about a->b, in (0, 360).
      const Vec wx = sub(pts_[x.apex], p), wy = sub(pts_[y.apex], p);
      const double ax = dot(wx, uh);
      Vec e1{wx[0] - ax * uh[0], wx[1] - ax * uh[1], wx[2] - ax * uh[2]};
      const double l1 = norm(e1);
      for (double& c : e1) c /= l1;
      const Vec e2 = cross(uh, e1);
      double theta = std::atan2(dot(wy, e2), dot(wy, e1)) * kDeg;
      if (theta <= 0) theta += 360;
      AngleRecord r;
      r.kind = AngleKind::FacetFacet;
      r.degrees = theta;
      r.segments = {ends(s)};
      r.facets = {x.facet, y.facet};
      record(std::move(r), acute_dihedral(p, q, pts_[x.apex], pts_[y.apex], delta_, out_.tolerated));
    }
  }

  const PlcDomain& dom_;
  const std::vector<Point>& pts_;
  const double delta_;  // uncertainty() of the input
  std::vector<std::vector<std::pair<std::uint32_t, Corner>>> corners_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<double, std::uint32_t>> sectors_;
  Admissibility out_;
};

}  // namespace

Admissibility check_admissibility(const PlcDomain& dom) { return Checker(dom).run(); }

double right_angle_opening(double lx, double ly, double delta) {
  return std::min(kMaxOpening, delta * (1 / lx + 1 / ly + std::hypot(1 / lx, 1 / ly)));
}

double positional_uncertainty(const PlcDomain& dom) {
  return uncertainty(dom.plc.points, dom.tolerance);
}

}  // namespace pdr::domain
