// `pdr mesh DOMAIN.poly -o PREFIX ...`: the sequential mesher (paper §2.1 initialization,
// §3 SeqRefinement), then the exact checker (src/check) on the written mesh.
//
// Phases (each timed): analyze (validation, admissibility, d: domain/analysis.hpp), surface
// (D_o: surface/init.hpp), initial (T_o: refine/initial.hpp), refine (refine/seq_refinement.hpp),
// write (only the tets inside Ω, and the subfacets as boundary faces with their facets'
// markers), check (check_mesh with the domain and --ratio B, unless --no-check).
// Exit codes (exit_codes.hpp): 0 ok; 1 the checker found violations (a bug); 2 invalid
// input (InputError, file:line); 3 some tet kept ratio >= B (each listed with its reason:
// a domain outside the theory, or a vertex cap reached: in the surface phase nothing is
// written); 4 an internal invariant failed (RefineError, SurfaceError: a bug, or an
// inadmissible domain the guards did not catch).

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>

#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "app/order_check.hpp"
#include "app/parallel.hpp"
#include "app/partitioned_output.hpp"
#include "app/pipeline.hpp"
#include "app/progress.hpp"
#include "app/regions.hpp"
#include "app/summary.hpp"
#include "check/check.hpp"
#include "delaunay/export.hpp"
#include "domain/analysis.hpp"
#include "geom/input_range.hpp"
#include "io/error.hpp"
#include "io/mesh_io.hpp"
#include "mesh/tables.hpp"
#include "par/affinity.hpp"
#include "refine/initial.hpp"
#include "refine/quality.hpp"
#include "refine/seq_refinement.hpp"
#include "refine/split.hpp"
#include "surface/init.hpp"

namespace pdr::app {

namespace {

void check_range(const Plc& plc) {
  for (std::size_t i = 0; i < plc.points.size(); ++i)
    if (!in_input_range(plc.points[i]))
      throw InputError(plc.source, i < plc.point_lines.size() ? plc.point_lines[i] : 0,
                       "point " + std::to_string(i + 1) +
                           " has a coordinate that is not 0 and not of magnitude in "
                           "[2^-100, 2^100] (about 1e-30 .. 1e30); rescale the input");
}

// The in-domain tets and the subfacets (with their facets' markers) as a MeshData: the
// boundary faces, then the faces of internal facets (between two regions, as TetGen lists
// them; oriented out of their lower tet slot); with region records in the input, or
// several regions (internal facets, or `cells` > 1: bodies apart, or touching along an
// edge), each tet's region attribute too (app/regions.hpp; TetGen's -A).
// Some facet lies inside the domain (Ω on both sides).
bool internal_facets(const refine::VolumeMesh& m) {
  const auto& facets = m.surf.facets;
  return std::any_of(facets.begin(), facets.end(), [](const auto& f) { return !f.separates; });
}

// Whether the tets get region attributes (export_domain).
bool needs_regions(const refine::VolumeMesh& m, const Plc& plc, std::size_t cells) {
  return !plc.regions.empty() || cells > 1 || internal_facets(m);
}

MeshData export_domain(const refine::VolumeMesh& m, const Plc& plc, std::size_t cells) {
  MeshData mesh = to_mesh_data(m.dt, m.inside);
  const bool internal = internal_facets(m);
  if (internal) {
    const TetStore& s = m.dt.store();
    for (TetId t = 0; t < s.slots(); ++t) {
      if (!s.is_alive(t) || s.is_ghost(t) || !m.is_inside(t)) continue;
      const VertexId* v = s.vertices(t);
      for (int f = 0; f < 4; ++f) {
        const TetId n = s.neighbour(t, f);
        if (n < t || s.is_ghost(n) || !m.is_inside(n) || !m.face_subfacet(t, f)) continue;
        const auto& fv = tables::kFaceVertex[f];
        mesh.faces.push_back({v[fv[0]], v[fv[1]], v[fv[2]]});
      }
    }
  }
  if (needs_regions(m, plc, cells)) {
    const std::vector<int> label = region_labels(m, plc.regions);
    const TetStore& s = m.dt.store();
    mesh.tet_regions.reserve(mesh.tets.size());
    for (TetId t = 0; t < s.slots(); ++t)  // the order of to_mesh_data
      if (s.is_alive(t) && !s.is_ghost(t) && m.inside[t] != 0) mesh.tet_regions.push_back(label[t]);
  }
  mesh.face_markers.resize(mesh.faces.size(), 0);
  for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
    const auto& f = mesh.faces[i];
    if (const auto sf = m.subfacet(f[0], f[1], f[2])) {
      const std::uint32_t facet = m.surf.subfacet(*sf).facet;
      mesh.face_markers[i] = facet < plc.facets.size() ? plc.facets[facet].marker : 0;
    }
  }
  return mesh;
}

void quality_summary(const refine::QualityRange& q, Summary& summary) {
  summary.set("ratio_min", q.tets == 0 ? 0.0 : q.ratio_min);
  summary.set("ratio_max", q.ratio_max);
  summary.set("dihedral_min_deg", q.dihedral_min_deg());
  summary.set("dihedral_max_deg", q.dihedral_max_deg());
  summary.set("shortest_edge", std::isfinite(q.shortest2) ? std::sqrt(q.shortest2) : 0.0);
}

refine::QualityRange quality_of(const MeshData& mesh) {
  refine::QualityRange q;
  for (std::size_t i = 0; i < mesh.tets.size(); ++i) {
    if (i + 8 < mesh.tets.size())  // a later tet's points, scattered, requested meanwhile
      for (const std::uint32_t v : mesh.tets[i + 8]) __builtin_prefetch(&mesh.points[v]);
    const auto& t = mesh.tets[i];
    q.add(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]);
  }
  return q;
}

}  // namespace

