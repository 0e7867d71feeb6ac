// `mpirun -np P pdr mesh`: see app/parallel.hpp.
#include "app/parallel.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>
#include <limits>
#include <stdexcept>
#include <span>
#include <string>
#include <string_view>
#include <system_error>

#include "io/mesh_io.hpp"
#include "io/tetgen_lines.hpp"
#include "io/text_sink.hpp"
#include "mesh/huge_pages.hpp"
#include "par/affinity.hpp"
#include "par/assembly.hpp"
#include "par/mesh_parts.hpp"
#include "par/mpi_collect.hpp"
#include "par/mpi_transport.hpp"
#include "par/par_refinement.hpp"
#include "par/partition.hpp"
#include "par/rank_files.hpp"
#include "refine/budget.hpp"

namespace pdr::app {
namespace {

// The volume of the inside tets, in double: it only sizes the coarse refinement.
double inside_volume(const refine::VolumeMesh& m) {
  const TetStore& s = m.dt.store();
  double vol = 0;
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t) || s.is_ghost(t) || !m.is_inside(t)) continue;
    const VertexId* v = s.vertices(t);
    const Point &a = m.dt.point(v[0]), &b = m.dt.point(v[1]), &c = m.dt.point(v[2]),
                &d = m.dt.point(v[3]);
    double u[3], w[3], x[3];
    for (int k = 0; k < 3; ++k) u[k] = b[k] - a[k], w[k] = c[k] - a[k], x[k] = d[k] - a[k];
    vol += std::abs(u[0] * (w[1] * x[2] - w[2] * x[1]) - u[1] * (w[0] * x[2] - w[2] * x[0]) +
                    u[2] * (w[0] * x[1] - w[1] * x[0])) / 6;
  }
  return vol;
}

// The coarse refinement's options: for interior tets the size bounds raised, to about
// `tets` interior tets (0: sixteen times the final volume bound, or 2.5 times the final
// radius bound, with at most about 100K interior tets, the size the paper started from),
// never finer than the user asked (no size bound: none here). Refinement under a volume
// bound V stops once no tet exceeds V, so its tets average less: about V / kFill
// (measured on cube-in-cube: 188K tets under the bound volume / 100K, 94K under volume /
// 50K), and about `tets` of them need the bound kFill * volume / tets. Calibrated for the
// volume bound only: where the user gives a radius bound (--size) and no volume bound,
// its floor cbrt(v0) binds earlier and M_o has more tets. The same for tets at
// the boundary when the parallel phase refines D too (`surface_steps`); else the user's
// bounds there, so that D is refined about as far as the final mesh needs, and the
// phase, which then defers every step on ∂Ω, rarely meets it.
refine::RefineOptions coarse_options(const refine::RefineOptions& opt, double volume,
                                     std::size_t tets, bool surface_steps) {
  constexpr double kAutoVolume = 16, kAutoRadius = 2.5, kAutoMaxTets = 100000, kFill = 1.9;
  refine::RefineOptions c = opt;
  c.on_progress = nullptr;
  const double v0 = kFill * volume / (tets > 0 ? static_cast<double>(tets) : kAutoMaxTets);
  refine::TetBounds in{opt.ratio, opt.size, opt.max_volume};
  if (in.max_volume)
    in.max_volume = std::max(*in.max_volume * (tets > 0 ? 1 : kAutoVolume), v0);
  if (in.size) in.size = std::max(*in.size * (tets > 0 ? 1 : kAutoRadius), std::cbrt(v0));
  c.interior = in;
  if (surface_steps) c.max_volume = in.max_volume, c.size = in.size;
  return c;
}

// The paper's Table 1 for one rank (docs/parallel.md: how each figure is measured).
double latency_tolerance(const par::InsertionStats& s) {
  const double masked = s.masked_local_s + s.masked_distributed_s;
  return masked + s.setback_s > 0 ? masked / (masked + s.setback_s) : 1.0;
}

nlohmann::json table1_json(const par::RankFigures& f) {
  const auto& s = f.steps;
  return nlohmann::json{{"execution_seconds", f.seconds},
                        {"completed_cavity_seconds", {{"local", s.completed_local_s},
                                                      {"distributed", s.completed_distributed_s}}},
                        {"masked_seconds", {{"local", s.masked_local_s},
                                            {"distributed", s.masked_distributed_s}}},
                        {"setback_seconds", s.setback_s},
                        {"latency_tolerance", latency_tolerance(s)},
                        {"served_seconds", s.served_s},
                        {"other_seconds", s.other_s},
                        {"poll_seconds", s.poll_s},
                        {"poll_excess_seconds", s.poll_excess_s}};
}

