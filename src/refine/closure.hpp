// Fig. 2's encroachment tests on a cavity's closure: which subsegment or subfacet of C_p
// a candidate point p encroaches (closed balls, exact: geom/encroach.hpp). The tets given
// are the closure of p's cavity (its conflict tets and ring), or a tet alone.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>

#include "delaunay/cavity.hpp"
#include "refine/volume_mesh.hpp"

namespace pdr::refine {

using ClosureTets = std::initializer_list<std::span<const TetId>>;

// A subsegment that is an edge of the tets and whose closed diametral ball holds p (Fig. 2
// "p encroaches subsegment s ∈ C_p"); the first found.
std::optional<std::uint32_t> closure_encroached_subsegment(const VolumeMesh& m,
                                                           ClosureTets tets, const Point& p);

// The subfacet of largest circumradius among the faces of the tets whose closed
// equatorial ball holds p (Fig. 2 "f <- max radius(f) that p encroaches"), compared
// exactly (geom/encroach.hpp); equal radii: the smaller sorted vertex coordinates.
std::optional<std::uint32_t> closure_encroached_subfacet(const VolumeMesh& m,
                                                         ClosureTets tets, const Point& p);

// Whether triangle a is the larger subfacet in Fig. 2's choice above: the larger
// circumradius, exactly; on a tie, the lexicographically smaller sorted vertices (a
// geometric rule: the same choice for every numbering of the same mesh).
bool larger_subfacet(std::array<Point, 3> a, std::array<Point, 3> b);

// Outside the theory: the first element of D, in the order of p's cavity (its conflict
// tets from p's own tet outwards, then its ring), that p encroaches (closed balls, as
// above) or that committing the cavity would take out of T (a subfacet between two
// conflict tets, a subsegment on no boundary face: refine/conformity.hpp doomed_elements).
// One pass that stops at the first: a skinny tet next to a sharp fold has its circumcenter
// far off and a cavity of thousands of tets, and the element found is most often one the
// guards refuse, so the rest of the scan was wasted. Fig. 2's order (every encroached
// subsegment before the largest encroached subfacet, then the doomed ones) needs the
// whole closure and stays with the admissible domains.
class ClosureScan {
 public:
  struct Hit {
    bool subsegment = false;  // else a subfacet
    bool encroached = false;  // else doomed
    std::uint32_t id = 0;
  };
  // The first such element of the built cavity c; `conflict_seen`: joins() already looked
  // at every conflict tet, so only the doomed subsegments and the ring are left.
  std::optional<Hit> first(const VolumeMesh& m, const Cavity& c, const Point& p,
                           bool conflict_seen = false);
  // While the cavity is searched (CavityBuilder::build_until): what tet u, joining it
  // across face `face` of conflict tet `from` (kNoTet for the seed), shows: the face
  // between them when it is a subfacet (doomed), else an edge or face of u that p
  // encroaches.
  std::optional<Hit> joins(const VolumeMesh& m, TetId from, int face, TetId u,
                           const Point& p) const;

 private:
  void stamp(const TetStore& s, std::span<const TetId> conflict);
  bool inside_cavity(const TetStore& s, TetId t, VertexId a, VertexId b) const;
  std::optional<Hit> look(const VolumeMesh& m, TetId t, const Point& p, bool encroached,
                          bool doomed) const;
  std::vector<std::uint32_t> stamp_;  // per tet slot: == gen_ for the conflict tets
  std::uint32_t gen_ = 0;
};

}  // namespace pdr::refine
