// The steps that `pdr delaunay` and the default job share: build the Delaunay
// tetrahedralization of a point set, write it atomically, check it exactly, and fill the
// summary (vertices, duplicates, tets, tets/s, time per phase, peak memory, verdict).
#pragma once

#include <string>
#include <vector>

#include "app/summary.hpp"
#include "check/check.hpp"
#include "domain/domain.hpp"
#include "geom/point.hpp"
#include "io/mesh_io.hpp"

namespace pdr::app {

std::vector<io::MeshFormat> parse_formats(const std::vector<std::string>& names);

// Writes `mesh` atomically in every format (creating the prefix's folder), lists the files
// in the summary's "written" and times the phase "write".
void write_outputs(const MeshData& mesh, const std::string& prefix,
                   const std::vector<io::MeshFormat>& formats, PhaseTimer& timer,
                   Summary& summary);

// The checker's verdict in the summary: "check" (pass/FAIL) and, when it failed,
// "check_failed" (the ids) and, with `with_report`, "check_report" (the text). Returns the
// failed ids.
std::vector<std::string> record_check(const check::Report& report, bool with_report,
                                      Summary& summary);

// The pieces of `dom` its analysis dropped (PlcDomain::dropped): the checker does not
// require them in the mesh, nor the isolated vertices outside Ω.
void skip_dropped(const domain::PlcDomain& dom, check::Options& options);

// The summary's closing entries: seconds per phase and the peak memory.
void finish_summary(const PhaseTimer& timer, Summary& summary);

// Returns an exit code: kExitOk, kExitViolations (the checker disagrees: a bug), or throws
// InputError (`source` names the input) when the points span no tetrahedron.
int triangulate_write_check(std::vector<Point> points, const std::string& source,
                            const std::string& prefix,
                            const std::vector<io::MeshFormat>& formats, bool check,
                            unsigned threads, PhaseTimer& timer, Summary& summary);

}  // namespace pdr::app
