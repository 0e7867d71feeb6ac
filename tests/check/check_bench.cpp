// Not a test: times check_mesh on ~1M-tet meshes (2 threads) and prints the phases.
//   check_bench [n_grid=55] [n_points=160000]
// (a) a structured Kuhn grid of n^3 cubes (6 n^3 tets, every cube's vertices cospherical:
//     the worst case for exact ties), checked against its box domain;
// (b) the kernel's Delaunay tetrahedralization of random points in the unit cube.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <random>

#include "check/check.hpp"
#include "delaunay/bulk.hpp"
#include "delaunay/export.hpp"
#include "mesh_gen.hpp"

using namespace pdr;

static void report(const char* name, const check::Report& r, double seconds, double cpu) {
  std::printf("%s: %llu points, %llu tets: %s in %.2f s wall, %.2f s cpu\n", name,
              static_cast<unsigned long long>(r.points), static_cast<unsigned long long>(r.tets),
              r.ok() ? "PASS" : "FAIL", seconds, cpu);
  for (const auto& [phase, s] : r.seconds) std::printf("  %-14s %6.2f s\n", phase.c_str(), s);
  for (const auto& c : r.checks) {
    auto it = c.counts.find("exact_evaluations");
    if (c.status == check::Status::Fail || (it != c.counts.end() && it->second > 0))
      std::printf("  %-28s %s violations=%llu exact=%llu\n", c.id.c_str(),
                  std::string(check::to_string(c.status)).c_str(),
                  static_cast<unsigned long long>(c.violations),
                  static_cast<unsigned long long>(it == c.counts.end() ? 0 : it->second));
  }
}

// Wall seconds of f; CPU seconds (all threads) in *cpu.
template <class F>
static double timed(F&& f, double* cpu) {
  const std::clock_t c0 = std::clock();
  const auto t0 = std::chrono::steady_clock::now();
  f();
  *cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 55;
  const std::size_t np = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 160000;
  check::Options o;
  o.threads = 2;
  o.ratio_bound = 2;
  {
    const MeshData m = check::test::kuhn_grid(n);
    const Plc d = check::test::box_domain(n);
    check::Report r;
    double cpu = 0;
    const double s = timed([&] { r = check::check_mesh(check::view_of(m), d, o); }, &cpu);
    report("kuhn grid + box domain", r, s, cpu);
  }
  {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Point> pts(np);
    for (Point& p : pts) p = {u(rng), u(rng), u(rng)};
    Delaunay dt(std::move(pts));
    bulk_insert(dt);
    const MeshData m = to_mesh_data(dt);
    check::Report r;
    double cpu = 0;
    const double s = timed([&] { r = check::check_mesh(check::view_of(m), o); }, &cpu);
    report("kernel Delaunay of random points", r, s, cpu);
  }
}
