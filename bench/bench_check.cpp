// bench_check: the time of `pdr check` on a mesh of about 1M tets, against an independent
// exact checker written on CGAL in this file, measured in the same run.
//
// The CGAL checker decides, with CGAL's exact predicates (Epick) and lazy exact
// constructions (Epeck), what `pdr check` decides without a domain:
//   orientation  every tet positive (CGAL::orientation)
//   faces        a face in at most two tets, on opposite sides; the boundary closed (every
//                boundary edge used once in each direction)
//   overlap      the boundary surface does not self-intersect
//                (Polygon_mesh_processing::does_self_intersect), and no component of it
//                lies inside another (Side_of_triangle_mesh): with the two checks above
//                this excludes overlapping tets (the degree argument, src/check/degree.cpp)
//   delaunay     no vertex strictly inside a tet's circumsphere: candidates from a kd-tree
//                (Fuzzy_sphere around the floating-point circumcenter, radius enlarged by
//                1e-6 relative), each decided by side_of_bounded_sphere
//   quality      circumradius^2 < 4 * shortest edge^2, exactly (Epeck)
// It does not check conformity to a domain or encroachment; `pdr check --domain` does
// (both pdr timings are printed). Per-tet loops run on the same number of threads as
// `pdr check` (2). Reading the files is not timed for either checker.
//
// Usage: bench_check [--pdr PATH] [--volume V] [--threads N] [--mesh PREFIX --domain D.poly]
// Without --mesh, `pdr mesh data/cube-in-cube.poly --max-volume V` (default 0.0018, about
// 1M tets) makes the mesh first.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using Pt = K::Point_3;
using Tet = std::array<std::uint32_t, 4>;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// TetGen .node/.ele, comments and attributes ignored, 0- or 1-based as the .node says.
bool read_mesh(const std::string& prefix, std::vector<Pt>& pts, std::vector<Tet>& tets) {
  auto lines = [](const std::string& path) {
    std::vector<std::string> out;
    std::ifstream in(path);
    std::string l;
    while (std::getline(in, l)) {
      const auto h = l.find('#');
      if (h != std::string::npos) l.resize(h);
      if (l.find_first_not_of(" \t\r") != std::string::npos) out.push_back(l);
    }
    return out;
  };
  const auto node = lines(prefix + ".node"), ele = lines(prefix + ".ele");
  if (node.empty() || ele.empty()) return false;
  std::size_t n = 0, m = 0;
  std::istringstream(node[0]) >> n;
  std::istringstream(ele[0]) >> m;
  long base = 0;
  pts.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::istringstream s(node[i + 1]);
    long id;
    double x, y, z;
    s >> id >> x >> y >> z;
    if (i == 0) base = id;
    pts[i] = Pt(x, y, z);
  }
  tets.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    std::istringstream s(ele[i + 1]);
    long id, a, b, c, d;
    s >> id >> a >> b >> c >> d;
    tets[i] = {static_cast<std::uint32_t>(a - base), static_cast<std::uint32_t>(b - base),
               static_cast<std::uint32_t>(c - base), static_cast<std::uint32_t>(d - base)};
  }
  return true;
}

template <class F>
std::uint64_t parallel_count(std::size_t n, unsigned threads, F&& f) {
  std::atomic<std::uint64_t> total{0};
  std::vector<std::thread> pool;
  for (unsigned w = 0; w < threads; ++w)
    pool.emplace_back([&, w] {
      std::uint64_t c = 0;
      for (std::size_t i = w; i < n; i += threads) c += f(i) ? 1 : 0;
      total += c;
    });
  for (auto& t : pool) t.join();
  return total;
}

struct CgalResult {
  std::map<std::string, double> seconds;
  std::map<std::string, std::uint64_t> violations;
};

