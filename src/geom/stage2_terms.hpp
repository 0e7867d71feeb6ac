// Building blocks of stage 2 (stage2_orient.cpp, stage2_sphere.cpp): exact 2x2 and 3x3
// minors, lifts and orientation minors as expansions (expansion.hpp). Internal to
// pdr_geom (needs PDR_GEOM_FP_STRICT like expansion.hpp).
//
// Notation: xy(p, q) = p_i q_j - p_j q_i on coordinates (i, j), default (x, y);
// det3(p, q, r) = det of rows p, q, r = p_z xy(q,r) - q_z xy(p,r) + r_z xy(p,q) (expanded
// along z); orient2(p, q, r) = xy(p,q) + xy(q,r) + xy(r,p) = det[q-p, r-p] untranslated;
// orient3 from four untranslated det3 (stage2_orient.cpp). Results that are multiplied
// again are compressed first (the cost of a product is the product of the lengths).
#pragma once

#include "geom/expansion.hpp"

namespace pdr::stage2::terms {

using expansion::compressed;
using expansion::cross_difference;
using expansion::Expansion;
using expansion::product;

inline Expansion<4> xy(const double* p, const double* q, int i = 0, int j = 1) {
  return cross_difference(p[i], q[j], p[j], q[i]);
}

inline Expansion<24> det3(const double* p, const double* q, const double* r) {
  return (xy(q, r) * p[2] - xy(p, r) * q[2]) + xy(p, q) * r[2];
}

inline Expansion<12> orient2(const double* p, const double* q, const double* r, int i = 0,
                             int j = 1) {
  return (xy(p, q, i, j) + xy(q, r, i, j)) + xy(r, p, i, j);
}

inline Expansion<4> lift2(const double* p) {
  return compressed(product(p[0], p[0]) + product(p[1], p[1]));
}
inline Expansion<6> lift3(const double* p) {
  return compressed((product(p[0], p[0]) + product(p[1], p[1])) + product(p[2], p[2]));
}

// out[i] = p[i] - o[i] for i < n; false if any difference is not exact in double.
inline bool exact_differences(const double* p, const double* o, int n, double* out) {
  for (int i = 0; i < n; ++i) {
    double err;
    expansion::two_diff(p[i], o[i], out[i], err);
    if (err != 0) return false;
  }
  return true;
}

}  // namespace pdr::stage2::terms
