// Exact tetrahedron quality and size tests (paper §1.1, §3); see refine/quality.hpp.
#include "refine/quality.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "geom/construct.hpp"
#include "geom/exact.hpp"
#include "geom/filter_kit.hpp"
#include "mesh/tables.hpp"

namespace pdr::refine {
namespace {


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

// Each test: the filter of geom/filter_kit.hpp on the measures when they are known and it
// decides, GMP otherwise.
using Measures = std::optional<filter::TetMeasures>;

bool ratio_test(const Measures& m, const Point& a, const Point& b, const Point& c,
                const Point& d, double bound) {
  if (m) {
    if (const auto l2 = filter::shortest_edge2(a, b, c, d)) {
      const Filtered f = filter::ratio_minus(*m, *l2, bound);
      if (f != Filtered::Unsure) return f == Filtered::Positive;
    }
  }
  const mpq_class bb = mpq_class(bound) * mpq_class(bound);
  return exact::circumradius2(a, b, c, d) >= bb * exact_min_edge2(a, b, c, d);
}

bool radius_test(const Measures& m, const Point& a, const Point& b, const Point& c,
                 const Point& d, double size) {
  if (m) {
    const Filtered f = filter::radius_minus(*m, size);
    if (f != Filtered::Unsure) return f == Filtered::Positive;
  }
  return exact::circumradius2(a, b, c, d) > mpq_class(size) * mpq_class(size);
}

bool volume_test(const Measures& m, const Point& a, const Point& b, const Point& c,
                 const Point& d, double max_volume) {
  if (m) {
    const Filtered f = filter::volume_minus(*m, max_volume);
    if (f != Filtered::Unsure) return f == Filtered::Positive;
  }
  return exact::volume6(a, b, c, d) > mpq_class(6) * mpq_class(max_volume);
}

}  // namespace

// R^2 >= B^2 lmin^2  <=>  |X|^2 >= 4 B^2 lmin^2 D^2.
bool ratio_at_least(const Point& a, const Point& b, const Point& c, const Point& d,
                    double bound) {
  return ratio_test(filter::tet_measures(a, b, c, d), a, b, c, d, bound);
}

// R^2 > L^2  <=>  |X|^2 > 4 L^2 D^2.
bool radius_above(const Point& a, const Point& b, const Point& c, const Point& d,
                  double size) {
  return radius_test(filter::tet_measures(a, b, c, d), a, b, c, d, size);
}

bool volume_above(const Point& a, const Point& b, const Point& c, const Point& d,
                  double max_volume) {
  return volume_test(filter::tet_measures(a, b, c, d), a, b, c, d, max_volume);
}

// The three tests on one evaluation of the measures; the volume test first (it needs no
// edge lengths).
bool is_bad(const Point& a, const Point& b, const Point& c, const Point& d,
            const TetBounds& bounds) {
  const Measures m = filter::tet_measures(a, b, c, d);
  if (bounds.max_volume && volume_test(m, a, b, c, d, *bounds.max_volume)) return true;
  if (bounds.regions && volume_test(m, a, b, c, d, bounds.regions->smallest())) {
    const double v = bounds.regions->bound(a, b, c, d);
    if (v > 0 && (v == bounds.regions->smallest() || volume_test(m, a, b, c, d, v))) return true;
  }
  if (bounds.size && radius_test(m, a, b, c, d, *bounds.size)) return true;
  return ratio_test(m, a, b, c, d, bounds.ratio);
}

namespace {

double shortest_edge2(const Point* const p[4]) {
  double l2 = std::numeric_limits<double>::infinity();
  for (const auto& [i, j] : tables::kEdgeVertex) {
    const Point e = filter::sub(*p[i], *p[j]);
    l2 = std::min(l2, filter::dot(e, e));
  }
  return l2;
}

// ratio_of, given the tet's shortest edge squared.
double ratio_with(const Point* const p[4], double l2) {
  if (l2 <= 0) return std::numeric_limits<double>::infinity();
  return std::sqrt(construct::circumradius2(*p[0], *p[1], *p[2], *p[3]) / l2);
}

}  // namespace

double ratio_of(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point* p[4] = {&a, &b, &c, &d};
  return ratio_with(p, shortest_edge2(p));
}

namespace {

// The extreme dot products of a tet's unit outward face normals. Faces listed by
// mesh/tables.hpp are all oriented outward, so the interior dihedral angle at the edge of
// faces i and j is pi - acos(n_i . n_j), increasing with the dot product: the smallest and
// largest angles are at the smallest and largest dot products.
void dihedral_dots(const Point* const p[4], double& lo, double& hi) {
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
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const double dot = n[i][0] * n[j][0] + n[i][1] * n[j][1] + n[i][2] * n[j][2];
      lo = std::min(lo, dot);
      hi = std::max(hi, dot);
    }
}

double dihedral_degrees(double dot) {
  return 180.0 - std::acos(std::clamp(dot, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

}  // namespace

double QualityRange::dihedral_min_deg() const { return tets == 0 ? 180.0 : dihedral_degrees(dot_lo); }
double QualityRange::dihedral_max_deg() const { return tets == 0 ? 0.0 : dihedral_degrees(dot_hi); }

void QualityRange::add(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point* p[4] = {&a, &b, &c, &d};
  const double l2 = shortest_edge2(p);
  const double r = ratio_with(p, l2);
  ratio_min = std::min(ratio_min, r);
  ratio_max = std::max(ratio_max, r);
  shortest2 = std::min(shortest2, l2);
  dihedral_dots(p, dot_lo, dot_hi);
  ++tets;
}

void QualityRange::merge(const QualityRange& o) {
  ratio_min = std::min(ratio_min, o.ratio_min);
  ratio_max = std::max(ratio_max, o.ratio_max);
  dot_lo = std::min(dot_lo, o.dot_lo);
  dot_hi = std::max(dot_hi, o.dot_hi);
  shortest2 = std::min(shortest2, o.shortest2);
  tets += o.tets;
}

}  // namespace pdr::refine
