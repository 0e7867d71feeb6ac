// Surface domains (io/surface.hpp): exactly coplanar faces merge into facets (a box of 12
// triangles is the box of 6 squares; a 2x2 grid per side loses its inner vertices; a ring
// of triangles becomes a facet with a hole point inside the hole), duplicate vertices
// merge, and every defect named in surface.hpp is an InputError naming the face and line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "geom/predicates.hpp"
#include "io/error.hpp"
#include "io/mesh_io.hpp"
#include "io/surface.hpp"
#include "io/surface_topology.hpp"
#include "io_test_util.hpp"
#include "surface_shapes.hpp"

namespace pdr::io::test {
namespace {

// Each facet as the set of its polygons' coordinates: independent of numbering.
std::multiset<std::set<Point>> facet_sets(const Plc& plc) {
  std::multiset<std::set<Point>> out;
  for (const PlcFacet& f : plc.facets) {
    std::set<Point> s;
    for (const auto& poly : f.polygons)
      for (std::uint32_t v : poly) s.insert(plc.points[v]);
    out.insert(s);
  }
  return out;
}

Plc read_off_text(const ScratchDir& dir, const std::string& text) {
  write_text(dir / "s.off", text);
  return read_domain(dir / "s.off");
}

// The message of the InputError that reading `text` as OFF throws ("" when none).
std::string off_error(const std::string& text) {
  ScratchDir dir;
  try {
    (void)read_off_text(dir, text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Surface, TwelveTrianglesAreTheBoxOfSixSquares) {
  ScratchDir dir;
  const Plc tri = read_off_text(dir, off_text(box_triangles()));
  const Plc quad = read_off_text(dir, off_text(box_squares()));
  EXPECT_EQ(tri.facets.size(), 6u);
  EXPECT_EQ(quad.facets.size(), 6u);
  EXPECT_EQ(tri.points.size(), 8u);
  EXPECT_EQ(facet_sets(tri), facet_sets(quad));
  for (const PlcFacet& f : tri.facets) {
    ASSERT_EQ(f.polygons.size(), 1u);
    EXPECT_EQ(f.polygons[0].size(), 4u);
    EXPECT_TRUE(f.holes.empty());
  }
}

TEST(Surface, GridSidesLoseTheirInnerVertices) {
  ScratchDir dir;
  const Shape g = box_grid();
  ASSERT_EQ(g.points.size(), 26u);
  const Plc plc = read_off_text(dir, off_text(g));
  EXPECT_EQ(plc.facets.size(), 6u);
  EXPECT_EQ(plc.points.size(), 20u);  // 8 corners + 12 edge midpoints
  for (const PlcFacet& f : plc.facets) {
    ASSERT_EQ(f.polygons.size(), 1u);
    EXPECT_EQ(f.polygons[0].size(), 8u);
  }
  for (const Point& p : plc.points)  // no side centre is left
    EXPECT_NE(std::count(p.begin(), p.end(), 0.5), 2) << p[0] << ' ' << p[1] << ' ' << p[2];
}

// Rotated by a rotation whose matrix entries are not dyadic: the corners of a side are then
// coplanar only within rounding (orient3d of the fourth corner is not exactly zero).
Shape rotated(Shape s) {
  const double c = std::cos(0.7), d = std::sin(0.7), e = std::cos(1.1), f = std::sin(1.1);
  for (Point& p : s.points) {
    const Point q{c * p[0] - d * p[1], d * p[0] + c * p[1], p[2]};
    p = {q[0], e * q[1] - f * q[2], f * q[1] + e * q[2]};
  }
  return s;
}

std::size_t inexact_sides(const Shape& s) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 1 < s.faces.size(); i += 2) {
    const auto &a = s.faces[i], &b = s.faces[i + 1];
    n += orient3d(s.points[a[0]], s.points[a[1]], s.points[a[2]], s.points[b[2]]) != Sign::Zero;
  }
  return n;
}

TEST(Surface, TrianglesCoplanarWithinToleranceMerge) {
  // Step 5b: a rotated box of 12 triangles is the rotated box of 6 squares, though the two
  // triangles of a side are a few ulps off each other's planes.
  ScratchDir dir;
  const Shape tri = rotated(box_triangles());
  ASSERT_GE(inexact_sides(tri), 3u);  // the case the exact merge of step 5 leaves apart
  const Plc plc = read_off_text(dir, off_text(tri));
  EXPECT_EQ(plc.facets.size(), 6u);
  for (const PlcFacet& f : plc.facets) {
    ASSERT_EQ(f.polygons.size(), 1u);
    EXPECT_EQ(f.polygons[0].size(), 4u);
  }
  EXPECT_EQ(facet_sets(plc), facet_sets(read_off_text(dir, off_text(rotated(box_squares())))));
  // The 2x2 grid per side, rotated: the side centres go, as without the rotation.
  const Plc grid = read_off_text(dir, off_text(rotated(box_grid())));
  EXPECT_EQ(grid.facets.size(), 6u);
  EXPECT_EQ(grid.points.size(), 20u);
  // With no tolerance only exactly coplanar faces merge.
  const Plc exact = surface_to_plc(read_off(dir / "s.off"), 0.0);
  EXPECT_GT(exact.facets.size(), 6u);
}

TEST(Surface, FoldsBeyondToleranceStayApart) {
  // One corner of the box moved out by 1e-6 along the diagonal (a relative deviation a
  // thousand times the tolerance): the three sides at it stay six triangles, the other
  // three merge.
  ScratchDir dir;
  Shape tri = box_triangles();
  for (double& x : tri.points[7]) x += 1e-6;
  const Plc plc = read_off_text(dir, off_text(rotated(tri)));
  EXPECT_EQ(plc.facets.size(), 3u + 6u);
}

// Step 0b: faces of four or more corners that are not planar within the tolerance (the
// bilinear patches of a quad mesh) are split into triangles. A box of squares with one
// corner moved out by 0.1 along the diagonal: the three squares at it become two triangles each, along the
// diagonal that misses the raised corner (the shorter one), and the other three stay
// whole; read as OBJ, the same facets. A non-planar pentagon (a box top with a raised
// point on an edge) is split by ear clipping; one whose projection crosses itself is an
// error naming its line.
TEST(Surface, NonPlanarFacesSplitIntoTriangles) {
  ScratchDir dir;
  Shape box = box_squares();
  box.points[7] = {1.1, 1.1, 1.1};  // (1, 1, 1), moved out along the diagonal
  const Plc plc = read_off_text(dir, off_text(box));
  EXPECT_EQ(plc.facets.size(), 3u + 6u);
  const Point raised{1.1, 1.1, 1.1};
  std::size_t triangles = 0;
  for (const std::set<Point>& f : facet_sets(plc)) {
    if (f.size() != 3) continue;
    ++triangles;
    // The diagonal from the raised corner is the longer one: no triangle has both ends.
    for (const Point& other : {Point{0, 0, 1}, Point{0, 1, 0}, Point{1, 0, 0}})
      EXPECT_FALSE(f.count(raised) && f.count(other));
  }
  EXPECT_EQ(triangles, 6u);
  write_text(dir / "s.obj", obj_text(box));
  EXPECT_EQ(facet_sets(read_domain(dir / "s.obj")), facet_sets(plc));

  Shape five = box_squares();
  five.points.push_back({0.5, 0, 1.05});  // 8: on the top's edge from 4 to 5, raised
  five.faces[1] = {4, 8, 5, 7, 6};       // the top: a non-planar pentagon
  five.faces[2] = {0, 1, 5, 8, 4};       // the side y = 0: a planar pentagon
  const Plc split = read_off_text(dir, off_text(five));
  EXPECT_EQ(split.facets.size(), 5u + 3u);
  for (const PlcFacet& f : split.facets) ASSERT_EQ(f.polygons.size(), 1u);

  // A pentagon whose projection crosses itself (its edge from the second corner to the third
  // crosses the one from the fourth to the fifth), every other corner raised. Ear clipping
  // alone would split it (each step finds an ear), so the simplicity test is what refuses it.
  const std::string star =
      "OFF\n5 1 0\n2 6 0\n6 2 0.2\n3 3 0\n6 6 0.2\n1 0 0\n5 0 1 2 3 4\n";
  const std::string m = off_error(star);
  EXPECT_NE(m.find("s.off:8: face 1: planar faces: the face is not planar"), std::string::npos)
      << m;
}

// A surface of one face through `corners` in order, on file line `line`.
Surface one_face(const std::string& source, const std::vector<Point>& corners, std::size_t line) {
  Surface s;
  s.source = source;
  std::vector<std::uint32_t> face;
  for (const Point& p : corners) {
    face.push_back(static_cast<std::uint32_t>(s.points.size()));
    s.add_point(p, 0, static_cast<std::int64_t>(s.points.size()));
  }
  s.add_face(face, line, 0);
  return s;
}

// A non-planar quad that is concave seen along its normal (corner 3 reflex): its shorter
// diagonal, 0-2, lies outside it in that view and would fold one triangle over the notch;
// the split takes 1-3, the diagonal inside.
TEST(Surface, ConcaveNonPlanarQuadSplitsAlongItsInnerDiagonal) {
  const auto split = split_nonplanar_faces(
      one_face("q.off", {{0, 0, 0}, {10, 0.5, 0}, {0, 1, 0}, {5, 0.5, 0.01}}, 7), {1e-9, {}});
  ASSERT_TRUE(split.has_value());
  ASSERT_EQ(split->face_count(), 2u);
  for (std::size_t f = 0; f < 2; ++f) {
    const auto c = split->face(f);
    EXPECT_TRUE(std::find(c.begin(), c.end(), 1u) != c.end() &&
                std::find(c.begin(), c.end(), 3u) != c.end());
    EXPECT_EQ(split->face_lines[f], 7u);
  }
}

// An L-shaped face (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), its inner corner a hair beyond the
// line from (2,0) to (0,2) and raised 1e-7 (non-planar): ear clipping took the ear at (0,0)
// first, then those at (2,1) and (1,2), and left the triangle (2,0) (1,1) (0,2), 1e-7 high
// in the view along the normal, whose segments 1e-7 apart drove the mesher to that size (a rotated
// L prism written with 7 digits: exit 1). The split is the triangulation of largest
// smallest angle: 45 degrees here.
TEST(Surface, NonPlanarFaceSplitsIntoItsBestShapedTriangulation) {
  const auto split = split_nonplanar_faces(
      one_face("l.off",
               {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1 + 1e-7, 1 + 1e-7, 1e-7}, {1, 2, 0}, {0, 2, 0}}, 3),
      {1e-9, {}});
  ASSERT_TRUE(split.has_value());
  ASSERT_EQ(split->face_count(), 4u);
  for (std::size_t f = 0; f < 4; ++f) {
    const auto c = split->face(f);
    double smallest = 180;
    for (int i = 0; i < 3; ++i) {
      const Point &o = split->points[c[i]], &u = split->points[c[(i + 1) % 3]],
                  &v = split->points[c[(i + 2) % 3]];
      double dot = 0, lu = 0, lv = 0;
      for (int k = 0; k < 3; ++k) {
        dot += (u[k] - o[k]) * (v[k] - o[k]);
        lu += (u[k] - o[k]) * (u[k] - o[k]);
        lv += (v[k] - o[k]) * (v[k] - o[k]);
      }
      smallest = std::min(smallest, std::acos(dot / std::sqrt(lu * lv)) * 180 / 3.141592653589793);
    }
    EXPECT_GT(smallest, 44.9) << "triangle " << f;
  }
  // Above 96 corners, ear clipping: a 120-gon, every other corner raised, in 118 triangles.
  std::vector<Point> ring;
  for (int i = 0; i < 120; ++i) {
    const double t = 2 * 3.141592653589793 * i / 120;
    ring.push_back({std::cos(t), std::sin(t), i % 2 ? 1e-6 : 0.0});
  }
  const auto fan = split_nonplanar_faces(one_face("big.off", ring, 1), {1e-9, {}});
  ASSERT_TRUE(fan.has_value());
  EXPECT_EQ(fan->face_count(), 118u);
}

TEST(Surface, SubnormalCoordinatesReadOrFailAsInput) {
  // A box whose corners carry subnormal and huge coordinates (a fuzzer's find): the double
  // normal of a face's plane triple underflows, and step 5's projection axis must still be
  // one along which the exact projection turns. Reading gives a PLC or an InputError,
  // never a logic_error.
  ScratchDir dir;
  Shape s = box_triangles();
  s.points = {{6.397087343208204e-308, 0, 0}, {0.0002288818359375, 0, 0},
              {9.713726e-318, 1, 4.0474e-320}, {0, 1, 0},
              {0, 6.80564733841877e+38, 1},    {1, 0, 1},
              {1, 1, 1},                       {2.781342323134e-309, 1, 1}};
  s.faces = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
             {1, 2, 6}, {1, 6, 5}, {2, 3, 6}, {3, 7, 6}, {0, 7, 3}, {0, 4, 7}};
  try {
    (void)read_off_text(dir, off_text(s));
  } catch (const InputError&) {
    // the answer to an invalid surface
  }
  // The unit box with subnormal offsets on its x = 0 side reads as the box of 6 sides.
  Shape box = box_triangles();
  for (Point& p : box.points)
    if (p[0] == 0) p[0] = p[1] == p[2] ? 5e-324 : 0;
  EXPECT_EQ(read_off_text(dir, off_text(box)).facets.size(), 6u);
}