nlohmann::json figures_json(int rank, const par::RankFigures& f) {
  const auto& s = f.steps;
  return nlohmann::json{
      {"rank", rank},
      {"seconds", f.seconds},
      {"busy_seconds", f.busy_seconds},
      {"commits", s.commits},
      {"splits", s.splits},
      {"facet_points", s.facet_points},
      {"deferred", {{"outside", f.deferred.outside},
                    {"subsegment", f.deferred.subsegment},
                    {"subfacet", f.deferred.subfacet},
                    {"removed", f.deferred.removed},
                    {"refused", f.deferred.refused},
                    {"cap", f.deferred.cap}}},
      {"deferred_early", s.deferred_early},
      {"setbacks", s.setbacks},
      {"rounds", s.rounds},
      {"fetches_served", s.fetches_served},
      {"fetches_refused", s.refused},
      {"fetches_rejected", s.fetches_rejected},
      {"tets_migrated", s.tets_sent},
      {"queued_tets_gone", s.gone},
      {"local_while_waiting", s.local_while_waiting},
      {"messages_sent", f.messages_sent},
      {"messages_received", f.messages_received},
      {"bytes_sent", f.bytes_sent},
      {"empty_polls", f.empty_polls},
      {"sleeps", f.sleeps},
      {"start_tets", f.start_tets},
      {"final_tets", f.final_tets},
      {"table1", table1_json(f)}};
}

void print_table(const std::vector<par::RankFigures>& all) {
  std::fprintf(stderr, "parallel phase: %-4s %8s %8s %9s %8s %9s %8s %9s %9s %10s\n", "rank",
               "seconds", "busy", "commits", "on_bdry", "deferred", "setbacks", "migrated",
               "messages", "final_tets");
  for (std::size_t r = 0; r < all.size(); ++r) {
    const par::RankFigures& f = all[r];
    const auto& d = f.deferred;
    std::fprintf(stderr,
                 "parallel phase: %-4zu %8.3f %8.3f %9llu %8llu %9llu %8llu %9llu %9llu %10llu\n",
                 r, f.seconds, f.busy_seconds, static_cast<unsigned long long>(f.steps.commits),
                 static_cast<unsigned long long>(f.steps.splits + f.steps.facet_points),
                 static_cast<unsigned long long>(d.outside + d.subsegment + d.subfacet + d.removed + d.cap),
                 static_cast<unsigned long long>(f.steps.setbacks),
                 static_cast<unsigned long long>(f.steps.tets_sent),
                 static_cast<unsigned long long>(f.messages_sent),
                 static_cast<unsigned long long>(f.final_tets));
  }
  // Table 1 (seconds), each rank and the slowest one.
  std::fprintf(stderr, "table 1:        %-5s %8s %9s %9s %9s %9s %8s %8s %8s %8s\n", "rank", "exec",
               "cav.local", "cav.dist", "mask.loc", "mask.dist", "setback", "lat.tol", "poll",
               "excess");
  std::size_t worst = 0;
  for (std::size_t r = 0; r < all.size(); ++r)
    if (all[r].seconds > all[worst].seconds) worst = r;
  auto row = [&](const std::string& name, const par::RankFigures& f) {
    const auto& s = f.steps;
    std::fprintf(stderr, "table 1:        %-5s %8.3f %9.3f %9.3f %9.3f %9.3f %8.3f %7.1f%% %8.3f %8.3f\n",
                 name.c_str(), f.seconds, s.completed_local_s, s.completed_distributed_s,
                 s.masked_local_s, s.masked_distributed_s, s.setback_s,
                 100 * latency_tolerance(s), s.poll_s, s.poll_excess_s);
  };
  for (std::size_t r = 0; r < all.size(); ++r) row(std::to_string(r), all[r]);
  if (!all.empty()) row("worst", all[worst]);
}