CgalResult cgal_check(const std::vector<Pt>& pts, const std::vector<Tet>& tets, unsigned threads) {
  CgalResult r;
  auto t0 = Clock::now();
  r.violations["orientation"] = parallel_count(tets.size(), threads, [&](std::size_t i) {
    const Tet& t = tets[i];
    return CGAL::orientation(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]]) != CGAL::POSITIVE;
  });
  r.seconds["orientation"] = since(t0);

  t0 = Clock::now();
  struct Rec {
    std::array<std::uint32_t, 3> key;
    std::uint32_t tet;
    int local;
  };
  static constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};  // outward
  std::vector<Rec> recs;
  recs.reserve(tets.size() * 4);
  for (std::uint32_t t = 0; t < tets.size(); ++t)
    for (int f = 0; f < 4; ++f) {
      std::array<std::uint32_t, 3> k = {tets[t][kFace[f][0]], tets[t][kFace[f][1]], tets[t][kFace[f][2]]};
      std::sort(k.begin(), k.end());
      recs.push_back({k, t, f});
    }
  std::sort(recs.begin(), recs.end(), [](const Rec& a, const Rec& b) { return a.key < b.key; });
  std::uint64_t bad_faces = 0;
  std::vector<std::array<std::uint32_t, 3>> boundary;  // outward
  for (std::size_t i = 0; i < recs.size();) {
    std::size_t j = i;
    while (j < recs.size() && recs[j].key == recs[i].key) ++j;
    const Tet& a = tets[recs[i].tet];
    const std::array<std::uint32_t, 3> fa = {a[kFace[recs[i].local][0]], a[kFace[recs[i].local][1]],
                                             a[kFace[recs[i].local][2]]};
    if (j - i == 1) {
      boundary.push_back(fa);
    } else if (j - i == 2) {
      const Tet& b = tets[recs[i + 1].tet];
      const auto sa = CGAL::orientation(pts[fa[0]], pts[fa[1]], pts[fa[2]], pts[a[recs[i].local]]);
      const auto sb = CGAL::orientation(pts[fa[0]], pts[fa[1]], pts[fa[2]], pts[b[recs[i + 1].local]]);
      if (sa == sb || sa == CGAL::COPLANAR || sb == CGAL::COPLANAR) ++bad_faces;
    } else {
      ++bad_faces;
    }
    i = j;
  }
  std::vector<std::pair<std::uint64_t, int>> uses;
  for (const auto& f : boundary)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = f[k], v = f[(k + 1) % 3];
      uses.emplace_back((std::uint64_t{std::min(u, v)} << 32) | std::max(u, v), u < v ? 1 : -1);
    }
  std::sort(uses.begin(), uses.end());
  std::uint64_t open_edges = 0;
  for (std::size_t i = 0; i < uses.size();) {
    int sum = 0;
    std::size_t j = i;
    while (j < uses.size() && uses[j].first == uses[i].first) sum += uses[j++].second;
    open_edges += sum != 0 ? 1 : 0;
    i = j;
  }
  r.violations["faces"] = bad_faces + open_edges;
  r.seconds["faces"] = since(t0);

  t0 = Clock::now();
  using Mesh = CGAL::Surface_mesh<Pt>;
  Mesh sm;
  std::map<std::uint32_t, Mesh::Vertex_index> vmap;
  for (const auto& f : boundary)
    for (std::uint32_t v : f)
      if (!vmap.count(v)) vmap[v] = sm.add_vertex(pts[v]);
  std::uint64_t not_added = 0;
  for (const auto& f : boundary)
    if (sm.add_face(vmap[f[0]], vmap[f[1]], vmap[f[2]]) == Mesh::null_face()) ++not_added;
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::uint64_t overlap = not_added;
  if (not_added == 0) {
    overlap += PMP::does_self_intersect<CGAL::Parallel_if_available_tag>(sm) ? 1 : 0;
    // Components nested in others: a point just inside a component that lies inside
    // another outward component is covered twice.
    auto fcc = sm.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first;
    const std::size_t ncc = PMP::connected_components(sm, fcc);
    if (ncc > 1) {
      std::vector<Mesh> parts(ncc);
      std::vector<Pt> probe(ncc);
      for (std::size_t c = 0; c < ncc; ++c) {
        std::map<Mesh::Vertex_index, Mesh::Vertex_index> m;
        for (auto f : sm.faces()) {
          if (fcc[f] != c) continue;
          std::array<Mesh::Vertex_index, 3> vs;
          int k = 0;
          for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
            if (!m.count(v)) m[v] = parts[c].add_vertex(sm.point(v));
            vs[k++] = m[v];
          }
          parts[c].add_face(vs[0], vs[1], vs[2]);
          probe[c] = sm.point(*CGAL::vertices_around_face(sm.halfedge(f), sm).begin());
        }
      }
      for (std::size_t c = 0; c < ncc; ++c) {
        const CGAL::Side_of_triangle_mesh<Mesh, K> inside(parts[c]);
        const bool outward = PMP::volume(parts[c]) > 0;
        for (std::size_t d = 0; d < ncc; ++d)
          if (d != c && outward && inside(probe[d]) == CGAL::ON_BOUNDED_SIDE) {
            // d inside outward c: fine only if d is a cavity (inward)
            if (PMP::volume(parts[d]) > 0) ++overlap;
          }
      }
    }
  }
  r.violations["overlap"] = overlap;
  r.seconds["overlap"] = since(t0);

  t0 = Clock::now();
  using Traits = CGAL::Search_traits_3<K>;
  using Tree = CGAL::Kd_tree<Traits>;
  Tree tree(pts.begin(), pts.end());
  tree.build();
  r.violations["delaunay"] = parallel_count(tets.size(), threads, [&](std::size_t i) {
    const Tet& t = tets[i];
    const Pt c = CGAL::circumcenter(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]]);
    const double radius = std::sqrt(CGAL::squared_distance(c, pts[t[0]])) * (1 + 1e-6);
    std::vector<Pt> near;
    tree.search(std::back_inserter(near), CGAL::Fuzzy_sphere<Traits>(c, radius, 0.0));
    for (const Pt& q : near) {
      if (q == pts[t[0]] || q == pts[t[1]] || q == pts[t[2]] || q == pts[t[3]]) continue;
      if (CGAL::side_of_bounded_sphere(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]], q) == CGAL::ON_BOUNDED_SIDE)
        return true;
    }
    return false;
  });
  r.seconds["delaunay"] = since(t0);

  t0 = Clock::now();
  r.violations["quality"] = parallel_count(tets.size(), threads, [&](std::size_t i) {
    const Tet& t = tets[i];
    std::array<EK::Point_3, 4> p;
    for (int k = 0; k < 4; ++k) p[k] = EK::Point_3(pts[t[k]].x(), pts[t[k]].y(), pts[t[k]].z());
    EK::FT shortest = CGAL::squared_distance(p[0], p[1]);
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) shortest = CGAL::min(shortest, CGAL::squared_distance(p[a], p[b]));
    return !(CGAL::squared_radius(p[0], p[1], p[2], p[3]) < 4 * shortest);
  });
  r.seconds["quality"] = since(t0);
  return r;
}

