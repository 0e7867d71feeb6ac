// The parallel phase of ParRefinement (paper §4, Fig. 7) on one rank, and what the
// sequential completion needs from it (docs/parallel.md).
//
// Every rank holds the same mesh M_o (built deterministically from the same input) and the
// same METIS partition of it into N >= P parts (par/partition.hpp); rank r keeps parts
// r, r + P, ... as its submeshes
// (par/submesh.hpp) and refines its bad tets with the InsertionActor's protocol and
// RefinementRules (par/refinement_rules.hpp): distributed cavities pulled to the root,
// closure locks, setbacks with seeded back-off, termination detection. With
// `surface_steps`, encroached subsegments and subfacets are refined there too (Refine(s),
// Refine(f)); else the steps that would change D, and those that leave Ω, are deferred.
//
// After termination, rank 0 gathers the submeshes' tets (par/mpi_collect.hpp) and
// assembles them into the whole mesh in place of its M_o (par/assembly.hpp): M_o plus the
// committed points, with their inside flags; it makes the phase's changes to D in its
// own. The sequential refinement (refine/seq_refinement.hpp) then completes
// the mesh from there.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "par/insertion_actor.hpp"
#include "par/partition.hpp"
#include "par/refinement_rules.hpp"
#include "refine/quality.hpp"
#include "par/transport.hpp"

namespace pdr::par {

// One rank's figures of the parallel phase (fixed size: gathered as bytes).
struct RankFigures {
  double seconds = 0;          // from the start of the loop to termination
  double busy_seconds = 0;     // in steps that did work, each from the previous step's
                               // last reading (InsertionActor::step) to its own
  InsertionStats steps;        // commits, setbacks, rounds, fetches, migrated tets, ...
  DeferCounts deferred;        // steps left to the sequential completion, by reason
  std::uint64_t messages_sent = 0, messages_received = 0, bytes_sent = 0;
  std::uint64_t empty_polls = 0, sleeps = 0;
  std::uint64_t start_tets = 0, final_tets = 0;  // real tets of the submesh
  std::uint64_t points = 0;                     // points committed (RankResult::points)
  refine::QualityRange quality;  // of the submeshes' inside tets at the end
};

// The quality figures of submesh s's inside tets (real, not ghosts).
refine::QualityRange submesh_quality(const Submesh& s);

struct RankResult {
  std::vector<Point> points;  // the points this rank committed, submesh by submesh
  std::vector<std::uint64_t> made;  // how many of them each of its submeshes made
  std::vector<SurfaceStep> surface_steps;  // its steps on ∂Ω (a point each, above)
  // Its submeshes at the end (submesh rank, rank + P, ...): for the pieces
  // (par/assembly.hpp) or the rank's part of the mesh (par/mesh_parts.hpp).
  std::vector<Submesh> submeshes;
  RankFigures figures;  // all but `quality`, which the caller adds from the submeshes
};

// The submeshes' tets (par/assembly.hpp), in a row, and their inside tets' quality figures.
Bytes pieces_of(std::span<const Submesh> submeshes);
refine::QualityRange quality_of(std::span<const Submesh> submeshes);

// The parallel phase on this rank (transport t). Submesh k of part.parts >= t.size() lives
// on rank k % t.size(): one actor each, the rank's transport itself when there are as many
// submeshes as ranks, else the ports of an ActorMux (par/actor_mux.hpp). The figures are
// the rank's: its actors' summed.
// `points`: at most that many points committed by this rank (its share of the vertex
// cap; past it, steps are deferred).
RankResult refine_part(const refine::VolumeMesh& m0, const Partition& part, Transport& t,
                       const refine::TetBounds& bounds, std::uint64_t seed,
                       bool surface_steps = false,
                       std::uint64_t points = ~std::uint64_t{0});

}  // namespace pdr::par
