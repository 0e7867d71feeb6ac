// `pdr check MESH [--domain D] [--ratio B] [--h H] [--json] [--explain T] [--vtu OUT.vtu]`:
// the exact oracle on a mesh from any mesher. Exit 0 when every check passes, 1 with
// violations, 2 on bad input. --explain T adds tet T described in full (check/explain.hpp);
// --vtu writes the mesh with per-tet fields (check/fields.hpp) for ParaView. Both see every
// finding (the checker runs unlimited, then the report is cut to --max-reported).
#include <iostream>
#include <limits>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "app/order_check.hpp"
#include "app/pipeline.hpp"
#include "app/progress.hpp"
#include "app/summary.hpp"
#include "check/check.hpp"
#include "check/explain.hpp"
#include "check/fields.hpp"
#include "domain/validate.hpp"
#include "io/error.hpp"
#include "io/mesh_io.hpp"
#include "io/vtu.hpp"
#include "par/affinity.hpp"

namespace pdr::app {

CLI::App* add_check_command(CLI::App& app, CheckArgs& chk) {
  auto* cchk = app.add_subcommand(
      "check", "Exact invariant checker for a tetrahedral mesh (any mesher's)");
  cchk->add_option("mesh", chk.mesh,
                   "Mesh: PREFIX (PREFIX.node + PREFIX.ele) or a .ele/.node/.msh/.mesh/.vtu")
      ->required();
  cchk->add_option("--domain", chk.domain, "The input domain (.poly/.smesh, or a closed surface: .off/.stl/.ply/.obj/.mesh/.msh)")
      ->check(CLI::ExistingFile);
  cchk->add_option("--ratio", chk.ratio, "Require radius-edge ratio < B")
      ->check(CLI::PositiveNumber);
  cchk->add_option("--h", chk.h, "Require every edge longer than H")
      ->check(CLI::NonNegativeNumber);
  cchk->add_flag("--json", chk.json, "Print the report as one JSON object");
  cchk->add_option("--threads", chk.threads, "Worker threads (default: every CPU it may use)")
      ->check(CLI::Range(1, 256));
  cchk->add_option("--planarity-tolerance", chk.planarity_tolerance,
                   "As pdr mesh's: the domain's facets may deviate T facet diameters (or the "
                   "rounding of their coordinates' digits) from a plane, and vertices within 2T "
                   "of an exact facet's plane, 8T of an inexact one's, count as on it")
      ->check(CLI::Range(1e-16, 1e-3));
  cchk->add_option("--max-reported", chk.max_reported, "Findings listed per check");
  cchk->add_option("--explain", chk.explain,
                   "Describe tet T (0-based, as in the report and ParaView's cell ids) in full");
  cchk->add_option("--vtu", chk.vtu,
                   "Write the mesh to OUT.vtu with per-tet fields: ratio, failed_checks, "
                   "fail:<check id>");
  return cchk;
}

namespace {

// Keeps the first `n` findings of each check (they are the first by element id).
void cut_findings(check::Report& report, std::size_t n) {
  for (check::CheckResult& r : report.checks)
    if (r.findings.size() > n) r.findings.resize(n);
  report.options.max_reported = n;
}

}  // namespace

int run_check(const CheckArgs& args) {
  PhaseTimer timer;
  Progress progress(Progress::wanted(args.json));
  progress.phase("read");
  io::ReadInfo info;
  const MeshData mesh = io::read_mesh(args.mesh, &info);
  std::optional<Plc> domain;
  if (args.domain)
    domain = io::read_domain(*args.domain, plc_options(args.planarity_tolerance).planarity_tolerance);
  timer.lap("read");
  if (args.explain && *args.explain >= mesh.tets.size()) {
    std::cerr << "pdr check: --explain " << *args.explain << ": the mesh has "
              << mesh.tets.size() << " tets, numbered from 0\n";
    return kExitBadInput;
  }

  check::Options opt;
  opt.ratio_bound = args.ratio;
  opt.min_edge = args.h;
  const unsigned threads = par::threads_or_usable(args.threads);
  opt.threads = threads;
  set_check_tolerances(args.planarity_tolerance, domain ? &*domain : nullptr, opt);
  if (progress.enabled())
    opt.on_phase = [&progress](std::string_view phase) { progress.phase("check: " + std::string(phase)); };
  const bool every_finding = args.explain || args.vtu;
  opt.max_reported = every_finding ? std::numeric_limits<std::size_t>::max() : args.max_reported;
  // The domain as pdr reads it: the pieces that bound no region are not required (TetGen
  // drops them too). A domain pdr refuses is checked as given.
  if (domain) try {
      skip_dropped(domain::build_domain(*domain, plc_options(args.planarity_tolerance)), opt);
    } catch (const InputError&) {
    }
  const auto view = check::view_of(mesh);
  check::Report report =
      domain ? check::check_mesh(view, *domain, opt) : check::check_mesh(view, opt);
  if (progress.enabled()) progress.phase("check: order independence");
  add_order_check(report, mesh, kOrderCheckSeed);
  timer.lap("check");
  progress.finish();

  std::optional<check::TetExplanation> explained;
  if (args.explain) explained = check::explain_tet(view, report, *args.explain);
  bool vtu_written = false;
  if (args.vtu) {
    std::vector<io::CellField> fields;
    for (check::TetField& f : check::tet_fields(view, report))
      fields.push_back({std::move(f.name), std::move(f.values)});
    try {
      io::write_vtu(mesh, *args.vtu, fields);
      vtu_written = true;
    } catch (const std::invalid_argument& e) {
      std::cerr << "pdr check: --vtu " << *args.vtu << " not written: " << e.what() << "\n";
    }
    timer.lap("vtu");
  }
  if (every_finding) cut_findings(report, args.max_reported);

  if (args.json) {
    nlohmann::json j = check::to_json(report);
    j["input"] = {{"mesh", args.mesh},
                  {"domain", args.domain ? *args.domain : ""},
                  {"skipped_elements", info.skipped_elements},
                  {"dropped_high_order_nodes", info.dropped_high_order_nodes}};
    if (explained) j["explain"] = check::to_json(*explained);
    if (args.vtu) j["vtu"] = vtu_written ? nlohmann::json(*args.vtu) : nlohmann::json(nullptr);
    j["seconds"] = timer.phases();
    for (const auto& [phase, s] : report.seconds) j["seconds"]["check." + phase] = s;
    std::cout << j.dump(2) << '\n';
  } else {
    std::cout << check::to_text(report);
    if (info.skipped_elements > 0)
      std::cout << "note: " << info.skipped_elements
                << " non-tetrahedral elements in the file were not checked\n";
    if (explained) std::cout << "explain " << check::to_text(*explained);
    if (vtu_written) std::cout << "wrote " << *args.vtu << " (per-tet fields)\n";
    std::cout << "time: read " << timer.phases()["read"].get<double>() << " s, check "
              << timer.phases()["check"].get<double>() << " s\n";
  }
  return report.ok() ? kExitOk : kExitViolations;
}

}  // namespace pdr::app
