// Stage 3 of the predicates: symbolic perturbation (SoS) of the lifted coordinate.
//
// Devillers & Teillaud (2011), "Perturbations for Delaunay and weighted Delaunay 3D
// triangulations": raise the lift |p|^2 of every point of a call by an infinitesimal
// eps(p), ranked by the lexicographic order of the points (sos_order.hpp: the lex-largest
// point dominates). The lifted determinant is affine in its lift column, so the perturbed
// sign is that of the exact predicate, else that of the first nonzero cofactor (an exact
// orientation of the other points) in dominance order; the cofactor table is derived in
// predicates.hpp. exact.cpp computes the same signs from the definition (cofactors as
// determinants), and tests/geom checks the two agree.
//
// Invariants: equals the unperturbed predicate when that is nonzero; never Zero when the
// orientation of the first four (three) points is nonzero (its cofactor, the last point's,
// is then reached at the latest); the ranks depend on coordinates only.
#include <array>

#include "geom/predicates.hpp"
#include "geom/sos_order.hpp"
#include "geom/stage2.hpp"

namespace pdr {

Sign incircle_sos(const double* a, const double* b, const double* c, const double* d) {
  const Sign s = incircle(a, b, c, d);
  if (s != Sign::Zero) return s;
  for (const int i : sos::dominance_order2<4>({a, b, c, d})) {
    Sign t = Sign::Zero;
    switch (i) {
      case 0: t = orient2d(b, c, d); break;
      case 1: t = -orient2d(a, c, d); break;
      case 2: t = orient2d(a, b, d); break;
      default: t = -orient2d(a, b, c); break;
    }
    if (t != Sign::Zero) return t;
  }
  return Sign::Zero;
}

Sign insphere_sos(const Point& a, const Point& b, const Point& c, const Point& d,
                  const Point& e) {
  const Sign s = insphere(a, b, c, d, e);
  if (s != Sign::Zero) return s;
  for (const int i : sos::dominance_order<5>({&a, &b, &c, &d, &e})) {
    Sign t = Sign::Zero;
    switch (i) {
      case 0: t = -orient3d(b, c, d, e); break;
      case 1: t = orient3d(a, c, d, e); break;
      case 2: t = -orient3d(a, b, d, e); break;
      case 3: t = orient3d(a, b, c, e); break;
      default: t = -orient3d(a, b, c, d); break;
    }
    if (t != Sign::Zero) return t;
  }
  return Sign::Zero;
}

Sign incircle3_sos(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Sign s = incircle3(a, b, c, d);
  if (s != Sign::Zero) return s;
  const int k = stage2::plane_axis(a, b, c);
  if (k < 0) return Sign::Zero;  // a, b, c collinear: no circle
  const Sign abc = stage2::orient2d_projected(k, a, b, c);
  for (const int i : sos::dominance_order<4>({&a, &b, &c, &d})) {
    Sign t = Sign::Zero;
    switch (i) {
      case 0: t = stage2::orient2d_projected(k, b, c, d); break;
      case 1: t = -stage2::orient2d_projected(k, a, c, d); break;
      case 2: t = stage2::orient2d_projected(k, a, b, d); break;
      default: t = -abc; break;
    }
    if (t != Sign::Zero) return t * abc;
  }
  return Sign::Zero;
}

}  // namespace pdr
