// Cavity: the Bowyer-Watson cavity of a point, as a value built read-only (paper §1.2,
// §4.1; docs/design.md §10).
//
// For a point p and a seed tet in conflict with p, CavityBuilder::build() collects, by a
// breadth-first search over faces that never modifies the store:
//   conflict  C_p: every tet in conflict with p (conflict.hpp) face-connected to the seed;
//             by the Delaunay property this is every tet in conflict with p;
//   boundary  H_p: the half-faces (t,f) with t in C_p whose neighbour is not in C_p, each
//             oriented out of the cavity (mesh/tables.hpp). B_p is p joined to these;
//   ring      the closure tets not in C_p, each once: face-neighbours of C_p that do not
//             conflict. The closure of §1.2 is conflict ∪ ring; §4.1 locks exactly this
//             set, since two cavities whose closures are disjoint commit independently.
// Nothing is written to the store, so abandoning a cavity costs nothing (a parallel search
// that meets a lock just drops the value). The builder's mark array is scratch: all zero
// between calls. A cavity is valid for commit only while the store is unchanged.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "geom/point.hpp"
#include "mesh/tet_store.hpp"

namespace pdr {

struct Cavity {
  Point point{};                    // p
  TetId seed = kNoTet;
  std::vector<TetId> conflict;      // C_p, seed first
  std::vector<HalfFace> boundary;   // H_p, half-faces of tets in C_p
  std::vector<TetId> ring;          // closure \ C_p

  void clear() {
    seed = kNoTet;
    conflict.clear();
    boundary.clear();
    ring.clear();
  }
  std::size_t closure_size() const { return conflict.size() + ring.size(); }
};

class CavityBuilder {
 public:
  // Fills `out` (its buffers are reused). Preconditions: `seed` is live and in conflict
  // with p; p is not a vertex of the triangulation; the store is a Delaunay triangulation
  // of pts (so the conflict region is face-connected and star-shaped from p).
  void build(const TetStore& s, std::span<const Point> pts, const Point& p, TetId seed,
             Cavity& out);
  // As build, but calls stop(from, f, u) for each tet u as it joins C_p, reached across
  // face f of conflict tet `from` (kNoTet and -1 for the seed), and gives up as soon as it
  // returns true: false then, with `out` partial. A caller that rejects p for something
  // it sees in one conflict tet need not build the rest (a far circumcenter's cavity can
  // span much of T).
  using Stop = std::function<bool(TetId from, int face, TetId u)>;
  bool build_until(const TetStore& s, std::span<const Point> pts, const Point& p,
                   TetId seed, Cavity& out, const Stop& stop);

 private:
  template <class StopFn>
  bool grow(const TetStore& s, std::span<const Point> pts, const Point& p, TetId seed,
            Cavity& out, const StopFn& stop);
  // A scoped enum, not a character type: stores to the marks then cannot alias every
  // other object, so the compiler keeps the search's state in registers.
  enum class Mark : std::uint8_t { Unseen = 0, Inside = 1, Outside = 2 };
  std::vector<Mark> mark_;  // per tet slot; Unseen between calls
};

}  // namespace pdr
