// The subcommands of `pdr`: each reads its options (parsed once, in main.cpp), runs, prints
// a summary (text, or one JSON object with --json) and returns an exit code (exit_codes.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "app/summary.hpp"
#include "check/check.hpp"
#include "domain/domain.hpp"
#include "io/precision.hpp"
#include "mesh/mesh_data.hpp"
#include "mesh/plc.hpp"
#include "refine/seq_refinement.hpp"
#include "surface/init.hpp"

namespace pdr::app {

struct DelaunayArgs {
  std::string points;                  // POINTS.node
  std::string prefix;                  // output prefix
  std::vector<std::string> formats{"node", "vtu"};
  bool check = true;
  bool json = false;
  unsigned threads = 0;                // checker threads (0: every usable CPU)
};
int run_delaunay(const DelaunayArgs& args);

struct CheckArgs {
  std::string mesh;                    // prefix or .ele/.node/.msh/.mesh/.vtu
  std::optional<std::string> domain;   // .poly/.smesh
  std::optional<double> ratio;
  std::optional<double> h;
  bool json = false;
  unsigned threads = 0;                // 0: every usable CPU
  std::size_t max_reported = 20;
  std::optional<std::size_t> explain;  // --explain T: describe tet T in full
  std::optional<std::string> vtu;      // --vtu OUT.vtu: the mesh with per-tet check fields
  std::optional<double> planarity_tolerance;  // as MeshArgs's
};
// Registers `pdr check` and its options on `app`, filling `args` when parsed.
CLI::App* add_check_command(CLI::App& app, CheckArgs& args);
int run_check(const CheckArgs& args);

struct MeshArgs {
  std::string domain;                  // DOMAIN.poly / .smesh
  std::string prefix;                  // output prefix
  std::vector<std::string> formats{"node", "vtu"};
  refine::RefineOptions options;
  bool check = true;
  bool json = false;
  std::uint64_t seed = 0x5EED;
  unsigned threads = 0;                // checker threads (0: every usable CPU)
  std::size_t initial_tets = 0;        // mpirun: M_o's interior size (0: automatic)
  std::uint64_t inject_latency_us = 0; // mpirun: each message held this long
  std::size_t submeshes = 0;          // mpirun: submeshes of M_o, >= ranks (0: one per rank)
  surface::SurfaceSizing surface_sizing = surface::SurfaceSizing::Auto;  // surface/init.hpp
  // --planarity-tolerance: the domain analysis's (domain::PlcOptions), and the check's
  // (set_check_tolerances below); absent: their defaults.
  std::optional<double> planarity_tolerance;
};
CLI::App* add_mesh_command(CLI::App& app, MeshArgs& args);
// The domain analysis's options under --planarity-tolerance (absent: the defaults).
inline domain::PlcOptions plc_options(const std::optional<double>& planarity) {
  domain::PlcOptions o;
  if (planarity) o.planarity_tolerance = *planarity;
  return o;
}
// The check's tolerances under --planarity-tolerance T (absent: the domain analysis's
// default T): vertices within 8T facet diameters of the least-squares plane of a facet
// planar only within tolerance count as on it (its vertices lie within T of it, the new
// ones pdr mesh puts on the plane of three of them within 7T: surface/chart.hpp); for
// exactly planar facets and segments, within max(2T, the check's default) when T is
// given, else the check's default (rounding only).
// The coordinates' uncertainty (io/precision.hpp) is the domain's, as its analysis infers
// it (none without a domain).
inline void set_check_tolerances(const std::optional<double>& planarity, const Plc* domain,
                                 check::Options& o) {
  const double t = plc_options(planarity).planarity_tolerance;
  o.inexact_facet_tolerance = 8 * t;
  o.coordinate_uncertainty = domain ? io::planarity_tolerance_of(*domain, t).uncertainty() : 0;
  if (planarity) o.relative_tolerance = std::max(o.relative_tolerance, 2 * *planarity);
}
int run_mesh(const MeshArgs& args);
// The mesher on a PLC (shared with the default job and the Python module); fills
// `summary`, returns an exit code; throws InputError, RefineError, SurfaceError. Writes the
// mesh under args.prefix, or nowhere when args.prefix is empty; `mesh_out`, when given,
// receives the mesh (the in-domain tets and the boundary faces, as written).
int mesh_plc(const Plc& plc, const MeshArgs& args, Summary& summary,
             MeshData* mesh_out = nullptr);
// mesh_plc with the failures that `pdr mesh` reports in its summary turned into exit codes:
// RefineError and SurfaceError exit 4 ("error"), SurfaceCapError exit 3 (nothing meshed:
// "quality", "stop_reason"). `failure` gets what the command prints on stderr after "pdr: "
// (empty when nothing failed). Other exceptions (InputError, ...) propagate.
int mesh_plc_reported(const Plc& plc, const MeshArgs& args, Summary& summary,
                      std::string& failure, MeshData* mesh_out = nullptr);

struct DefaultArgs {
  std::string prefix = "out/default";
  bool json = false;
};
int run_default(const DefaultArgs& args);

}  // namespace pdr::app
