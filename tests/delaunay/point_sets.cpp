// Test point sets (point_sets.hpp).
#include "delaunay/point_sets.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace pdr::testing {

std::vector<Point> random_cube(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> pts(n);
  for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
  return pts;
}

std::vector<Point> grid(int k) {
  std::vector<Point> pts;
  for (int x = 0; x < k; ++x)
    for (int y = 0; y < k; ++y)
      for (int z = 0; z < k; ++z) pts.push_back({double(x), double(y), double(z)});
  return pts;
}

std::vector<Point> sphere_lattice(int r2) {
  std::vector<Point> pts;
  int r = 0;
  while ((r + 1) * (r + 1) <= r2) ++r;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      for (int z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r2) pts.push_back({double(x), double(y), double(z)});
  return pts;
}

std::vector<Point> cube_surface(int k, std::size_t interior, std::uint64_t seed) {
  std::vector<Point> pts;
  for (int x = 0; x <= k; ++x)
    for (int y = 0; y <= k; ++y)
      for (int z = 0; z <= k; ++z)
        if (x == 0 || y == 0 || z == 0 || x == k || y == k || z == k)
          pts.push_back({double(x), double(y), double(z)});
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> q(1, 4 * k - 1);
  for (std::size_t i = 0; i < interior; ++i)
    pts.push_back({q(rng) / 4.0, q(rng) / 4.0, q(rng) / 4.0});
  return pts;
}

std::vector<Point> with_duplicates(std::vector<Point> pts, std::size_t copies,
                                   std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < copies && n > 0; ++i) pts.push_back(pts[rng() % n]);
  return shuffled(std::move(pts), seed + 1);
}

std::vector<Point> shuffled(std::vector<Point> pts, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (std::size_t i = pts.size(); i > 1; --i) std::swap(pts[i - 1], pts[rng() % i]);
  return pts;
}

std::vector<Point> read_node_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("read_node_file: cannot open " + path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
  }
  if (lines.empty()) throw std::runtime_error("read_node_file: empty " + path);
  std::istringstream head(lines[0]);
  std::size_t n = 0;
  int dim = 0;
  if (!(head >> n >> dim) || dim != 3 || lines.size() < n + 1)
    throw std::runtime_error("read_node_file: bad header in " + path);
  std::vector<Point> pts(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::istringstream row(lines[i + 1]);
    long id;
    if (!(row >> id >> pts[i][0] >> pts[i][1] >> pts[i][2]))
      throw std::runtime_error("read_node_file: bad point line in " + path);
  }
  return pts;
}

}  // namespace pdr::testing
