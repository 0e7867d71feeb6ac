// Where a subsegment is split (paper Fig. 2 "Refine(s)": at its midpoint), with the guards
// for domains outside the theory (angles < 90°, domain/angles.hpp), after Ruppert's and
// Shewchuk's concentric shells:
//   acute vertices  the input vertices where an inadmissible pair meets (the shared
//                   vertex of a record; for a dihedral along a segment, its two ends);
//                   a segment with an acute end is guarded;
//   shells          a subsegment (u, w) with u an acute input vertex and w not one is split
//                   at the point at distance 2^k from u (k integer) closest to its
//                   midpoint, so in [l/3, 2l/3]: the subsegments around u end on the same
//                   spheres centred at u, and a split near u never encroaches the
//                   subsegment of a neighbouring segment at the same radius (the cascade
//                   around a small angle stops); otherwise the midpoint;
//   protected       on a guarded segment no split leaves a piece shorter than the
//                   protected length (the caller's floor of the subsegment's local d, the
//                   d the surface mesh sized it for: resolution / 64 with d_local in
//                   place of d, a floor on how fine the shells go); plan then refuses,
//                   with the reason, and the caller reports the element it could not
//                   refine. Likewise a subfacet of circumradius below the protected length
//                   of its local d on a guarded facet (one containing a guarded segment) is
//                   not refined (refuse_subfacet). With the surface graded by position the
//                   floor is local, as the protecting balls of Cheng, Dey, Ramos and Ray
//                   are sized by the local feature size: a small feature elsewhere no
//                   longer makes every acute corner as fine as it (a pyramid 6 high with a
//                   void 0.002 above its base: the apex refined to edges of 3.5e-6 before,
//                   of 4.5e-4 now, at V = 0.001); uniform, it is the domain's d
//                   everywhere. Near a sharp dihedral the subfacets of the two facets
//                   encroach each other at every scale, and this floor ends that cascade. Rounding repairs (refine/
//                   flat.hpp rule 1: a flat tet on a facet) and conformity repairs
//                   (refine/conformity.hpp: an element of D missing from T) are not held
//                   by it (plan's below_floor); the vertex cap bounds them.
//   cylinders       along a sharp segment (two facets meeting along it at a dihedral
//                   below arccos(1/3) = 70.5° or above 289.5°) the subfacets of the two
//                   facets encroach each other at every scale, so a protected length
//                   alone leaves a band as wide as the segment is long refined down to it. After the protecting
//                   balls of Cheng, Dey, Ramos and Ray (polyhedra with small angles), a
//                   cylinder around the segment, of radius a fraction (kCylinderFraction)
//                   of the segment's local feature size (its distance to the components
//                   sharing no vertex with it), and no wider than the element size the
//                   run asks for (min(L, cbrt(V)): a finer mesh leaves fewer tets near the
//                   segment unrefined), has a protected length of its own: a subfacet of a
//                   facet containing the segment, whose circumcenter lies in the cylinder,
//                   is not refined once its circumradius is below kCylinderFloor times the
//                   radius (refuse_subfacet). The mutual encroachment then stops at sizes
//                   proportional to the local feature size (or the element size), not to
//                   the global protected length; tets whose refinement needed such a split
//                   are refused (listed, exit 3), as below the floor. Measured on the
//                   bench's domains (bench_mesh --outside): at 60-70 degrees the cascade
//                   ends by itself above the cylinder's floor (nothing is refused, as
//                   before); at 33 degrees the run makes about a tenth of the vertices.
// For an admissible domain the guard is empty: every split is the midpoint, as Lemma 1
// needs. Lengths and the split point are floating point: they say where, not whether; the
// point is a + t (b - a), on the segment up to rounding like the midpoint.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "domain/analysis.hpp"
#include "surface/surface_mesh.hpp"

namespace pdr::refine {

// The acute vertices of a domain (Plc vertex ids = D's input vertex ids), sorted, unique.
std::vector<std::uint32_t> acute_vertices(const domain::DomainReport& r);

// The protecting cylinders' radii, kCylinderFraction times the local feature size, per
// segment of the domain (parallel to domain::PlcDomain::segments, as D's segments); 0 for a
// segment along which no two facets meet at a dihedral whose acute side (the dihedral, or
// 360 degrees minus it) is below kCylinderAngleDeg. Empty when there is none.
// kCylinderAngleDeg = arccos(1/3), about 70.53 degrees: H. Si (An analysis of Shewchuk's
// Delaunay refinement algorithm, IMR 2009) proves that Shewchuk's refinement terminates
// with input dihedral angles down to it, so a dihedral at or above it needs no protection
// (and a cylinder there only leaves tets unrefined: a twisted square prism of triangle
// facets with 80-degree dihedrals kept 1,143 tets with ratio >= 2 with one, 22 without).
inline constexpr double kCylinderAngleDeg = 70.52877936550931;
inline constexpr double kCylinderFraction = 0.5;
inline constexpr double kCylinderFloor = 0.5;
std::vector<double> protecting_cylinders(const domain::DomainAnalysis& an);

class SplitGuard {
 public:
  SplitGuard() = default;  // no guard: midpoints
  // The protected length of an element refined for the local d `d` (surface::SurfaceMesh::
  // subsegment_size, subfacet_size).
  using Floor = std::function<double(double d)>;
  SplitGuard(const surface::SurfaceMesh& m, const std::vector<std::uint32_t>& acute, Floor floor,
             const std::vector<double>& cylinders = {},
             double cylinder_cap = std::numeric_limits<double>::infinity());

  struct Plan {
    bool ok = true;
    Point p{};           // where (ok)
    std::string reason;  // why not (!ok)
  };
  // `below_floor`: the split repairs rounding or conformity and may go below the
  // protected length (shells still apply).
  Plan plan(const surface::SurfaceMesh& m, std::uint32_t subsegment,
            bool below_floor = false) const;
  // Why subfacet f may not be refined, or empty. `scale` < 1 lowers the protected lengths
  // (a repair's deeper floor).
  std::string refuse_subfacet(const surface::SurfaceMesh& m, std::uint32_t f,
                              double scale = 1) const;
  bool active() const { return !acute_.empty(); }

 private:
  std::vector<std::uint8_t> acute_;    // per input vertex of D
  std::vector<std::uint8_t> guarded_;  // per segment
  std::vector<std::uint8_t> guarded_facet_;
  Floor floor_;
  struct Cylinder {
    Point a, b;
    double radius = 0;
    std::uint32_t segment = 0;
  };
  std::vector<std::vector<Cylinder>> facet_cylinders_;  // per facet, of its sharp segments

  bool is_acute(std::uint32_t v) const { return v < acute_.size() && acute_[v] != 0; }
};

}  // namespace pdr::refine
