// bench_mesh: pdr's quality mesher against TetGen 1.5 on the same domains, in the same run.
//
// For each case (a .poly domain and a volume bound V chosen so that both produce about a
// million tets) it runs, each as its own child process:
//   pdr     pdr mesh D.poly -o DIR/pdr/D --ratio 2 --max-volume V --no-check --formats node
//   TetGen  tetgen -pq2.0aV -Q DIR/tetgen/D.poly     (writes D.1.node/.ele/.face)
//   check   pdr check PREFIX --domain D.poly --ratio 2, on pdr's and on TetGen's mesh
//           (separately, so that the exact check's time and memory are reported on their
//           own lines, not in the meshers' figures)
// Both meshers write comparable output (TetGen's .node/.ele/.face). Per run: wall seconds
// (steady_clock around fork..wait4), CPU seconds (user + system of the child, from wait4's
// rusage) and peak RSS (its ru_maxrss: the whole process, input and output included, for
// both alike). Then the bench reads both meshes with pdr's reader and computes, the same
// way for both, the tet count, the largest radius-edge ratio (double, display) and the
// number of tets with ratio >= 2 decided exactly (refine/quality.hpp).
//
// Usage: bench_mesh [--pdr PATH] [--tetgen PATH] [--data DIR] [--runs N] [--no-check]
//                   [--keep] [--outside] [--parallel] [--pairs N] [CASE.poly:V ...]
// Default cases: cube-in-cube.poly and tee.poly at about 1M tets (see kDefaultCases);
// --outside: the domains outside the theory of kOutsideCases (issue #11's benchmark). The
// checker runs on both meshers' outputs; a failing check is named.
// --parallel: `mpirun -n P pdr mesh` (issue #8's benchmark): per case, in the same run, the
// sequential command, np = 1 and np = 2 (each with --json, its summary read from its log;
// np = 1 and np = 2 alternately, --pairs N times, default 3), and TetGen; prints every
// wall time, the speed-ups np = 1 / sequential and np = 2 / np = 1 (those of the pair
// whose speed-up is the median: one pair is at the mercy of a spell of this virtual
// machine, which moved a single pair's ratio by 0.15) against the targets (np = 1 at most
// 1.15x the sequential time, np = 2 at least 1.6x faster than np = 1), that pair's np = 2
// run's phases (coarse M_o, parallel phase, assembly,
// completion) and, per rank, busy / phase seconds (the share of the parallel phase in
// which the rank worked rather than waited); and np = 2 at twice V with the check on, its
// check's seconds against the parallel refinement's (the target: no longer). For scale, the
// sequential command at twice V alone and two of it at once: the speed-up a parallel layer
// without costs of its own would reach on this machine at that moment.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <metis.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/partitioned_output.hpp"
#include "io/mesh_io.hpp"
#include "refine/quality.hpp"

namespace fs = std::filesystem;