// A rank's part of the listed mesh, for the files the ranks write themselves: its inside
// tets and boundary faces (in output vertex numbers) and the points its submeshes made,
// in number order (par/mesh_parts.hpp).
struct OwnPart {
  MeshData mesh;
  std::vector<Point> points;
  std::uint64_t quality_tets = 0;  // the tets its quality figures cover
  std::size_t vertices = 0;        // the output's vertices (par::VertexNumbers::total)
};

// Every rank writes its lines of PREFIX.node, .ele and .face (io/tetgen_lines.hpp) at its
// place in the files (par/rank_files.hpp): rank 0 the headers and M_o's points `m0`
// first, then each rank its points, tets and faces in rank order (the order in which
// rank 0 would have joined them), the last rank the tails. Collective; returns the mesh's
// counts (vertices, tets, faces) on every rank.
std::array<std::size_t, 3> write_parts(const std::string& prefix, const OwnPart& own,
                                       std::span<const Point> m0, const World& w) {
  // Per rank: points, tets, faces, and the tets its quality figures cover.
  const std::vector<std::uint64_t> counts = par::all_values(
      {own.points.size(), own.mesh.tets.size(), own.mesh.faces.size(), own.quality_tets});
  std::array<std::size_t, 3> first{m0.size(), 0, 0}, total{m0.size(), 0, 0};
  std::size_t quality_tets = 0;
  for (int r = 0; r < w.size; ++r) {
    const std::size_t row = 4 * static_cast<std::size_t>(r);
    for (std::size_t k = 0; k < 3; ++k) {
      const auto n = static_cast<std::size_t>(counts[row + k]);
      total[k] += n;
      if (r < w.rank) first[k] += n;
    }
    quality_tets += static_cast<std::size_t>(counts[row + 3]);
  }
  // What the joined path checks before it writes; every rank finds it alike, rank 0 says
  // it (an internal error) and the others write nothing.
  if (total[0] != own.vertices || quality_tets != total[1]) {
    if (w.rank != 0) return total;
    throw std::logic_error("the ranks' parts list " + std::to_string(total[0]) + " points (their " +
                           "numbers " + std::to_string(own.vertices) + ") and " +
                           std::to_string(total[1]) + " tets (their quality figures " +
                           std::to_string(quality_tets) + ")");
  }
  // The .node and .face parts are formatted in memory (points' lengths are known only
  // once formatted; faces are few); the .ele part, most of the bytes, is formatted as it
  // is written, in pieces of about 1 MiB, its length counted first from the digits, so
  // that its text never stands whole in memory.
  std::array<io::TextSink, 2> out;  // .node, .face
  reserve_huge(out[0].text(), (own.points.size() + (w.rank == 0 ? m0.size() : 0)) * 72 + 256);
  const bool markers = total[2] > 0;  // as the joined mesh's face_markers (one per face)
  io::TextSink ele_head, ele_tail;  // rank 0's header, the last rank's tail
  if (w.rank == 0) {
    io::tetgen_lines::node_header(out[0], total[0], false);
    io::tetgen_lines::nodes(out[0], m0, 0, {});
    io::tetgen_lines::ele_header(ele_head, total[1], false);
    io::tetgen_lines::face_header(out[1], total[2], markers);
  }
  io::tetgen_lines::nodes(out[0], own.points, first[0], {});
  io::tetgen_lines::faces(out[1], own.mesh.faces, first[2], own.mesh.face_markers);
  if (w.rank == w.size - 1) {
    for (io::TextSink& o : out) io::tetgen_lines::tail(o);
    io::tetgen_lines::tail(ele_tail);
  }
  if (w.rank == 0) {
    // A directory that cannot be made is reported when its files cannot be created.
    std::error_code ignored;
    if (const auto parent = std::filesystem::path(prefix).parent_path(); !parent.empty())
      std::filesystem::create_directories(parent, ignored);
  }
  const std::vector<std::string> paths = io::output_paths(prefix, io::MeshFormat::TetGen);
  using Put = std::function<void(std::string_view)>;
  const auto whole = [](const std::string* text) {
    return par::StreamedPart{text->size(), [text](const Put& put) { put(*text); }};
  };
  const std::array<par::StreamedPart, 3> parts{
      whole(&out[0].text()),
      par::StreamedPart{
          ele_head.text().size() + io::tetgen_lines::eles_bytes(own.mesh.tets, first[1], {}) +
              ele_tail.text().size(),
          [&](const Put& put) {
            put(ele_head.text());
            io::TextSink lines(put);
            io::tetgen_lines::eles(lines, own.mesh.tets, first[1], {});
            lines.flush();
            put(ele_tail.text());
          }},
      whole(&out[1].text())};
  par::write_in_rank_order(paths, parts);  // false elsewhere than rank 0: rank 0 ends the run
  return total;
}

}  // namespace