// Runs argv, stdout to `out`; returns the exit code.
int run(const std::vector<std::string>& argv, const fs::path& out) {
  std::fflush(stdout);  // or the child's copy of the buffer is printed twice
  const pid_t pid = fork();
  if (pid == 0) {
    std::FILE* f = std::freopen(out.c_str(), "w", stdout);
    if (!f) _exit(127);
    std::vector<char*> a;
    for (const auto& s : argv) a.push_back(const_cast<char*>(s.c_str()));
    a.push_back(nullptr);
    execv(a[0], a.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

}  // namespace

int main(int argc, char** argv) {
  std::string pdr = PDR_BENCH_PDR, mesh, domain = std::string(PDR_BENCH_DATA) + "/cube-in-cube.poly",
              volume = "0.0018";
  unsigned threads = 2;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&] { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (a == "--pdr") pdr = next();
    else if (a == "--mesh") mesh = next();
    else if (a == "--domain") domain = next();
    else if (a == "--volume") volume = next();
    else if (a == "--threads") threads = static_cast<unsigned>(std::stoul(next()));
    else {
      std::fprintf(stderr, "usage: bench_check [--pdr PATH] [--volume V] [--threads N] [--mesh PREFIX --domain D.poly]\n");
      return 2;
    }
  }
  const fs::path dir = fs::temp_directory_path() / ("pdr-bench-check-" + std::to_string(getpid()));
  fs::create_directories(dir);
  if (mesh.empty()) {
    mesh = (dir / "m").string();
    if (run({pdr, "mesh", domain, "-o", mesh, "--max-volume", volume, "--no-check", "--formats", "node"},
            dir / "mesh.log") != 0) {
      std::fprintf(stderr, "bench_check: pdr mesh failed (see %s)\n", (dir / "mesh.log").c_str());
      return 1;
    }
  }
  std::vector<Pt> pts;
  std::vector<Tet> tets;
  if (!read_mesh(mesh, pts, tets)) {
    std::fprintf(stderr, "bench_check: cannot read %s.node/.ele\n", mesh.c_str());
    return 1;
  }
  std::printf("bench_check: %s: %zu points, %zu tets, %u threads\n", mesh.c_str(), pts.size(), tets.size(), threads);
  auto pdr_check = [&](bool with_domain) {
    std::vector<std::string> a = {pdr, "check", mesh, "--ratio", "2", "--json", "--threads", std::to_string(threads)};
    if (with_domain) a.insert(a.end(), {"--domain", domain});
    const int code = run(a, dir / "check.json");
    std::ifstream in(dir / "check.json");
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded()) return std::make_pair(code, -1.0);
    std::printf("  pdr check%s: %s, check %.2f s (read %.2f s):", with_domain ? " --domain" : "         ",
                code == 0 ? "pass" : "FAIL", j["seconds"]["check"].get<double>(), j["seconds"]["read"].get<double>());
    for (const auto& [k, v] : j["seconds"].items())
      if (k.rfind("check.", 0) == 0) std::printf(" %s %.2f", k.c_str() + 6, v.get<double>());
    std::printf("\n");
    return std::make_pair(code, j["seconds"]["check"].get<double>());
  };
  const auto [code_d, pdr_domain] = pdr_check(true);
  const auto [code_n, pdr_plain] = pdr_check(false);
  const auto t0 = Clock::now();
  const CgalResult c = cgal_check(pts, tets, threads);
  const double cgal = since(t0);
  std::uint64_t bad = 0;
  std::printf("  CGAL checker   : ");
  for (const auto& [k, v] : c.violations) bad += v;
  std::printf("%s, %.2f s:", bad == 0 ? "pass" : "FAIL", cgal);
  for (const auto& [k, s] : c.seconds) std::printf(" %s %.2f (%llu)", k.c_str(), s, static_cast<unsigned long long>(c.violations.at(k)));
  std::printf("\n");
  std::printf("  ratio pdr check / CGAL checker: %.2f without a domain (same checks), %.2f with --domain "
              "(plus conformity and encroachment); target <= 1.2\n",
              pdr_plain / cgal, pdr_domain / cgal);
  fs::remove_all(dir);
  return code_d == 0 && code_n == 0 && bad == 0 ? 0 : 1;
}