namespace {

#ifndef PDR_BENCH_PDR
#define PDR_BENCH_PDR "pdr"
#endif
#ifndef PDR_BENCH_TETGEN
#define PDR_BENCH_TETGEN "tetgen"
#endif
#ifndef PDR_BENCH_DATA
#define PDR_BENCH_DATA "data"
#endif
#ifndef PDR_BENCH_MPIEXEC
#define PDR_BENCH_MPIEXEC "mpirun"
#endif
#ifndef PDR_BENCH_EXTRA
#define PDR_BENCH_EXTRA "bench/data"
#endif

struct Case {
  std::string poly;  // file name under the data directory, or a path
  std::string volume;  // V, as text (passed to both meshers verbatim)
};

// About 1M tets for both meshers (their counts differ by a few percent; compare tets/s).
const Case kDefaultCases[] = {{"cube-in-cube.poly", "0.002"}, {"tee.poly", "0.00125"}};
// --outside: domains outside the theory (angles below 90 degrees or above 270), at about
// 200K tets, and two tees also at about 1M: the paper's tee (tips 69 degrees, re-entrant
// edges 291), data/tee.poly (tips 70), a 60-degree wedge, and bench/data's tee with
// 33-degree tips (re-entrant edges 327) and star prism with 64-degree corners.
const Case kOutsideCases[] = {{"tee-paper.poly", "0.008"},
                              {"tee-paper.poly", "0.0016"},
                              {"tee.poly", "0.006"},
                              {"wedge60.poly", "0.004"},
                              {PDR_BENCH_EXTRA "/tee-sharp.poly", "0.006"},
                              {PDR_BENCH_EXTRA "/tee-sharp.poly", "0.0012"},
                              {PDR_BENCH_EXTRA "/star-prism.poly", "2.5e-6"}};

// The checks a failing `pdr check` reports ("FAIL  id: k of n violate: ..."), as "id k/n".
std::string failed_checks(const fs::path& log) {
  std::FILE* f = std::fopen(log.c_str(), "r");
  if (!f) return "failed";
  std::string out;
  char line[512];
  while (std::fgets(line, sizeof line, f)) {
    const std::string l(line);
    if (l.rfind("FAIL  ", 0) != 0) continue;
    const auto colon = l.find(':');
    const auto of = l.find(" of ", colon);
    const auto end = l.find(" violate", of);
    if (!out.empty()) out.append(", ");
    out.append(l, 6, colon - 6);
    if (colon != std::string::npos && of != std::string::npos && end != std::string::npos) {
      out.push_back(' ');
      out.append(l, colon + 2, of - colon - 2);
      out.push_back('/');
      out.append(l, of + 4, end - of - 4);
    }
  }
  std::fclose(f);
  if (out.empty()) return "failed";
  out.insert(0, "failed: ");
  return out;
}

struct Run {
  double wall = 0, cpu = 0;
  std::uint64_t peak = 0;  // bytes
  int exit_code = -1;
};

using Clock = std::chrono::steady_clock;

// A child started by start_child: its pid and start time.
struct Child {
  pid_t pid = -1;
  Clock::time_point t0;
};

// Starts argv[0] with argv, stdout and stderr to `log`.
Child start_child(const std::vector<std::string>& argv, const fs::path& log) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::fflush(nullptr);  // else the child's freopen flushes our buffered lines a second time
  Child c{-1, Clock::now()};
  c.pid = fork();
  if (c.pid == 0) {
    if (!freopen(log.c_str(), "w", stdout) || !freopen(log.c_str(), "a", stderr)) _exit(126);
    execv(args[0], args.data());
    _exit(127);
  }
  return c;
}

// The Run of a child that wait4 returned with `status` and `ru`, `end` its end.
Run ended(const Child& c, int status, const rusage& ru, Clock::time_point end) {
  Run r;
  r.wall = std::chrono::duration<double>(end - c.t0).count();
  r.cpu = double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
          1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  r.peak = static_cast<std::uint64_t>(ru.ru_maxrss) * 1024;  // Linux: KiB
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

// Waits for started children, each timed when it ends (whichever ends first): their wall
// times and their own rusage from wait4.
std::vector<Run> finish_children(const std::vector<Child>& children) {
  std::vector<Run> runs(children.size());
  std::size_t left = 0;
  for (const Child& c : children) left += c.pid > 0;
  while (left > 0) {
    int status = 0;
    rusage ru{};
    const pid_t pid = wait4(-1, &status, 0, &ru);
    if (pid < 0) break;
    const auto end = Clock::now();
    for (std::size_t i = 0; i < children.size(); ++i)
      if (children[i].pid == pid) {
        runs[i] = ended(children[i], status, ru, end);
        --left;
      }
  }
  return runs;
}

// Runs argv[0] with argv, stdout and stderr to `log`, and waits for it.
Run run_child(const std::vector<std::string>& argv, const fs::path& log) {
  return finish_children({start_child(argv, log)}).front();
}

struct Quality {
  std::size_t tets = 0;
  double max_ratio = 0;     // display
  std::size_t skinny = 0;   // ratio >= 2, exact
  bool read = false;
};

Quality measure(const std::string& prefix) {
  Quality q;
  try {
    const pdr::MeshData m = pdr::io::read_mesh(prefix);
    q.tets = m.tets.size();
    for (const auto& t : m.tets) {
      const pdr::Point &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]],
                       &d = m.points[t[3]];
      q.max_ratio = std::max(q.max_ratio, pdr::refine::ratio_of(a, b, c, d));
      if (pdr::refine::ratio_at_least(a, b, c, d, 2.0)) ++q.skinny;
    }
    q.read = true;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_mesh: cannot read %s: %s\n", prefix.c_str(), e.what());
  }
  return q;
}

