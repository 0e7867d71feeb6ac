// in_conflict: does point p conflict with tet t (paper §1.2: p lies in t's open
// circumsphere)? The one geometric decision of the cavity search, made only by predicates.
//
//   finite tet (a,b,c,d), positive:  insphere_sos(a,b,c,d,p) == Positive.
//   ghost tet (a,b,c,ghost):         (a,b,c) is a hull face oriented out of the hull
//                                    (tet_store.hpp). p conflicts when it is strictly
//                                    outside, orient3d(a,b,c,p) > 0, or on the face's
//                                    plane and incircle3_sos(a,b,c,p) == Positive.
//   proxy tet (a,b,c,remote):        never (mesh/tet_store.hpp: the tet behind the face
//                                    lives in another submesh; the cavity search lists
//                                    it in the ring, and the parallel layer fetches it).
// A ghost tet is the limit of a finite tet whose fourth vertex runs to infinity beyond the
// hull face, so its "circumsphere" is the open half-space outside the face plus, on the
// plane itself, the open circumdisk of the face. Because incircle3_sos is insphere_sos
// restricted to the plane (geom/predicates.hpp), a point on a hull plane conflicts with
// the ghost tet exactly when it conflicts with the finite tet behind the same face; and
// since SoS ranks points by coordinates only, the resulting tetrahedralization (hull
// included) is the same for every insertion order.
// Speed: semi-static filters (semistatic.hpp) are inlined here, since this test
// runs ~45 times per insertion; only an Unsure filter calls the full adaptive predicate.
// The filters are exact decisions (proven error bounds), so this changes no outcome.
// Precondition: p is not a vertex of t (duplicates are filtered by the walk).
#pragma once

#include <span>

#include "delaunay/semistatic.hpp"
#include "geom/predicates.hpp"
#include "mesh/tet_store.hpp"

namespace pdr {

inline bool in_conflict(const TetStore& s, std::span<const Point> pts, TetId t,
                        const Point& p) {
  const VertexId* v = s.vertices(t);
  if (v[3] >= kFirstSpecialVertex) [[unlikely]] {
    if (v[3] != kGhostVertex) return false;  // a proxy
    const Filtered quick = semistatic::orient3d(pts[v[0]].data(), pts[v[1]].data(),
                                                pts[v[2]].data(), p.data());
    if (quick == Filtered::Positive) return true;
    if (quick == Filtered::Negative) return false;
    const Sign o = orient3d(pts[v[0]], pts[v[1]], pts[v[2]], p);
    if (o != Sign::Zero) return o == Sign::Positive;
    return incircle3_sos(pts[v[0]], pts[v[1]], pts[v[2]], p) == Sign::Positive;
  }
  const Filtered quick = semistatic::insphere(pts[v[0]].data(), pts[v[1]].data(),
                                             pts[v[2]].data(), pts[v[3]].data(), p.data());
  if (quick == Filtered::Positive) return true;
  if (quick == Filtered::Negative) return false;
  return insphere_sos(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]], p) == Sign::Positive;
}

// Whether t can seed p's cavity without a walk to p: p is none of t's vertices (the
// precondition above) and conflicts with t. Then p is no vertex of the triangulation at
// all, since no other vertex lies strictly inside (or, perturbed, on) a Delaunay tet's
// circumsphere. A tet's own circumcenter passes but for rounding.
inline bool seeds_cavity(const TetStore& s, std::span<const Point> pts, TetId t, const Point& p) {
  const VertexId* v = s.vertices(t);
  for (int i = 0; i < 4; ++i)
    if (v[i] < pts.size() && pts[v[i]] == p) return false;
  return in_conflict(s, pts, t, p);
}

}  // namespace pdr
