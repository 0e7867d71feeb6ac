// Exact geometric predicates (adaptive precision, after Shewchuk's method; written here).
//
// Every function returns the exact sign of a polynomial in the input doubles, as if the
// doubles were rationals. Stage 1 is a floating-point filter with a proven error bound
// (filter.hpp); stage 2 is exact expansion arithmetic (expansion.hpp); the *_sos variants
// add stage 3, symbolic perturbation (sos.cpp). Stage 2 and 3 live in pdr_geom, compiled
// with -ffp-contract=off; the inline filters stay correct wherever they are inlined.
//
// Conventions and laws (each is a RapidCheck property in tests/geom):
//   orient2d(a,b,c)     = sign det[b-a, c-a]              > 0: a,b,c counter-clockwise.
//   orient3d(a,b,c,d)   = sign det[b-a, c-a, d-a]         > 0: d on the side of plane abc
//                         that (b-a)x(c-a) points to; a tet (a,b,c,d) is *positive* then.
//   incircle(a,b,c,d)   > 0: d strictly inside the circle abc when orient2d(a,b,c) > 0.
//   insphere(a,b,c,d,e) > 0: e strictly inside the sphere abcd when orient3d(a,b,c,d) > 0.
//   Swapping two arguments of orient2d/orient3d/incircle (first three) /insphere (first
//   four) negates the result; an even permutation keeps it. incircle and insphere change
//   sign with the orientation of their first three/four points.
//   incircle3(a,b,c,d): for coplanar a,b,c,d (precondition, unchecked beyond debug), the
//   sign of "d strictly inside the circle through a,b,c"; orientation-free (the plane has
//   no preferred side). Positive = inside, Negative = outside, Zero = on the circle, and
//   Zero if a,b,c are collinear. Non-coplanar input gives an unspecified (deterministic) sign.
//
// Symbolic perturbation (SoS). The lifted coordinate |p|^2 of the point of lexicographic
// rank i (rank by lex_less over the points of one call) is raised by eps^(2^i)-style
// infinitesimals in the manner of Devillers & Teillaud (2011), "Perturbations for Delaunay
// and weighted Delaunay 3D triangulations". Consequences:
//   insphere_sos(a,b,c,d,e) never returns Zero when orient3d(a,b,c,d) != 0 and e differs
//   from a,b,c,d; it equals insphere whenever insphere != 0.
//   incircle3_sos(a,b,c,d) never returns Zero when a,b,c are not collinear and d differs
//   from them; it equals incircle3 whenever that is nonzero, and it is the restriction of
//   insphere_sos to the plane, so a facet triangulation and the tetrahedralization agree.
//   incircle_sos is the same for planar (2D) input.
// Since the ranks come from coordinates alone, the perturbed Delaunay tetrahedralization of
// a point set is unique: every insertion order, rank count and checker agree on it.
// Dominance order (sos_order.hpp): the lex-largest point's infinitesimal dominates, so the
// sign is that of the unperturbed determinant, else of the cofactor of the lex-largest
// point, and so on. The cofactors, with p taken in that order, are (o = orient3d/orient2d,
// and for incircle3 o2 = orient2d in the plane, any orientation of the plane):
//   insphere_sos(a,b,c,d,e): a: -o(b,c,d,e)  b: +o(a,c,d,e)  c: -o(a,b,d,e)  d: +o(a,b,c,e)
//                            e: -o(a,b,c,d)  (a raised lift moves a point outward)
//   incircle_sos(a,b,c,d):   a: +o(b,c,d)  b: -o(a,c,d)  c: +o(a,b,d)  d: -o(a,b,c)
//   incircle3_sos(a,b,c,d):  the incircle_sos cofactors times o2(a,b,c).
//
// Input range: the adaptive predicates are exact when every coordinate is an integer
// multiple of 2^(-E-52) of magnitude at most 2^E (e.g. 0, or any double with magnitude in
// [2^-E, 2^E]), E = 450 (orient2d), 270 (orient3d), 190 (incircle, incircle3 and their
// _sos), 130 (insphere, insphere_sos): about 1e+-135, 1e+-81, 1e+-57, 1e+-39. Beyond it
// the filter's answer is not used (a product may underflow: see below) and stage 2 hands
// the input to the GMP reference, exact.hpp, which has no range limit (stage2_range.hpp):
// exact for all finite doubles (fuzz_predicates checks it). No inf/NaN.
//
// Speed: the filter is inline (filter.hpp, no allocation, proven bound valid even under
// FMA contraction); stage 2 is out of line in pdr_geom (stage2.hpp, stack arrays only).
#pragma once

#include "geom/filter.hpp"
#include "geom/point.hpp"
#include "geom/stage2.hpp"
#include "geom/stage2_range.hpp"

namespace pdr {

// Each predicate trusts its filter only when every coordinate is in the filter's range
// (0 or magnitude in [2^-E, 2^E], stage2_range.hpp): outside it a product may underflow to
// zero or a lift overflow, and neither error is covered by the filter's relative bound (a
// zero permanent may then hide a nonzero determinant, and a small term lost to underflow
// may be the one that decides the sign), so stage 2 (the GMP reference there) decides. The
// range test is a few compares per coordinate, on well-predicted branches.
inline Sign orient2d(const double* a, const double* b, const double* c) {
  const Filtered f = filter::orient2d(a, b, c);
  if (f != Filtered::Unsure && stage2::in_range<450>({a, b, c}, 2)) [[likely]]
    return static_cast<Sign>(f);
  return stage2::orient2d(a, b, c);
}

inline Sign incircle(const double* a, const double* b, const double* c, const double* d) {
  const Filtered f = filter::incircle(a, b, c, d);
  if (f != Filtered::Unsure && stage2::in_range<190>({a, b, c, d}, 2)) [[likely]]
    return static_cast<Sign>(f);
  return stage2::incircle(a, b, c, d);
}

inline Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Filtered f = filter::orient3d(a.data(), b.data(), c.data(), d.data());
  if (f != Filtered::Unsure && stage2::in_range<270>({a.data(), b.data(), c.data(), d.data()}, 3)) [[likely]]
    return static_cast<Sign>(f);
  return stage2::orient3d(a, b, c, d);
}

inline Sign insphere(const Point& a, const Point& b, const Point& c, const Point& d,
                     const Point& e) {
  const Filtered f = filter::insphere(a.data(), b.data(), c.data(), d.data(), e.data());
  if (f != Filtered::Unsure && stage2::in_range<130>({a.data(), b.data(), c.data(), d.data(), e.data()}, 3)) [[likely]]
    return static_cast<Sign>(f);
  return stage2::insphere(a, b, c, d, e);
}

// Precondition: a, b, c, d coplanar. Zero if a, b, c are collinear.
inline Sign incircle3(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Filtered f = filter::incircle3(a.data(), b.data(), c.data(), d.data());
  if (f != Filtered::Unsure && stage2::in_range<190>({a.data(), b.data(), c.data(), d.data()}, 3)) [[likely]]
    return static_cast<Sign>(f);
  return stage2::incircle3(a, b, c, d);
}

// Symbolic perturbation (sos.cpp). Zero only when the unperturbed orientation of the first
// three (2D) / four (3D) points is zero, or for incircle3_sos when a, b, c are collinear.
Sign incircle_sos(const double* a, const double* b, const double* c, const double* d);
Sign insphere_sos(const Point& a, const Point& b, const Point& c, const Point& d,
                  const Point& e);
Sign incircle3_sos(const Point& a, const Point& b, const Point& c, const Point& d);

}  // namespace pdr
