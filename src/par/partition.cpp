// Element-wise partition with METIS: par/partition.hpp.
#include "par/partition.hpp"

#include <metis.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace pdr::par {

Partition partition_tets(const TetStore& s, std::span<const std::uint8_t> inside,
                         std::uint32_t parts, std::uint64_t seed) {
  // Nodes: finite live tets, numbered in slot order.
  std::vector<idx_t> node(s.slots(), -1);
  std::vector<TetId> tet_of_node;
  for (TetId t = 0; t < s.slots(); ++t)
    if (s.is_alive(t) && !s.is_ghost(t)) {
      node[t] = static_cast<idx_t>(tet_of_node.size());
      tet_of_node.push_back(t);
    }
  const std::size_t n = tet_of_node.size();
  if (parts < 1 || parts > n)
    throw std::invalid_argument("partition: " + std::to_string(parts) + " parts for " +
                                std::to_string(n) + " tets");
  if (n > static_cast<std::size_t>(std::numeric_limits<idx_t>::max() / 4))
    throw std::length_error("partition: too many tets for METIS's 32-bit indices");
  std::vector<idx_t> xadj{0}, adjncy, vwgt;
  xadj.reserve(n + 1);
  adjncy.reserve(4 * n);
  vwgt.reserve(n);
  for (const TetId t : tet_of_node) {
    for (int f = 0; f < 4; ++f) {
      const TetId u = s.neighbour(t, f);
      if (!s.is_ghost(u)) adjncy.push_back(node[u]);
    }
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
    vwgt.push_back(t < inside.size() && inside[t] ? kInsideWeight : 1);
  }
  Partition p;
  p.parts = parts;
  p.part.assign(s.slots(), kNoPart);
  std::vector<idx_t> where(n, 0);
  if (parts > 1) {
    idx_t nvtxs = static_cast<idx_t>(n), ncon = 1, nparts = static_cast<idx_t>(parts), cut = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_CONTIG] = 1;
    options[METIS_OPTION_SEED] = static_cast<idx_t>(seed & 0x7FFFFFFF);
    const int rc = METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), vwgt.data(),
                                       nullptr, nullptr, &nparts, nullptr, nullptr, options,
                                       &cut, where.data());
    if (rc != METIS_OK)
      throw std::runtime_error("partition: METIS_PartGraphKway failed (code " +
                               std::to_string(rc) + ") for " + std::to_string(n) + " tets into " +
                               std::to_string(parts) + " parts");
  }
  p.tets.assign(parts, 0);
  p.weight.assign(parts, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t k = static_cast<std::uint32_t>(where[i]);
    p.part[tet_of_node[i]] = k;
    ++p.tets[k];
    p.weight[k] += static_cast<std::uint64_t>(vwgt[i]);
  }
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t)) continue;
    if (s.is_ghost(t)) {
      p.part[t] = p.part[s.neighbour(t, 3)];  // the finite tet across its hull face
      continue;
    }
    for (int f = 0; f < 4; ++f) {
      const TetId u = s.neighbour(t, f);
      if (u > t && !s.is_ghost(u) && p.part[u] != p.part[t]) ++p.interface_faces;
    }
  }
  return p;
}

}  // namespace pdr::par
