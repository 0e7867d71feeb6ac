// Facet planes and the planarity tolerance (paper §1.1); see domain/plane.hpp.
#include "domain/plane.hpp"

#include <cmath>

#include "geom/plane_fit.hpp"
#include "geom/predicates.hpp"

namespace pdr::domain {

namespace {

double dist2(const Point& a, const Point& b) {
  double s = 0;
  for (int k = 0; k < 3; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return s;
}

double cross_norm2(const Point& a, const Point& b, const Point& c) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double x = uy * vz - uz * vy, y = uz * vx - ux * vz, z = ux * vy - uy * vx;
  return x * x + y * y + z * z;
}

}  // namespace

double relative_deviation(const FacetPlane& plane, const Point& p) {
  const double d = geom::signed_distance({plane.centroid, plane.normal, plane.diameter}, p);
  return plane.diameter > 0 ? std::fabs(d) / plane.diameter : 0;
}

PlaneFit fit_facet_plane(const std::vector<Point>& pts, const std::vector<std::uint32_t>& verts,
                         double tolerance) {
  PlaneFit fit;
  FacetPlane& pl = fit.plane;
  std::vector<Point> facet_pts;
  facet_pts.reserve(verts.size());
  for (std::uint32_t v : verts) facet_pts.push_back(pts[v]);
  const geom::FittedPlane lsq = geom::fit_plane(facet_pts);
  pl.centroid = lsq.centroid;
  pl.normal = lsq.normal;
  pl.diameter = lsq.diameter;

  // Defining triple (a choice in floating point; non-collinearity is then decided exactly).
  std::uint32_t a = verts[0], b = verts[0], c = verts[0];
  for (std::uint32_t v : verts)
    if (dist2(pts[v], pl.centroid) > dist2(pts[a], pl.centroid)) a = v;
  for (std::uint32_t v : verts)
    if (dist2(pts[v], pts[a]) > dist2(pts[b], pts[a])) b = v;
  double best = -1;
  for (std::uint32_t v : verts)
    if (const double area = cross_norm2(pts[a], pts[b], pts[v]); area > best) {
      best = area;
      c = v;
    }
  if (a == b || collinear(pts[a], pts[b], pts[c])) {
    bool found = false;
    for (std::uint32_t v : verts)
      if (a != b && !collinear(pts[a], pts[b], pts[v])) {
        c = v;
        found = true;
        break;
      }
    if (!found) {
      fit.status = PlaneStatus::Collinear;
      return fit;
    }
  }
  pl.triple = {a, b, c};
  pl.projection.drop = nondegenerate_drop(pts[a], pts[b], pts[c]);
  pl.projection.swap =
      orient2d_dropping(pl.projection.drop, pts[a], pts[b], pts[c]) == Sign::Negative;

  pl.exact = true;
  for (std::uint32_t v : verts)
    if (orient3d(pts[a], pts[b], pts[c], pts[v]) != Sign::Zero) {
      pl.exact = false;
      break;
    }

  if (pl.exact) return fit;  // max_deviation stays 0: exactly planar
  for (std::uint32_t v : verts)
    if (const double dev = relative_deviation(pl, pts[v]); dev > pl.max_deviation) {
      pl.max_deviation = dev;
      fit.worst = v;
    }
  if (!(pl.max_deviation <= tolerance)) fit.status = PlaneStatus::NotPlanar;
  return fit;
}

}  // namespace pdr::domain
