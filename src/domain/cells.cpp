// The cells of a domain and point location among them; see domain/cells.hpp.
#include "domain/cells.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "geom/predicates.hpp"
#include "mesh/union_find.hpp"

namespace pdr::domain {

namespace {

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
bool ray_crosses(const RatPoint& o, int axis, int dir, const Point& a, const Point& b, const Point& c) {
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

// Side node of triangle g: 2g its front, 2g + 1 its back.
std::size_t side_node(std::size_t g, int side) { return 2 * g + (side > 0 ? 0 : 1); }
std::uint32_t side(std::size_t g, int s) { return static_cast<std::uint32_t>(side_node(g, s)); }

}  // namespace

RayCaster::RayCaster(const PlcDomain& dom) : dom_(dom) {
  for (std::uint32_t f = 0; f < dom.facets.size(); ++f)
    for (std::uint32_t t = 0; t < dom.facets[f].tris.size(); ++t) tris_.push_back({f, t});
  std::vector<Box> boxes(tris_.size());
  for (std::size_t i = 0; i < tris_.size(); ++i)
    for (std::uint32_t v : tri(tris_[i]).v) boxes[i].add(dom.plc.points[v]);
  bvh_ = Bvh(std::move(boxes));
}

bool RayCaster::crosses(const RatPoint& o, int axis, int dir, std::uint32_t i) const {
  const FacetTri& t = tri(tris_[i]);
  const std::vector<Point>& p = dom_.plc.points;
  return ray_crosses(o, axis, dir, p[t.v[0]], p[t.v[1]], p[t.v[2]]);
}

Cells::Cells(const PlcDomain& dom) : dom_(dom), rays_(dom) {
  offset_.assign(dom.facets.size() + 1, 0);
  for (std::size_t f = 0; f < dom.facets.size(); ++f)
    offset_[f + 1] = offset_[f] + dom.facets[f].tris.size();
  join_sides();
  seed_components();
  number_cells();
}

int Cells::cell_of_side(std::uint32_t facet, std::uint32_t tri, int side) const {
  return cell_[comp_[side_node(offset_[facet] + tri, side)]];
}

int Cells::locate(const RatPoint& p, int* total) const {
  std::vector<int> odd;
  const int t = cast(p, 0, +1, -1, odd);
  if (total) *total = t;
  return innermost(odd);
}

void Cells::join_sides() {
  const std::size_t n = offset_.back();
  UnionFind joins(2 * n);
  for (std::size_t f = 0; f < dom_.facets.size(); ++f)
    for (std::size_t t = 0; t < dom_.facets[f].tris.size(); ++t)
      for (int e = 0; e < 3; ++e) {
        // Across a segment inside the facet the wedges around it join the sides (a wall
        // may stand on it).
        const FacetTri& x = dom_.facets[f].tris[t];
        if (x.nbr[e] < 0 || x.on_segment[e]) continue;
        for (int s : {+1, -1})
          joins.join(side(offset_[f] + t, s), side(offset_[f] + static_cast<std::size_t>(x.nbr[e]), s));
      }
  for (const DomainSegment& s : dom_.segments)
    for (std::size_t i = 0; i < s.sides.size(); ++i) {  // one side: its front joins its back
      const HalfFacet &x = s.sides[i], &y = s.sides[(i + 1) % s.sides.size()];
      joins.join(side(offset_[x.facet] + x.tri, x.dir), side(offset_[y.facet] + y.tri, -y.dir));
    }
  comp_.assign(2 * n, -1);
  std::vector<int> id(2 * n, -1);
  for (std::size_t v = 0; v < 2 * n; ++v) {
    int& c = id[joins.find(static_cast<std::uint32_t>(v))];
    if (c < 0) c = static_cast<int>(comps_++);
    comp_[v] = c;
  }
}

// Crossings of the ray per component: a triangle counts for the components of its two
// sides when they differ (else it is not on that component's surface). Fills `odd` with
// the components crossed an odd number of times; returns the crossings of all triangles.
int Cells::cast(const RatPoint& o, int axis, int dir, std::int64_t skip, std::vector<int>& odd) const {
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

void Cells::seed_components() {
  std::vector<std::int64_t> seed(comps_, -1);
  for (std::size_t g = 0; g < offset_.back(); ++g) {
    const int a = comp_[2 * g], b = comp_[2 * g + 1];
    if (a == b) continue;
    if (seed[a] < 0) seed[a] = static_cast<std::int64_t>(2 * g);
    if (seed[b] < 0) seed[b] = static_cast<std::int64_t>(2 * g + 1);
  }
  // A component whose every triangle has both sides in it (a 2-complex enclosing no
  // volume, Bing's house) bounds no cell of its own: seeded off any triangle, it is an
  // inner boundary of the cell around it (its surface mod 2 is empty, so never outer).
  for (std::size_t g = 0; g < offset_.back(); ++g)
    if (seed[comp_[2 * g]] < 0) seed[comp_[2 * g]] = static_cast<std::int64_t>(2 * g);
  const std::vector<Point>& pts = dom_.plc.points;
  odd_.resize(comps_);
  seed_total_.resize(comps_);
  is_outer_.assign(comps_, 0);
  for (std::size_t k = 0; k < comps_; ++k) {
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
int Cells::innermost(const std::vector<int>& odd) const {
  int best = -1;
  for (const int j : odd)
    if (is_outer_[j] && (best < 0 || depth_[j] > depth_[best])) best = j;
  return best < 0 ? -1 : cell_[best];
}

void Cells::number_cells() {
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

std::shared_ptr<const RegionVolumes> RegionVolumes::of(const PlcDomain& dom) {
  if (std::none_of(dom.plc.regions.begin(), dom.plc.regions.end(),
                   [](const PlcRegion& r) { return r.max_volume > 0; }))
    return nullptr;
  return std::shared_ptr<const RegionVolumes>(new RegionVolumes(dom));
}

RegionVolumes::RegionVolumes(const PlcDomain& dom) : dom_(dom), cells_(dom_) {
  bound_.assign(cells_.count(), 0);
  smallest_ = std::numeric_limits<double>::infinity();
  for (const PlcRegion& r : dom_.plc.regions) {
    if (!(r.max_volume > 0)) continue;
    const int c = cells_.locate(make_rat(r.point));
    if (c < 0) continue;  // validation refuses it
    double& b = bound_[static_cast<std::size_t>(c)];
    b = b > 0 ? std::min(b, r.max_volume) : r.max_volume;
    smallest_ = std::min(smallest_, r.max_volume);
  }
}

double RegionVolumes::bound(const Point& a, const Point& b, const Point& c, const Point& d) const {
  QPoint q;
  for (int k = 0; k < 3; ++k)
    q[k] = (mpq_class(a[k]) + mpq_class(b[k]) + mpq_class(c[k]) + mpq_class(d[k])) / 4;
  const int cell = cells_.locate(make_rat(q));
  return cell < 0 ? 0 : bound_[static_cast<std::size_t>(cell)];
}

}  // namespace pdr::domain
