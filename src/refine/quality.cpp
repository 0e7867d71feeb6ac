// Exact tetrahedron quality and size tests (paper §1.1, §3); see refine/quality.hpp.
#include "refine/quality.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geom/construct.hpp"
#include "geom/exact.hpp"
#include "mesh/tables.hpp"

namespace pdr::refine {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;
constexpr double kRel = 0x1p-30;

struct Interval {
  double lo, hi;
};

// |X|^2 and D^2 as intervals (see the header), from the differences to a.
struct Measures {
  Interval x2, d2;
  bool degenerate;  // D's interval contains 0: let GMP decide
};

Measures measure(const Point& a, const Point& b, const Point& c, const Point& d) {
  double u[3], v[3], w[3], au[3], av[3], aw[3];
  for (int i = 0; i < 3; ++i) {
    u[i] = b[i] - a[i];
    v[i] = c[i] - a[i];
    w[i] = d[i] - a[i];
    au[i] = std::fabs(u[i]);
    av[i] = std::fabs(v[i]);
    aw[i] = std::fabs(w[i]);
  }
  auto cross = [](const double* p, const double* q, double* r) {
    r[0] = p[1] * q[2] - p[2] * q[1];
    r[1] = p[2] * q[0] - p[0] * q[2];
    r[2] = p[0] * q[1] - p[1] * q[0];
  };
  auto cross_abs = [](const double* p, const double* q, double* r) {
    r[0] = p[1] * q[2] + p[2] * q[1];
    r[1] = p[2] * q[0] + p[0] * q[2];
    r[2] = p[0] * q[1] + p[1] * q[0];
  };
  double vw[3], wu[3], uv[3], avw[3], awu[3], auv[3];
  cross(v, w, vw);
  cross(w, u, wu);
  cross(u, v, uv);
  cross_abs(av, aw, avw);
  cross_abs(aw, au, awu);
  cross_abs(au, av, auv);
  const double nu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  const double nv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const double nw = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  Measures m{};
  double lo2 = 0, hi2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double x = nu * vw[i] + nv * wu[i] + nw * uv[i];
    const double e = 64 * kU * (nu * avw[i] + nv * awu[i] + nw * auv[i]);
    const double ax = std::fabs(x);
    const double lo = std::max(0.0, ax - e), hi = ax + e;
    lo2 += lo * lo;
    hi2 += hi * hi;
  }
  m.x2 = {lo2 * (1 - kRel), hi2 * (1 + kRel)};
  const double det = u[0] * vw[0] + u[1] * vw[1] + u[2] * vw[2];
  const double edet = 64 * kU * (au[0] * avw[0] + au[1] * avw[1] + au[2] * avw[2]);
  const double adet = std::fabs(det);
  m.degenerate = adet <= edet;
  const double dlo = std::max(0.0, adet - edet), dhi = adet + edet;
  m.d2 = {dlo * dlo * (1 - kRel), dhi * dhi * (1 + kRel)};
  return m;
}

double min_edge2(const Point& a, const Point& b, const Point& c, const Point& d,
                 double& abs_bound) {
  const Point* p[4] = {&a, &b, &c, &d};
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) {
        const double t = (*p[i])[k] - (*p[j])[k];
        s += t * t;
      }
      best = std::min(best, s);
    }
  abs_bound = best * 8 * kU;  // two roundings per difference, three per sum of squares
  return best;
}

mpq_class exact_min_edge2(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point* p[4] = {&a, &b, &c, &d};
  mpq_class best = exact::squared_distance(a, b);
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      mpq_class s = exact::squared_distance(*p[i], *p[j]);
      if (s < best) best = s;
    }
  return best;
}

// Each test on precomputed measures: Positive/Negative when the filter decides, Zero when
// GMP must.
Sign ratio_filter(const Measures& m, const Point& a, const Point& b, const Point& c,
                  const Point& d, double bound) {
  if (m.degenerate) return Sign::Zero;
  double eb;
  const double l2 = min_edge2(a, b, c, d, eb);
  const double k = 4 * bound * bound;
  const double rhs_lo = k * std::max(0.0, l2 - eb) * m.d2.lo * (1 - kRel);
  const double rhs_hi = k * (l2 + eb) * m.d2.hi * (1 + kRel);
  if (m.x2.lo > rhs_hi) return Sign::Positive;
  if (m.x2.hi < rhs_lo) return Sign::Negative;
  return Sign::Zero;
}
bool ratio_exact(const Point& a, const Point& b, const Point& c, const Point& d,
                 double bound) {
  const mpq_class bb = mpq_class(bound) * mpq_class(bound);
  return exact::circumradius2(a, b, c, d) >= bb * exact_min_edge2(a, b, c, d);
}

Sign radius_filter(const Measures& m, double size) {
  if (m.degenerate) return Sign::Zero;
  const double k = 4 * size * size;
  if (m.x2.lo > k * m.d2.hi * (1 + kRel)) return Sign::Positive;
  if (m.x2.hi < k * m.d2.lo * (1 - kRel)) return Sign::Negative;
  return Sign::Zero;
}
bool radius_exact(const Point& a, const Point& b, const Point& c, const Point& d,
                  double size) {
  return exact::circumradius2(a, b, c, d) > mpq_class(size) * mpq_class(size);
}

