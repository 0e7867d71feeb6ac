// Encroachment and size tests on a SurfaceMesh (paper §1.1 "encroached"; §2.1 properties
// 2 and 3; Lemma 1 invariants 2 and 3), by element id, all exact.
//
//   subsegment_encroached_by  p in the closed diametral ball of subsegment s
//                             (geom/encroach.hpp: (p - a).(p - b) <= 0);
//   subfacet_encroached_by    p in the closed equatorial ball of subfacet t;
//   longer_than               |ab| >= L, i.e. |ab|^2 >= L^2 (L = 2d for §2.1 step 1);
//   circumradius_at_least     R(abc) >= r, i.e. |u|^2 |v|^2 |b-c|^2 >= 4 r^2 |u x v|^2
//                             (u = b - a, v = c - a; r = d√2 for §2.1 step 2).
// The bounds L and r are given as a double d and an exact factor: L^2 = k d^2 with k = 4
// ("2d"), r^2 = k d^2 with k = 2 ("d√2"), so no square root is rounded. Each test is a
// floating-point filter of geom/filter_kit.hpp (bounds derived there: 7u and 19u) and GMP
// rationals when unsure or out of the filter's range (every difference and d 0 or in
// [2^-150, 2^150]).
#pragma once

#include <cstdint>

#include "geom/point.hpp"
#include "surface/surface_mesh.hpp"

namespace pdr::surface {

bool subsegment_encroached_by(const SurfaceMesh& m, std::uint32_t s, const Point& p);
bool subfacet_encroached_by(const SurfaceMesh& m, std::uint32_t t, const Point& p);

// |b - a|^2 >= k d^2 (k > 0 a small integer: exact in double).
bool length2_at_least(const Point& a, const Point& b, double d, double k);
// circumradius(abc)^2 >= k d^2; precondition: a, b, c not collinear.
bool circumradius2_at_least(const Point& a, const Point& b, const Point& c, double d, double k);

// §2.1 property 2: the subsegment is at least 2d long (must be split).
bool subsegment_too_long(const SurfaceMesh& m, std::uint32_t s, double d);
// §2.1 property 3: the subfacet's circumradius is at least d√2 (must be refined).
bool subfacet_too_large(const SurfaceMesh& m, std::uint32_t t, double d);

}  // namespace pdr::surface
