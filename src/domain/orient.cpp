// Which side of the boundary is the domain (paper §1.1: "a closed polyhedral domain,
// possibly having holes and voids"), and the volume hole checks (step 7 of build_domain).
//
// The boundary is closed mod 2 (every segment bounds an even number of facet sides), so a
// ray from a point crosses it an odd number of times iff the point is enclosed by an odd
// number of closed surfaces; pdr's domain Ω is that set (a void inside a body is even).
// Orientation:
//   1. the facet sides around each segment are sorted by angle about a->b (exact:
//      orient3d against a reference side, then pairwise);
//   2. triangles are connected through their facet (same inward side) and around each
//      segment, where the wedges between consecutive sides alternate in / out of Ω, so
//      inward(next) = -inward(this) * dir(this) * dir(next);
//   3. each connected component ("shell") is seeded by an exact ray from a rational
//      point inside one of its triangles along the axis of that triangle's largest normal
//      component, counting crossings (orient3d / orient2d of the rational point,
//      domain/exact.hpp: a floating-point filter, then GMP); the ray's origin is moved
//      symbolically off every edge line it meets, so one ray always decides, whatever
//      the input's symmetry (crosses() below).
// Hole points are tested the same way with one axis ray from the point itself, counting
// crossings per shell; so are region points, which must lie inside the domain.
#include <algorithm>
#include <stdexcept>

#include "domain/bvh.hpp"
#include "domain/exact.hpp"
#include "domain/intersect.hpp"
#include "domain/steps.hpp"
#include "geom/predicates.hpp"

namespace pdr::domain::detail {

namespace {

struct TriRef {
  std::uint32_t facet, tri;
};

// The sign of orient2d_rat(axis, p, q, o) for o moved by (eps, eps^2) in the two
// coordinates kept, i = axis + 1 and j = axis + 2 (mod 3), when o lies on the line pq
// (Simulation of Simplicity): the value (q_i - p_i)(o_j - p_j) - (q_j - p_j)(o_i - p_i)
// gains -(q_j - p_j) eps + (q_i - p_i) eps^2. Exact: two comparisons of input doubles.
// Precondition: p and q differ in the kept coordinates.
Sign perturbed_edge_sign(int axis, const Point& p, const Point& q) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  if (p[j] != q[j]) return p[j] > q[j] ? Sign::Positive : Sign::Negative;
  return q[i] > p[i] ? Sign::Positive : Sign::Negative;
}

// The ray from o along direction dir * e_axis against the closed triangle abc, with o
// symbolically moved off every line and plane it lies on (above): the ray then never
// touches an edge or a vertex, and never runs in a triangle's plane, so one ray decides.
// Precondition: o lies in no triangle but the skipped one. The ray meets the triangle's
// plane at o + t dir e_axis with t = -n.(o - a) / (dir n_axis), n = (b-a)x(c-a); it
// crosses the triangle iff t > 0 and the projection of o (dropping the axis) lies inside
// the projected triangle, whose orientation is sign(n_axis). A triangle parallel to the
// axis (n_axis = 0) projects to a segment, which the moved o misses; o in a triangle's
// plane (outside it, by the precondition) meets it only at t = 0: a miss. The moved o is
// on the same side of every edge line for the two triangles that share the edge, so a
// ray through an edge or a vertex counts the crossing once.
bool crosses(const RatPoint& o, int axis, int dir, const Point& a, const Point& b, const Point& c) {
  const Sign nk = orient2d_dropping(axis, a, b, c);
  if (nk == Sign::Zero) return false;
  const Sign so = orient3d_rat(a, b, c, o);
  if (so == Sign::Zero) return false;
  if (to_int(so) != -dir * to_int(nk)) return false;  // the plane is behind o
  const auto inner = [&](const Point& p, const Point& q) {
    Sign e = orient2d_rat(axis, p, q, o);
    if (e == Sign::Zero) e = perturbed_edge_sign(axis, p, q);
    return e * nk == Sign::Positive;
  };
  return inner(a, b) && inner(b, c) && inner(c, a);
}

class RayCaster {
 public:
  explicit RayCaster(const PlcDomain& dom) : dom_(dom) {
    for (std::uint32_t f = 0; f < dom.facets.size(); ++f)
      for (std::uint32_t t = 0; t < dom.facets[f].tris.size(); ++t) tris_.push_back({f, t});
    std::vector<Box> boxes(tris_.size());
    for (std::size_t i = 0; i < tris_.size(); ++i)
      for (std::uint32_t v : tri(tris_[i]).v) {
        boxes[i].add(dom.plc.points[v]);
        all_.add(dom.plc.points[v]);
      }
    bvh_ = Bvh(std::move(boxes));
  }
  const std::vector<TriRef>& tris() const { return tris_; }
  const FacetTri& tri(const TriRef& r) const { return dom_.facets[r.facet].tris[r.tri]; }
  const Box& bounds() const { return all_; }
  const Bvh& bvh() const { return bvh_; }

