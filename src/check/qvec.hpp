// Rational 3-vectors (GMP) for the checker's exact reference computations: differences of
// double points are exact, and so are the cross and dot products built from them.
#pragma once

#include <gmpxx.h>

#include <array>

#include "geom/point.hpp"

namespace pdr::check::qvec {

using Q = mpq_class;
using QVec = std::array<Q, 3>;

inline QVec qdiff(const Point& p, const Point& q) {
  return {Q(p[0]) - Q(q[0]), Q(p[1]) - Q(q[1]), Q(p[2]) - Q(q[2])};
}
inline QVec qcross(const QVec& a, const QVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Q qdot(const QVec& a, const QVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace pdr::check::qvec
