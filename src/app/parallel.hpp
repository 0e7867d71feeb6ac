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

#include "app/summary.hpp"
#include "refine/seq_refinement.hpp"

namespace pdr::app {

// This process's place in the run: set once by main (rank 0 of 1 without mpirun).
struct World {
  int rank = 0;
  int size = 1;
};
World& world();

// The refinement of vm by every rank of the run (world().size > 1). On rank 0: the result of
// the completion, with the parallel figures in the summary (object "parallel") and on
// stderr; elsewhere nullopt (rank 0 finishes the run). `seconds` gets the wall time of the
// phases before the completion (coarse, parallel, gather, absorb). `latency_us` > 0: every
// message of the parallel phase is held that long before it is delivered.
std::optional<refine::RefineResult> refine_in_parallel(refine::VolumeMesh& vm,
                                                       const refine::RefineOptions& opt,
                                                       std::size_t initial_tets,
                                                       std::uint64_t latency_us,
                                                       std::uint64_t seed, Summary& summary,
                                                       PhaseTimer& timer, double& seconds);

// The exit code of the run: rank 0's, on every rank (returns `code` without mpirun).
int agree_exit_code(int code);

}  // namespace pdr::app
