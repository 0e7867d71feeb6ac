// The encroachment guard of SeqRefinement (refine/seq_refinement.hpp) for domains outside
// the theory.
//
// In an admissible domain Lemma 1 keeps D unencroached, and Fig. 2 only needs to look at
// the closure of each new point's cavity. With angles < 90° neither holds: the initial
// mesh may already have a vertex strictly inside the equatorial ball of a subfacet, and a
// new vertex on one facet may encroach a subfacet of another one outside its cavity.
// find_encroached lists, among the subsegments and subfacets of the given tets, those that
// a vertex of the same tets lies STRICTLY inside the diametral / equatorial ball of
// (geom/encroach.hpp, exact, as the checker's encroachment.* checks; a vertex on the
// sphere is not encroaching, so cospherical structured meshes do not cascade).
// Why looking at tets suffices (T is Delaunay, every subfacet a face and every
// subsegment an edge of T):
//   subfacet f with tets t1, t2 on its sides: the spheres through f's circle form a pencil;
//   on t1's side the ball of t1's circumsphere contains the equatorial ball's half when
//   t1's apex is not strictly inside the equatorial ball, so a vertex strictly inside that
//   half would be strictly inside t1's circumball: if any vertex encroaches f, an apex does;
//   subsegment ab: the dual Voronoi polygon V(ab) lies in the bisector plane; the midpoint
//   m is outside it iff a vertex is strictly inside the diametral ball; the nearest point
//   x of V(ab) to m lies on edges of V(ab) dual to triangles abc of T, and m violates one
//   of the constraints active at x: that c (a vertex of a tet around ab) is strictly
//   inside. With cospherical vertices the active constraint may be a vertex of the
//   cluster off ab's ring; the exact checker on the output catches what this misses.
// So an insertion creates new encroachment only among the elements of the new tets (the
// star of the new vertex): the refinement calls find_encroached on the star after every
// insertion, and once on every tet of the initial mesh.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "refine/volume_mesh.hpp"

namespace pdr::refine {

struct Encroached {
  std::uint32_t id = 0;               // subsegment or subfacet id in D
  std::array<std::uint32_t, 3> v{};   // its D vertices when found (v[2]: subfacets only)
  VertexId by = 0;                    // an encroaching vertex of T
  TetId tet = kNoTet;                 // a tet holding both (a hint for locating)
};

struct EncroachedLists {
  std::vector<Encroached> subsegments, subfacets;
};

// Appends the encroached elements of the live finite tets in `tets` (duplicates possible).
void find_encroached(const VolumeMesh& m, std::span<const TetId> tets, EncroachedLists& out);

// Whether the element is still the one found (ids are reused after splits).
bool still_subsegment(const SurfaceMesh& s, const Encroached& e);
bool still_subfacet(const SurfaceMesh& s, const Encroached& e);

}  // namespace pdr::refine
