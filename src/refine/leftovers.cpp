// The refused tets and the leftovers of SeqRefinement; see leftovers.hpp.
#include "refine/leftovers.hpp"

#include <algorithm>

#include "refine/quality.hpp"

namespace pdr::refine {

const std::string* RefusedTets::reason(const std::array<VertexId, 4>& v) const {
  auto it = std::lower_bound(items_.begin(), items_.end(),
                             std::pair<std::array<VertexId, 4>, std::string>{v, ""});
  return it != items_.end() && it->first == v ? &it->second : nullptr;
}

std::vector<Leftover> collect_leftovers(const VolumeMesh& m, double ratio,
                                        const RefusedTets& refused,
                                        const std::string& stop_reason,
                                        const std::vector<TetId>* among) {
  std::vector<Leftover> out;
  const TetStore& s = m.dt.store();
  const std::size_t n = among ? among->size() : s.slots();
  for (std::size_t i = 0; i < n; ++i) {
    // A later tet's points, scattered, requested meanwhile (the scan reads every tet).
    if (const std::size_t k = i + 8; k < n) {
      const TetId u = among ? (*among)[k] : static_cast<TetId>(k);
      if (u < s.slots() && s.is_alive(u) && !s.is_ghost(u))
        for (int j = 0; j < 4; ++j) __builtin_prefetch(&m.dt.point(s.vertex(u, j)));
    }
    const TetId t = among ? (*among)[i] : static_cast<TetId>(i);
    if (t >= s.slots() || !s.is_alive(t) || s.is_ghost(t) || !m.is_inside(t)) continue;
    const VertexId* v = s.vertices(t);
    const Point &a = m.dt.point(v[0]), &b = m.dt.point(v[1]), &c = m.dt.point(v[2]),
                &d = m.dt.point(v[3]);
    if (!ratio_at_least(a, b, c, d, ratio)) continue;
    Leftover l;
    l.tet = t;
    l.v = {v[0], v[1], v[2], v[3]};
    l.p = {a, b, c, d};
    l.ratio = ratio_of(a, b, c, d);
    if (const std::string* why = refused.reason(l.v))
      l.reason = *why;
    else
      l.reason = stop_reason.empty() ? "refine.unrefined: never refined" : stop_reason;
    out.push_back(std::move(l));
  }
  return out;
}

}  // namespace pdr::refine
