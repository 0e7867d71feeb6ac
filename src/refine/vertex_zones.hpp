// Protecting balls around acute input vertices: conformity where several facets meet at one
// vertex at small angles (issue #11; outside the theory only).
//
// The cascade they end. Facets through an input vertex v that meet there at small face
// angles and sharp dihedrals (a needle triangle folded against its neighbours) take each
// other's subfacets out of T at every scale: the repair of a subfacet of F near v puts a
// vertex whose ball holds a vertex of G, whose repair does the same to F, each level about
// half the size of the last, down towards v (a crumpled top: edges of 1e-12 at the repair
// floor, NOT CONFORMING). The protected lengths do not hold repairs, and the rotation
// copies of refine/axis_zones.hpp need walls that hold a strip along one axis.
//
// The construction, after the protecting balls of Cheng, Dey, Ramos and Ray (quality
// meshing of polyhedra with small angles) and the concentric shells of Ruppert and
// Shewchuk. The zone of v is the open ball B of radius r around v (a power of two, at most
// the protected length at v and half the distance to v's nearest vertex when the
// refinement starts; when a repair turns the zone on, at most half the distance from v to
// its nearest vertex then and to the elements of D of segments and facets not through v:
// B then holds v alone, and inside B every facet through v is a union of wedges at v).
// Seen from v, each wedge is a great-circle arc on the unit sphere between two segment
// directions. The zone samples every arc once (sample_arcs): the arcs' ends plus points
// such that the spherical diametral cap of every piece between consecutive samples holds
// no other sample of any arc. Invariant: the vertices of T strictly inside B are v and,
// once the shell is filled, nothing else; the shell's vertices v + r u (u a sample) lie on
// the sphere of radius r.
//
// Why the fans are Delaunay. Let a, b be consecutive samples of the arc of facet F, at
// angle theta. The triangle (v, a, b) lies in F; its equatorial ball E passes through v,
// a and b, so E meets the sphere of radius r around v exactly in the spherical cap around
// the direction of the arc's midpoint of angular radius theta / 2 (|x - v| = r and
// |x - c| = |c - v| give cos(angle(x, c)) = r / (2 |c - v|) = cos(theta / 2)). That cap
// is the piece's diametral cap: it holds no other shell vertex. The rest of E inside the
// sphere holds no vertex (the invariant), and E reaches r / cos(theta / 2) at most. So E
// is empty unless a vertex lies in the thin lens between the sphere and that radius;
// then (v, a, b) may leave T, its circumcenter (at r / (2 cos(theta / 2)) < r from v)
// falls in B, and the piece is split on the sphere (as sample_arcs splits: at its middle,
// or at the power of two nearest it for a piece at an end of its arc), which shortens it
// to at most two thirds and thins the lens, until the vertex is outside it. (A new sample
// can lie in a piece's cap on another arc; that fan then leaves T and is split in turn.)
// Every subfacet of F with the shell edge (a, b) whose circumcenter falls in B goes the
// same way: its circle passes through a and b and does not hold v (D is Delaunay in F's
// plane), so its centre is no farther than v from the chord, and its disc holds the whole
// arc of the sphere from a to b, where the split's sample goes.
//
// The rules (refine/seq_refinement.cpp). A zone is dormant, and changes nothing, until a
// repair's point falls in its ball; that turns it on (the radius bound above). A point a
// step would insert strictly inside the ball of an active zone:
//   - a tet circumcenter, or any refinement that is no repair: refused and listed (a
//     guard, as the protected length: B is no wider);
//   - a repair of a subfacet of F with a shell edge (a, b) on F's arc: the piece is split;
//   - another repair, with the shell empty: the shell is filled;
//   - another repair, with the shell filled: the zone shrinks (r / 2: B then holds v
//     alone again, the old shell lying at twice the new radius) and is filled anew;
//   - a rotation copy: dropped.
// Shrinking stops at 2^-40 of the coordinates' magnitude (doubles cannot place the
// shell), where the repair is refused and listed (NOT CONFORMING, exit 3).
//
// Floating point says where (the directions, the radius, the samples): it decides nothing
// about T, whose exact predicates judge every insertion. A sample that rounding puts a
// hair off the sphere is a vertex like any other.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "geom/point.hpp"
#include "surface/surface_mesh.hpp"

