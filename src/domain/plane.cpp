// Facet planes and the planarity tolerance (paper §1.1); see domain/plane.hpp.
#include "domain/plane.hpp"

#include <cmath>

#include "geom/predicates.hpp"

namespace pdr::domain {

namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;

// Cyclic Jacobi rotations: the unit eigenvector of the smallest eigenvalue of a symmetric
// 3x3 matrix (the normal of the least-squares plane when m is the scatter matrix).
Point smallest_eigenvector(Mat3 m) {
  Mat3 v{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (int sweep = 0; sweep < 60; ++sweep) {
    const double off = m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2];
    const double diag = m[0][0] * m[0][0] + m[1][1] * m[1][1] + m[2][2] * m[2][2];
    if (off <= 1e-36 * diag || off == 0) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (m[p][q] == 0) continue;
        const double theta = (m[q][q] - m[p][p]) / (2 * m[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < 3; ++k) {  // m <- m J
          const double mkp = m[k][p], mkq = m[k][q];
          m[k][p] = c * mkp - s * mkq;
          m[k][q] = s * mkp + c * mkq;
        }
        for (int k = 0; k < 3; ++k) {  // m <- J^T m
          const double mpk = m[p][k], mqk = m[q][k];
          m[p][k] = c * mpk - s * mqk;
          m[q][k] = s * mpk + c * mqk;
        }
        for (int k = 0; k < 3; ++k) {  // v <- v J
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  int best = 0;
  for (int k = 1; k < 3; ++k)
    if (m[k][k] < m[best][best]) best = k;
  Point n{v[0][best], v[1][best], v[2][best]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& x : n) x /= len;
  return n;
}

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
  double d = 0;
  for (int k = 0; k < 3; ++k) d += plane.normal[k] * (p[k] - plane.centroid[k]);
  return plane.diameter > 0 ? std::fabs(d) / plane.diameter : 0;
}

PlaneFit fit_facet_plane(const std::vector<Point>& pts, const std::vector<std::uint32_t>& verts,
                         const io::PlanarityTolerance& tolerance) {
  PlaneFit fit;
  FacetPlane& pl = fit.plane;
  Point lo = pts[verts[0]], hi = lo;
  for (std::uint32_t v : verts)
    for (int k = 0; k < 3; ++k) {
      pl.centroid[k] += pts[v][k] / static_cast<double>(verts.size());
      lo[k] = std::min(lo[k], pts[v][k]);
      hi[k] = std::max(hi[k], pts[v][k]);
    }
  pl.diameter = std::sqrt(dist2(lo, hi));

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

  Mat3 m{};
  for (std::uint32_t v : verts) {
    Point d;
    for (int k = 0; k < 3; ++k) d[k] = pts[v][k] - pl.centroid[k];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] += d[i] * d[j];
  }
  pl.normal = smallest_eigenvector(m);
  if (pl.exact) return fit;  // max_deviation stays 0: exactly planar
  for (std::uint32_t v : verts)
    if (const double dev = relative_deviation(pl, pts[v]); dev > pl.max_deviation) {
      pl.max_deviation = dev;
      fit.worst = v;
    }
  if (!(pl.max_deviation * pl.diameter <= tolerance.admitted(pl.diameter)))
    fit.status = PlaneStatus::NotPlanar;
  return fit;
}

}  // namespace pdr::domain
