// Region attributes of the output; see app/regions.hpp.
#include "app/regions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "delaunay/walk.hpp"

namespace pdr::app {

std::vector<int> region_labels(const refine::VolumeMesh& m, std::span<const PlcRegion> regions) {
  const TetStore& s = m.dt.store();
  constexpr std::uint32_t kNone = ~std::uint32_t{0};
  std::vector<std::uint32_t> comp(s.slots(), kNone);
  std::uint32_t count = 0;
  std::vector<TetId> queue;
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t) || s.is_ghost(t) || !m.is_inside(t) || comp[t] != kNone) continue;
    comp[t] = count;
    queue.assign(1, t);
    for (std::size_t i = 0; i < queue.size(); ++i)
      for (int f = 0; f < 4; ++f) {
        const TetId n = s.neighbour(queue[i], f);
        if (s.is_ghost(n) || !m.is_inside(n) || comp[n] != kNone ||
            m.face_subfacet(queue[i], f))
          continue;
        comp[n] = count;
        queue.push_back(n);
      }
    ++count;
  }
  TetId start = 0;
  while (start < s.slots() && !s.is_alive(start)) ++start;
  WalkRng rng;
  std::vector<int> label(count, 0);
  std::vector<std::uint8_t> named(count, 0);
  long largest = 0;
  for (const PlcRegion& r : regions) {
    const long a = std::lround(std::clamp(r.attribute, -2147483647.0, 2147483646.0));
    largest = std::max(largest, a);
    if (start == s.slots()) break;
    const Location loc = locate(s, m.dt.points(), r.point, start, rng);
    if (loc.kind == Location::Kind::OutsideHull || loc.tet == kNoTet) continue;
    const std::uint32_t c = comp[loc.tet];
    if (c == kNone || named[c]) continue;  // outside Ω (validation excludes it), or named
    named[c] = 1;
    label[c] = static_cast<int>(a);
  }
  int next = static_cast<int>(largest);
  for (std::uint32_t c = 0; c < count; ++c)
    if (!named[c]) label[c] = ++next;
  std::vector<int> out(s.slots(), 0);
  for (TetId t = 0; t < s.slots(); ++t)
    if (comp[t] != kNone) out[t] = label[comp[t]];
  return out;
}

}  // namespace pdr::app