void print(const char* name, const Run& r, const Quality& q) {
  const double n = double(q.tets);
  std::printf("  %-7s %9zu tets %7.2f s wall %7.2f s cpu %9.0f tets/s wall %9.0f tets/s cpu "
              "%7.1f MiB peak %6.1f B/tet  max ratio %.3f, %zu >= 2 (exact)  exit %d\n",
              name, q.tets, r.wall, r.cpu, n / r.wall, n / r.cpu, double(r.peak) / 1048576.0,
              double(r.peak) / n, q.max_ratio, q.skinny, r.exit_code);
}

// The JSON summary a `pdr mesh --json` child wrote to its log (an empty object if none).
nlohmann::json summary_of(const fs::path& log) {
  std::ifstream in(log);
  std::string text, line;
  bool inside = false;  // from the line "{" to the line "}" (stderr lines come before)
  while (std::getline(in, line)) {
    inside = inside || line == "{";
    if (inside) text += line + "\n";
    if (inside && line == "}") break;
  }
  auto j = nlohmann::json::parse(text, nullptr, false);
  return j.is_discarded() ? nlohmann::json::object() : j;
}

// The paper's Table 2: what a parallel run saves over the sequential alternative of getting
// a partitioned mesh, which is to mesh sequentially, partition the final mesh with METIS
// (its dual graph over shared faces, METIS_PartMeshDual), write the parts and read them
// back. Times the three steps after the mesh, in this process, on the sequential output
// at `prefix`: the read of that output, METIS, writing PREFIX.pvtu with one .vtu piece per
// part (app/partitioned_output.hpp, as `mpirun -np P pdr mesh --formats vtu` writes it),
// and reading every piece.
struct Table2 {
  double read = 0, partition = 0, write = 0, reread = 0;
  std::size_t tets = 0, pieces_tets = 0;
  bool ok = false;
  double total() const { return read + partition + write + reread; }
};

Table2 sequential_pipeline(const std::string& prefix, int parts) {
  Table2 r;
  try {
    auto t0 = Clock::now();
    auto lap = [&t0] {
      const double s = std::chrono::duration<double>(Clock::now() - t0).count();
      t0 = Clock::now();
      return s;
    };
    const pdr::MeshData m = pdr::io::read_mesh(prefix);
    r.read = lap();
    r.tets = m.tets.size();
    idx_t ne = static_cast<idx_t>(m.tets.size()), nn = static_cast<idx_t>(m.points.size());
    idx_t ncommon = 3, nparts = parts, objval = 0;
    std::vector<idx_t> eptr(m.tets.size() + 1), eind(4 * m.tets.size());
    for (std::size_t i = 0; i < m.tets.size(); ++i) {
      eptr[i + 1] = static_cast<idx_t>(4 * (i + 1));
      for (int k = 0; k < 4; ++k) eind[4 * i + k] = static_cast<idx_t>(m.tets[i][k]);
    }
    std::vector<idx_t> epart(m.tets.size()), npart(m.points.size());
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    if (METIS_PartMeshDual(&ne, &nn, eptr.data(), eind.data(), nullptr, nullptr, &ncommon,
                           &nparts, nullptr, options, &objval, epart.data(),
                           npart.data()) != METIS_OK)
      return r;
    std::vector<std::uint32_t> owner(epart.begin(), epart.end());
    r.partition = lap();
    const std::vector<std::string> files =
        pdr::app::write_partitioned_vtu(m, owner, parts, prefix + "_table2");
    r.write = lap();
    for (const std::string& f : files)
      if (f.size() > 4 && f.compare(f.size() - 4, 4, ".vtu") == 0)
        r.pieces_tets += pdr::io::read_mesh(f).tets.size();
    r.reread = lap();
    r.ok = r.pieces_tets == r.tets;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_mesh: Table 2 on %s: %s\n", prefix.c_str(), e.what());
  }
  return r;
}

