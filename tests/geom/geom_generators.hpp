// Input generators for the geometry tests: random doubles over wide exponent ranges,
// near-degenerate configurations (points on a plane, sphere or circle, computed in double
// and then moved by a few ulps with nextafter), and exactly degenerate ones (integer grids,
// cospherical and cocircular lattice points, coplanar and collinear sets), scaled by powers
// of two to the edges of the documented input range (filter.hpp).
//
// Bulk differential tests draw from `Rng` (a seeded mt19937_64: every failure names its
// seed); RapidCheck properties draw a seed with rc_seed() and build a case from it (the
// failure report then names the seed to replay).
#pragma once

#include <rapidcheck.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "geom/point.hpp"

namespace pdr::geomgen {

// Range exponents E of filter.hpp: coordinates 0 or of magnitude in [2^-E, 2^E].
inline constexpr int kOrient2dRange = 450, kOrient3dRange = 270;
inline constexpr int kIncircleRange = 190, kInsphereRange = 130;

// Integer points on spheres |p|^2 = 9 and |p|^2 = 25 (all sign and axis permutations).
inline constexpr std::array<std::array<int, 3>, 7> kSphere9Seeds = {
    {{1, 2, 2}, {2, 1, 2}, {2, 2, 1}, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}, {1, 2, 2}}};
inline constexpr std::array<std::array<int, 3>, 9> kSphere25Seeds = {
    {{3, 4, 0}, {4, 3, 0}, {3, 0, 4}, {4, 0, 3}, {0, 3, 4}, {0, 4, 3}, {5, 0, 0}, {0, 5, 0},
     {0, 0, 5}}};
// Integer points on the circle i^2 + j^2 = 25.
inline constexpr std::array<std::array<int, 2>, 12> kCircle25 = {
    {{5, 0}, {-5, 0}, {0, 5}, {0, -5}, {3, 4}, {-3, 4}, {3, -4}, {-3, -4}, {4, 3}, {-4, 3},
     {4, -3}, {-4, -3}}};
// Orthogonal integer vectors of equal length spanning tilted planes: |U| = |V|, U.V = 0.
inline constexpr std::array<std::array<std::array<int, 3>, 2>, 3> kPlaneFrames = {
    {{{{1, 2, 2}, {2, 1, -2}}}, {{{2, 3, 6}, {3, -6, 2}}}, {{{1, 0, 0}, {0, 1, 0}}}}};

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : eng_(seed) {}

  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(eng_); }
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(eng_);
  }
  bool coin() { return integer(0, 1) == 1; }

  // +-m 2^(e-52), m a random 53-bit significand, e in [lo, hi]: a value in [2^e, 2^(e+1)).
  // One time in ten 0, one in ten a small integer.
  double wide(int lo, int hi) {
    const int kind = integer(0, 9);
    if (kind == 0) return 0.0;
    if (kind == 1) return integer(-8, 8);
    const auto m = std::uniform_int_distribution<std::uint64_t>(std::uint64_t{1} << 52,
                                                                (std::uint64_t{1} << 53) - 1)(eng_);
    const double x = std::ldexp(static_cast<double>(m), integer(lo, hi) - 52);
    return coin() ? -x : x;
  }
  Point wide_point(int lo, int hi) { return {wide(lo, hi), wide(lo, hi), wide(lo, hi)}; }
  Point unit_point() { return {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)}; }
  Point grid_point(int r) {
    return {double(integer(-r, r)), double(integer(-r, r)), double(integer(-r, r))};
  }

  // x moved by up to `ulps` ulps in a random direction.
  double nudge(double x, int ulps) {
    const int k = integer(-ulps, ulps);
    const double to = k < 0 ? -HUGE_VAL : HUGE_VAL;
    for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, to);
    return x;
  }
  Point nudge(Point p, int ulps) {
    for (double& x : p) x = nudge(x, ulps);
    return p;
  }

  // A power of two 2^k, k in [-limit, limit].
  double scale(int limit) { return std::ldexp(1.0, integer(-limit, limit)); }

  std::mt19937_64& engine() { return eng_; }

 private:
  std::mt19937_64 eng_;
};

