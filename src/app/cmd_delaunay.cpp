// `pdr delaunay POINTS.node -o PREFIX`: the Delaunay tetrahedralization of a point set,
// written in the requested formats and checked exactly (validity, empty spheres).
// Duplicate points are reported and not inserted; a point set with no four affinely
// independent points is bad input (exit 2).
#include <iostream>
#include <stdexcept>

#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "app/pipeline.hpp"
#include "app/summary.hpp"
#include "io/error.hpp"
#include "io/mesh_io.hpp"
#include "par/affinity.hpp"

namespace pdr::app {

std::vector<io::MeshFormat> parse_formats(const std::vector<std::string>& names) {
  std::vector<io::MeshFormat> formats;
  for (const auto& n : names) {
    try {
      formats.push_back(io::parse_mesh_format(n));
    } catch (const std::invalid_argument& e) {
      throw InputError("--formats", 0, e.what());
    }
  }
  return formats;
}

int run_delaunay(const DelaunayArgs& args) {
  const auto formats = parse_formats(args.formats);
  PhaseTimer timer;
  Summary summary;
  summary.set("command", "delaunay");
  summary.set("input", args.points);
  std::vector<Point> points = io::read_domain(args.points).points;
  timer.lap("read");
  const int code = triangulate_write_check(std::move(points), args.points, args.prefix,
                                           formats, args.check,
                                           par::threads_or_usable(args.threads),
                                           timer, summary);
  summary.print(args.json);
  return code;
}

}  // namespace pdr::app