// The paper's Table 1 for each rank of a parallel run's summary, and for the worst rank
// (the one whose parallel phase took longest), in seconds (docs/parallel.md).
void print_table1(const nlohmann::json& parallel) {
  if (!parallel.contains("per_rank")) return;
  std::printf("  Table 1 (np=2, seconds): rank | execution | completed cavity local, distributed "
              "| masked local, distributed | setback | latency tolerance | poll (excess)\n");
  const int worst = parallel.value("worst_rank", -1);
  for (const auto& r : parallel.at("per_rank")) {
    if (!r.contains("table1")) continue;
    const auto& t = r.at("table1");
    std::printf("    %d%s | %.3f | %.3f, %.3f | %.3f, %.3f | %.3f | %.1f%% | %.3f (%.3f)\n",
                r.at("rank").get<int>(), r.at("rank").get<int>() == worst ? " (worst)" : "",
                t.at("execution_seconds").get<double>(),
                t.at("completed_cavity_seconds").at("local").get<double>(),
                t.at("completed_cavity_seconds").at("distributed").get<double>(),
                t.at("masked_seconds").at("local").get<double>(),
                t.at("masked_seconds").at("distributed").get<double>(),
                t.at("setback_seconds").get<double>(),
                100 * t.at("latency_tolerance").get<double>(), t.at("poll_seconds").get<double>(),
                t.at("poll_excess_seconds").get<double>());
  }
}