TEST(Surface, RingBecomesAFacetWithAHole) {
  ScratchDir dir;
  const Plc plc = read_off_text(dir, off_text(step()));
  // bottom, 4 big sides, the ring, 4 small sides, the small top
  EXPECT_EQ(plc.facets.size(), 11u);
  std::size_t rings = 0;
  for (const PlcFacet& f : plc.facets) {
    if (f.polygons.size() == 1) {
      EXPECT_TRUE(f.holes.empty());
      continue;
    }
    ++rings;
    ASSERT_EQ(f.polygons.size(), 2u);
    ASSERT_EQ(f.holes.size(), 1u);
    const Point& h = f.holes[0];
    EXPECT_EQ(h[2], 1.0);
    EXPECT_GT(h[0], 0.5);
    EXPECT_LT(h[0], 1.5);
    EXPECT_GT(h[1], 0.5);
    EXPECT_LT(h[1], 1.5);
  }
  EXPECT_EQ(rings, 1u);
}

TEST(Surface, RepeatedCornersMergeIntoOneVertex) {
  // Every triangle with its own three vertices, as STL stores them; -0 equals 0.
  const Shape t = box_triangles();
  Shape soup;
  for (const auto& f : t.faces) {
    std::vector<std::uint32_t> c;
    for (std::uint32_t v : f) {
      c.push_back(static_cast<std::uint32_t>(soup.points.size()));
      Point p = t.points[v];
      if (soup.points.size() % 2 == 0) p[0] = p[0] == 0 ? -0.0 : p[0];
      soup.points.push_back(p);
    }
    soup.faces.push_back(c);
  }
  ScratchDir dir;
  const Plc plc = read_off_text(dir, off_text(soup));
  EXPECT_EQ(plc.points.size(), 8u);
  EXPECT_EQ(plc.facets.size(), 6u);
}

