// The least-squares plane of a point set; see geom/plane_fit.hpp.
#include "geom/plane_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace pdr::geom {
namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;

// Cyclic Jacobi rotations: the unit eigenvector of the smallest eigenvalue of a symmetric
// 3x3 matrix (the zero vector for the zero matrix).
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
  if (len > 0)
    for (double& x : n) x /= len;
  return n;
}

}  // namespace

FittedPlane fit_plane(std::span<const Point> pts) {
  FittedPlane pl;
  Point lo = pts[0], hi = lo;
  const auto n = static_cast<double>(pts.size());
  for (const Point& p : pts)
    for (int k = 0; k < 3; ++k) {
      pl.centroid[k] += p[k] / n;
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  pl.diameter = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                          (hi[2] - lo[2]) * (hi[2] - lo[2]));
  Mat3 m{};
  for (const Point& p : pts) {
    Point d;
    for (int k = 0; k < 3; ++k) d[k] = p[k] - pl.centroid[k];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] += d[i] * d[j];
  }
  pl.normal = smallest_eigenvector(m);
  return pl;
}

double signed_distance(const FittedPlane& plane, const Point& p) {
  double d = 0;
  for (int k = 0; k < 3; ++k) d += plane.normal[k] * (p[k] - plane.centroid[k]);
  return d;
}

}  // namespace pdr::geom