// --parallel: the sequential command, np = 1, np = 2 and TetGen on one case.
bool parallel_case(const std::string& pdr, const std::string& tetgen, const fs::path& poly,
                   const std::string& volume, const fs::path& dir, int pairs) {
  const std::string prefix = (dir / "pdr" / poly.stem()).string();
  const std::vector<std::string> mesh = {pdr, "mesh", poly.string(), "-o", prefix, "--ratio", "2",
                                         "--max-volume", volume, "--no-check", "--formats",
                                         "node", "--json"};
  auto mpirun = [&](int np) {
    std::vector<std::string> a = {PDR_BENCH_MPIEXEC, "-n", std::to_string(np), "--oversubscribe",
                                  "--allow-run-as-root"};
    a.insert(a.end(), mesh.begin(), mesh.end());
    return a;
  };
  const Run seq = run_child(mesh, dir / "seq.log");
  const Quality sq = measure(prefix);
  const Table2 t2 = sequential_pipeline(prefix, 2);
  // np = 1 and np = 2 in turn, so that a pair's two runs meet about the same spell of the
  // machine; each np = 2 mesh measured right after its run (the next run replaces it).
  std::vector<Run> np1s, np2s;
  std::vector<Quality> pqs;
  for (int k = 0; k < pairs; ++k) {
    const std::string n = std::to_string(k + 1);
    np1s.push_back(run_child(mpirun(1), dir / ("np1-" + n + ".log")));
    np2s.push_back(run_child(mpirun(2), dir / ("np2-" + n + ".log")));
    pqs.push_back(measure(prefix));
  }
  // The pair of median speed-up (the upper median for an even count) among the pairs
  // whose runs both succeeded (a failed run's time says nothing); pair 1 if none did.
  std::vector<std::size_t> ok;
  for (int k = 0; k < pairs; ++k)
    if (np1s[k].exit_code == 0 && np2s[k].exit_code == 0 && pqs[k].read) ok.push_back(k);
  std::sort(ok.begin(), ok.end(), [&](std::size_t a, std::size_t b) {
    return np1s[a].wall / np2s[a].wall < np1s[b].wall / np2s[b].wall;
  });
  const std::size_t m = ok.empty() ? 0 : ok[ok.size() / 2];
  const Run &np1 = np1s[m], &np2 = np2s[m];
  const Quality& pq = pqs[m];
  const fs::path np2_log = dir / ("np2-" + std::to_string(m + 1) + ".log");
  const std::string v2 = [&] {
    char b[32];
    std::snprintf(b, sizeof b, "%g", 2 * std::stod(volume));
    return std::string(b);
  }();
  // What the two cores give this workload now: the sequential command at twice V (half
  // the tets) alone, then two of them at once. Two independent halves at once are np = 2
  // without any cost of its own (no M_o on every rank, no partition, no message, no
  // migration, no listing), so np=1 over the pair's time is the speed-up a perfect
  // parallel layer would reach on this machine in this spell; on a virtual machine whose
  // cores share a physical one, or whose host is busy, it can be well below 2.
  const auto half = [&](const std::string& name) {
    std::vector<std::string> a = mesh;
    for (std::size_t i = 0; i + 1 < a.size(); ++i) {
      if (a[i] == "--max-volume") a[i + 1] = v2;
      if (a[i] == "-o") a[i + 1] = (dir / "half" / name / poly.stem()).string();
    }
    fs::create_directories(dir / "half" / name);
    return a;
  };
  const Run alone = run_child(half("alone"), dir / "half-alone.log");
  const std::vector<Run> pair_runs = finish_children(
      {start_child(half("a"), dir / "half-a.log"), start_child(half("b"), dir / "half-b.log")});
  const Run &pa = pair_runs[0], &pb = pair_runs[1];
  const bool halves_ok = alone.exit_code == 0 && pa.exit_code == 0 && pb.exit_code == 0;
  // Issue #8's check target: on 2 ranks, at twice V (about 2M tets for the default case),
  // the exact check (and the order check) at rank 0 against the parallel refinement
  // (everything before the write: analysis, M_o, the phase, gather, assembly, completion).
  std::vector<std::string> checked = mpirun(2);
  for (std::size_t i = 0; i + 1 < checked.size(); ++i)
    if (checked[i] == "--max-volume") checked[i + 1] = v2;
  checked.erase(std::find(checked.begin(), checked.end(), "--no-check"));
  const Run np2c = run_child(checked, dir / "np2-check.log");
  const nlohmann::json jc = summary_of(dir / "np2-check.log");
  const fs::path tpoly = dir / "tetgen" / poly.filename();
  fs::copy_file(poly, tpoly, fs::copy_options::overwrite_existing);
  const Run t = run_child({tetgen, "-pq2.0a" + volume, "-Q", tpoly.string()}, dir / "tetgen.log");
  const Quality tq = measure((dir / "tetgen" / (poly.stem().string() + ".1")).string());
  std::printf("%s, V = %s\n", poly.filename().c_str(), volume.c_str());
  print("seq", seq, sq);
  std::printf("  np=1    %7.2f s wall %7.2f s cpu, exit %d (pair %zu of %d, the median speed-up)\n",
              np1.wall, np1.cpu, np1.exit_code, m + 1, pairs);
  print("np=2", np2, pq);
  std::printf("  np=1, np=2 in turn (s wall):");
  for (int k = 0; k < pairs; ++k) std::printf(" %.2f %.2f (%.2fx)%s", np1s[k].wall, np2s[k].wall,
                                              np1s[k].wall / np2s[k].wall, k + 1 < pairs ? "," : "\n");
  print("TetGen", t, tq);
  const double r1 = np1.wall / seq.wall, r2 = np1.wall / np2.wall;
  std::printf("  np=1 / sequential: %.2fx wall (target <= 1.15: %s)\n", r1,
              r1 <= 1.15 ? "met" : "NOT MET");
  std::printf("  np=2 speed-up over np=1: %.2fx wall, the median of %zu pairs (target >= 1.6: %s)\n",
              r2, ok.size(), r2 >= 1.6 ? "met" : "NOT MET");
  if (halves_ok) {
    const double pair = std::max(pa.wall, pb.wall), ideal = np1.wall / pair;
    std::printf("  two cores on this workload, right after np=2: the sequential command at V = "
                "%s alone %.2f s, two at once %.2f s and %.2f s (%.2fx one alone); a parallel "
                "layer without costs of its own would have been about %.2fx faster than np=1: "
                "np=2 reached about %.0f%% of that\n",
                v2.c_str(), alone.wall, pa.wall, pb.wall, pair / alone.wall, ideal,
                100 * r2 / ideal);
  } else {
    std::printf("  two cores on this workload: A HALF-SIZE SEQUENTIAL RUN FAILED (exit %d, %d, %d)\n",
                alone.exit_code, pa.exit_code, pb.exit_code);
  }
  std::printf("  np=2 vs TetGen: %.2fx TetGen's tets/s (wall)\n",
              (double(pq.tets) / np2.wall) / (double(tq.tets) / t.wall));
  if (jc.contains("seconds")) {
    const auto& s = jc.at("seconds");
    double refinement = 0, check = 0;
    for (const auto& [k, v] : s.items()) {
      if (k == "check" || k == "order_check") check += v.get<double>();
      else if (k != "write") refinement += v.get<double>();
    }
    std::printf("  np=2 with the check, V = %s: %llu tets, check %.2f s (order check "
                "included) against the parallel refinement %.2f s (target: no longer: %s), "
                "exit %d\n",
                v2.c_str(), jc.value("tets", 0ull), check, refinement,
                check <= refinement ? "met" : "NOT MET", np2c.exit_code);
  }
  const nlohmann::json j = summary_of(np2_log);
  if (j.contains("seconds")) {
    std::printf("  np=2 phases:");
    for (const auto& [k, v] : j.at("seconds").items()) std::printf(" %s %.2f s", k.c_str(), v.get<double>());
    std::printf("\n");
  }
  std::printf("  Table 2 (2 parts): sequential pipeline %.2f s = mesh %.2f + read %.2f + METIS "
              "%.2f + write %.2f + read the pieces %.2f (%s); parallel pipeline (np=2) "
              "%.2f s: %.2fx faster\n",
              seq.wall + t2.total(), seq.wall, t2.read, t2.partition, t2.write, t2.reread,
              t2.ok ? "every tet in one piece" : "FAILED", np2.wall,
              (seq.wall + t2.total()) / np2.wall);
  if (j.contains("parallel")) print_table1(j.at("parallel"));
  if (j.contains("parallel"))
    for (const auto& r : j.at("parallel").at("per_rank"))
      std::printf("  rank %d: %.2f s phase, %.2f s busy (%.0f%%), %llu commits (%llu while "
                  "waiting, %llu on the boundary), %llu setbacks, %llu tets migrated, %llu "
                  "messages\n",
                  r.at("rank").get<int>(), r.at("seconds").get<double>(),
                  r.at("busy_seconds").get<double>(),
                  100 * r.at("busy_seconds").get<double>() /
                      std::max(1e-9, r.at("seconds").get<double>()),
                  r.at("commits").get<unsigned long long>(),
                  r.at("local_while_waiting").get<unsigned long long>(),
                  r.at("splits").get<unsigned long long>() +
                      r.at("facet_points").get<unsigned long long>(),
                  r.at("setbacks").get<unsigned long long>(),
                  r.at("tets_migrated").get<unsigned long long>(),
                  r.at("messages_sent").get<unsigned long long>());
  bool all_ok = true;
  for (int k = 0; k < pairs; ++k)
    all_ok = all_ok && np1s[k].exit_code == 0 && np2s[k].exit_code == 0 && pqs[k].read;
  return seq.exit_code == 0 && all_ok && np2c.exit_code == 0 && halves_ok && sq.read;
}

}  // namespace

