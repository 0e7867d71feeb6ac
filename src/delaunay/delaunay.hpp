// Delaunay: an incremental Delaunay tetrahedralization of a growing point set
// (Bowyer-Watson, paper §1.2), with the hull closed by ghost tets.
//
// Owns the points (vertex id = index into points()) and a TetStore. Inserting a point:
// locate it from a hint tet (walk.hpp), build its cavity read-only (cavity.hpp), commit
// the cavity (insert.hpp). The steps are public so refinement can start from a known tet
// (the one whose circumcentre it inserts), inspect a cavity before committing it
// (encroachment, §3) and parallel code can drop it (§4.1):
//   Location loc = dt.locate(p, known_tet);            // OnVertex: a duplicate
//   dt.build_cavity(p, loc.tet, cavity);               // read-only
//   if (acceptable(cavity)) dt.commit(cavity);         // p becomes a vertex
// or in one call: dt.insert(p, known_tet).
//
// Invariants after every public call (the tests' audit level checks them all):
//   - the store is topologically valid (TetStore::check_topology), every finite tet is
//     positive, ghost tets cover the hull faces, oriented out of the hull;
//   - the triangulation is the unique SoS-Delaunay tetrahedralization of the inserted
//     points: no inserted point conflicts with any tet (conflict.hpp);
//   - last_tet() is live and incident to the last inserted vertex.
// Points added but not inserted (or reported Duplicate) belong to no tet.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "delaunay/cavity.hpp"
#include "delaunay/insert.hpp"
#include "delaunay/outcome.hpp"
#include "delaunay/walk.hpp"
#include "geom/point.hpp"
#include "mesh/tet_store.hpp"

namespace pdr {

// Tuning knobs of the kernel (none changes the triangulation, only how it is computed).
struct KernelOptions {
  std::uint32_t walk_seed = 0x9E3779B9u;     // the walk's face-choice generator (nonzero)
  std::uint32_t dense_pairing_limit = 128;  // insert.hpp: L x L table up to this many
                                            // boundary vertices, hashing beyond
};

struct InsertResult {
  Outcome outcome = Outcome::Inserted;
  VertexId vertex = kNoVertex;  // Inserted: the new vertex; Duplicate: the existing one
  TetId tet = kNoTet;           // a live tet incident to `vertex`: a good next hint
};

class Delaunay {
 public:
  Delaunay() = default;
  explicit Delaunay(std::vector<Point> points, KernelOptions options = {})
      : points_(std::move(points)), committer_(options.dense_pairing_limit) {
    rng_.state = options.walk_seed != 0 ? options.walk_seed : 1;
  }

  // ---- points ------------------------------------------------------------------------
  VertexId add_point(const Point& p) {
    points_.push_back(p);
    return static_cast<VertexId>(points_.size() - 1);
  }
  std::span<const Point> points() const { return points_; }
  // Replace the point set (e.g. reordered for locality). Precondition: empty().
  void set_points(std::vector<Point> points) { points_ = std::move(points); }
  const Point& point(VertexId v) const { return points_[v]; }
  std::size_t num_points() const { return points_.size(); }
  void reserve(std::size_t points, std::size_t tets) {
    points_.reserve(points);
    store_.reserve(tets);
  }

  // ---- tets --------------------------------------------------------------------------
  const TetStore& store() const { return store_; }
  // Replaces the triangulation by `store` over `points`, built elsewhere (the parallel
  // layer's assembly, par/assembly.hpp). Precondition: they meet the invariants above,
  // every point a vertex of a finite tet. last_tet() becomes a finite tet of the last
  // point.
  void adopt(std::vector<Point> points, TetStore store);
  bool empty() const { return store_.live() == 0; }
  TetId last_tet() const { return last_; }
  std::size_t count_finite_tets() const;

  // The first tet, from four points with orient3d(a,b,c,d) != 0 (either sign: it is
  // reordered to be positive), and its four ghost tets. Precondition: empty(). Four
  // coplanar points throw std::invalid_argument (always checked: a flat first tet would
  // corrupt every later step).
  void init(VertexId a, VertexId b, VertexId c, VertexId d);

  // ---- insertion ---------------------------------------------------------------------
  // Walk from `hint` (kNoTet: from last_tet()). Precondition: !empty(), hint live.
  Location locate(const Point& p, TetId hint = kNoTet);
  // Cavity of p from a seed in conflict with p (a Location of kind InTet or OutsideHull
  // gives one). Read-only on the triangulation; `out`'s buffers are reused.
  void build_cavity(const Point& p, TetId seed, Cavity& out) {
    builder_.build(store_, points_, p, seed, out);
  }
  // The same, giving up when stop(from, face, u) says so for a tet u joining the cavity
  // (CavityBuilder::build_until): false then, `out` partial.
  bool build_cavity_until(const Point& p, TetId seed, Cavity& out,
                          const CavityBuilder::Stop& stop) {
    return builder_.build_until(store_, points_, p, seed, out, stop);
  }
  // Commit a cavity built on the current triangulation (nothing changed since): c.point
  // becomes a new vertex (appended to points()). Outcome Inserted; .tet as below.
  InsertResult commit(const Cavity& c);
  // The same for a point already added as vertex v (point(v) == c.point). Returns a new
  // tet incident to v (a finite one when there is one), which is also last_tet().
  TetId commit(const Cavity& c, VertexId v);
  // The tets made by the last commit, in the order of its cavity's boundary: entry i
  // holds the new vertex and boundary face c.boundary[i], at the same face index (valid
  // until the next commit).
  std::span<const TetId> last_created() const { return committer_.created(); }
  // Locate + cavity + commit, walking from `hint` (kNoTet: last_tet()). Inserted, or
  // Duplicate (then nothing changes, and the point is not added).
  InsertResult insert(const Point& p, TetId hint = kNoTet);
  // The same for a point already added as vertex v (bulk construction).
  InsertResult insert(VertexId v, TetId hint = kNoTet);

  // Audit: the topological invariants (geometry is checked by the tests' oracles).
  std::vector<std::string> check_topology() const { return store_.check_topology(); }

  // Statistics of the insertions so far.
  struct Stats {
    std::uint64_t walk_steps = 0;
    std::uint64_t conflict_tets = 0;
    std::uint64_t boundary_faces = 0;
    std::uint64_t inserted = 0;
    std::uint64_t duplicates = 0;
  };
  const Stats& stats() const { return stats_; }

 private:
  std::vector<Point> points_;
  TetStore store_;
  CavityBuilder builder_;
  CavityCommitter committer_;
  Cavity cavity_;  // reused by insert()
  WalkRng rng_;
  TetId last_ = kNoTet;
  Stats stats_;
};

}  // namespace pdr