  // Crossings per shell of the ray from o along dir * e_axis (symbolically perturbed:
  // crosses()), skipping triangle `skip` (numbered as in tris()). Boxes are filtered with
  // the floating-point shadow of o widened by its error (a superset of the exact test).
  std::vector<int> cast_axis(const RatPoint& o, int axis, int dir, std::int64_t skip) const {
    std::vector<int> crossings(dom_.shells, 0);
    auto keep = [&](const Box& b) {
      for (int j = 0; j < 3; ++j) {
        if (j == axis) continue;
        if (o.d[j] + o.err < b.lo[j] || o.d[j] - o.err > b.hi[j]) return false;
      }
      return dir > 0 ? o.d[axis] - o.err <= b.hi[axis] : o.d[axis] + o.err >= b.lo[axis];
    };
    bvh_.for_each_kept(keep, [&](std::uint32_t i) {
      if (static_cast<std::int64_t>(i) == skip) return;
      if (crosses(o, axis, dir, point(i, 0), point(i, 1), point(i, 2)))
        ++crossings[dom_.facets[tris_[i].facet].shell];
    });
    return crossings;
  }

 private:
  const Point& point(std::uint32_t i, int k) const { return dom_.plc.points[tri(tris_[i]).v[k]]; }

  const PlcDomain& dom_;
  std::vector<TriRef> tris_;
  Bvh bvh_;
  Box all_;
};

void sort_sides(const std::vector<Point>& pts, DomainSegment& s) {
  if (s.sides.size() < 2) return;
  const Point &p = pts[s.a], &q = pts[s.b], &w0 = pts[s.sides[0].apex];
  const int drop = nondegenerate_drop(p, q, w0);
  auto half = [&](const HalfFacet& h) {
    if (h.apex == s.sides[0].apex) return 0;
    const Sign o = orient3d(p, q, w0, pts[h.apex]);
    if (o != Sign::Zero) return o == Sign::Positive ? 0 : 1;
    if (orient2d_dropping(drop, p, q, w0) == orient2d_dropping(drop, p, q, pts[h.apex]))
      throw std::logic_error("plc_orient: two facet sides overlap along a segment");
    return 1;  // the opposite half-plane: angle pi
  };
  std::stable_sort(s.sides.begin() + 1, s.sides.end(), [&](const HalfFacet& x, const HalfFacet& y) {
    const int hx = half(x), hy = half(y);
    if (hx != hy) return hx < hy;
    return orient3d(p, q, pts[x.apex], pts[y.apex]) == Sign::Positive;
  });
}

// A point given to mark a cell (a hole or region point) must lie off every facet (a ray
// cast from it needs that): else fail(line, what + " lies on <facet>" + advice).
void check_off_facets(const Plc& plc, const RayCaster& rays, const Point& p, std::size_t line,
                      const std::string& what, const std::string& advice) {
  Box q;
  q.add(p);
  rays.bvh().for_overlapping(q, [&](std::uint32_t k) {
    const FacetTri& t = rays.tri(rays.tris()[k]);
    if (point_in_triangle(plc.points[t.v[0]], plc.points[t.v[1]], plc.points[t.v[2]], p))
      fail(plc, line, what + " lies on " + facet_name(plc, rays.tris()[k].facet) + advice);
  });
}

void check_hole_off_facets(const PlcDomain& dom, const RayCaster& rays, std::size_t i) {
  const Plc& plc = dom.plc;
  check_off_facets(plc, rays, plc.holes[i], i < plc.hole_lines.size() ? plc.hole_lines[i] : 0,
                   "volume hole off facets: volume hole point " + std::to_string(i + 1),
                   "; move it into the void it marks");
}

// The innermost shell enclosing a point, from its ray's crossings per shell (-1: none).
int innermost(const std::vector<int>& crossings, const std::vector<int>& depth) {
  int best = -1;
  for (std::size_t s = 0; s < crossings.size(); ++s)
    if (crossings[s] % 2 == 1 && (best < 0 || depth[s] > depth[best])) best = static_cast<int>(s);
  return best;
}

// Nesting of the shells and which cells are in Ω (domain.hpp): shell_parent, cell_inside,
// separates, void_shell and cells_by_hole_points, from the seed rays' crossings per shell.
void classify_cells(PlcDomain& dom, const RayCaster& rays,
                    const std::vector<std::vector<int>>& crossings) {
  const std::size_t shells = crossings.size();
  std::vector<int>& depth = dom.shell_depth;
  depth.assign(shells, 1);
  for (std::size_t c = 0; c < shells; ++c)
    for (std::size_t s = 0; s < shells; ++s)
      if (s != c && crossings[c][s] % 2 == 1) ++depth[c];
  dom.shell_parent.assign(shells, -1);
  for (std::size_t c = 0; c < shells; ++c) {
    std::vector<int> others = crossings[c];
    others[c] = 0;
    dom.shell_parent[c] = innermost(others, depth);
  }
  // Cells by hole points (TetGen's reading) only where every shell is a closed 2-manifold,
  // each bounding one cell; otherwise parity.
  bool manifold = true;
  for (const DomainSegment& s : dom.segments) manifold = manifold && (s.sides.empty() || s.sides.size() == 2);
  dom.cells_by_hole_points = dom.plc.enclosure == Enclosure::HolePoints && manifold;
  std::vector<std::uint8_t> holed(shells, 0);
  if (dom.cells_by_hole_points)
    for (std::size_t i = 0; i < dom.plc.holes.size(); ++i) {
      check_hole_off_facets(dom, rays, i);
      const int cell = innermost(rays.cast_axis(make_rat(dom.plc.holes[i]), 0, +1, -1), depth);
      if (cell >= 0) holed[cell] = 1;
    }
  dom.cell_inside.assign(shells, 0);
  for (std::size_t c = 0; c < shells; ++c)
    dom.cell_inside[c] = dom.cells_by_hole_points ? !holed[c] : depth[c] % 2 == 1;
  dom.separates.assign(shells, 1);
  dom.void_shell.assign(shells, 0);
  for (std::size_t c = 0; c < shells; ++c) {
    const int parent = dom.shell_parent[c];
    const bool outside_in = parent >= 0 && dom.cell_inside[parent] != 0;
    dom.separates[c] = (dom.cell_inside[c] != 0) != outside_in;
    dom.void_shell[c] = !dom.cell_inside[c];
    if (dom.separates[c] || dom.cell_inside[c]) continue;
    // Holes on both sides: the shell bounds no part of Ω, and no mesh could hold it.
    for (std::uint32_t f = 0; f < dom.facets.size(); ++f)
      if (dom.facets[f].shell == static_cast<int>(c))
        fail(dom.plc, dom.plc.facets[f].line,
             "volume holes: the closed surface of " + facet_name(dom.plc, f) +
                 " has no domain on either side (a volume hole point marks the region inside "
                 "it and the one around it, or it lies in a void); remove that surface or "
                 "the hole point that empties the region it bounds");
  }
}

}  // namespace