CLI::App* add_mesh_command(CLI::App& app, MeshArgs& a) {
  auto* c = app.add_subcommand("mesh", "Guaranteed-quality tetrahedral mesh of a domain");
  c->add_option("domain", a.domain, "Domain: .poly, .smesh, or a closed surface: .off, .stl, .ply, .obj, .mesh, .msh")->required()->check(
      CLI::ExistingFile);
  c->add_option("-o,--output", a.prefix, "Output prefix")->required();
  c->add_option("--ratio", a.options.ratio, "Radius-edge ratio bound B")
      ->check(CLI::Range(1.0, 1e6))
      ->capture_default_str();
  c->add_option("--max-volume", a.options.max_volume, "Refine tets of volume > V")
      ->check(CLI::PositiveNumber);
  c->add_option("--size", a.options.size, "Refine tets of circumradius > L")
      ->check(CLI::PositiveNumber);
  c->add_option("--formats", a.formats, "Output formats, comma separated: node,vtu,msh,mesh")
      ->delimiter(',')
      ->capture_default_str();
  c->add_flag("!--no-check", a.check, "Skip the exact check of the result");
  c->add_flag("--audit", a.options.audit, "Check Lemma 1's invariants after every insertion");
  c->add_flag("--json", a.json, "Print the summary as one JSON object");
  c->add_option("--seed", a.seed, "Seed of the initial insertion order");
  c->add_option("--threads", a.threads, "Checker threads (default: every CPU it may use)")
      ->check(CLI::Range(1, 256));
  c->add_option("--planarity-tolerance", a.planarity_tolerance,
                "Accept facets whose vertices lie within T facet diameters of a plane "
                "(default 1e-9; TetGen's -T), or within the rounding of the coordinates' "
                "digits; the check then counts vertices within 2T (8T for inexact facets) as "
                "on a facet")
      ->check(CLI::Range(1e-16, 1e-3));
  c->add_option("--max-vertices", a.options.max_vertices, "Vertex cap (0: derived)");
  c->add_option("--surface-sizing", a.surface_sizing,
                "Initial surface mesh: uniform (paper 2.1, global d), graded (each segment "
                "and facet by its distance to unrelated components), auto (graded when "
                "estimated 4x smaller)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, surface::SurfaceSizing>{
              {"auto", surface::SurfaceSizing::Auto},
              {"uniform", surface::SurfaceSizing::Uniform},
              {"graded", surface::SurfaceSizing::Graded}},
          CLI::ignore_case))
      ->option_text("auto|uniform|graded (default auto)");
  c->add_option("--initial-tets", a.initial_tets,
                "Under mpirun: refine the interior sequentially to about K tets before "
                "distributing (0: automatic)")
      ->capture_default_str();
  c->add_option("--inject-latency", a.inject_latency_us,
                "Under mpirun: hold every message that many microseconds before delivery")
      ->check(CLI::Range(0, 10'000'000));
  c->add_option("--submeshes", a.submeshes,
                "Under mpirun: cut M_o into N submeshes, at least one per rank (submesh k on "
                "rank k mod P; 0: one per rank)")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            long long n = 0;
            const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
            if (ec != std::errc() || end != text.data() + text.size() || n < 0)
              return "a number of submeshes: " + text;
            if (n != 0 && n < world().size)
              return "at least one submesh per rank: " + text + " for " +
                     std::to_string(world().size) + " ranks";
            if (n > 1'000'000) return "at most 1000000 submeshes";
            return "";
          },
          "N >= ranks"));
  return c;
}

