// What SeqRefinement could not finish (paper §3 outside the theory; Theorem 1.2 inside it
// says nothing is left): the tets it refused to refine, each with the reason, and the
// inside tets left with ratio >= B at the end, each listed with its reason (the refusal,
// the vertex cap, or "never refined").
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "refine/seq_refinement.hpp"

namespace pdr::refine {

// The refused tets, by their vertices (ids are reused, vertices are not).
class RefusedTets {
 public:
  void add(const std::array<VertexId, 4>& v, std::string why) {
    items_.emplace_back(v, std::move(why));
  }
  // Sorts the list; call once, before reason().
  void seal() { std::sort(items_.begin(), items_.end()); }
  // The reason a tet with these vertices was refused, or nullptr.
  const std::string* reason(const std::array<VertexId, 4>& v) const;

 private:
  std::vector<std::pair<std::array<VertexId, 4>, std::string>> items_;
};

// Every inside tet of m with ratio >= B (exact), with its reason: the refusal recorded for
// it, else `stop_reason` (the cap), else "refine.unrefined: never refined". With `among`,
// only those of these tets (live ones; the caller knows every other tet meets B).
std::vector<Leftover> collect_leftovers(const VolumeMesh& m, double ratio,
                                        const RefusedTets& refused,
                                        const std::string& stop_reason,
                                        const std::vector<TetId>* among = nullptr);

}  // namespace pdr::refine