void orient_boundary(PlcDomain& dom) {
  const std::vector<Point>& pts = dom.plc.points;
  for (DomainSegment& s : dom.segments) sort_sides(pts, s);

  // Components of the triangle graph.
  std::vector<std::size_t> offset(dom.facets.size() + 1, 0);
  for (std::size_t f = 0; f < dom.facets.size(); ++f)
    offset[f + 1] = offset[f] + dom.facets[f].tris.size();
  const std::size_t n = offset.back();
  std::vector<std::int8_t> inward(n, 0);
  std::vector<int> comp(n, -1);
  // Around-segment links: side i to side i+1, with the factor -dir_i * dir_{i+1}.
  std::vector<std::vector<std::pair<std::size_t, std::int8_t>>> links(n);
  for (const DomainSegment& s : dom.segments)
    for (std::size_t i = 0; i < s.sides.size() && s.sides.size() >= 2; ++i) {
      const HalfFacet &x = s.sides[i], &y = s.sides[(i + 1) % s.sides.size()];
      const std::size_t tx = offset[x.facet] + x.tri, ty = offset[y.facet] + y.tri;
      const auto factor = static_cast<std::int8_t>(-x.dir * y.dir);
      links[tx].push_back({ty, factor});
      links[ty].push_back({tx, factor});
    }
  auto facet_of = [&](std::size_t g) {
    return static_cast<std::uint32_t>(std::upper_bound(offset.begin(), offset.end(), g) - offset.begin() - 1);
  };
  std::vector<std::size_t> seeds;
  for (std::size_t g0 = 0; g0 < n; ++g0) {
    if (comp[g0] >= 0) continue;
    const int c = static_cast<int>(seeds.size());
    seeds.push_back(g0);
    std::vector<std::size_t> stack{g0};
    comp[g0] = c;
    while (!stack.empty()) {
      const std::size_t g = stack.back();
      stack.pop_back();
      const std::uint32_t f = facet_of(g);
      const FacetTri& t = dom.facets[f].tris[g - offset[f]];
      auto visit = [&](std::size_t h) {
        if (comp[h] < 0) {
          comp[h] = c;
          stack.push_back(h);
        }
      };
      for (std::int32_t nb : t.nbr)
        if (nb >= 0) visit(offset[f] + static_cast<std::size_t>(nb));
      for (const auto& [h, factor] : links[g]) visit(h);
    }
  }
  dom.shells = seeds.size();
  for (std::size_t f = 0; f < dom.facets.size(); ++f)
    if (!dom.facets[f].tris.empty()) dom.facets[f].shell = comp[offset[f]];

  const RayCaster rays(dom);
  // Seeds: a ray from a rational point strictly inside a triangle of each shell, along the
  // axis of that triangle's largest normal component (the side of the normal iff n_axis
  // > 0). Shell s encloses shell c iff c's ray crosses s an odd number of times; the ray
  // leaves from inside c iff it crosses c itself (its own triangle skipped) an odd number
  // of times.
  const std::size_t shells = seeds.size();
  std::vector<std::vector<int>> crossings(shells);
  std::vector<Sign> normal_sign(shells);
  for (std::size_t c = 0; c < shells; ++c) {
    const std::size_t g = seeds[c];
    const std::uint32_t f = facet_of(g);
    const FacetTri& t = dom.facets[f].tris[g - offset[f]];
    const Point &a = pts[t.v[0]], &b = pts[t.v[1]], &cc = pts[t.v[2]];
    const int axis = nondegenerate_drop(a, b, cc);
    normal_sign[c] = orient2d_dropping(axis, a, b, cc);
    const mpq_class w1(3), w2(5), w3(7), sum(15);
    QPoint q;
    for (int k = 0; k < 3; ++k)
      q[k] = (w1 * mpq_class(a[k]) + w2 * mpq_class(b[k]) + w3 * mpq_class(cc[k])) / sum;
    // RayCaster numbers triangles as g.
    crossings[c] = rays.cast_axis(make_rat(q), axis, +1, static_cast<std::int64_t>(g));
  }
  classify_cells(dom, rays, crossings);
  for (std::size_t c = 0; c < shells; ++c) {
    const std::size_t g = seeds[c];
    const int parent = dom.shell_parent[c];
    const bool parent_inside = parent >= 0 && dom.cell_inside[parent] != 0;
    // Which cell the seed ray enters: the one inside c, or the one around it.
    const bool plus_into_c = crossings[c][c] % 2 == 1;
    int total = 0;
    for (const int x : crossings[c]) total += x;
    const bool plus_inside =
        !dom.cells_by_hole_points ? total % 2 == 1  // parity: odd crossings
        : dom.separates[c]        ? (plus_into_c ? dom.cell_inside[c] != 0 : parent_inside)
                                  : plus_into_c;  // both sides alike: towards c's cell
    const auto seed_inward =
        static_cast<std::int8_t>((normal_sign[c] == Sign::Positive ? 1 : -1) * (plus_inside ? 1 : -1));
    inward[g] = seed_inward;
    std::vector<std::size_t> stack{g};
    while (!stack.empty()) {
      const std::size_t x = stack.back();
      stack.pop_back();
      const std::uint32_t f = facet_of(x);
      const FacetTri& t = dom.facets[f].tris[x - offset[f]];
      auto visit = [&](std::size_t h, std::int8_t value) {
        if (inward[h] == 0) {
          inward[h] = value;
          stack.push_back(h);
        } else if (inward[h] != value) {
          throw std::logic_error("plc_orient: inconsistent boundary orientation");
        }
      };
      for (std::int32_t nb : t.nbr)
        if (nb >= 0) visit(offset[f] + static_cast<std::size_t>(nb), inward[x]);
      for (const auto& [h, factor] : links[x]) visit(h, static_cast<std::int8_t>(inward[x] * factor));
    }
  }
  for (std::size_t f = 0; f < dom.facets.size(); ++f)
    for (std::size_t t = 0; t < dom.facets[f].tris.size(); ++t)
      dom.facets[f].tris[t].inward = inward[offset[f] + t];
  for (std::size_t f = 0; f < dom.facets.size(); ++f)
    if (dom.facets[f].shell >= 0) dom.facets[f].separates = dom.separates[dom.facets[f].shell] != 0;
  for (DomainSegment& s : dom.segments)
    for (HalfFacet& h : s.sides) {
      const int shell = dom.facets[h.facet].shell;
      h.inside_after = dom.separates[shell]
                           ? static_cast<std::int8_t>(dom.facets[h.facet].tris[h.tri].inward * h.dir)
                           : static_cast<std::int8_t>(dom.cell_inside[shell] ? 1 : -1);
    }
}