int mesh_plc(const Plc& plc, const MeshArgs& args, Summary& summary, MeshData* mesh_out) {
  PhaseTimer timer;
  Progress progress(Progress::wanted(args.json) && world().size == 1);
  progress.phase("analyze");
  check_range(plc);
  const auto formats = parse_formats(args.formats);
  domain::DomainAnalysis an = domain::analyze(plc, plc_options(args.planarity_tolerance));
  summary.set("domain", plc.source);
  summary.set("admissible", an.report.admissible);
  const nlohmann::json report = domain::to_json(an.report);
  summary.set("admissibility_violations", report.at("admissibility").at("violations"));
  summary.set("admissibility_violation_count", report.at("admissibility").at("violation_count"));
  if (const std::string hint = domain::bent_right_angles_hint(an.report); !hint.empty())
    summary.set("admissibility_hint", hint);
  // Angle tests a hair off 90 or 270 degrees, read as right angles (domain/angles.hpp).
  summary.set("right_angles_within_tolerance", an.report.right_within_tolerance);
  // Facets accepted as planar only within the documented relative tolerance (README).
  summary.set("planarity", report.at("planarity"));
  summary.set("d", an.report.feature.d);
  // Voids no hole point marks: TetGen would mesh them as regions (README, Formats).
  if (!an.report.unmarked_voids.empty())
    summary.set("unmarked_voids", report.at("unmarked_voids"));
  // A surface file with walls: every bounded cell is a region, as TetGen reads it.
  if (an.report.surface_walls)
    summary.set("surface_walls", "edges of three or more faces: every bounded cell is a region");
  // Facets between voids, or a void and the outside: dropped, as TetGen drops them.
  if (!an.report.dropped_facets.empty())
    summary.set("dropped_facets", report.at("dropped_facets"));
  timer.lap("analyze");

  int code = kExitOk;
  refine::RefineOptions opt = args.options;
  refine::set_domain(opt, an);  // d, admissibility, the guards
  if (progress.enabled())
    opt.on_progress = [&progress](std::size_t vertices) { progress.count(vertices, "vertices"); };
  progress.phase("surface");
  surface::SurfaceOptions so;
  so.max_vertices = args.options.max_vertices;  // --max-vertices bounds every phase
  so.sizing = args.surface_sizing;
  surface::SurfaceInit si = surface::init_surface(an, so);
  summary.set("surface_sizing", si.stats.graded ? "graded" : "uniform");
  summary.set("surface_vertices", si.mesh.vertex_count());
  summary.set("subfacets", si.mesh.live_subfacets());
  timer.lap("surface");
  progress.phase("initial mesh");
  refine::VolumeMesh vm = refine::build_initial(std::move(si.mesh), an.domain.plc.holes,
                                                args.seed);
  summary.set("initial_tets", vm.inside_tets());
  timer.lap("initial");
  progress.phase("refine");
  double t_before = 0;  // parallel runs: the phases before rank 0's completion
  // Parallel runs with vtu output: who made each vertex (PREFIX.pvtu).
  const bool partitioned = world().size > 1 && !args.prefix.empty() &&
                           std::find(formats.begin(), formats.end(), io::MeshFormat::Vtu) !=
                               formats.end();
  VertexOwners owners;
  std::optional<refine::QualityRange> ranks_quality;  // the ranks' figures, when whole
  // Bodies apart (or touching along an edge): several regions even without region
  // records or internal facets (export_domain).
  const auto cells = static_cast<std::size_t>(
      std::count(an.domain.cell_inside.begin(), an.domain.cell_inside.end(), 1));
  // The ranks may list the output mesh themselves where it needs no region attributes
  // (app/parallel.hpp).
  std::optional<Listing> listing;
  if (!needs_regions(vm, an.domain.plc, cells)) {
    listing.emplace();
    for (const auto& f : an.domain.plc.facets) listing->facet_markers.push_back(f.marker);
    // TetGen's files alone, no check (which needs the whole mesh at rank 0) and no
    // caller that wants the mesh: the ranks write their parts of the files themselves.
    if (!args.check && !args.prefix.empty() && mesh_out == nullptr &&
        std::all_of(formats.begin(), formats.end(),
                    [](io::MeshFormat f) { return f == io::MeshFormat::TetGen; }))
      listing->write_prefix = args.prefix;
  }
  std::optional<ListedMesh> listed;
  std::optional<refine::RefineResult> refined =
      world().size > 1 ? refine_in_parallel(vm, opt, args.initial_tets, args.submeshes,
                                            args.inject_latency_us, args.seed, summary, timer,
                                            t_before, partitioned ? &owners : nullptr,
                                            ranks_quality, listing ? &*listing : nullptr, listed)
                       : refine::refine(vm, opt);
  if (!refined) return kExitOk;  // not rank 0: rank 0 writes, checks and decides the code
  const refine::RefineResult& rr = *refined;
  const double t_refine = t_before + timer.lap("refine");
  summary.set("ratio_bound", opt.ratio);
  summary.set("h", std::isfinite(rr.stats.h) ? rr.stats.h : 0.0);
  // Theorem 1's a-priori h, where its hypotheses hold exactly: the final check requires
  // every edge to be longer (quality.shortest_edge).
  if (rr.stats.h_theorem > 0) summary.set("h_theorem", rr.stats.h_theorem);
  summary.set("inserted", nlohmann::json{{"tet_circumcenters", rr.stats.tet_circumcenters},
                           {"subfacet_circumcenters", rr.stats.subfacet_circumcenters},
                           {"axis_copies", rr.stats.axis_copies},
                           {"axis_copies_dropped", rr.stats.axis_copies_dropped},
                           {"ball_zones", rr.stats.ball_zones},
                           {"ball_fills", rr.stats.ball_fills},
                           {"ball_vertices", rr.stats.ball_vertices},
                           {"subsegment_splits", rr.stats.subsegment_splits},
                           {"refused", rr.stats.refused},
                           {"vertex_cap", rr.stats.vertex_cap},
                           {"conformity_breaks", rr.stats.conformity_breaks},
                           {"conformity_splits", rr.stats.conformity_splits},
                           {"conformity_refused", rr.stats.conformity_refused},
                           {"flag_repairs", rr.stats.flag_repairs},
                           {"flat_repairs", rr.stats.flat_repairs},
                           {"face_repairs", rr.stats.face_repairs}});
  if (!rr.stop_reason.empty()) summary.set("stop_reason", rr.stop_reason);
  if (!rr.unsplit.empty()) summary.set("unsplit", rr.unsplit);  // refused by the guards
  if (rr.stats.audit_failures > 0)
    summary.set("audit", std::to_string(rr.stats.audit_failures) +
                             " Lemma 1 failures (inadmissible domain); first: " +
                             rr.stats.audit_note);

  MeshData mesh = listed ? std::move(listed->mesh) : export_domain(vm, an.domain.plc, cells);
  // The ranks wrote the files themselves: rank 0 has the mesh's counts, not the mesh.
  const bool ranks_wrote = listed && !listed->written.empty();
  const std::size_t vertices = ranks_wrote ? listed->vertices : mesh.points.size();
  const std::size_t tets = ranks_wrote ? listed->tets : mesh.tets.size();
  const unsigned threads = par::threads_or_usable(args.threads);
  summary.set("vertices", vertices);
  summary.set("tets", tets);
  summary.set("boundary_faces", ranks_wrote ? listed->faces : mesh.faces.size());
  summary.set("tets_per_second", t_refine > 0 ? static_cast<double>(tets) / t_refine : 0.0);
  // The ranks' listing: their stores at the end (proxies and spare slots included), not
  // comparable with one assembled store.
  if (listed)
    summary.set("ranks_topology_bytes", listed->topology_bytes);
  else
    summary.set("topology_bytes", vm.dt.store().bytes_allocated());
  if (ranks_quality && ranks_quality->tets != tets)
    throw std::logic_error("the ranks' quality figures cover " +
                           std::to_string(ranks_quality->tets) + " tets, the mesh has " +
                           std::to_string(tets));
  quality_summary(ranks_quality ? *ranks_quality : quality_of(mesh), summary);
  if (!rr.leftovers.empty()) {
    nlohmann::json left = nlohmann::json::array();
    for (const auto& l : rr.leftovers) {
      if (left.size() >= 50) break;
      nlohmann::json pts = nlohmann::json::array();
      for (const auto& p : l.p) pts.push_back({p[0], p[1], p[2]});
      left.push_back(nlohmann::json{{"tet", l.tet}, {"vertices", l.v}, {"points", pts},
                      {"ratio", l.ratio}, {"reason", l.reason}});
    }
    summary.set("quality", "NOT GUARANTEED: " + std::to_string(rr.leftovers.size()) +
                               " tets with ratio >= " + std::to_string(opt.ratio));
    summary.set("leftovers", left);
    code = kExitNotGuaranteed;
  }
  if (!rr.stop_reason.empty() && code == kExitOk) {
    // Every tet is below B, but the refinement stopped early: the size bounds (--size,
    // --max-volume) may be unmet, so the run does not claim success.
    summary.set("quality", "NOT GUARANTEED: " + rr.stop_reason);
    code = kExitNotGuaranteed;
  }

  if (rr.stats.conformity_refused > 0) {
    // Elements of D stayed out of T (refine/conformity.hpp): said even with --no-check.
    summary.set("conformity", "NOT CONFORMING: " + std::to_string(rr.stats.conformity_refused) +
                                  " refinements of surface elements missing from the "
                                  "tetrahedralization were refused (see unsplit)");
    if (code == kExitOk) code = kExitNotGuaranteed;
  }
  // Slivers of a facet's rounding, not a break of conformity (refine/flat.hpp): said, since
  // their radius-edge ratio is often small (a near-cocircular quad) and the check then
  // lists none of them.
  if (rr.stats.flat_left > 0)
    summary.set("flat_tets", std::to_string(rr.stats.flat_left) +
                                 " flat tets (slivers within a facet's planarity tolerance) "
                                 "lie on facets inside the domain: " +
                                 (rr.stop_reason.empty() ? std::string("their repair was refused")
                                                         : rr.stop_reason));
  if (ranks_wrote) {
    summary.set("written", listed->written);
  } else if (!args.prefix.empty()) {
    progress.phase("write");
    write_outputs(mesh, args.prefix, formats, timer, summary);
  }
  if (partitioned) {
    // One piece per rank, the owner as a cell field (app/partitioned_output.hpp).
    nlohmann::json written = summary.get("written");
    const std::vector<std::uint32_t> tet_rank = listed ? std::move(listed->tet_rank) : tet_owners(mesh, owners);
    for (const std::string& p : write_partitioned_vtu(mesh, tet_rank, world().size, args.prefix))
      written.push_back(p);
    summary.set("written", written);
    timer.lap("write");
  }

  if (args.check) {
    check::Options co;
    co.ratio_bound = opt.ratio;
    co.threads = threads;
    set_check_tolerances(args.planarity_tolerance, &an.domain.plc, co);
    if (rr.stats.h_theorem > 0) co.min_edge = rr.stats.h_theorem;
    if (progress.enabled())
      co.on_phase = [&progress](std::string_view phase) { progress.phase("check: " + std::string(phase)); };
    skip_dropped(an.domain, co);
    const check::Report report = check::check_mesh(check::view_of(mesh), an.domain.plc, co);
    timer.lap("check");
    // quality.ratio failing is what exit 3 already reports; so is encroachment on an
    // inadmissible domain (Lemma 1 needs the angle bounds); anything else is a bug.
    bool other = false, expected = false;
    for (const auto& c : report.checks) {
      if (c.status != check::Status::Fail) continue;
      const std::string& s = c.id;
      const bool outside_theory = !opt.admissible && s.rfind("encroachment.", 0) == 0;
      expected = expected || outside_theory;
      other = other || (s != "quality.ratio" && !outside_theory);
    }
    if (expected && code == kExitOk) {
      summary.set("quality", "NOT GUARANTEED: inadmissible domain, encroached boundary "
                             "elements remain (see check_report)");
      summary.set("check_report", check::to_text(report));
      code = kExitNotGuaranteed;
    }
    std::vector<std::string> failed = record_check(report, other, summary);
    if (other) code = kExitViolations;
    // Remarks 1-2: the mesh is DT(V) restricted to the domain, whatever the insertion
    // order (order_check.hpp): decided from the check's vertices on spheres where it
    // passed, else DT(V) rebuilt here in a seeded order unlike the mesher's.
    progress.phase("order check");
    const bool implied = order_implied(report);
    const OrderCheck oc =
        implied ? order_from_report(mesh, report, kOrderCheckSeed, 10, threads)
                : check_order_independence(mesh, rebuild_dt(mesh.points, kOrderCheckSeed),
                                           kOrderCheckSeed, 10, true, threads);
    timer.lap("order_check");
    summary.set("order_independence",
                nlohmann::json{{"seed", oc.seed}, {"tets", oc.tets}, {"missing", oc.missing},
                               {"cospherical_ties", oc.ties},
                               {"implied_by_check", implied},
                               {"first_missing", oc.first}});
    if (!oc.ok()) {
      failed.push_back("order.independence");
      summary.set("check", "FAIL");
      summary.set("check_failed", failed);
      code = kExitViolations;
    }
  } else {
    summary.set("check", "skipped (--no-check)");
    // Without the check the run still knows that its guards refused to refine encroached
    // elements (refine/split.hpp): some may remain, which the check would report (exit 3).
    if (!rr.unsplit.empty() && code == kExitOk) {
      summary.set("quality", "NOT GUARANTEED: the guards refused to refine encroached boundary "
                             "elements (see unsplit); some may remain encroached: run without "
                             "--no-check to list them");
      code = kExitNotGuaranteed;
    }
  }
  finish_summary(timer, summary);
  if (mesh_out) *mesh_out = std::move(mesh);
  return code;
}

