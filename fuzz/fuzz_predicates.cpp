// Fuzz target: every adaptive predicate (geom/predicates.hpp) must agree with the GMP
// reference (geom/exact.hpp), SoS variants included, for any finite coordinates. The first
// byte picks how the 15 coordinates are drawn:
//   0, 1  from a small alphabet (integers, halves, tiny offsets, ulp neighbours), so that
//         exactly and nearly degenerate configurations are frequent;
//   2     the same configurations scaled by 2^k, k from the next byte pair in
//         [-1074, 1023] (tiny and huge degenerate inputs, where products underflow or
//         overflow);
//   3     raw doubles from the input's bytes (any finite value; NaN and inf map to 0).
// Property: tests/geom (same laws).
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>

#include "fuzz_target.hpp"
#include "geom/exact.hpp"
#include "geom/predicates.hpp"

namespace {

double finite_or_zero(double x) { return std::isfinite(x) ? x : 0.0; }

double raw_double(const std::uint8_t* b) {
  double x = 0;
  std::memcpy(&x, b, sizeof x);
  return finite_or_zero(x);
}

double coordinate(std::uint8_t b) {
  static const double base[] = {0.0, 1.0, -1.0, 2.0, 3.0, 0.5, 1e-3, 7.0};
  const double x = base[b & 7] * ((b & 8) ? 1024.0 : 1.0);
  if (x == 0) return (b >> 4) % 4 == 0 ? 0.0 : 0x1p-60 * (b >> 4);
  switch (b >> 4) {
    case 1: return std::nextafter(x, 1e300);
    case 2: return std::nextafter(x, -1e300);
    case 3: return x + 0x1p-30;
    default: return x;
  }
}

const pdr::Point* g_points = nullptr;  // the current input, for the failure report

void agree(pdr::Sign fast, pdr::Sign exact, const char* what) {
  if (fast != exact) {
    std::fprintf(stderr, "fuzz_predicates: %s gives %d, the GMP reference %d, on\n", what,
                 pdr::to_int(fast), pdr::to_int(exact));
    for (int i = 0; i < 5; ++i)
      std::fprintf(stderr, "  (%a, %a, %a)\n", g_points[i][0], g_points[i][1], g_points[i][2]);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 18) return 0;
  const int mode = data[0] % 4;
  const int scale = static_cast<int>((data[1] | (data[2] << 8)) % 2098) - 1074;
  data += 3;
  size -= 3;
  if (mode == 3 && size < 15 * 8) return 0;
  pdr::Point p[5];
  for (int i = 0; i < 5; ++i)
    for (int k = 0; k < 3; ++k) {
      const int j = 3 * i + k;
      p[i][k] = mode == 3 ? raw_double(data + 8 * j)
                : mode == 2 ? finite_or_zero(std::ldexp(coordinate(data[j]), scale))
                            : coordinate(data[j]);
    }
  g_points = p;
  namespace ex = pdr::exact;
  agree(pdr::orient2d(p[0].data(), p[1].data(), p[2].data()),
        ex::orient2d(p[0].data(), p[1].data(), p[2].data()), "orient2d");
  agree(pdr::incircle(p[0].data(), p[1].data(), p[2].data(), p[3].data()),
        ex::incircle(p[0].data(), p[1].data(), p[2].data(), p[3].data()), "incircle");
  agree(pdr::orient3d(p[0], p[1], p[2], p[3]), ex::orient3d(p[0], p[1], p[2], p[3]),
        "orient3d");
  agree(pdr::insphere(p[0], p[1], p[2], p[3], p[4]),
        ex::insphere(p[0], p[1], p[2], p[3], p[4]), "insphere");
  if (ex::orient3d(p[0], p[1], p[2], p[3]) != pdr::Sign::Zero &&
      p[4] != p[0] && p[4] != p[1] && p[4] != p[2] && p[4] != p[3])
    agree(pdr::insphere_sos(p[0], p[1], p[2], p[3], p[4]),
          ex::insphere_sos(p[0], p[1], p[2], p[3], p[4]), "insphere_sos");
  // Coplanar inputs for incircle3: project the fourth point onto the plane z = p0.z.
  pdr::Point q[4] = {p[0], p[1], p[2], p[3]};
  for (auto& x : q) x[2] = p[0][2];
  agree(pdr::incircle3(q[0], q[1], q[2], q[3]), ex::incircle3(q[0], q[1], q[2], q[3]),
        "incircle3");
  if (ex::orient2d(q[0].data(), q[1].data(), q[2].data()) != pdr::Sign::Zero &&
      q[3] != q[0] && q[3] != q[1] && q[3] != q[2])
    agree(pdr::incircle3_sos(q[0], q[1], q[2], q[3]), ex::incircle3_sos(q[0], q[1], q[2], q[3]),
          "incircle3_sos");
  return 0;
}
