// The resources of SeqRefinement: the resolution the run asks for and the vertex cap that
// bounds it (paper §3, Theorem 1: the refinement ends because no two vertices come closer
// than h; outside the theory, where that argument fails, the cap ends it).
//
// resolution(): the smallest of d/2, L/2 and cbrt(V) that the run was given (without d,
// an eighth of the cube root of the bounding box's volume); resolution_at(d_v) the same
// with a local d (the protected lengths at acute vertices, refine/split.hpp). The cap is
// RefineOptions::max_vertices, or 1000 + 64 n + 16 (box volume) / u^3 for n input vertices
// and resolution u, and never more than half the machine's memory holds at
// kRefineVertexBytes a vertex (a run outside the theory that would not end stops with exit
// 3 and a report, not in the kernel's out-of-memory killer): a resource limit, never a
// geometric decision.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "geom/point.hpp"

namespace pdr::refine {

// What the refinement holds per vertex, for the memory bound of the derived cap: about 6.5
// tets a vertex at some 110 bytes of topology and flags each, the point, its maps and D's
// share (cube-in-cube at 3.7M tets: 355 MiB of peak for 640K vertices, 580 bytes a vertex;
// outside the theory D holds more).
inline constexpr std::size_t kRefineVertexBytes = 1024;
// Half the machine's physical memory over kRefineVertexBytes (2e9 when unknown).
std::size_t memory_vertex_limit();

struct RefineOptions;

class VertexBudget {
 public:
  // `points`: the vertices of T before refinement.
  VertexBudget(std::span<const Point> points, const RefineOptions& o);

  double resolution() const { return resolution_; }
  // The resolution with a local d in place of the domain's (the same rule: d/2, L/2 and
  // cbrt(V), the box's share without a finite d).
  double resolution_at(double d) const;
  std::size_t cap() const { return cap_; }
  // True when `vertices` reached the cap, or when the process's resident memory, read at
  // every 4096th call, passed the memory limit (half the machine's memory: the cap counts
  // kRefineVertexBytes a vertex, and a run outside the theory can hold more, its refused
  // tets' reasons among it); `why` then says so (refine.cap: ... or refine.memory: ...),
  // and every later call says the same.
  bool reached(std::size_t vertices, std::string& why) const;
  void set_memory_limit(double bytes) { memory_limit_ = bytes; }  // 0: none

 private:
  double resolution_ = 0;
  double without_d_ = 0;  // the smallest of L/2 and cbrt(V), or infinity
  double box_share_ = 0;  // cbrt(box volume) / 8
  std::size_t cap_ = 0;
  bool user_cap_ = false;
  double memory_limit_ = 0;
  mutable std::size_t calls_ = 0;
  mutable std::string memory_why_;  // set once the limit was passed
};

// This process's resident memory in bytes (/proc/self/statm; 0 when unknown).
double resident_bytes();

}  // namespace pdr::refine