int mesh_plc_reported(const Plc& plc, const MeshArgs& args, Summary& summary,
                      std::string& failure, MeshData* mesh_out) {
  failure.clear();
  try {
    return mesh_plc(plc, args, summary, mesh_out);
  } catch (const refine::RefineError& e) {
    summary.set("error", e.what());
    failure = e.what();
    return kExitInternal;
  } catch (const surface::SurfaceCapError& e) {
    // A resource limit, not a bug: nothing is written, and the run says why (exit 3).
    summary.set("quality", "NOT GUARANTEED: stopped before meshing, nothing written");
    summary.set("stop_reason", e.what());
    failure = std::string("stopped: ") + e.what();
    return kExitNotGuaranteed;
  } catch (const surface::SurfaceError& e) {
    summary.set("error", e.what());
    failure = e.what();
    return kExitInternal;
  }
}

namespace {

// mesh_plc on the file args.domain, the summary printed, the exit code returned.
int mesh_and_report(const MeshArgs& args) {
  Summary summary;
  summary.set("command", "mesh");
  const Plc plc =
      io::read_domain(args.domain, plc_options(args.planarity_tolerance).planarity_tolerance);
  std::string failure;
  const int code = mesh_plc_reported(plc, args, summary, failure);
  summary.print(args.json);
  if (!failure.empty()) std::cerr << "pdr: " << failure << "\n";
  return code;
}

}  // namespace

int run_mesh(const MeshArgs& args) { return mesh_and_report(args); }

}  // namespace pdr::app
