// The resources of SeqRefinement: the resolution the run asks for and the vertex cap that
// bounds it (paper §3, Theorem 1: the refinement ends because no two vertices come closer
// than h; outside the theory, where that argument fails, the cap ends it).
//
// resolution(): the smallest of d/2, L/2 and cbrt(V) that the run was given (without d,
// an eighth of the cube root of the bounding box's volume). The cap is
// RefineOptions::max_vertices, or 1000 + 64 n + 16 (box volume) / u^3 for n input vertices
// and resolution u: a resource limit, never a geometric decision.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "geom/point.hpp"

namespace pdr::refine {

struct RefineOptions;

class VertexBudget {
 public:
  // `points`: the vertices of T before refinement.
  VertexBudget(std::span<const Point> points, const RefineOptions& o);

  double resolution() const { return resolution_; }
  std::size_t cap() const { return cap_; }
  // True when `vertices` reached the cap; `why` then says so (refine.cap: ...).
  bool reached(std::size_t vertices, std::string& why) const;

 private:
  double resolution_ = 0;
  std::size_t cap_ = 0;
  bool user_cap_ = false;
};

}  // namespace pdr::refine