int main(int argc, char** argv) {
  std::string pdr = PDR_BENCH_PDR, tetgen = PDR_BENCH_TETGEN;
  fs::path data = PDR_BENCH_DATA;
  int runs = 1, pairs = 3;
  bool check = true, keep = false, outside = false, parallel = false;
  std::vector<Case> cases;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "bench_mesh: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--pdr") pdr = next();
    else if (a == "--tetgen") tetgen = next();
    else if (a == "--data") data = next();
    else if (a == "--runs") runs = std::atoi(next().c_str());
    else if (a == "--no-check") check = false;
    else if (a == "--keep") keep = true;
    else if (a == "--outside") outside = true;
    else if (a == "--parallel") parallel = true;
    else if (a == "--pairs") {
      pairs = std::atoi(next().c_str());
      if (pairs < 1) {
        std::fprintf(stderr, "bench_mesh: --pairs needs a count of at least 1\n");
        return 2;
      }
    }
    else if (const auto colon = a.rfind(':'); colon != std::string::npos && colon > 0)
      cases.push_back({a.substr(0, colon), a.substr(colon + 1)});
    else {
      std::fprintf(stderr,
                   "usage: bench_mesh [--pdr PATH] [--tetgen PATH] [--data DIR] [--runs N] "
                   "[--no-check] [--keep] [--outside] [--parallel] [--pairs N] [CASE.poly:V ...]\n");
      return 2;
    }
  }
  // --parallel: the paper's largest run, cube-in-cube at about 4M tets.
  if (cases.empty() && parallel) cases.push_back({"cube-in-cube.poly", "0.0005"});
  if (cases.empty() && outside) cases.assign(std::begin(kOutsideCases), std::end(kOutsideCases));
  if (cases.empty()) cases.assign(std::begin(kDefaultCases), std::end(kDefaultCases));

  char tmpl[] = "/tmp/bench_mesh.XXXXXX";
  if (!mkdtemp(tmpl)) {
    std::perror("bench_mesh: mkdtemp");
    return 1;
  }
  const fs::path dir = tmpl;
  fs::create_directories(dir / "pdr");
  fs::create_directories(dir / "tetgen");
  int status = 0;
  if (parallel) {
    std::printf("pdr mesh sequential, mpirun -n 1 and -n 2 pdr mesh (--ratio 2 --no-check), "
                "TetGen (-pq2.0a<V>), each a child process\n");
    for (const Case& c : cases) {
      const fs::path poly = fs::path(c.poly).is_absolute() || fs::exists(c.poly)
                                ? fs::path(c.poly)
                                : data / c.poly;
      for (int run = 0; run < runs; ++run)
        if (!parallel_case(pdr, tetgen, poly, c.volume, dir, pairs)) status = 1;
    }
    if (keep) std::printf("outputs kept in %s\n", dir.c_str());
    else fs::remove_all(dir);
    return status;
  }
  std::printf("pdr mesh (--ratio 2) vs TetGen (-pq2.0a<V>), each a child process; peak = "
              "max RSS of the process; B/tet = peak / tets\n");
  for (const Case& c : cases) {
    const fs::path poly = fs::path(c.poly).is_absolute() || fs::exists(c.poly)
                              ? fs::path(c.poly)
                              : data / c.poly;
    const std::string stem = poly.stem().string();
    // TetGen writes next to its input: give it its own copy.
    const fs::path tpoly = dir / "tetgen" / poly.filename();
    fs::copy_file(poly, tpoly, fs::copy_options::overwrite_existing);
    const std::string pprefix = (dir / "pdr" / stem).string();
    const std::string tprefix = (dir / "tetgen" / (stem + ".1")).string();
    for (int run = 0; run < runs; ++run) {
      std::printf("%s, V = %s%s\n", poly.filename().c_str(), c.volume.c_str(),
                  runs > 1 ? (" (run " + std::to_string(run + 1) + ")").c_str() : "");
      const Run p = run_child({pdr, "mesh", poly.string(), "-o", pprefix, "--ratio", "2",
                               "--max-volume", c.volume, "--no-check", "--formats", "node"},
                              dir / "pdr.log");
      const Quality pq = measure(pprefix);
      const Run t = run_child({tetgen, "-pq2.0a" + c.volume, "-Q", tpoly.string()},
                              dir / "tetgen.log");
      const Quality tq = measure(tprefix);
      print("pdr", p, pq);
      print("TetGen", t, tq);
      if (pq.read && tq.read)
        std::printf("  pdr/TetGen: speed %.2fx wall, %.2fx cpu (tets/s); memory %.2fx "
                    "(B/tet)\n",
                    (double(pq.tets) / p.wall) / (double(tq.tets) / t.wall),
                    (double(pq.tets) / p.cpu) / (double(tq.tets) / t.cpu),
                    (double(p.peak) / double(pq.tets)) / (double(t.peak) / double(tq.tets)));
      // Issue #11's targets outside the theory: pdr's time (without its check) within 1.5x
      // TetGen's, and fewer tets with ratio >= 2 than TetGen leaves (none where it leaves none).
      if (outside && pq.read && tq.read)
        std::printf("  targets: time pdr/TetGen %.2fx wall (<= 1.5x: %s); ratio >= 2 pdr %zu, "
                    "TetGen %zu (fewer: %s)\n",
                    p.wall / t.wall, p.wall <= 1.5 * t.wall ? "met" : "NOT met", pq.skinny,
                    tq.skinny,
                    pq.skinny < tq.skinny || (pq.skinny == 0 && tq.skinny == 0) ? "met"
                                                                                : "NOT met");
      if (check) {
        // The exact checker on both outputs, against the domain: validity, Delaunay,
        // conformity, encroachment, and the ratio bound.
        const auto checked = [&](const char* who, const std::string& prefix, bool read) {
          if (!read) return;
          const Run k = run_child({pdr, "check", prefix, "--domain", poly.string(), "--ratio", "2"},
                                  dir / "check.log");
          std::printf("  check   pdr check of %s mesh: %.2f s wall %.2f s cpu %.1f MiB peak, "
                      "exit %d (%s)\n",
                      who, k.wall, k.cpu, double(k.peak) / 1048576.0, k.exit_code,
                      k.exit_code == 0 ? "pass" : failed_checks(dir / "check.log").c_str());
        };
        checked("pdr's", pprefix, pq.read);
        checked("TetGen's", tprefix, tq.read);
      }
      if (!pq.read || !tq.read || (p.exit_code != 0 && p.exit_code != 3) || t.exit_code != 0)
        status = 1;
    }
  }
  if (keep) std::printf("outputs kept in %s\n", dir.c_str());
  else fs::remove_all(dir);
  return status;
}
