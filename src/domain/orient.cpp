// Which side of the boundary is the domain (paper §1.1: "a closed polyhedral domain,
// possibly having holes and voids"), and the volume hole and region point checks (step 7
// of build_domain).
//
// The facets cut space into open cells: one unbounded, the others bounded. Which cells
// form Ω depends on plc.enclosure: by parity, the points from which a ray crosses the
// boundary an odd number of times (the boundary is then closed mod 2); by hole points
// (TetGen's reading of a .poly), every bounded cell in which no volume hole point lies.
// The cells are found exactly:
//   1. the facet sides around each segment are sorted by angle about a->b (exact:
//      orient3d against a reference side, then pairwise);
//   2. every triangle has two sides, front (where (v1-v0)x(v2-v0) points) and back. Sides
//      are joined within a facet (its triangles are oriented alike) and across each wedge
//      between consecutive facets around a segment: the wedge from side x to the next side
//      y (positive rotation about a->b) is bounded by x's side facing the rotation (front
//      iff x runs a->b) and y's side facing back. A connected set of sides ("component")
//      lies in the closure of one cell. Its one-sided triangles (those whose other side
//      is another component) form a surface closed mod 2: each wedge adds two sides of a
//      segment, and a triangle with both sides in it cancels;
//   3. each component is seeded by an exact ray leaving a rational point inside one of its
//      one-sided triangles on its side, along the axis of that triangle's largest normal
//      component, counting crossings per component (orient3d / orient2d of the rational
//      point, domain/exact.hpp: a floating-point filter, then GMP); the ray's origin is
//      moved symbolically off every edge line it meets, so one ray always decides, whatever
//      the input's symmetry (crosses() below). An odd count of its own surface means the
//      component's cell lies inside that surface: it is the cell's outer boundary ("outer"),
//      and each bounded cell has exactly one. Otherwise the component bounds a cavity of
//      the cell around it: the innermost outer surface enclosing the seed point (the outer
//      surfaces nest like the cells they bound; depth orders them).
// A facet wall splitting a region (a segment with three facet sides) is two cells with the
// wall between them; a closed shell inside another is a cell inside a cell. Hole and
// region points are located the same way, with one axis ray from the point itself.
#include <algorithm>
#include <numeric>
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

// The domain's triangles numbered g = offset[facet] + tri, in a box hierarchy.
class RayCaster {
 public:
  explicit RayCaster(const PlcDomain& dom) : dom_(dom) {
    for (std::uint32_t f = 0; f < dom.facets.size(); ++f)
      for (std::uint32_t t = 0; t < dom.facets[f].tris.size(); ++t) tris_.push_back({f, t});
    std::vector<Box> boxes(tris_.size());
    for (std::size_t i = 0; i < tris_.size(); ++i)
      for (std::uint32_t v : tri(tris_[i]).v) boxes[i].add(dom.plc.points[v]);
    bvh_ = Bvh(std::move(boxes));
  }
  const std::vector<TriRef>& tris() const { return tris_; }
  const FacetTri& tri(const TriRef& r) const { return dom_.facets[r.facet].tris[r.tri]; }
  const Bvh& bvh() const { return bvh_; }

  // hit(g) for every triangle g the ray from o along dir * e_axis crosses (symbolically
  // perturbed: crosses()), skipping triangle `skip`. Boxes are filtered with the
  // floating-point shadow of o widened by its error (a superset of the exact test).
  template <class Hit>
  void cast_axis(const RatPoint& o, int axis, int dir, std::int64_t skip, Hit&& hit) const {
    auto keep = [&](const Box& b) {
      for (int j = 0; j < 3; ++j) {
        if (j == axis) continue;
        if (o.d[j] + o.err < b.lo[j] || o.d[j] - o.err > b.hi[j]) return false;
      }
      return dir > 0 ? o.d[axis] - o.err <= b.hi[axis] : o.d[axis] + o.err >= b.lo[axis];
    };
    bvh_.for_each_kept(keep, [&](std::uint32_t i) {
      if (static_cast<std::int64_t>(i) == skip) return;
      if (crosses(o, axis, dir, point(i, 0), point(i, 1), point(i, 2))) hit(i);
    });
  }

 private:
  const Point& point(std::uint32_t i, int k) const { return dom_.plc.points[tri(tris_[i]).v[k]]; }