namespace pdr::refine {

// A great-circle arc of directions: cos(t) e1 + sin(t) e2 for t in [0, length]; e1 and e2
// orthonormal.
struct SphereArc {
  Point e1{}, e2{};
  double length = 0;
  Point at(double t) const;
};

// The angles of samples on each arc, sorted, the first 0 and the last its length, such
// that every piece between consecutive samples is at most max_piece long and its
// spherical diametral cap (centred at its middle, of angular radius half its length) holds
// no other sample of any arc (an arc's ends excepted: they stand for its segments, whose
// directions `points` must hold) nor any of `points` strictly inside (with a relative margin of
// 1e-9: it places samples, it decides nothing). A piece at the end of its arc is split at
// the power of two (in radians from that end) nearest its middle: arcs that share an end
// (facets along one segment) then get samples at the same angles from it, which do not
// encroach each other's pieces, as Ruppert's concentric shells on segments; other pieces
// at their middle. nullopt when that needs more than `cap` samples in all.
std::optional<std::vector<std::vector<double>>> sample_arcs(const std::vector<SphereArc>& arcs,
                                                            const std::vector<Point>& points,
                                                            double max_piece, std::size_t cap);

class VertexZones {
 public:
  VertexZones() = default;
  // A zone for each vertex of `candidates` (input vertices of m) whose facets are wedges at
  // it and whose arcs sample within the cap; radius(v): the largest radius its ball may
  // have (the caller's bound: protected length, nearest vertex).
  template <class Radius>
  VertexZones(const surface::SurfaceMesh& m, const std::vector<std::uint32_t>& candidates,
              Radius radius) {
    for (const std::uint32_t v : candidates) {
      const double r = radius(v);
      if (r > 0) add(m, v, r);
    }
    index();
  }

  bool empty() const { return zones_.empty(); }
  std::size_t size() const { return zones_.size(); }

  // The zone whose open ball holds p, if any.
  std::optional<std::uint32_t> holding(const Point& p) const;

  // Where a shell vertex goes: on `segment` (kNone: inside `facet`), at p; `arc` and
  // `sample` name it for record().
  struct ShellPoint {
    std::uint32_t segment = kNone, facet = kNone;
    std::uint32_t arc = 0, sample = 0;
    Point p{};
  };
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  // The vertices of zone z's shell at its current radius: the segments' first, then the
  // arcs' inner samples.
  std::vector<ShellPoint> shell(std::uint32_t z) const;
  // D's vertex `vertex` is shell point s of zone z (the caller inserted it).
  void record(std::uint32_t z, const ShellPoint& s, std::uint32_t vertex);
  // A zone is dormant until the first repair in its ball: dormant, it changes nothing.
  // activate(z, bound) makes it active, its radius then the largest power of two at most
  // its radius and `bound` (the caller's: half the distance from v to its nearest vertex).
  bool active(std::uint32_t z) const { return zones_[z].active; }
  bool any_active() const { return active_ > 0; }
  void activate(std::uint32_t z, double bound);
  bool filled(std::uint32_t z) const { return zones_[z].filled; }
  void set_filled(std::uint32_t z) { zones_[z].filled = true; }
  // If D's vertices a and b are consecutive shell vertices of an arc of facet f in zone z:
  // that piece split as sample_arcs splits (the sample is added to the arc, for later
  // shells too), as the point to insert.
  std::optional<ShellPoint> split_piece(std::uint32_t z, std::uint32_t f, std::uint32_t a,
                                        std::uint32_t b);
  // Whether a and b are consecutive shell vertices of an arc of f in zone z, the piece
  // split_piece looks for (it may still find no angle to split it at); changes nothing.
  bool has_piece(std::uint32_t z, std::uint32_t f, std::uint32_t a, std::uint32_t b) const;
  // Halves zone z's radius and empties its shell; false (nothing changed) when the new
  // radius would be below `floor` or below 2^-40 of the first.
  bool shrink(std::uint32_t z, double floor);
  std::uint32_t vertex(std::uint32_t z) const { return zones_[z].vertex; }
  double radius(std::uint32_t z) const { return zones_[z].r; }

 private:
  // The arc of f and the index i of the piece (a, b) = (vertices[i], vertices[i + 1]) of
  // zone z's shell, in either order.
  std::optional<std::pair<std::uint32_t, std::uint32_t>> find_piece(std::uint32_t z,
                                                                    std::uint32_t f,
                                                                    std::uint32_t a,
                                                                    std::uint32_t b) const;
  struct Arc {
    std::uint32_t facet = 0;
    SphereArc geometry;
    std::uint32_t first = 0, last = 0;    // the segments at t = 0 and t = length
    std::vector<double> angles;           // the samples (sample_arcs)
    std::vector<std::uint32_t> vertices;  // D's vertex of each sample in the shell, or kNone
  };
  struct Zone {
    std::uint32_t vertex = 0;
    Point v{};
    double r = 0, r0 = 0;  // the radius, and the first one
    bool active = false, filled = false;
    std::vector<std::pair<std::uint32_t, Point>> segments;  // segment, unit direction from v
    std::vector<std::uint32_t> segment_vertex;             // its shell vertex, or kNone
    std::vector<Arc> arcs;
  };
  std::vector<Zone> zones_;
  std::size_t active_ = 0;  // zones turned on
  // A uniform grid of cell size cell_ over the zones' centres (radii only shrink).
  double cell_ = 0;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> grid_;  // (cell key, zone), sorted

  void add(const surface::SurfaceMesh& m, std::uint32_t v, double r);
  // D's vertex of segment `segment`'s shell point in zone z (the arcs' ends there too).
  void record_segment(std::uint32_t z, std::uint32_t segment, std::uint32_t vertex);
  void index();
  std::uint64_t key(const Point& p, int dx, int dy, int dz) const;
};

}  // namespace pdr::refine
