// Lemma 1 audit (paper §3): after each insertion of SeqRefinement, check on what the
// insertion touched (the star of the new vertex and the tets across its faces: the new
// tets and the closure's ring) that
//   invariant 1  no subsegment that is an edge of those tets and no subfacet that is a face
//                of them has a vertex of those tets STRICTLY inside its diametral /
//                equatorial ball (exact). Vertices ON the sphere are allowed here: a facet
//                with cocircular vertices (a square grid) is triangulated by SoS, and the
//                fourth vertex of each square lies on the sphere of both triangles, from
//                the start (§2.1) on; the refinement itself still decides with closed
//                balls (refine/seq_refinement.hpp), as Fig. 2 does;
//   invariants 2-4, in the form the proof of Theorem 1 uses them: h is the smallest of
//                l/2, R_f/√2 and R_t/2 over the subsegments (length l), subfacets
//                (circumradius R_f) and tets (circumradius R_t) refined so far (the
//                largest h for which invariants 2-4 hold); every edge created at the new
//                vertex is at least h long (Theorem 1 (1)). h is a double from rounded
//                sizes, so the comparison (exact, GMP) is against h (1 - 2^-40): this only
//                absorbs the rounding of h itself.
// A failure throws RefineError("lemma1.invariantK: ..."), naming the elements and their
// coordinates; it is the first failure (the audit runs after every insertion).
#pragma once

#include <vector>

#include "refine/volume_mesh.hpp"

namespace pdr::refine {

// what: "tet", "subfacet" or "subsegment" (the refined element). Invariant 1 on `star`,
// the current star of v in T (SeqRefinement audits it once the rounding repairs of v's
// insertion step are done, refine/flat.hpp rule 2).
void audit_encroachment(const VolumeMesh& m, VertexId v, const std::vector<TetId>& star,
                        const char* what);
// Invariants 2-4 on `star`, the tets created by v's insertion (right after it); h as above.
void audit_edges(const VolumeMesh& m, VertexId v, const std::vector<TetId>& star,
                 const char* what, double size2, double h);

// Global audit (tests): every subfacet of D is a face of T, flags obey the parity rule
// across every face, and no subsegment or subfacet is encroached by any vertex of the tets
// containing it. Returns "invariant: ..." lines; empty when all hold. O(T).
std::vector<std::string> audit_volume(const VolumeMesh& m);

}  // namespace pdr::refine