  const PlcDomain& dom_;
  std::vector<TriRef> tris_;
  Bvh bvh_;
};

// Union-find over the sides of the triangles, with path halving.
class Joins {
 public:
  explicit Joins(std::size_t n) : up_(n) { std::iota(up_.begin(), up_.end(), std::size_t{0}); }
  std::size_t root(std::size_t x) {
    while (up_[x] != x) x = up_[x] = up_[up_[x]];
    return x;
  }
  void join(std::size_t a, std::size_t b) { up_[root(a)] = root(b); }

 private:
  std::vector<std::size_t> up_;
};

// Side node of triangle g: 2g its front, 2g + 1 its back.
std::size_t side_node(std::size_t g, int side) { return 2 * g + (side > 0 ? 0 : 1); }

// The components of step 2, their seeds and nesting (step 3), and the cells.
class Cells {
 public:
  explicit Cells(PlcDomain& dom) : dom_(dom), rays_(dom) {
    offset_.assign(dom.facets.size() + 1, 0);
    for (std::size_t f = 0; f < dom.facets.size(); ++f)
      offset_[f + 1] = offset_[f] + dom.facets[f].tris.size();
    join_sides();
    seed_components();
    number_cells();
  }

  const RayCaster& rays() const { return rays_; }
  std::size_t count() const { return outer_.size(); }
  int cell_of_node(std::size_t node) const { return cell_[comp_[node]]; }
  int cell_of_side(std::uint32_t facet, std::uint32_t tri, int side) const {
    return cell_of_node(side_node(offset_[facet] + tri, side));
  }
  // Crossings of the seed ray of cell c's outer boundary with every triangle: odd iff the
  // cell is enclosed by an odd number of closed surfaces (meaningful when the boundary is
  // closed mod 2).
  bool seed_parity(int c) const { return seed_total_[outer_[c]] % 2 == 1; }

  // The cell holding point p (off every facet): -1 for the unbounded one. `total` gets the
  // ray's crossings with every triangle.
  int locate(const Point& p, int* total) const {
    std::vector<int> odd;
    const int t = cast(make_rat(p), 0, +1, -1, odd);
    if (total) *total = t;
    return innermost(odd);
  }

 private:
  void join_sides() {
    const std::size_t n = offset_.back();
    Joins joins(2 * n);
    for (std::size_t f = 0; f < dom_.facets.size(); ++f)
      for (std::size_t t = 0; t < dom_.facets[f].tris.size(); ++t)
        for (std::int32_t nb : dom_.facets[f].tris[t].nbr)
          if (nb >= 0)
            for (int side : {+1, -1})
              joins.join(side_node(offset_[f] + t, side), side_node(offset_[f] + static_cast<std::size_t>(nb), side));
    for (const DomainSegment& s : dom_.segments)
      for (std::size_t i = 0; i < s.sides.size() && s.sides.size() >= 2; ++i) {
        const HalfFacet &x = s.sides[i], &y = s.sides[(i + 1) % s.sides.size()];
        joins.join(side_node(offset_[x.facet] + x.tri, x.dir), side_node(offset_[y.facet] + y.tri, -y.dir));
      }
    comp_.assign(2 * n, -1);
    std::vector<int> id(2 * n, -1);
    for (std::size_t v = 0; v < 2 * n; ++v) {
      int& c = id[joins.root(v)];
      if (c < 0) c = static_cast<int>(comps_++);
      comp_[v] = c;
    }
  }

  // Crossings of the ray per component: a triangle counts for the components of its two
  // sides when they differ (else it is not on that component's surface). Fills `odd` with
  // the components crossed an odd number of times; returns the crossings of all triangles.
  int cast(const RatPoint& o, int axis, int dir, std::int64_t skip, std::vector<int>& odd) const {
    std::vector<int> hits;
    int total = 0;
    rays_.cast_axis(o, axis, dir, skip, [&](std::uint32_t g) {
      ++total;
      const int a = comp_[2 * g], b = comp_[2 * g + 1];
      if (a == b) return;
      hits.push_back(a);
      hits.push_back(b);
    });
    std::sort(hits.begin(), hits.end());
    odd.clear();
    for (std::size_t i = 0; i < hits.size();) {
      std::size_t j = i;
      while (j < hits.size() && hits[j] == hits[i]) ++j;
      if ((j - i) % 2 == 1) odd.push_back(hits[i]);
      i = j;
    }
    return total;
  }