// x rounded to a multiple of 2^(-E-52) and clamped to [-2^E, 2^E]: inside the documented
// range (filter.hpp) whatever arithmetic produced x. Exact for values already inside.
inline double fit(double x, int E) {
  const double lim = std::ldexp(1.0, E);
  x = std::fmax(-lim, std::fmin(lim, x));
  return std::ldexp(std::nearbyint(std::ldexp(x, E + 52)), -E - 52);
}
template <std::size_t N>
std::array<Point, N> fit(std::array<Point, N> p, int E) {
  for (auto& q : p)
    for (double& x : q) x = fit(x, E);
  return p;
}

// A random point of an integer sphere (|p|^2 = 9 or 25), signs and order random.
inline Point lattice_sphere_point(Rng& r, bool big) {
  const auto& s = big ? kSphere25Seeds[r.integer(0, 8)] : kSphere9Seeds[r.integer(0, 6)];
  Point p;
  for (int i = 0; i < 3; ++i) p[i] = r.coin() ? s[i] : -s[i];
  return p;
}

// The kinds of test input. Each configuration generator below understands all of them.
enum class Kind { Wide, Unit, Clustered, NearDegenerate, Grid, Lattice, Repeated, Count };
inline constexpr int kKinds = static_cast<int>(Kind::Count);

// N points in 3D for orient3d / insphere, within range exponent E, of the given kind.
// NearDegenerate: the last point near the plane of the first three (N = 4) or near the
// sphere of the first four (N = 5); Lattice: points of one integer sphere, shifted by an
// integer center, all scaled by one power of two.
template <std::size_t N>
std::array<Point, N> space_case(Rng& r, Kind kind, int E) {
  std::array<Point, N> p;
  const double s = r.scale(E - 8);
  switch (kind) {
    case Kind::Wide:
      for (auto& q : p) q = r.wide_point(-E, E - 1);
      break;
    case Kind::Unit:
      for (auto& q : p) q = r.unit_point();
      break;
    case Kind::Clustered: {
      const Point base = r.unit_point();
      const int e = r.integer(1, 40);
      for (auto& q : p) {
        const Point o = r.unit_point();
        for (int i = 0; i < 3; ++i) q[i] = (base[i] + std::ldexp(o[i], -e)) * s;
      }
      break;
    }
    case Kind::NearDegenerate: {
      const Point c = r.unit_point();
      const double rad = r.uniform(0.1, 2);
      for (std::size_t k = 0; k < N; ++k) {
        Point d = r.unit_point();
        const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int i = 0; i < 3; ++i) p[k][i] = (c[i] + rad * d[i] / len) * s;
      }
      if constexpr (N == 4) {  // on the plane of a, b, c instead
        const double t = r.uniform(-2, 2), u = r.uniform(-2, 2);
        for (int i = 0; i < 3; ++i)
          p[3][i] = p[0][i] + t * (p[1][i] - p[0][i]) + u * (p[2][i] - p[0][i]);
      }
      p[N - 1] = r.nudge(p[N - 1], 3);
      break;
    }
    case Kind::Grid:
    case Kind::Lattice: {
      const Point c = r.grid_point(3);
      const bool big = r.coin();
      for (auto& q : p) {
        const Point g = kind == Kind::Grid ? r.grid_point(2) : lattice_sphere_point(r, big);
        for (int i = 0; i < 3; ++i) q[i] = (g[i] + c[i]) * s;
      }
      break;
    }
    case Kind::Repeated:
    default:
      for (auto& q : p) q = r.coin() ? r.unit_point() : r.grid_point(1);
      p[r.integer(0, N - 1)] = p[r.integer(0, N - 1)];
      break;
  }
  return fit(p, E);
}

using Point2 = std::array<double, 2>;

