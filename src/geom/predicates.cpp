// Temporary definitions of predicates.hpp, forwarding to the GMP reference (exact.hpp),
// so that dependent code links while the adaptive predicates are written.
#include "geom/predicates.hpp"

#include "geom/exact.hpp"

namespace pdr {

Sign orient2d(const double* a, const double* b, const double* c) {
  return exact::orient2d(a, b, c);
}
Sign incircle(const double* a, const double* b, const double* c, const double* d) {
  return exact::incircle(a, b, c, d);
}
Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
  return exact::orient3d(a, b, c, d);
}
Sign insphere(const Point& a, const Point& b, const Point& c, const Point& d, const Point& e) {
  return exact::insphere(a, b, c, d, e);
}
Sign incircle3(const Point& a, const Point& b, const Point& c, const Point& d) {
  return exact::incircle3(a, b, c, d);
}
Sign incircle_sos(const double* a, const double* b, const double* c, const double* d) {
  return exact::incircle_sos(a, b, c, d);
}
Sign insphere_sos(const Point& a, const Point& b, const Point& c, const Point& d,
                  const Point& e) {
  return exact::insphere_sos(a, b, c, d, e);
}
Sign incircle3_sos(const Point& a, const Point& b, const Point& c, const Point& d) {
  return exact::incircle3_sos(a, b, c, d);
}

}  // namespace pdr
