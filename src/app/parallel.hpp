// `mpirun -np P pdr mesh`: the refinement of a mesh by P ranks (paper §4, docs/parallel.md).
//
// Every rank reads the input and builds M_o alike (analysis, surface mesh, initial mesh, a
// coarse sequential refinement to about --initial-tets tets: deterministic, so the ranks
// agree without sending it); the parallel phase refines the METIS parts of M_o concurrently
// (par/par_refinement.hpp); rank 0 gathers the points, adds them to its M_o and completes
// the refinement sequentially (the steps the parallel phase deferred: Refine(s), Refine(f),
// the guards and the conformity rules), then writes, checks and decides the exit code,
// which every rank returns. Only rank 0 prints; a rank that fails in the parallel phase
// prints its error and ends the whole run (MPI_Abort, exit 4).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/partitioned_output.hpp"
#include "app/summary.hpp"
#include "mesh/mesh_data.hpp"
#include "refine/seq_refinement.hpp"

namespace pdr::app {

// This process's place in the run: set once by main (rank 0 of 1 without mpirun), and
// where the ranks stand on the run's outcome (below).
struct World {
  int rank = 0;
  int size = 1;
  bool checkpoint_passed = false;  // the ranks have met at checkpoint()
  std::optional<int> decided;      // the run's exit code, when the checkpoint fixed it
  bool root_failed = false;        // at the checkpoint, rank 0 had failed too
};
World& world();

// The ranks' first meeting (before any other exchange of a parallel run, and at the end
// of a run that had none): every rank gives its exit code so far (0: going on), and gets
// the largest. A non-zero result fixes the run's exit code (World::decided): a rank that
// failed alone (bad input on one host only) ends every rank without a hang.
int checkpoint(int code);

// Thrown on the ranks that were going on when the checkpoint says another one failed.
class RunAbandoned : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The output mesh as the ranks listed it from their submeshes (par/mesh_parts.hpp), in
// place of rank 0's export of the assembled mesh.
struct ListedMesh {
  MeshData mesh;                        // points, inside tets, boundary faces and markers
  std::vector<std::uint32_t> tet_rank;  // the rank that listed each tet
  std::uint64_t topology_bytes = 0;     // the ranks' tet stores at the end
  // When the ranks wrote the files themselves (Listing::write_prefix): the files, and the
  // mesh's counts (`mesh` and `tet_rank` are then empty).
  std::vector<std::string> written;
  std::size_t vertices = 0, tets = 0, faces = 0;
};

// What the ranks need to list it: the markers of D's facets (0 beyond). With a
// `write_prefix`, each rank writes its part of PREFIX.node, .ele and .face itself
// (par/rank_files.hpp) instead of sending it to rank 0: for a run whose only output is
// TetGen's files and that is not checked (the check needs the whole mesh at rank 0).
struct Listing {
  std::vector<int> facet_markers;
  std::string write_prefix;
};

// The refinement of vm by every rank of the run (world().size > 1). On rank 0: the result of
// the completion, with the parallel figures in the summary (object "parallel") and on
// stderr; elsewhere nullopt (rank 0 finishes the run). `seconds` gets the wall time of the
// phases before the completion (coarse, parallel, gather, assemble). `latency_us` > 0: every
// message of the parallel phase is held that long before it is delivered. `submeshes`
// N >= P (0: P) parts of M_o, submesh k on rank k mod P (par/actor_mux.hpp). `owners`
// (when given) gets, on rank 0, who made each vertex (app/partitioned_output.hpp).
// `quality` gets, on rank 0, the quality figures of the final inside tets when the ranks
// computed them on their submeshes (the completion then added no vertex and changed no
// flag, so those are the mesh's tets: refine::QualityRange), else nothing. With `listing`
// (the output needs no region attributes: every facet separates the domain from its
// outside), the ranks list the mesh themselves when the completion would have nothing to
// do (par/mesh_parts.hpp): rank 0 then gets it in `listed`, and vm stays M_o.
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
                                                       std::optional<ListedMesh>& listed);

// The exit code of the run, on every rank (`code` without mpirun): the code the checkpoint
// fixed; else, past the checkpoint, rank 0's; else (no checkpoint yet: a command without
// a parallel phase, or a failure before it) the checkpoint's.
int agree_exit_code(int code);

}  // namespace pdr::app
