// Encroachment and size tests by element id (paper §1.1, §2.1); see surface/encroach.hpp.
#include "surface/encroach.hpp"

#include <gmpxx.h>

#include "geom/encroach.hpp"
#include "geom/exact.hpp"
#include "geom/filter_kit.hpp"

namespace pdr::surface {

bool subsegment_encroached_by(const SurfaceMesh& m, std::uint32_t s, const Point& p) {
  const Subsegment& g = m.subsegment(s);
  return in_diametral_ball(m.point(g.v[0]), m.point(g.v[1]), p) != Sign::Negative;
}

bool subfacet_encroached_by(const SurfaceMesh& m, std::uint32_t t, const Point& p) {
  const Subfacet& f = m.subfacet(t);
  return in_equatorial_ball(m.point(f.v[0]), m.point(f.v[1]), m.point(f.v[2]), p) !=
         Sign::Negative;
}

bool length2_at_least(const Point& a, const Point& b, double d, double k) {
  const Filtered f = filter::length2_minus(a, b, d, k);
  if (f != Filtered::Unsure) return f == Filtered::Positive;
  return exact::squared_distance(a, b) >= mpq_class(k) * mpq_class(d) * mpq_class(d);
}

bool circumradius2_at_least(const Point& a, const Point& b, const Point& c, double d, double k) {
  const Filtered f = filter::circumradius2_minus(a, b, c, d, k);
  if (f != Filtered::Unsure) return f == Filtered::Positive;
  return exact::triangle_circumradius2(a, b, c) >= mpq_class(k) * mpq_class(d) * mpq_class(d);
}

bool subsegment_too_long(const SurfaceMesh& m, std::uint32_t s, double d) {
  const Subsegment& g = m.subsegment(s);
  return length2_at_least(m.point(g.v[0]), m.point(g.v[1]), d, 4);
}

bool subfacet_too_large(const SurfaceMesh& m, std::uint32_t t, double d) {
  const Subfacet& f = m.subfacet(t);
  return circumradius2_at_least(m.point(f.v[0]), m.point(f.v[1]), m.point(f.v[2]), d, 2);
}

}  // namespace pdr::surface
