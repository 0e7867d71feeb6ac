// Faces, boundary and edges of a tet soup by sorting (see topology.hpp).
#include "check/topology.hpp"

#include <algorithm>
#include <thread>

namespace pdr::check {
namespace {

template <class T, class Cmp>
void parallel_sort(std::vector<T>& v, unsigned threads, Cmp cmp) {
  if (threads < 2 || v.size() < (1u << 16)) {
    std::sort(v.begin(), v.end(), cmp);
    return;
  }
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  {
    std::jthread half([&] { std::sort(v.begin(), mid, cmp); });
    std::sort(mid, v.end(), cmp);
  }
  std::inplace_merge(v.begin(), mid, v.end(), cmp);
}

struct Rec {
  std::uint64_t ab;  // two smallest vertex ids
  std::uint32_t c;   // largest vertex id
  std::uint32_t tl;  // tet * 4 + local face
};

Tri sorted(Tri f) {
  std::sort(f.begin(), f.end());
  return f;
}

}  // namespace

std::optional<std::size_t> Topology::find_face(Tri key) const {
  const auto it = std::lower_bound(faces.begin(), faces.end(), key);
  if (it == faces.end() || *it != key) return std::nullopt;
  return static_cast<std::size_t>(it - faces.begin());
}

bool Topology::has_edge(std::uint32_t u, std::uint32_t v) const {
  return std::binary_search(edges.begin(), edges.end(), edge_key(u, v));
}

Topology build_topology(std::span<const Tet> tets, unsigned threads) {
  Topology topo;
  {
    std::vector<Rec> recs;
    recs.reserve(tets.size() * 4);
    for (std::size_t t = 0; t < tets.size(); ++t)
      for (int f = 0; f < 4; ++f) {
        const Tri k = sorted(face_of(tets[t], f));
        recs.push_back({(std::uint64_t{k[0]} << 32) | k[1], k[2],
                        static_cast<std::uint32_t>(t * 4 + static_cast<std::size_t>(f))});
      }
    parallel_sort(recs, threads, [](const Rec& x, const Rec& y) {
      if (x.ab != y.ab) return x.ab < y.ab;
      if (x.c != y.c) return x.c < y.c;
      return x.tl < y.tl;
    });
    topo.refs.reserve(recs.size());
    for (std::size_t i = 0; i < recs.size();) {
      std::size_t j = i;
      topo.face_start.push_back(static_cast<std::uint32_t>(topo.refs.size()));
      topo.faces.push_back({static_cast<std::uint32_t>(recs[i].ab >> 32),
                            static_cast<std::uint32_t>(recs[i].ab), recs[i].c});
      while (j < recs.size() && recs[j].ab == recs[i].ab && recs[j].c == recs[i].c) {
        topo.refs.push_back({recs[j].tl >> 2, static_cast<std::uint8_t>(recs[j].tl & 3)});
        ++j;
      }
      if (j - i == 1) topo.boundary.push_back(static_cast<std::uint32_t>(topo.faces.size() - 1));
      i = j;
    }
    topo.face_start.push_back(static_cast<std::uint32_t>(topo.refs.size()));
  }
  topo.edges.reserve(tets.size() * 6);
  for (const Tet& t : tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (t[i] != t[j]) topo.edges.push_back(edge_key(t[i], t[j]));
  parallel_sort(topo.edges, threads, std::less<>());
  topo.edges.erase(std::unique(topo.edges.begin(), topo.edges.end()), topo.edges.end());
  return topo;
}

}  // namespace pdr::check