Sign volume_filter(const Measures& m, double max_volume) {
  if (m.degenerate) return Sign::Zero;
  const double v6 = 6 * max_volume;  // exact up to one rounding: covered by kRel
  if (m.d2.lo > v6 * v6 * (1 + kRel)) return Sign::Positive;
  if (m.d2.hi < v6 * v6 * (1 - kRel)) return Sign::Negative;
  return Sign::Zero;
}
bool volume_exact(const Point& a, const Point& b, const Point& c, const Point& d,
                  double max_volume) {
  return exact::volume6(a, b, c, d) > mpq_class(6) * mpq_class(max_volume);
}

bool decide(Sign filtered, auto exact) {
  return filtered == Sign::Zero ? exact() : filtered == Sign::Positive;
}

}  // namespace

// R^2 >= B^2 lmin^2  <=>  |X|^2 >= 4 B^2 lmin^2 D^2.
bool ratio_at_least(const Point& a, const Point& b, const Point& c, const Point& d,
                    double bound) {
  return decide(ratio_filter(measure(a, b, c, d), a, b, c, d, bound),
                [&] { return ratio_exact(a, b, c, d, bound); });
}

// R^2 > L^2  <=>  |X|^2 > 4 L^2 D^2.
bool radius_above(const Point& a, const Point& b, const Point& c, const Point& d,
                  double size) {
  return decide(radius_filter(measure(a, b, c, d), size),
                [&] { return radius_exact(a, b, c, d, size); });
}

bool volume_above(const Point& a, const Point& b, const Point& c, const Point& d,
                  double max_volume) {
  return decide(volume_filter(measure(a, b, c, d), max_volume),
                [&] { return volume_exact(a, b, c, d, max_volume); });
}

// The three tests on one evaluation of the measures; the volume test first (it needs no
// edge lengths), each falling back to GMP alone when its filter cannot decide.
bool is_bad(const Point& a, const Point& b, const Point& c, const Point& d,
            const TetBounds& bounds) {
  const Measures m = measure(a, b, c, d);
  if (bounds.max_volume && decide(volume_filter(m, *bounds.max_volume), [&] {
        return volume_exact(a, b, c, d, *bounds.max_volume);
      }))
    return true;
  if (bounds.size &&
      decide(radius_filter(m, *bounds.size), [&] { return radius_exact(a, b, c, d, *bounds.size); }))
    return true;
  return decide(ratio_filter(m, a, b, c, d, bounds.ratio),
                [&] { return ratio_exact(a, b, c, d, bounds.ratio); });
}

double ratio_of(const Point& a, const Point& b, const Point& c, const Point& d) {
  double eb;
  const double l2 = min_edge2(a, b, c, d, eb);
  if (l2 <= 0) return std::numeric_limits<double>::infinity();
  return std::sqrt(construct::circumradius2(a, b, c, d) / l2);
}

void dihedral_range(const Point& a, const Point& b, const Point& c, const Point& d,
                    double& min_deg, double& max_deg) {
  const Point* p[4] = {&a, &b, &c, &d};
  // Outward normals of the faces opposite each vertex; the dihedral angle at the edge
  // shared by faces i and j is pi minus the angle between their outward normals.
  double n[4][3];
  for (int f = 0; f < 4; ++f) {
    const Point& x = *p[tables::kFaceVertex[f][0]];
    const Point& y = *p[tables::kFaceVertex[f][1]];
    const Point& z = *p[tables::kFaceVertex[f][2]];
    const double e1[3] = {y[0] - x[0], y[1] - x[1], y[2] - x[2]};
    const double e2[3] = {z[0] - x[0], z[1] - x[1], z[2] - x[2]};
    double* r = n[f];
    r[0] = e1[1] * e2[2] - e1[2] * e2[1];
    r[1] = e1[2] * e2[0] - e1[0] * e2[2];
    r[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int k = 0; k < 3; ++k) r[k] = len > 0 ? r[k] / len : 0;
  }
  // Faces listed by mesh/tables.hpp are all oriented outward, so the interior dihedral
  // angle is pi - angle(n_i, n_j) = pi - acos(n_i . n_j), increasing with the dot
  // product: the extreme angles are at the extreme dot products (two acos, not six).
  double lo = 1, hi = -1;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const double dot = n[i][0] * n[j][0] + n[i][1] * n[j][1] + n[i][2] * n[j][2];
      lo = std::min(lo, dot);
      hi = std::max(hi, dot);
    }
  auto degrees = [](double dot) {
    return 180.0 - std::acos(std::clamp(dot, -1.0, 1.0)) * 180.0 / std::numbers::pi;
  };
  min_deg = std::min(min_deg, degrees(lo));
  max_deg = std::max(max_deg, degrees(hi));
}

}  // namespace pdr::refine