TEST(Surface, MarkersSeparateFacets) {
  const Shape t = box_triangles();
  Surface s;
  s.source = "m";
  for (std::size_t i = 0; i < t.points.size(); ++i)
    s.add_point(t.points[i], i + 1, static_cast<std::int64_t>(i));
  for (std::size_t f = 0; f < t.faces.size(); ++f)
    s.add_face(t.faces[f], 100 + f, f == 0 ? 7 : 1);  // half of the bottom differs
  const Plc plc = surface_to_plc(s);
  EXPECT_EQ(plc.facets.size(), 7u);
  EXPECT_EQ(plc.facets[0].marker, 7);
  EXPECT_EQ(plc.facets[0].line, 100u);
}

// Two unit cubes of triangles sharing the square x = 1, given once (a wall): its edges
// join three faces, which pair no faces, so the wall and the faces beside it stay apart
// (exactly coplanar neighbours across other edges still merge): 11 square facets. Touching
// along an edge only (four faces there) is read too: 12 facets.
TEST(Surface, EdgesOfThreeOrMoreFacesSeparateFacets) {
  std::string off = "OFF\n12 22 0\n";
  for (int x = 0; x <= 2; ++x)
    for (const auto& [y, z] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}})
      off += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  const auto quad = [&](int a, int b, int c, int d) {
    off += "3 " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
    off += "3 " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
  };
  for (int x = 0; x <= 2; ++x) quad(4 * x, 4 * x + 1, 4 * x + 2, 4 * x + 3);
  for (int c = 0; c < 2; ++c) {
    const int a = 4 * c, b = 4 * c + 4;
    quad(a, b, b + 1, a + 1);
    quad(a + 3, b + 3, b + 2, a + 2);
    quad(a, b, b + 3, a + 3);
    quad(a + 1, b + 1, b + 2, a + 2);
  }
  ScratchDir dir;
  const Plc wall = read_off_text(dir, off);
  EXPECT_EQ(wall.facets.size(), 11u);
  for (const PlcFacet& f : wall.facets) {
    ASSERT_EQ(f.polygons.size(), 1u);
    EXPECT_EQ(f.polygons[0].size(), 4u);
  }

  // Two unit cubes of triangles, the second moved by (1, dy, 0), each closed.
  const auto two_cubes = [](int dy, bool other_diagonal = false) {
    std::string off = "OFF\n16 24 0\n";
    for (int b = 0; b < 2; ++b)
      for (int k = 0; k < 8; ++k)
        off += std::to_string(b + (k & 1)) + " " + std::to_string(b * dy + (k >> 1 & 1)) + " " +
               std::to_string(k >> 2) + "\n";
    const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int b = 0; b < 2; ++b)
      for (const auto& f : q) {
        const std::string o[4] = {std::to_string(8 * b + f[0]), std::to_string(8 * b + f[1]),
                                  std::to_string(8 * b + f[2]), std::to_string(8 * b + f[3])};
        if (other_diagonal && b == 1)
          off += "3 " + o[0] + " " + o[1] + " " + o[3] + "\n3 " + o[1] + " " + o[2] + " " + o[3] + "\n";
        else
          off += "3 " + o[0] + " " + o[1] + " " + o[2] + "\n3 " + o[0] + " " + o[2] + " " + o[3] + "\n";
      }
    return off;
  };
  const Plc touching = read_off_text(dir, two_cubes(1));
  EXPECT_EQ(touching.facets.size(), 12u);
  EXPECT_EQ(touching.points.size(), 14u);  // corners (1, 1, 0) and (1, 1, 1) shared

  // Two closed cubes of an assembly, each giving the face x = 1 they share: the repeat is
  // read once, as the wall above.
  const Plc shared = read_off_text(dir, two_cubes(0));
  EXPECT_EQ(shared.facets.size(), 11u);
  // The second cube triangulates its faces along the other diagonals: the shared square is
  // no repeated face, but the same facet once merged, read once too.
  const Plc other = read_off_text(dir, two_cubes(0, true));
  EXPECT_EQ(other.facets.size(), 11u);
  EXPECT_EQ(shared.points.size(), 12u);
}

