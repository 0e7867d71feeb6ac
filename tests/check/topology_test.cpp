// build_topology against a brute-force one: on random tet soups (repeated vertices within a
// tet included), the same distinct faces in lexicographic order with the same holders, the
// same boundary faces and the same distinct edges, for any number of threads; each holder's
// parity bit (FaceRef::odd) as the permutations say.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "check/topology.hpp"

namespace pdr::check {
namespace {

struct Brute {
  std::map<Tri, std::vector<std::pair<std::uint32_t, int>>> faces;  // sorted face -> holders
  std::set<std::uint64_t> edges;
};

// Sign of the permutation taking tet t's vertex order to `seq` (ids of t, distinct).
int parity(const Tet& t, const std::array<std::uint32_t, 4>& seq) {
  std::array<int, 4> pos{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (t[j] == seq[i]) pos[i] = j;
  int inv = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) inv += pos[i] > pos[j] ? 1 : 0;
  return inv % 2 == 0 ? 1 : -1;
}

bool distinct(const Tet& t) {
  return t[0] != t[1] && t[0] != t[2] && t[0] != t[3] && t[1] != t[2] && t[1] != t[3] &&
         t[2] != t[3];
}

Brute brute(const std::vector<Tet>& tets) {
  Brute b;
  for (std::uint32_t t = 0; t < tets.size(); ++t) {
    for (int f = 0; f < 4; ++f) {
      Tri k = face_of(tets[t], f);
      std::sort(k.begin(), k.end());
      b.faces[k].push_back({t, f});
    }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (tets[t][i] < tets[t][j]) b.edges.insert(edge_key(tets[t][i], tets[t][j]));
  }
  return b;
}

RC_GTEST_PROP(Topology, EqualsTheBruteForceOne, ()) {
  const auto n = *rc::gen::inRange<std::uint32_t>(1, 40);
  const auto count = *rc::gen::inRange<std::size_t>(0, 300);
  std::vector<Tet> tets(count);
  for (Tet& t : tets)
    for (auto& v : t) v = *rc::gen::inRange<std::uint32_t>(0, n);
  const unsigned threads = *rc::gen::inRange(1u, 5u);
  // With and without the stamps that list each edge end once.
  const Topology topo = *rc::gen::arbitrary<bool>() ? build_topology(tets, threads)
                                                    : build_topology(tets, threads, 0);
  const Brute b = brute(tets);
  RC_ASSERT(topo.faces.size() == b.faces.size());
  RC_ASSERT(topo.face_start.size() == b.faces.size() + 1);
  std::size_t i = 0;
  std::vector<std::uint32_t> boundary;
  for (const auto& [key, holders] : b.faces) {
    RC_ASSERT(topo.faces[i] == key);
    std::vector<std::pair<std::uint32_t, int>> got;
    for (const FaceRef& r : topo.holders(i)) {
      got.push_back({r.tet, r.local});
      // FaceRef::odd: the sorted face and the apex are an even permutation of the tet
      // exactly when it is set.
      const Tet& t = tets[r.tet];
      if (distinct(t))
        RC_ASSERT(parity(t, {key[0], key[1], key[2], t[r.local]}) == (r.odd ? 1 : -1));
    }
    // Two holders list the face in opposite orientations exactly when their bits differ.
    const auto h = topo.holders(i);
    if (h.size() == 2 && distinct(tets[h[0].tet]) && distinct(tets[h[1].tet])) {
      const Tri x = face_of(tets[h[0].tet], h[0].local), y = face_of(tets[h[1].tet], h[1].local);
      const Tri yr = {y[0], y[2], y[1]};
      const bool opposite =
          x == yr || x == Tri{yr[1], yr[2], yr[0]} || x == Tri{yr[2], yr[0], yr[1]};
      RC_ASSERT(opposite == (h[0].odd != h[1].odd));
    }
    std::sort(got.begin(), got.end());
    RC_ASSERT(got == holders);
    if (holders.size() == 1) boundary.push_back(static_cast<std::uint32_t>(i));
    ++i;
  }
  RC_ASSERT(std::ranges::equal(topo.boundary, boundary));
  RC_ASSERT(std::ranges::equal(b.edges, topo.edges));
}

}  // namespace
}  // namespace pdr::check