  void seed_components() {
    std::vector<std::int64_t> seed(comps_, -1);
    for (std::size_t g = 0; g < offset_.back(); ++g) {
      const int a = comp_[2 * g], b = comp_[2 * g + 1];
      if (a == b) continue;
      if (seed[a] < 0) seed[a] = static_cast<std::int64_t>(2 * g);
      if (seed[b] < 0) seed[b] = static_cast<std::int64_t>(2 * g + 1);
    }
    const std::vector<Point>& pts = dom_.plc.points;
    odd_.resize(comps_);
    seed_total_.resize(comps_);
    is_outer_.assign(comps_, 0);
    for (std::size_t k = 0; k < comps_; ++k) {
      if (seed[k] < 0) throw std::logic_error("plc_orient: a surface component with no one-sided triangle");
      const auto node = static_cast<std::size_t>(seed[k]);
      const std::size_t g = node / 2;
      const TriRef r = rays_.tris()[g];
      const FacetTri& t = rays_.tri(r);
      const Point &a = pts[t.v[0]], &b = pts[t.v[1]], &c = pts[t.v[2]];
      const int axis = nondegenerate_drop(a, b, c);
      // The +axis ray leaves towards the front iff the normal's axis component is positive.
      const int front = orient2d_dropping(axis, a, b, c) == Sign::Positive ? 1 : -1;
      const int dir = node % 2 == 0 ? front : -front;
      const mpq_class w1(3), w2(5), w3(7), sum(15);
      QPoint q;
      for (int j = 0; j < 3; ++j)
        q[j] = (w1 * mpq_class(a[j]) + w2 * mpq_class(b[j]) + w3 * mpq_class(c[j])) / sum;
      seed_total_[k] = cast(make_rat(q), axis, dir, static_cast<std::int64_t>(g), odd_[k]);
      is_outer_[k] = std::binary_search(odd_[k].begin(), odd_[k].end(), static_cast<int>(k));
    }
  }

  // The innermost outer component among those a ray crossed an odd number of times (the
  // surfaces enclosing its origin) -> its cell; -1 when none encloses it.
  int innermost(const std::vector<int>& odd) const {
    int best = -1;
    for (const int j : odd)
      if (is_outer_[j] && (best < 0 || depth_[j] > depth_[best])) best = j;
    return best < 0 ? -1 : cell_[best];
  }

  void number_cells() {
    depth_.assign(comps_, 0);
    cell_.assign(comps_, -1);
    for (std::size_t k = 0; k < comps_; ++k) {
      if (!is_outer_[k]) continue;
      for (const int j : odd_[k]) depth_[k] += is_outer_[j] && j != static_cast<int>(k);
      cell_[k] = static_cast<int>(outer_.size());
      outer_.push_back(static_cast<int>(k));
    }
    for (std::size_t k = 0; k < comps_; ++k)
      if (!is_outer_[k]) cell_[k] = innermost(odd_[k]);
  }

