// Conformity of T to D during refinement (paper §1.1: "the subsegments and subfacets in D
// appear in T"), kept outside the theory too.
//
// In an admissible domain Lemma 1 keeps every subsegment an edge and every subfacet a face
// of T. Outside the theory an insertion can break this in two ways: its cavity swallows an
// element of D that the insertion does not replace (a subfacet that is a face between two
// conflict tets, a subsegment that is an edge of conflict tets but of no boundary face), or
// an element the insertion creates in D (a subfacet or subsegment at the new vertex) is
// not Delaunay in 3D. Either way the element has a vertex of T in its closed diametral or
// equatorial ball (a triangle or segment whose smallest circumscribing ball is empty of
// other vertices is a face of the Delaunay tetrahedralization, with the kernel's symbolic
// perturbation deciding ties): it is encroached, and Fig. 2's remedy applies, Refine(f) or
// Refine(s), repeated until the pieces are edges and faces of T again (conforming Delaunay
// refinement by splitting encroached elements; Shewchuk, "Tetrahedral mesh generation by
// Delaunay refinement", SoCG 1998).
//
//   doomed_elements  before a commit: the elements of D the cavity would take out of T;
//                    a tet circumcenter with any is not inserted, the element is refined
//                    instead (as if the point encroached it); for the other insertions
//                    they are recorded as missing after the commit;
//   missing_at       after a commit: the elements of D at the new vertex that are not
//                    edges or faces of its star;
//   reflag           after every missing element is back (or was refused): the inside
//                    flags of the tets made meanwhile, from the flags of the tets around
//                    them. While an element of D is missing from T, flags derived across
//                    faces (refine/volume_mesh.hpp commit_point) can be wrong; they are
//                    recomputed once T conforms again, toggling across the subfacets of
//                    separating facets (face_flips) from the tets whose flags predate
//                    the break.
// The protected length (refine/split.hpp) does not hold these refinements: a finer mesh
// near a sharp corner is a cost, a non-conforming one is a bug. Elements that stay missing
// (the vertex cap stopped their refinement) make the output non-conforming there; the exact checker reports it and pdr mesh exits 3 with the
// reasons (refine/seq_refinement.hpp unsplit).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include "delaunay/cavity.hpp"
#include "refine/guard.hpp"
#include "refine/volume_mesh.hpp"

namespace pdr::refine {

// Appends the subfacets and subsegments of D that committing c would remove from T
// (c built on m.dt's current triangulation, D already updated for this insertion).
void doomed_elements(const VolumeMesh& m, const Cavity& c, EncroachedLists& out);

// Appends the subfacets and subsegments of D at T vertex v that are not faces or edges of
// the tets of `star` (v's star in T, every tet holding v); true when one of them was not
// listed in `out` yet (an entry with the same, reused id and other vertices is replaced).
bool missing_at(const VolumeMesh& m, VertexId v, std::span<const TetId> star,
                EncroachedLists& out);

// Recomputes the inside flag of every live finite tet in `made` from its neighbours
// outside `made` (ghosts are outside), toggling across face_flips faces; returns the live
// finite tets of `made`, each once.
std::vector<TetId> reflag(VolumeMesh& m, std::span<const TetId> made);

// Inside flags after a surface insertion whose cavity missed an element D just replaced.
// commit_point derives each new tet's flag across its old face, toggled when that face is a
// subfacet; this is right when every subfacet (and subsegment) the surface update replaced
// lies inside the cavity. In exact arithmetic it does: a point on a subsegment's chord, or
// on a subfacet's plane inside its circumcircle, is strictly inside every sphere through
// the element's vertices. With a constructed point a few ulps off (a split on a segment
// between two facets coplanar within rounding), a flat tet holding the replaced element
// with a huge circumsphere can test outside the cavity: the element stays a face or edge
// of T while it is no longer in D, and flags derived across it take the wrong side. The
// new vertex's star then shows it: across a face through the new vertex the flags differ
// iff the face is a subfacet, unless the derivation went wrong.
//   star_flags_consistent  that test on the faces of the star's finite tets;
//   reflag_all             recomputes every flag by parity from the ghost tets (outside)
//                          across T's faces, toggling at subfacets; returns the live
//                          finite tets whose flag changed, and counts in `conflicts` the
//                          faces where the parity disagrees (T does not separate Ω from the
//                          rest along D there; 0 when T conforms to D).
bool star_flags_consistent(const VolumeMesh& m, std::span<const TetId> star);
std::vector<TetId> reflag_all(VolumeMesh& m, std::size_t& conflicts);

// SeqRefinement's bookkeeping of the above: the elements of D missing from T and the tets
// made while any is (T conforms iff none is dirty).
class ConformityTracker {
 public:
  // T_o's missing elements (VolumeMesh::missing_*): every tet becomes dirty.
  void start(const VolumeMesh& m);
  // The elements committing c would take out of T (filled anew; the buffers are reused).
  const EncroachedLists& doomed(const VolumeMesh& m, const Cavity& c);
  // The same when the caller knows c dooms nothing (refine/closure.hpp ClosureScan found
  // none in the whole cavity): the lists are emptied without a scan.
  void doomed_none();
  // After the commit of vertex v with `star`: the last doomed() elements and missing_at
  // join the missing ones, and the star is dirty while any is. True when new elements
  // went missing.
  bool committed(const VolumeMesh& m, VertexId v, std::span<const TetId> star);
  // The next missing element D still holds (subsegments first); nullopt when none.
  struct Next {
    bool subsegment;
    Encroached e;
  };
  std::optional<Next> next(const SurfaceMesh& s);
  void wait_again(const Next& n);  // refined, but still missing (Refine(f) split a segment)
  bool broken() const { return !dirty_.empty(); }
  // Once nothing is missing: reflags the dirty tets and returns the live ones.
  std::vector<TetId> restore(VolumeMesh& m);
  // The budget ended: the elements still missing (each still in D); flags reflagged.
  std::vector<Next> abandon(VolumeMesh& m);

 private:
  // A list of missing elements with an index by id (an element is listed once; a reused
  // id with other vertices replaces its entry): thousands can be missing at once in a
  // cascade of repairs, and a search of the list per element made that quadratic.
  struct Missing {
    std::vector<Encroached> list;
    std::unordered_map<std::uint32_t, std::size_t> at;  // id -> its index in list
    bool add(std::uint32_t id, const std::array<std::uint32_t, 3>& v);  // true: new or changed
    void push(const Encroached& e);
    Encroached pop();
  };
  bool add(bool subsegment, const VolumeMesh& m, std::uint32_t id);
  Missing segments_, facets_;
  EncroachedLists doomed_, found_;
  std::vector<TetId> dirty_;
};

}  // namespace pdr::refine