World& world() {
  static World w;
  return w;
}

std::optional<refine::RefineResult> refine_in_parallel(refine::VolumeMesh& vm,
                                                       const refine::RefineOptions& opt,
                                                       std::size_t initial_tets,
                                                       std::size_t submeshes,
                                                       std::uint64_t latency_us,
                                                       std::uint64_t seed, Summary& summary,
                                                       PhaseTimer& timer, double& seconds,
                                                       VertexOwners* owners,
                                                       std::optional<refine::QualityRange>& quality,
                                                       const Listing* listing,
                                                       std::optional<ListedMesh>& listed) {
  const World w = world();
  // M_o: the same on every rank.
  // Steps on ∂Ω in the phase where D's changes are exact (par/refinement_rules.hpp).
  const bool surface_steps = opt.exact_theory;
  const double shortest_t0 = refine::shortest_inside_edge(vm);  // T_o's, for Theorem 1's h
  // The sequential command's vertex cap (the same base: T_o): the phase's ranks share what
  // M_o leaves of it.
  const std::size_t cap = refine::VertexBudget(vm.dt.points(), opt).cap();
  const refine::RefineResult coarse = refine::refine(
      vm, coarse_options(opt, inside_volume(vm), initial_tets, surface_steps));
  vm.missing_subfacets.clear();  // restored (or reported again by the completion below)
  vm.missing_subsegments.clear();
  const std::size_t m0_tets = vm.inside_tets();
  seconds = timer.lap("coarse");
  if (const int other = checkpoint(0); other != 0)
    throw RunAbandoned("another rank failed (exit " + std::to_string(other) + ")");
  // A coarse run that stopped at its cap, or left D out of T, is not a mesh to distribute:
  // every rank then leaves the whole refinement to rank 0.
  bool distribute = coarse.stop_reason.empty() && coarse.stats.conformity_refused == 0;
  std::vector<Point> points;  // for `owners`
  std::vector<std::byte> pieces;
  std::vector<par::SurfaceStep> d_steps;  // the phase's steps on ∂Ω, all ranks'
  std::vector<par::RankFigures> figures;
  // The ranks' parts of the mesh, joined at rank 0 (par/mesh_parts.hpp).
  struct Joined {
    std::vector<Point> points;        // the phase's, in vertex-number order
    MeshData mesh;                    // tets, faces and markers
    std::vector<std::uint64_t> sizes;  // per rank: its tets, its stores' bytes
    std::size_t vertices = 0;
  };
  std::optional<Joined> joined;
  // This rank's part, when the ranks write the files themselves (Listing::write_prefix).
  std::optional<OwnPart> own;
  std::array<std::size_t, 3> own_counts{};  // the written mesh's vertices, tets, faces
  par::Partition part;
  // More submeshes than M_o can give (METIS would leave one empty): one per rank instead;
  // fewer tets than ranks: rank 0 refines alone. Every rank decides alike (same M_o, seed).
  std::string partition_note;
  if (distribute) {
    const std::size_t wanted = submeshes == 0 ? std::size_t(w.size) : submeshes;
    for (const std::size_t parts : {wanted, std::size_t(w.size)}) {
      try {
        part = par::partition_tets(vm.dt.store(), vm.inside, static_cast<std::uint32_t>(parts), seed);
        break;
      } catch (const std::invalid_argument& e) {
        partition_note += (partition_note.empty() ? "" : "; ") + std::string(e.what());
        part = {};
      }
    }
    distribute = part.parts > 0;
  }
  if (distribute) {
    try {
      par::RankResult mine;
      {
        par::MpiTransport t{std::chrono::microseconds(latency_us)};
        try {
          const std::size_t n0 = vm.dt.num_points();
          mine = par::refine_part(vm, part, t,
                                  {opt.ratio, opt.size, opt.max_volume, opt.region_volumes.get()},
                                  seed, surface_steps,
                                  cap > n0 ? (cap - n0) / static_cast<std::size_t>(w.size) : 0);
        } catch (const std::exception& e) {
          // Here, not after the transport's destructor: it would wait for sends and a
          // reduction round that the other ranks, waiting for this one, never complete.
          std::fprintf(stderr, "pdr: rank %d: internal error in the parallel phase: %s\n",
                       w.rank, e.what());
          par::MpiSession::abort(4);
        }
      }
      seconds += timer.lap("parallel");
      // The ranks list the mesh themselves when the completion would have nothing to do
      // (par/mesh_parts.hpp): the completion would resume the phase's run (M_o met
      // Theorem 1's hypotheses), an admissible one (no guards), no step was deferred and
      // each part is final. Every rank learns the verdict and every submesh's count of
      // made vertices (the vertex numbers) in one sum.
      bool final_here = listing != nullptr && opt.admissible && coarse.stats.h_theorem > 0;
      for (const par::Submesh& sub : mine.submeshes) final_here = final_here && par::part_is_final(sub);
      // The sum's last entry: the submeshes' tets, a bound on the listed ones (rank 0
      // reserves room for all of them and receives the others' where they go).
      std::vector<std::uint64_t> sums(2 + part.parts, 0);
      sums[0] = final_here ? 0 : 1;
      for (std::size_t i = 0; i < mine.made.size(); ++i)
        sums[1 + static_cast<std::size_t>(w.rank) + i * static_cast<std::size_t>(w.size)] = mine.made[i];
      for (const par::Submesh& sub : mine.submeshes) sums.back() += sub.real_tets();
      sums = par::sum_over_ranks(sums);
      if (sums[0] == 0) {
        const par::VertexNumbers num(vm.dt.num_points(), std::span(sums).subspan(1, part.parts), w.size);
        MeshData mesh;
        const bool ranks_write = !listing->write_prefix.empty();
        if (w.rank == 0 && !ranks_write) {
          reserve_huge(mesh.tets, sums.back());
          reserve_huge(mine.points, num.total() - vm.dt.num_points());
        } else if (ranks_write) {
          std::size_t mine_tets = 0;
          for (const par::Submesh& sub : mine.submeshes) mine_tets += sub.real_tets();
          reserve_huge(mesh.tets, mine_tets);
        }
        std::uint64_t bytes = 0;
        for (const par::Submesh& sub : mine.submeshes) {
          par::add_part(sub, num, listing->facet_markers, mesh, mine.figures.quality);
          bytes += sub.store().bytes_allocated();
        }
        std::vector<par::Submesh>().swap(mine.submeshes);
        joined.emplace();
        joined->sizes = par::gather_values(std::vector<std::uint64_t>{mesh.tets.size(), bytes});
        joined->vertices = num.total();
        if (ranks_write) {
          // The boundary faces close a surface (below), checked before anything is written:
          // every rank's odd edges, together at rank 0.
          // If they do not, rank 0 says so (an internal error) and the others write nothing.
          const std::vector<std::uint64_t> odd = par::gather_values(par::odd_edges(mesh.faces));
          const bool closed = par::broadcast_from_root((w.rank != 0 || par::edges_pair_up(odd)) ? 1 : 0) != 0;
          if (!closed && w.rank == 0)
            throw std::logic_error("the ranks' parts: their boundary faces do not close a "
                                   "surface (an edge in an odd number of them)");
          if (closed)
            own.emplace(OwnPart{std::move(mesh), std::move(mine.points), mine.figures.quality.tets,
                                num.total()});
          if (w.rank != 0) joined.reset();
        } else {
          // Rank 0's arrays take the others' parts; the others free each once it is sent.
          par::gather_append(mine.points);
          joined->points = std::move(mine.points);
          par::gather_append(mesh.tets);
          joined->mesh.tets = std::move(mesh.tets);
          par::gather_append(mesh.faces);
          joined->mesh.faces = std::move(mesh.faces);
          par::gather_append(mesh.face_markers);
          joined->mesh.face_markers = std::move(mesh.face_markers);
          if (w.rank != 0) joined.reset();
        }
      } else {
        mine.figures.quality = par::quality_of(mine.submeshes);
        {
          const par::Bytes mine_pieces = par::pieces_of(mine.submeshes);
          std::vector<par::Submesh>().swap(mine.submeshes);
          pieces = par::gather_bytes(mine_pieces);
        }
        if (owners != nullptr) points = par::gather_points(mine.points);
        const std::vector<std::byte> step_bytes =
            par::gather_bytes(std::as_bytes(std::span(mine.surface_steps)));
        d_steps.resize(step_bytes.size() / sizeof(par::SurfaceStep));
        if (!step_bytes.empty()) std::memcpy(d_steps.data(), step_bytes.data(), step_bytes.size());
      }
      figures = par::gather_figures(mine.figures);
      seconds += timer.lap("gather");
    } catch (const std::exception& e) {
      std::fprintf(stderr, "pdr: rank %d: internal error in the parallel phase: %s\n", w.rank,
                   e.what());
      par::MpiSession::abort(4);
    }
  }
  // Outside the phase's try: a file that cannot be written is the user's to mend (exit 2,
  // as in the sequential command), not an internal error.
  if (own) {
    own_counts = write_parts(listing->write_prefix, *own, vm.dt.points(), w);
    own.reset();
    timer.lap("write");
  }
  if (w.rank != 0) return std::nullopt;
  // The other ranks are done; they sleep until rank 0 says how the run ended, so rank 0's
  // threads (the writers', the checker's) may use their cores (par/affinity.hpp).
  par::use_every_cpu();
  // Table 1 and the run's parallel figures (docs/parallel.md); `absorbed`: the vertices
  // the phase added to M_o.
  const auto report = [&](std::size_t absorbed) {
    std::uint64_t committed = 0;
    for (const par::RankFigures& f : figures) committed += f.points;
    nlohmann::json ranks = nlohmann::json::array();
    double slowest = 0;
    std::size_t worst = 0;
    for (std::size_t r = 0; r < figures.size(); ++r) {
      ranks.push_back(figures_json(static_cast<int>(r), figures[r]));
      slowest = std::max(slowest, figures[r].seconds);
      if (figures[r].seconds > figures[worst].seconds) worst = r;
    }
    summary.set("parallel", nlohmann::json{{"schema_version", 3},
                                           {"worst_rank", figures.empty() ? nlohmann::json(nullptr)
                                                                          : nlohmann::json(worst)},
                                           {"ranks", w.size},
                                           {"submeshes", distribute ? part.parts : 0u},
                                           {"injected_latency_us", latency_us},
                                           {"distributed", distribute},
                                           {"partition_note", partition_note},
                                           {"initial_tets", m0_tets},
                                           {"points", committed},
                                           {"points_absorbed", absorbed},
                                           {"listed_by_ranks", listed.has_value()},
                                           {"written_by_ranks", listed && !listed->written.empty()},
                                           {"slowest_rank_seconds", slowest},
                                           {"per_rank", ranks}});
    if (!figures.empty()) print_table(figures);
  };
  if (joined) {
    // The mesh is the ranks' parts joined: M_o's points, then the phase's, numbered as
    // the parts number them; the completion would have changed nothing, so its result is
    // what it would have returned (RefineOptions::resumed_h, no start tets).
    ListedMesh& out = listed.emplace();
    const std::size_t vertices = joined->vertices;
    const auto unchanged = [&] {
      report(vertices - vm.dt.num_points());
      refine::RefineResult rr;
      rr.stats.h = std::numeric_limits<double>::infinity();
      rr.stats.h_theorem = refine::theorem_h(shortest_t0, opt);
      rr.stats.vertex_cap = cap;  // the sequential command's (its base: T_o)
      rr.tets_unchanged = true;
      quality.emplace();
      for (const par::RankFigures& f : figures) quality->merge(f.quality);
      return rr;
    };
    for (std::size_t r = 0; r * 2 + 1 < joined->sizes.size(); ++r)
      out.topology_bytes += joined->sizes[2 * r + 1];
    if (!listing->write_prefix.empty()) {
      // The ranks wrote the files (write_parts checked the counts before).
      out.written = io::output_paths(listing->write_prefix, io::MeshFormat::TetGen);
      out.vertices = own_counts[0];
      out.tets = own_counts[1];
      out.faces = own_counts[2];
      joined.reset();
      return unchanged();
    }
    out.mesh.points.reserve(vertices);
    out.mesh.points.assign(vm.dt.points().begin(), vm.dt.points().end());
    out.mesh.points.insert(out.mesh.points.end(), joined->points.begin(), joined->points.end());
    if (out.mesh.points.size() != vertices)
      throw std::logic_error("the ranks' parts list " + std::to_string(out.mesh.points.size()) +
                             " points, their numbers " + std::to_string(vertices));
    out.mesh.tets = std::move(joined->mesh.tets);
    out.mesh.faces = std::move(joined->mesh.faces);
    out.mesh.face_markers = std::move(joined->mesh.face_markers);
    for (std::size_t r = 0; r * 2 + 1 < joined->sizes.size(); ++r)
      out.tet_rank.insert(out.tet_rank.end(), joined->sizes[2 * r], static_cast<std::uint32_t>(r));
    joined.reset();
    if (out.tet_rank.size() != out.mesh.tets.size())
      throw std::logic_error("the ranks' parts: tet counts do not add up");
    // The ranks read the boundary off their labels (par/mesh_parts.hpp); a surface that
    // does not close (labels that are not D) is an internal error, not an output.
    if (!par::surface_closed(out.mesh.faces))
      throw std::logic_error("the ranks' parts: their boundary faces do not close a surface "
                             "(an edge in an odd number of them)");
    seconds += timer.lap("join");
    return unchanged();
  }
  if (owners != nullptr) {
    owners->parts = w.size;
    if (distribute) {
      std::size_t next = 0;
      for (std::size_t r = 0; r < figures.size(); ++r)
        for (std::uint64_t i = 0; i < figures[r].points && next < points.size(); ++i)
          owners->committed.emplace(points[next++], static_cast<std::uint32_t>(r));
      const TetStore& s = vm.dt.store();
      for (TetId t = 0; t < part.part.size(); ++t) {
        if (part.part[t] == par::kNoPart || s.vertex(t, 3) >= kFirstSpecialVertex) continue;  // ghosts too
        for (int k = 0; k < 4; ++k) {
          const std::uint32_t rank = part.part[t] % static_cast<std::uint32_t>(w.size);
          const auto [it, fresh] = owners->initial.emplace(vm.dt.point(s.vertex(t, k)), rank);
          if (!fresh) it->second = std::min(it->second, rank);
        }
      }
    }
    seconds += timer.lap("owners");
  }
  // The whole mesh from the submeshes' tets, in place of M_o (par/assembly.hpp).
  par::Assembled assembled;
  if (distribute) {
    par::Assembly a(vm);
    for (par::WireReader r(pieces); !r.done();) a.add(par::get_piece_view(r));
    assembled = a.finish(vm, d_steps);
    std::vector<std::byte>().swap(pieces);
  }
  seconds += timer.lap("assemble");
  report(assembled.added);
  // The completion: every bad tet the phase left is one it marked deferred (its steps
  // and arrivals are all tested, and termination leaves no queue), so only those are
  // queued at the start, not every tet tested again.
  refine::RefineOptions rest = opt;
  if (distribute) rest.start_tets = std::move(assembled.deferred);
  // T_o met Theorem 1's hypotheses exactly (the coarse run found its h), every point
  // since was a step of Fig. 2 (the coarse run's, then the phase's, each rank's tested by
  // the same rules), D is whole in T, and nothing is encroached around the phase's points
  // on ∂Ω (the only ones it inserted without testing what they encroach: Lemma 1 says
  // nothing, par/assembly.hpp checks): the completion resumes that run, with T_o's h
  // under the final bounds (refine::RefineOptions::resumed_h).
  if (distribute && coarse.stats.h_theorem > 0 && vm.missing_subfacets.empty() &&
      vm.missing_subsegments.empty() && assembled.encroached == 0)
    rest.resumed_h = refine::theorem_h(shortest_t0, opt);
  refine::RefineResult rr = refine::refine(vm, rest);
  if (distribute && rr.tets_unchanged) {
    quality.emplace();
    for (const par::RankFigures& f : figures) quality->merge(f.quality);
  }
  return rr;
}

int checkpoint(int code) {
  World& w = world();
  const std::array<int, 2> m = par::max_over_ranks({code, w.rank == 0 ? code : 0});
  w.checkpoint_passed = true;
  w.root_failed = m[1] != 0;
  if (m[0] != 0) w.decided = m[0];
  return m[0];
}

int agree_exit_code(int code) {
  const World& w = world();
  if (w.size == 1) return code;
  if (w.decided) return *w.decided;
  if (w.checkpoint_passed) return par::broadcast_from_root(code);
  return checkpoint(code);
}

}  // namespace pdr::app
