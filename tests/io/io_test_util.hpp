// Helpers for the pdr_io tests: a scratch directory removed at the end of each test, file
// writing, a determinant in long double (exact on small integer coordinates, and of
// unambiguous sign on the well-shaped tets the meshers produce), orientation counts, a
// canonical form of a mesh (so meshes from different files or tools can be compared), and
// a bit-exact comparison of MeshData.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

#include "mesh/mesh_data.hpp"

namespace pdr::io::test {

class ScratchDir {
 public:
  ScratchDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("pdr_io_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  std::string str() const { return path_.string(); }
  // Names of the entries in the directory, sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(path_))
      out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  std::filesystem::path path_;
};

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
}

inline std::string read_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

inline long double det3(const Point& a, const Point& b, const Point& c, const Point& d) {
  long double u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = static_cast<long double>(b[k]) - a[k];
    v[k] = static_cast<long double>(c[k]) - a[k];
    w[k] = static_cast<long double>(d[k]) - a[k];
  }
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

struct Orientation {
  std::size_t positive = 0, negative = 0, zero = 0;
};

inline Orientation tet_orientation(const MeshData& m) {
  Orientation o;
  for (const Tet& t : m.tets) {
    const long double d = det3(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]);
    (d > 0 ? o.positive : d < 0 ? o.negative : o.zero)++;
  }
  return o;
}

// For each boundary face (a face of exactly one tet): `positive` counts those whose normal
// (b-a)x(c-a) points away from the tet's fourth vertex (outward), `negative` inward;
// `zero` counts faces of no tet or of two tets (interior faces, e.g. between regions).
inline Orientation face_orientation(const MeshData& m) {
  std::map<std::array<std::uint32_t, 3>, std::pair<std::uint32_t, int>> opposite;
  for (const Tet& t : m.tets)
    for (int k = 0; k < 4; ++k) {
      std::array<std::uint32_t, 3> f;
      int j = 0;
      for (int i = 0; i < 4; ++i)
        if (i != k) f[j++] = t[i];
      std::sort(f.begin(), f.end());
      auto& entry = opposite[f];
      entry.first = t[k];
      ++entry.second;
    }
  Orientation o;
  for (const Tri& f : m.faces) {
    std::array<std::uint32_t, 3> key{f[0], f[1], f[2]};
    std::sort(key.begin(), key.end());
    const auto it = opposite.find(key);
    if (it == opposite.end() || it->second.second != 1) {
      ++o.zero;
      continue;
    }
    const long double d =
        det3(m.points[f[0]], m.points[f[1]], m.points[f[2]], m.points[it->second.first]);
    (d < 0 ? o.positive : o.negative)++;
  }
  return o;
}

// Tets and faces as sorted tuples of coordinates, with orientation kept by the parity of
// the sorting permutation: independent of point numbering and element order. With
// `quantum` > 0 coordinates are first rounded to multiples of it (tools that print 16
// significant digits in ASCII and exact bits in binary then compare equal).
struct Canonical {
  std::multiset<std::pair<std::array<Point, 4>, bool>> tets;
  std::multiset<std::pair<std::array<Point, 3>, bool>> faces;
  bool operator==(const Canonical&) const = default;
};

template <std::size_t N>
std::pair<std::array<Point, N>, bool> sorted_with_parity(std::array<Point, N> p) {
  bool odd = false;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j + 1 < N - i; ++j)
      if (p[j + 1] < p[j]) {
        std::swap(p[j], p[j + 1]);
        odd = !odd;
      }
  return {p, odd};
}

inline Canonical canonical(const MeshData& mesh, double quantum = 0) {
  MeshData m = mesh;
  if (quantum > 0)
    for (Point& p : m.points)
      for (double& x : p) x = std::round(x / quantum) * quantum;
  Canonical c;
  for (const Tet& t : m.tets)
    c.tets.insert(sorted_with_parity<4>({m.points[t[0]], m.points[t[1]], m.points[t[2]],
                                         m.points[t[3]]}));
  for (const Tri& f : m.faces)
    c.faces.insert(sorted_with_parity<3>({m.points[f[0]], m.points[f[1]], m.points[f[2]]}));
  return c;
}

inline bool same_bits(const std::vector<Point>& a, const std::vector<Point>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Point)) == 0);
}

// Empty marker arrays and all-zero ones are the same information.
inline std::vector<int> zeros_if_empty(const std::vector<int>& v, std::size_t n) {
  return v.empty() ? std::vector<int>(n, 0) : v;
}

// Bit-exact equality of everything a format carries; `point_markers` false for formats
// without point markers (Gmsh).
inline void expect_same_mesh(const MeshData& want, const MeshData& got, bool point_markers,
                             const std::string& label) {
  SCOPED_TRACE(label);
  EXPECT_TRUE(same_bits(want.points, got.points));
  EXPECT_EQ(want.tets, got.tets);
  EXPECT_EQ(want.faces, got.faces);
  EXPECT_EQ(zeros_if_empty(want.tet_regions, want.tets.size()),
            zeros_if_empty(got.tet_regions, got.tets.size()));
  EXPECT_EQ(zeros_if_empty(want.face_markers, want.faces.size()),
            zeros_if_empty(got.face_markers, got.faces.size()));
  if (point_markers) {
    EXPECT_EQ(zeros_if_empty(want.point_markers, want.points.size()),
              zeros_if_empty(got.point_markers, got.points.size()));
  }
}

// True when `tool` is on PATH.
inline bool have_tool(const std::string& tool) {
  return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0;
}

// Runs `command` in `dir` with output to dir/log; returns its exit status.
inline int run_in(const std::string& dir, const std::string& command) {
  const std::string cmd = "cd '" + dir + "' && " + command + " >log.txt 2>&1";
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

// A unit cube split into 6 positive tets around the diagonal 0-6, with its 12 boundary
// triangles oriented outward, markers 1..6 per side, regions 7/8, point markers 0/1.
inline MeshData cube_mesh() {
  MeshData m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
              {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  m.tets = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  for (Tet& t : m.tets)
    if (det3(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) < 0)
      std::swap(t[2], t[3]);
  m.faces = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
             {1, 2, 6}, {1, 6, 5}, {2, 3, 6}, {3, 7, 6}, {0, 7, 3}, {0, 4, 7}};
  m.face_markers = {1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6};
  m.tet_regions = {7, 7, 7, 8, 8, 8};
  m.point_markers = {1, 1, 1, 1, 0, 0, 0, 1};
  return m;
}

}  // namespace pdr::io::test
