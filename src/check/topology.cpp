// Faces, boundary and edges of a tet soup (see topology.hpp), bucketed by smallest vertex:
// a face (a < b < c) or an edge (a < b) belongs to vertex a, and the tets holding it are
// among the tets incident to a. Buckets are filled in vertex order from the incidence
// lists (a counting sort), and each bucket is sorted alone (a few dozen records), so the
// faces and edges come out in lexicographic order without sorting the whole soup.
#include "check/topology.hpp"

#include <algorithm>

#include "check/parallel.hpp"

namespace pdr::check {
namespace {

struct Rec {
  std::uint32_t b, c;  // the face's other two vertex ids, b <= c
  std::uint32_t tl;    // tet * 4 + local face
  std::uint8_t odd;    // FaceRef::odd
  bool operator<(const Rec& o) const {
    return b != o.b ? b < o.b : (c != o.c ? c < o.c : tl < o.tl);
  }
};

Tri sorted(Tri f) {
  std::sort(f.begin(), f.end());
  return f;
}

// The parity of the inversions of f's vertex order (FaceRef::odd).
std::uint8_t odd(const Tri& f) {
  return static_cast<std::uint8_t>(((f[0] > f[1]) + (f[0] > f[2]) + (f[1] > f[2])) & 1);
}

// One block of vertices' share of the topology, with face indices local to the block.
struct Part {
  HugePageVector<Tri> faces;
  HugePageVector<std::uint32_t> face_start;  // local offsets into refs
  HugePageVector<FaceRef> refs;
  HugePageVector<std::uint32_t> boundary;    // local face indices
  HugePageVector<std::uint64_t> edges;
};

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
  constexpr std::size_t kStampEntries = std::size_t{1} << 28;  // 1 GiB of stamps at most
  return build_topology(tets, threads, kStampEntries);
}

Topology build_topology(std::span<const Tet> tets, unsigned threads, std::size_t stamp_entries) {
  // Incidence lists: each tet once in the list of each of its distinct vertices.
  std::uint32_t n = 0;
  for (const Tet& t : tets)
    for (std::uint32_t v : t) n = std::max(n, v + 1);
  HugePageVector<std::uint32_t> start(std::size_t{n} + 1, 0);
  auto distinct = [](const Tet& t, int i) {
    for (int j = 0; j < i; ++j)
      if (t[j] == t[i]) return false;
    return true;
  };
  for (const Tet& t : tets)
    for (int i = 0; i < 4; ++i)
      if (distinct(t, i)) ++start[t[i] + 1];
  for (std::uint32_t v = 0; v < n; ++v) start[v + 1] += start[v];
  HugePageVector<std::uint32_t> inc(start[n]);
  {
    HugePageVector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < tets.size(); ++t)
      for (int i = 0; i < 4; ++i)
        if (distinct(tets[t], i)) inc[fill[tets[t][i]]++] = static_cast<std::uint32_t>(t);
  }
  // Parts over vertex ranges holding about equal numbers of incidences, several per
  // thread, taken in turn: a low vertex id is the smallest of more of its faces than a
  // high one, so equal incidences are not equal work (one part per thread: the first
  // took twice as long as the second). Each part's arrays are reserved to their bounds
  // at once (growing them would copy and, on a virtual machine, fault in pages several
  // times).
  constexpr unsigned kPartsPerThread = 16;
  const unsigned workers = std::max(1u, std::min(threads, 64u));
  const unsigned nparts = workers * kPartsPerThread;
  std::vector<std::uint32_t> cut(nparts + 1, n);
  cut[0] = 0;
  for (unsigned p = 1; p < nparts; ++p)
    cut[p] = static_cast<std::uint32_t>(std::lower_bound(start.begin(), start.end() - 1,
                                                         static_cast<std::uint32_t>(std::uint64_t{start[n]} * p / nparts)) -
                                        start.begin());
  std::vector<Part> parts(nparts);
  // Per worker, within the budget: the bucket (plus one) that last listed each vertex as an
  // edge's end, so each is listed once; beyond it, the repeats are sorted away.
  const bool stamped = std::uint64_t{workers} * n <= stamp_entries;
  std::vector<std::vector<std::uint32_t>> seen_by(workers);
  parallel_blocks(nparts, workers, 1, [&](unsigned w, std::size_t b, std::size_t) {
    Part& part = parts[b];
    const std::uint32_t v0 = cut[b], v1 = std::max(cut[b], cut[b + 1]);
    const std::size_t incidences = start[v1] - start[v0];
    part.faces.reserve(incidences);  // each face counted in its smallest vertex's bucket
    part.face_start.reserve(incidences);
    part.refs.reserve(incidences);
    part.boundary.reserve(incidences / 8);
    part.edges.reserve(incidences * 3 / 2);
    std::vector<Rec> recs;
    std::vector<std::uint32_t> ends;
    std::vector<std::uint32_t>& seen = seen_by[w];
    if (stamped && seen.empty()) seen.assign(n, 0);
    const auto add_end = [&](std::uint32_t u, std::uint32_t v) {
      if (v <= u) return;
      if (stamped) {
        if (seen[v] == u + 1) return;
        seen[v] = u + 1;
      }
      ends.push_back(v);
    };
    for (std::uint32_t u = v0; u < v1; ++u) {
      recs.clear();
      ends.clear();
      // The next bucket's tets are requested now: they lie anywhere in the soup, and
      // their loads overlap this bucket's work instead of stalling it one by one.
      if (u + 1 < v1)
        for (std::uint32_t k = start[u + 1]; k < start[u + 2]; ++k)
          __builtin_prefetch(&tets[inc[k]]);
      for (std::uint32_t k = start[u]; k < start[u + 1]; ++k) {
        const std::uint32_t t = inc[k];
        const Tet& q = tets[t];
        if (q[0] != q[1] && q[0] != q[2] && q[0] != q[3] && q[1] != q[2] && q[1] != q[3] && q[2] != q[3]) {
          // Distinct vertices: the faces held by bucket u are those without vertex f where
          // u is in the face and the face's other two vertices are greater.
          int i = 0;
          while (q[i] != u) ++i;
          for (int f = 0; f < 4; ++f) {
            if (f == i) continue;
            std::uint32_t o[2];
            int m = 0;
            for (int j = 0; j < 4; ++j)
              if (j != f && j != i) o[m++] = q[j];
            if (o[0] > u && o[1] > u)
              recs.push_back({std::min(o[0], o[1]), std::max(o[0], o[1]),
                              t * 4 + static_cast<std::uint32_t>(f), odd(face_of(q, f))});
          }
          for (std::uint32_t v : q) add_end(u, v);
          continue;
        }
        for (int f = 0; f < 4; ++f) {
          const Tri s = sorted(face_of(q, f));
          if (s[0] == u)
            recs.push_back({s[1], s[2], t * 4 + static_cast<std::uint32_t>(f), odd(face_of(q, f))});
        }
        for (std::uint32_t v : q) add_end(u, v);
      }
      std::sort(recs.begin(), recs.end());
      for (std::size_t i = 0; i < recs.size();) {
        std::size_t j = i;
        part.face_start.push_back(static_cast<std::uint32_t>(part.refs.size()));
        part.faces.push_back({u, recs[i].b, recs[i].c});
        for (; j < recs.size() && recs[j].b == recs[i].b && recs[j].c == recs[i].c; ++j)
          part.refs.push_back(
              {recs[j].tl >> 2, static_cast<std::uint8_t>(recs[j].tl & 3), recs[j].odd});
        if (j - i == 1) part.boundary.push_back(static_cast<std::uint32_t>(part.faces.size() - 1));
        i = j;
      }
      std::sort(ends.begin(), ends.end());
      if (!stamped) ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
      for (std::uint32_t v : ends) part.edges.push_back(edge_key(u, v));
    }
  });
  // Each part's place in the whole, then every part copied there by the threads (one
  // thread would fault in and copy the whole topology alone).
  std::vector<std::size_t> face_at(nparts + 1, 0), ref_at(nparts + 1, 0), bnd_at(nparts + 1, 0),
      edge_at(nparts + 1, 0);
  for (unsigned p = 0; p < nparts; ++p) {
    face_at[p + 1] = face_at[p] + parts[p].faces.size();
    ref_at[p + 1] = ref_at[p] + parts[p].refs.size();
    bnd_at[p + 1] = bnd_at[p] + parts[p].boundary.size();
    edge_at[p + 1] = edge_at[p] + parts[p].edges.size();
  }
  Topology topo;
  topo.faces.resize(face_at[nparts]);
  topo.face_start.resize(face_at[nparts] + 1);
  topo.refs.resize(ref_at[nparts]);
  topo.boundary.resize(bnd_at[nparts]);
  topo.edges.resize(edge_at[nparts]);
  parallel_blocks(nparts, workers, 1, [&](unsigned, std::size_t p, std::size_t) {
    Part& part = parts[p];
    std::copy(part.faces.begin(), part.faces.end(), topo.faces.begin() + face_at[p]);
    const auto ref_base = static_cast<std::uint32_t>(ref_at[p]);
    std::transform(part.face_start.begin(), part.face_start.end(),
                   topo.face_start.begin() + face_at[p], [&](std::uint32_t s) { return ref_base + s; });
    std::copy(part.refs.begin(), part.refs.end(), topo.refs.begin() + ref_at[p]);
    const auto face_base = static_cast<std::uint32_t>(face_at[p]);
    std::transform(part.boundary.begin(), part.boundary.end(),
                   topo.boundary.begin() + bnd_at[p], [&](std::uint32_t f) { return face_base + f; });
    std::copy(part.edges.begin(), part.edges.end(), topo.edges.begin() + edge_at[p]);
    part = Part{};
  });
  topo.face_start.back() = static_cast<std::uint32_t>(topo.refs.size());
  return topo;
}

}  // namespace pdr::check