void check_volume_holes(PlcDomain& dom) {
  const Plc& plc = dom.plc;
  dom.shell_holes.assign(dom.shells, 0);
  if (plc.holes.empty()) return;
  const RayCaster rays(dom);
  for (std::size_t i = 0; i < plc.holes.size(); ++i) {
    const Point& h = plc.holes[i];
    const std::size_t line = i < plc.hole_lines.size() ? plc.hole_lines[i] : 0;
    const std::string which = "volume hole point " + std::to_string(i + 1);
    check_hole_off_facets(dom, rays, i);
    const std::vector<int> crossings = rays.cast_axis(make_rat(h), 0, +1, -1);
    int total = 0, enclosing = 0;
    for (std::size_t s = 0; s < crossings.size(); ++s) {
      total += crossings[s];
      enclosing += crossings[s] % 2;
    }
    if (const int cell = innermost(crossings, dom.shell_depth); cell >= 0 && dom.shell_holes[cell] < 255)
      ++dom.shell_holes[cell];
    if (enclosing == 0)
      fail(plc, line,
           "volume hole in a void: " + which +
               " lies outside the domain's closed boundary; a volume hole point must mark "
               "a void enclosed by the boundary. Move it into the void or remove it");
    if (!dom.cells_by_hole_points && total % 2 == 1)
      fail(plc, line,
           "volume hole in a void: " + which +
               " lies inside the domain (it is enclosed by an odd number of closed boundary "
               "surfaces), not in a void; pdr's domain is what the closed boundary encloses, "
               "so a hole point can only mark a void. Move it into the void or remove it");
  }
}