TEST(Surface, DefectsAreNamedWithTheirLine) {
  // An open box: the side x = 1 is missing (faces on lines 11.. of the OFF text).
  Shape open = box_squares();
  open.faces.pop_back();
  std::string m = off_error(off_text(open));
  EXPECT_NE(m.find("s.off:11: face 1: closed surface:"), std::string::npos) << m;
  EXPECT_NE(m.find("close it"), std::string::npos) << m;

  // A fin: a triangle hanging from an edge of the box. Given twice it is read once (a face
  // two bodies share), and either way its free edges are open.
  Shape fin = box_triangles();
  fin.points.push_back({0.5, -1, 0.5});
  fin.faces.push_back({0, 1, 8});
  fin.faces.push_back({0, 8, 1});
  m = off_error(off_text(fin));
  EXPECT_NE(m.find("closed surface: the edge from vertex 0 (0, 0, 0) to vertex 8"), std::string::npos) << m;
  fin.faces.pop_back();
  const std::string once = off_error(off_text(fin));
  EXPECT_EQ(once.substr(once.find("s.off:")), m.substr(m.find("s.off:")));
  // After a repeated face is read once, messages still number faces as the file does.
  Shape late = box_triangles();
  late.faces.push_back(late.faces[0]);
  late.points.push_back({0.5, -1, 0.5});
  late.faces.push_back({0, 1, 8});
  m = off_error(off_text(late));
  EXPECT_NE(m.find(": face 14: closed surface:"), std::string::npos) << m;


  // A sliver triangle with three collinear corners.
  Shape flat = box_squares();
  flat.points.push_back({0.5, 0, 0});
  flat.faces.push_back({0, 8, 1});
  m = off_error(off_text(flat));
  EXPECT_NE(m.find("s.off:18: face 7: non-degenerate faces: all corners"), std::string::npos)
      << m;

  // A corner repeated through a duplicate vertex.
  Shape twice = box_squares();
  twice.points.push_back({0, 0, 0});
  twice.faces[0] = {0, 2, 3, 8};
  m = off_error(off_text(twice));
  EXPECT_NE(m.find("face 1: non-degenerate faces: the face visits vertex 0"), std::string::npos)
      << m;

  // Two copies of one triangle are read once: open.
  m = off_error("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n");
  EXPECT_NE(m.find("closed surface"), std::string::npos) << m;

  // Not finite, out of range, too few corners.
  m = off_error("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  EXPECT_NE(m.find("s.off:4:"), std::string::npos) << m;
  m = off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  EXPECT_NE(m.find("s.off:6: corner index 3 is out of range"), std::string::npos) << m;
  m = off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n");
  EXPECT_NE(m.find("s.off:6: face 1: non-degenerate faces: the face has 2 corners"),
            std::string::npos)
      << m;
  m = off_error("4OFF\n");
  EXPECT_NE(m.find("s.off:1: expected the keyword OFF"), std::string::npos) << m;
}

}  // namespace
}  // namespace pdr::io::test