// N planar points for orient2d / incircle. NearDegenerate: the last point a few ulps off
// the circle of the others; Grid: integer points; Lattice: points of one integer circle
// (kCircle25), shifted and scaled by a power of two.
template <std::size_t N>
std::array<Point2, N> flat_case(Rng& r, Kind kind, int E) {
  std::array<Point2, N> p;
  const double s = r.scale(E - 8);
  if (kind == Kind::NearDegenerate && N == 3) {  // the last point near the line of two
    for (std::size_t k = 0; k < 2; ++k) p[k] = {r.uniform(-1, 1) * s, r.uniform(-1, 1) * s};
    const double t = r.uniform(-2, 2);
    for (int i = 0; i < 2; ++i) p[2][i] = r.nudge(p[0][i] + t * (p[1][i] - p[0][i]), 3);
  } else if (kind == Kind::NearDegenerate) {  // the last point near the circle of the others
    const double cx = r.uniform(-1, 1), cy = r.uniform(-1, 1), rad = r.uniform(0.1, 2);
    for (auto& q : p) {
      const double t = r.uniform(0, 6.283185307179586);
      q = {(cx + rad * std::cos(t)) * s, (cy + rad * std::sin(t)) * s};
    }
    p[N - 1] = {r.nudge(p[N - 1][0], 3), r.nudge(p[N - 1][1], 3)};
  } else if (kind == Kind::Lattice) {
    const int cx = r.integer(-4, 4), cy = r.integer(-4, 4);
    for (auto& q : p) {
      const auto& ij = kCircle25[r.integer(0, 11)];
      q = {(cx + ij[0]) * s, (cy + ij[1]) * s};
    }
  } else {
    const std::array<Point, N> sp = space_case<N>(r, kind, E);
    for (std::size_t k = 0; k < N; ++k) p[k] = {sp[k][0], sp[k][1]};
  }
  for (auto& q : p) q = {fit(q[0], E), fit(q[1], E)};
  return p;
}

// N coplanar points (exactly) for incircle3. Grid and Lattice kinds: integer points
// o + iU + jV of a tilted plane (kPlaneFrames), Lattice ones on one circle of it. The
// other kinds: flat_case placed on a coordinate plane at a random level, or on x = y
// (NearDegenerate there: near a circle of that tilted plane).
template <std::size_t N>
std::array<Point, N> plane_case(Rng& r, Kind kind, int E) {
  std::array<Point, N> p;
  if (kind == Kind::Grid || kind == Kind::Lattice) {
    const double s = r.scale(E - 8);
    const auto& f = kPlaneFrames[r.integer(0, 2)];
    const Point o = r.grid_point(4);
    for (auto& q : p) {
      int i = r.integer(-3, 3), j = r.integer(-3, 3);
      if (kind == Kind::Lattice) {
        const auto& ij = kCircle25[r.integer(0, 11)];
        i = ij[0];
        j = ij[1];
      }
      for (int k = 0; k < 3; ++k) q[k] = (o[k] + i * f[0][k] + j * f[1][k]) * s;
    }
    return p;
  }
  std::array<Point2, N> flat = flat_case<N>(r, kind, E);
  const double level = r.coin() ? 0.0 : fit(r.wide(-E / 2, E / 2 - 1), E);
  const int plane = r.integer(0, 3);
  if (plane == 3 && kind == Kind::NearDegenerate) {
    // On x = y, |(s, s, t)|^2 = 2 s^2 + t^2: a circle of the plane is an ellipse in (s, t).
    const double cs = r.uniform(-1, 1), ct = r.uniform(-1, 1), rad = r.uniform(0.1, 2);
    const double sc = r.scale(E - 8);
    for (auto& q : flat) {
      const double t = r.uniform(0, 6.283185307179586);
      q = {fit((cs + rad * std::cos(t) / std::sqrt(2.0)) * sc, E),
           fit((ct + rad * std::sin(t)) * sc, E)};
    }
    flat[N - 1] = {fit(r.nudge(flat[N - 1][0], 3), E), fit(r.nudge(flat[N - 1][1], 3), E)};
  }
  for (std::size_t k = 0; k < N; ++k) {
    const double x = flat[k][0], y = flat[k][1];
    switch (plane) {
      case 0: p[k] = {x, y, level}; break;
      case 1: p[k] = {level, x, y}; break;
      case 2: p[k] = {y, level, x}; break;
      default: p[k] = {x, x, y}; break;  // the plane x = y
    }
  }
  return p;
}

// A full 64-bit seed for Rng inside a RapidCheck property (fixed size: RapidCheck would
// otherwise draw few distinct small seeds early in a run; shrinking a seed is useless).
inline std::uint64_t rc_seed() {
  return *rc::gen::noShrink(rc::gen::resize(100, rc::gen::arbitrary<std::uint64_t>()));
}

// RapidCheck generator of wide-range doubles, as Rng::wide.
inline rc::Gen<double> wide_double(int lo, int hi) {
  return rc::gen::exec([lo, hi] {
    Rng r(rc_seed());
    return r.wide(lo, hi);
  });
}

}  // namespace pdr::geomgen
