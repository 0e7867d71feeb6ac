// Region attributes of the output; see app/regions.hpp.
#include "app/regions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "delaunay/walk.hpp"

namespace pdr::app {

std::vector<int> region_labels(const refine::VolumeMesh& m, std::span<const PlcRegion> regions) {
  const TetStore& s = m.dt.store();
  constexpr std::uint32_t kNone = ~std::uint32_t{0};
  std::vector<std::uint32_t> comp(s.slots(), kNone);
  std::uint32_t count = 0;
  std::vector<TetId> queue;
  std::vector<std::vector<std::uint32_t>> facets;  // per region: the facets it touches
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t) || s.is_ghost(t) || !m.is_inside(t) || comp[t] != kNone) continue;
    comp[t] = count;
    queue.assign(1, t);
    std::vector<std::uint32_t>& touched = facets.emplace_back();
    for (std::size_t i = 0; i < queue.size(); ++i)
      for (int f = 0; f < 4; ++f) {
        if (const auto sf = m.face_subfacet(queue[i], f)) {
          touched.push_back(m.surf.subfacet(*sf).facet);
          continue;
        }
        const TetId n = s.neighbour(queue[i], f);
        if (s.is_ghost(n) || !m.is_inside(n) || comp[n] != kNone) continue;
        comp[n] = count;
        queue.push_back(n);
      }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
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
  // Unnamed regions in the order of the facets they touch: a property of the domain, so
  // the sequential and the parallel runs number them alike.
  std::vector<std::uint32_t> unnamed;
  for (std::uint32_t c = 0; c < count; ++c)
    if (!named[c]) unnamed.push_back(c);
  std::sort(unnamed.begin(), unnamed.end(),
            [&](std::uint32_t a, std::uint32_t b) { return facets[a] < facets[b]; });
  long next = largest;
  for (const std::uint32_t c : unnamed)
    label[c] = static_cast<int>(std::min<long>(++next, std::numeric_limits<int>::max()));
  std::vector<int> out(s.slots(), 0);
  for (TetId t = 0; t < s.slots(); ++t)
    if (comp[t] != kNone) out[t] = label[comp[t]];
  return out;
}

}  // namespace pdr::app