void check_enclosure(const PlcDomain& dom) {
  if (dom.plc.enclosure != Enclosure::HolePoints || dom.cells_by_hole_points) return;
  // Read by parity although the file asks for hole points: refuse where the two readings
  // differ, a shell bounding a void that no hole point marks.
  std::string joint;
  for (const DomainSegment& s : dom.segments)
    if (s.sides.size() > 2) {
      joint = "the segment from " + vertex_name(dom.plc, s.a) + " to " + vertex_name(dom.plc, s.b) +
              " bounds " + std::to_string(s.sides.size()) + " facet sides";
      break;
    }
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f) {
    const int c = dom.facets[f].shell;
    if (c < 0 || !dom.void_shell[c] || dom.shell_holes[c] != 0) continue;
    fail(dom.plc, dom.plc.facets[f].line,
         "nested regions: the closed surface of " + facet_name(dom.plc, f) +
             " lies inside another and no volume hole point lies in it, so TetGen reads it as a "
             "second region; pdr meshes such regions only when every closed surface is a "
             "2-manifold, and here " + joint + ". Add a hole point inside it to make it a "
             "void, or separate the surfaces that touch");
  }
}

void check_region_points(const PlcDomain& dom) {
  const Plc& plc = dom.plc;
  if (plc.regions.empty()) return;
  const RayCaster rays(dom);
  for (std::size_t i = 0; i < plc.regions.size(); ++i) {
    const Point& p = plc.regions[i].point;
    const std::size_t line = plc.regions[i].line;
    const std::string which = "region point " + std::to_string(i + 1);
    check_off_facets(plc, rays, p, line, "region point in the domain: " + which,
                     "; move it into the region it names");
    const int cell = innermost(rays.cast_axis(make_rat(p), 0, +1, -1), dom.shell_depth);
    if (cell < 0 || !dom.cell_inside[cell])
      fail(plc, line,
           "region point in the domain: " + which +
               " lies outside the domain (outside its closed boundary, or in a void); a region "
               "point must lie inside the region it names. Move it there or remove it");
  }
}

}  // namespace pdr::domain::detail
