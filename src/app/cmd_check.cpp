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
