// `pdr check MESH [--domain D] [--ratio B] [--h H] [--json]`: the exact oracle on a mesh
// from any mesher. Exit 0 when every check passes, 1 with violations, 2 on bad input.
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "app/summary.hpp"
#include "check/check.hpp"
#include "io/mesh_io.hpp"

namespace pdr::app {

CLI::App* add_check_command(CLI::App& app, CheckArgs& chk) {
  auto* cchk = app.add_subcommand(
      "check", "Exact invariant checker for a tetrahedral mesh (any mesher's)");
  cchk->add_option("mesh", chk.mesh,
                   "Mesh: PREFIX (PREFIX.node + PREFIX.ele) or a .ele/.node/.msh/.mesh/.vtu")
      ->required();
  cchk->add_option("--domain", chk.domain, "The input domain (.poly/.smesh)")
      ->check(CLI::ExistingFile);
  cchk->add_option("--ratio", chk.ratio, "Require radius-edge ratio < B")
      ->check(CLI::PositiveNumber);
  cchk->add_option("--h", chk.h, "Require every edge longer than H")
      ->check(CLI::NonNegativeNumber);
  cchk->add_flag("--json", chk.json, "Print the report as one JSON object");
  cchk->add_option("--threads", chk.threads, "Worker threads")->check(CLI::Range(1, 256));
  cchk->add_option("--max-reported", chk.max_reported, "Findings listed per check");
  return cchk;
}

int run_check(const CheckArgs& args) {
  PhaseTimer timer;
  io::ReadInfo info;
  const MeshData mesh = io::read_mesh(args.mesh, &info);
  std::optional<Plc> domain;
  if (args.domain) domain = io::read_domain(*args.domain);
  timer.lap("read");

  check::Options opt;
  opt.ratio_bound = args.ratio;
  opt.min_edge = args.h;
  opt.threads = args.threads;
  opt.max_reported = args.max_reported;
  const auto view = check::view_of(mesh);
  const check::Report report =
      domain ? check::check_mesh(view, *domain, opt) : check::check_mesh(view, opt);
  timer.lap("check");

  if (args.json) {
    nlohmann::json j = check::to_json(report);
    j["input"] = {{"mesh", args.mesh},
                  {"domain", args.domain ? *args.domain : ""},
                  {"skipped_elements", info.skipped_elements},
                  {"dropped_high_order_nodes", info.dropped_high_order_nodes}};
    j["seconds"] = timer.phases();
    std::cout << j.dump(2) << '\n';
  } else {
    std::cout << check::to_text(report);
    if (info.skipped_elements > 0)
      std::cout << "note: " << info.skipped_elements
                << " non-tetrahedral elements in the file were not checked\n";
    std::cout << "time: read " << timer.phases()["read"].get<double>() << " s, check "
              << timer.phases()["check"].get<double>() << " s\n";
  }
  return report.ok() ? kExitOk : kExitViolations;
}

}  // namespace pdr::app
