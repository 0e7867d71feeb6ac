// `pdr` without a command: the default job on an embedded input, so that line 1 of the
// README's Quick start shows the whole pipeline with no file at hand.
//
// The job meshes the cube-in-cube domain of paper §5 (data/cube-in-cube.poly: the cube
// [0,10]^3 with a suspended cubical void [4,6]^3, outer facets marker 1, void facets
// marker 2, a hole point at (5,5,5)), built here in code, with ratio bound 2 and a volume
// bound of 0.05, checks the result exactly against the domain and writes
// out/default.{node,ele,face,vtu}. Under mpirun the ranks refine it together
// (app/parallel.hpp).
#include <array>

#include "app/commands.hpp"
#include "app/summary.hpp"

namespace pdr::app {
namespace {

// Adds the six facets of the axis-aligned cube [lo, hi]^3 with corner ids from `base`.
void add_cube(Plc& plc, double lo, double hi, int marker) {
  const auto base = static_cast<std::uint32_t>(plc.points.size());
  for (int c = 0; c < 8; ++c) {
    plc.points.push_back({c & 1 ? hi : lo, c & 2 ? hi : lo, c & 4 ? hi : lo});
    plc.point_lines.push_back(0);
  }
  // Corner c has bit 0 = x, bit 1 = y, bit 2 = z; each face is a cycle of four corners.
  const std::array<std::array<std::uint32_t, 4>, 6> faces = {{{0, 1, 3, 2},
                                                              {4, 5, 7, 6},
                                                              {0, 1, 5, 4},
                                                              {2, 3, 7, 6},
                                                              {0, 2, 6, 4},
                                                              {1, 3, 7, 5}}};
  for (const auto& f : faces) {
    PlcFacet facet;
    facet.polygons.push_back({base + f[0], base + f[1], base + f[2], base + f[3]});
    facet.marker = marker;
    plc.facets.push_back(facet);
  }
}

Plc cube_in_cube() {
  Plc plc;
  plc.source = "<embedded cube-in-cube>";
  add_cube(plc, 0.0, 10.0, 1);
  add_cube(plc, 4.0, 6.0, 2);
  plc.holes.push_back({5.0, 5.0, 5.0});
  plc.hole_lines.push_back(0);
  return plc;
}

}  // namespace

int run_default(const DefaultArgs& args) {
  MeshArgs mesh;
  mesh.domain = "<embedded cube-in-cube>";
  mesh.prefix = args.prefix;
  mesh.json = args.json;
  mesh.options.max_volume = 0.05;
  Summary summary;
  summary.set("command", "default job: pdr mesh on the embedded cube-in-cube domain");
  const int code = mesh_plc(cube_in_cube(), mesh, summary);
  summary.print(args.json);
  return code;
}

}  // namespace pdr::app