  PlcDomain& dom_;
  RayCaster rays_;
  std::vector<std::size_t> offset_;      // first triangle number of each facet
  std::vector<int> comp_;                // per side node: its component
  std::size_t comps_ = 0;
  std::vector<std::vector<int>> odd_;    // per component: components its seed ray crossed oddly
  std::vector<int> seed_total_;          // per component: its seed ray's crossings, all triangles
  std::vector<std::uint8_t> is_outer_;   // per component: the outer boundary of its cell
  std::vector<int> depth_;               // per outer component: outer components around it
  std::vector<int> cell_;                // per component: its cell (-1: unbounded)
  std::vector<int> outer_;               // per cell: its outer component
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

// Shells: the connected components of the boundary surface (triangles joined within their
// facet and at segments), a figure of the domain report.
void number_shells(PlcDomain& dom) {
  Joins joins(dom.facets.size());
  for (const DomainSegment& s : dom.segments)
    for (const HalfFacet& h : s.sides) joins.join(h.facet, s.sides[0].facet);
  std::vector<int> id(dom.facets.size(), -1);
  dom.shells = 0;
  for (std::size_t f = 0; f < dom.facets.size(); ++f) {
    if (dom.facets[f].tris.empty()) continue;
    int& c = id[joins.root(f)];
    if (c < 0) c = static_cast<int>(dom.shells++);
    dom.facets[f].shell = c;
  }
}

// Volume hole points: each lies off the facets and in a bounded cell, and (by parity) in
// a void. Counts them per cell.
void locate_holes(PlcDomain& dom, const Cells& cells) {
  const Plc& plc = dom.plc;
  dom.cell_holes.assign(cells.count(), 0);
  for (std::size_t i = 0; i < plc.holes.size(); ++i) {
    const std::size_t line = i < plc.hole_lines.size() ? plc.hole_lines[i] : 0;
    const std::string which = "volume hole point " + std::to_string(i + 1);
    check_hole_off_facets(dom, cells.rays(), i);
    int total = 0;
    const int cell = cells.locate(plc.holes[i], &total);
    if (cell < 0)
      fail(plc, line,
           "volume hole in a void: " + which +
               " lies outside the domain's closed boundary; a volume hole point must mark "
               "a void enclosed by the boundary. Move it into the void or remove it");
    if (plc.enclosure == Enclosure::Parity && total % 2 == 1)
      fail(plc, line,
           "volume hole in a void: " + which +
               " lies inside the domain (it is enclosed by an odd number of closed boundary "
               "surfaces), not in a void; pdr's domain is what the closed boundary encloses, "
               "so a hole point can only mark a void. Move it into the void or remove it");
    std::uint8_t& n = dom.cell_holes[static_cast<std::size_t>(cell)];
    if (n < 255) ++n;
  }
}

// Which cells are in Ω, which facets separate, which triangle sides and wedges face Ω.
void mark_inside(PlcDomain& dom, const Cells& cells) {
  dom.cells = cells.count();
  dom.cell_inside.assign(dom.cells, 0);
  for (std::size_t c = 0; c < dom.cells; ++c)
    dom.cell_inside[c] = dom.plc.enclosure == Enclosure::Parity ? cells.seed_parity(static_cast<int>(c))
                                                                : dom.cell_holes[c] == 0;
  const auto inside = [&](int c) { return c >= 0 && dom.cell_inside[static_cast<std::size_t>(c)] != 0; };
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f) {
    DomainFacet& F = dom.facets[f];
    if (F.tris.empty()) continue;
    F.cells = {cells.cell_of_side(f, 0, +1), cells.cell_of_side(f, 0, -1)};
    const bool front = inside(F.cells[0]), back = inside(F.cells[1]);
    if (!front && !back)
      fail(dom.plc, dom.plc.facets[f].line,
           "volume holes: " + facet_name(dom.plc, f) +
               " has no domain on either side (volume hole points mark the regions on both "
               "sides of it, or it lies in a void); remove that surface or the hole point "
               "that empties the region it bounds");
    F.separates = front != back;
    for (FacetTri& t : F.tris) t.inward = static_cast<std::int8_t>(front ? 1 : -1);
  }
  for (DomainSegment& s : dom.segments)
    for (HalfFacet& h : s.sides)
      h.inside_after = static_cast<std::int8_t>(inside(cells.cell_of_side(h.facet, h.tri, h.dir)) ? 1 : -1);
}

void check_region_points(const PlcDomain& dom, const Cells& cells) {
  const Plc& plc = dom.plc;
  for (std::size_t i = 0; i < plc.regions.size(); ++i) {
    const Point& p = plc.regions[i].point;
    const std::size_t line = plc.regions[i].line;
    const std::string which = "region point " + std::to_string(i + 1);
    check_off_facets(plc, cells.rays(), p, line, "region point in the domain: " + which,
                     "; move it into the region it names");
    const int cell = cells.locate(p, nullptr);
    if (cell < 0 || !dom.cell_inside[static_cast<std::size_t>(cell)])
      fail(plc, line,
           "region point in the domain: " + which +
               " lies outside the domain (outside its closed boundary, or in a void); a region "
               "point must lie inside the region it names. Move it there or remove it");
  }
}

}  // namespace

void orient_boundary(PlcDomain& dom) {
  for (DomainSegment& s : dom.segments) sort_sides(dom.plc.points, s);
  number_shells(dom);
  const Cells cells(dom);
  locate_holes(dom, cells);
  mark_inside(dom, cells);
  check_region_points(dom, cells);
}

}  // namespace pdr::domain::detail
