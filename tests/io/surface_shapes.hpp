// Closed surfaces for the surface-reader tests, as points and faces (0-based, outward), and
// their OFF text: a box of 12 triangles and of 6 squares, a box of 24 squares (a 2x2 grid on
// every side, so each side has an inner vertex and edge midpoints), and a step (a box with
// a smaller box standing on its top, so the top is a square with a square hole).
#pragma once

#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "geom/point.hpp"

namespace pdr::io::test {

struct Shape {
  std::vector<Point> points;
  std::vector<std::vector<std::uint32_t>> faces;
};

inline std::string off_text(const Shape& s) {
  std::ostringstream o;
  o.precision(17);
  o << "OFF\n" << s.points.size() << ' ' << s.faces.size() << " 0\n";
  for (const Point& p : s.points) o << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& f : s.faces) {
    o << f.size();
    for (std::uint32_t v : f) o << ' ' << v;
    o << '\n';
  }
  return o.str();
}

// The shape as Wavefront OBJ, 1-based, with `v/vt/vn` corners and the statements exporters
// add around them.
inline std::string obj_text(const Shape& s) {
  std::ostringstream o;
  o.precision(17);
  o << "# by hand\nmtllib m.mtl\no Shape\n";
  for (const Point& p : s.points) o << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  o << "vt 0 0\nvn 0 0 1\nusemtl M\ns off\ng side\n";
  for (const auto& f : s.faces) {
    o << 'f';
    for (std::uint32_t v : f) o << ' ' << v + 1 << "/1/1";
    o << '\n';
  }
  o << "l 1 2\n";
  return o.str();
}

// The box [0,a]x[0,b]x[z0,z1] as 6 outward squares, corners numbered from `base`.
inline void add_box_squares(Shape& s, double x0, double y0, double x1, double y1, double z0,
                            double z1) {
  const auto b = static_cast<std::uint32_t>(s.points.size());
  for (int k = 0; k < 8; ++k)
    s.points.push_back({k & 1 ? x1 : x0, k & 2 ? y1 : y0, k & 4 ? z1 : z0});
  const std::uint32_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                 {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : q) s.faces.push_back({b + f[0], b + f[1], b + f[2], b + f[3]});
}

inline Shape box_squares() {
  Shape s;
  add_box_squares(s, 0, 0, 1, 1, 0, 1);
  return s;
}

// Each square split along a diagonal.
inline Shape box_triangles() {
  const Shape q = box_squares();
  Shape s{q.points, {}};
  for (const auto& f : q.faces) {
    s.faces.push_back({f[0], f[1], f[2]});
    s.faces.push_back({f[0], f[2], f[3]});
  }
  return s;
}

// Every side of the unit box as a 2x2 grid of squares: 26 points, 24 faces.
inline Shape box_grid() {
  Shape s;
  std::vector<std::int32_t> id(27, -1);
  auto vertex = [&](int i, int j, int k) {
    std::int32_t& v = id[static_cast<std::size_t>(i + 3 * j + 9 * k)];
    if (v < 0) {
      v = static_cast<std::int32_t>(s.points.size());
      s.points.push_back({i * 0.5, j * 0.5, k * 0.5});
    }
    return static_cast<std::uint32_t>(v);
  };
  // Side `axis` at `level` (0 or 2); (u, v) run over the other two axes, outward order.
  for (int axis = 0; axis < 3; ++axis)
    for (int level : {0, 2})
      for (int u = 0; u < 2; ++u)
        for (int v = 0; v < 2; ++v) {
          std::array<int, 3> c[4];
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            c[k][axis] = level;
            c[k][(axis + 1) % 3] = u + du[k];
            c[k][(axis + 2) % 3] = v + dv[k];
          }
          std::vector<std::uint32_t> f;
          for (int k = 0; k < 4; ++k) f.push_back(vertex(c[k][0], c[k][1], c[k][2]));
          if (level == 0) std::swap(f[1], f[3]);
          s.faces.push_back(f);
        }
  return s;
}

// The box [0,2]^2 x [0,1] with the box [0.5,1.5]^2 x [1,2] on top, all triangles: the big
// top is the ring between the two squares (8 triangles), so merged it is a square with a
// square hole. 16 points; 2 + 8 + 8 + 8 + 2 = 28 triangles.
inline Shape step() {
  Shape s;
  for (int k = 0; k < 4; ++k) {  // 0-3 bottom, 4-7 big top, counter-clockwise from above
    const double x = (k == 1 || k == 2) ? 2 : 0, y = k >= 2 ? 2 : 0;
    s.points.push_back({x, y, 0});
  }
  for (int k = 0; k < 4; ++k) s.points.push_back({s.points[k][0], s.points[k][1], 1});
  for (int k = 0; k < 4; ++k)  // 8-11 small bottom (z = 1), 12-15 small top (z = 2)
    s.points.push_back({0.5 + s.points[k][0] / 2, 0.5 + s.points[k][1] / 2, 1});
  for (int k = 0; k < 4; ++k) s.points.push_back({s.points[8 + k][0], s.points[8 + k][1], 2});
  auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    s.faces.push_back({a, b, c});
    s.faces.push_back({a, c, d});
  };
  quad(0, 3, 2, 1);  // bottom, facing -z
  for (std::uint32_t k = 0; k < 4; ++k) {
    const std::uint32_t n = (k + 1) % 4;
    quad(k, n, 4 + n, 4 + k);             // big sides
    quad(4 + k, 4 + n, 8 + n, 8 + k);     // the ring
    quad(8 + k, 8 + n, 12 + n, 12 + k);   // small sides
  }
  quad(12, 13, 14, 15);  // small top
  return s;
}

}  // namespace pdr::io::test
