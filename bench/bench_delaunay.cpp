// bench_delaunay: time and memory of the Delaunay tetrahedralization of N uniform random
// points in the unit cube, pdr against CGAL's Delaunay_triangulation_3 with the
// Exact_predicates_inexact_constructions_kernel (range insertion, its own spatial sort).
//
// Each build runs in its own forked child, so the peaks do not mix: the child records its
// resident set before creating the points, resets the kernel's high-water mark
// (/proc/self/clear_refs, "5"), generates the points, builds, and reports the peak
// (VmHWM) minus that baseline. Bytes per tet are this whole-process peak over the finite
// tets, input points and every temporary included, for both libraries alike. Time is the
// build alone (points excluded), by steady_clock.
//
// Usage: bench_delaunay [N=1000000] [seed=1] [runs=1] [pdr|cgal|both]
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "delaunay/bulk.hpp"

namespace {

struct Result {
  double seconds = 0;      // wall clock
  double cpu_seconds = 0;  // CPU time of the process (user + system)
  std::uint64_t tets = 0;
  std::uint64_t peak_bytes = 0;  // peak RSS over the baseline
  std::uint64_t store_bytes = 0;  // pdr only: topology arrays allocated
  int ok = 0;
};

// A field of /proc/self/status in bytes ("VmRSS", "VmHWM"); 0 if unavailable.
std::uint64_t status_kib(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(field);
  while (std::getline(in, line))
    if (line.compare(0, n, field) == 0 && line[n] == ':')
      return std::strtoull(line.c_str() + n + 1, nullptr, 10) * 1024;
  return 0;
}

bool reset_peak() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return static_cast<bool>(out);
}

template <class Point, class Make>
std::vector<Point> random_points(std::size_t n, std::uint64_t seed, Make make) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> pts;
  pts.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    pts.push_back(make(x, y, z));
  }
  return pts;
}

using Clock = std::chrono::steady_clock;

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

Result run_pdr(std::size_t n, std::uint64_t seed) {
  Result r;
  const std::uint64_t base = status_kib("VmRSS");
  auto pts = random_points<pdr::Point>(n, seed, [](double x, double y, double z) {
    return pdr::Point{x, y, z};
  });
  const double c0 = cpu_now();
  const auto t0 = Clock::now();
  pdr::Delaunay dt(std::move(pts));
  const pdr::BulkResult b = pdr::bulk_insert(dt);
  const auto t1 = Clock::now();
  r.cpu_seconds = cpu_now() - c0;
  r.seconds = std::chrono::duration<double>(t1 - t0).count();
  r.tets = dt.count_finite_tets();
  r.peak_bytes = status_kib("VmHWM") - base;
  r.store_bytes = dt.store().bytes_allocated();
  r.ok = b.status == pdr::BulkStatus::Ok;
  const auto& s = dt.stats();
  std::fprintf(stderr,
               "pdr: %llu insertions, %.2f walk steps, %.2f conflict tets, %.2f new tets "
               "per insertion; %zu tet slots\n",
               static_cast<unsigned long long>(s.inserted),
               double(s.walk_steps) / double(s.inserted + s.duplicates),
               double(s.conflict_tets) / double(s.inserted),
               double(s.boundary_faces) / double(s.inserted), dt.store().slots());
  return r;
}

Result run_cgal(std::size_t n, std::uint64_t seed) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using DT = CGAL::Delaunay_triangulation_3<K>;
  Result r;
  const std::uint64_t base = status_kib("VmRSS");
  auto pts = random_points<K::Point_3>(n, seed, [](double x, double y, double z) {
    return K::Point_3(x, y, z);
  });
  const double c0 = cpu_now();
  const auto t0 = Clock::now();
  DT dt(pts.begin(), pts.end());
  const auto t1 = Clock::now();
  r.cpu_seconds = cpu_now() - c0;
  r.seconds = std::chrono::duration<double>(t1 - t0).count();
  r.tets = dt.number_of_finite_cells();
  r.peak_bytes = status_kib("VmHWM") - base;
  r.ok = dt.number_of_vertices() == n;
  return r;
}

// Runs f in a forked child and returns its Result through a pipe.
template <class F>
Result in_child(F f) {
  int fd[2];
  if (pipe(fd) != 0) std::abort();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    if (!reset_peak()) std::fprintf(stderr, "warning: cannot reset VmHWM; peak may include "
                                            "the parent's\n");
    const Result r = f();
    if (write(fd[1], &r, sizeof r) != static_cast<ssize_t>(sizeof r)) _exit(2);
    _exit(0);
  }
  close(fd[1]);
  Result r;
  if (read(fd[0], &r, sizeof r) != static_cast<ssize_t>(sizeof r)) r.ok = 0;
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return r;
}

void print(const char* name, const Result& r) {
  std::printf("%-5s %8.3f s wall %8.3f s cpu %10llu tets %10.0f tets/s (wall) %10.0f tets/s "
              "(cpu) %6.1f B/tet peak",
              name, r.seconds, r.cpu_seconds, static_cast<unsigned long long>(r.tets),
              double(r.tets) / r.seconds, double(r.tets) / r.cpu_seconds,
              double(r.peak_bytes) / double(r.tets));
  if (r.store_bytes) std::printf("  (%.1f B/tet topology allocated)",
                                 double(r.store_bytes) / double(r.tets));
  std::printf("%s\n", r.ok ? "" : "  FAILED");
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const int runs = argc > 3 ? std::atoi(argv[3]) : 1;
  const std::string which = argc > 4 ? argv[4] : "both";
  std::printf("Delaunay of %zu uniform random points in the unit cube (seed %llu)\n", n,
              static_cast<unsigned long long>(seed));
  for (int run = 0; run < runs; ++run) {
    Result p, c;
    if (which != "cgal") {
      p = in_child([&] { return run_pdr(n, seed); });
      print("pdr", p);
    }
    if (which != "pdr") {
      c = in_child([&] { return run_cgal(n, seed); });
      print("CGAL", c);
    }
    if (which == "both") {
      std::printf("ratio pdr/CGAL: speed (tets/s) %.2fx wall, %.2fx cpu; memory (B/tet) "
                  "%.2fx%s\n",
                  (double(p.tets) / p.seconds) / (double(c.tets) / c.seconds),
                  (double(p.tets) / p.cpu_seconds) / (double(c.tets) / c.cpu_seconds),
                  (double(p.peak_bytes) / double(p.tets)) /
                      (double(c.peak_bytes) / double(c.tets)),
                  p.tets == c.tets ? "; same tet count" : "; TET COUNTS DIFFER");
    }
  }
  return 0;
}
