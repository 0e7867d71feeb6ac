// Element-wise partition with METIS: par/partition.hpp.
#include "par/partition.hpp"

#include <metis.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace pdr::par {
namespace {

// Whether the graph (CSR) is connected: one breadth-first search.
bool is_connected(const std::vector<idx_t>& xadj, const std::vector<idx_t>& adjncy) {
  const std::size_t n = xadj.size() - 1;
  std::vector<std::uint8_t> seen(n, 0);
  std::vector<idx_t> queue{0};
  seen[0] = 1;
  for (std::size_t i = 0; i < queue.size(); ++i)
    for (idx_t e = xadj[static_cast<std::size_t>(queue[i])]; e < xadj[static_cast<std::size_t>(queue[i]) + 1]; ++e) {
      const idx_t u = adjncy[static_cast<std::size_t>(e)];
      if (!seen[static_cast<std::size_t>(u)]) seen[static_cast<std::size_t>(u)] = 1, queue.push_back(u);
    }
  return queue.size() == n;
}

}  // namespace

Partition partition_tets(const TetStore& s, std::span<const std::uint8_t> inside,
                         std::uint32_t parts, std::uint64_t seed) {
  // Nodes: finite live tets, numbered in slot order.
  std::vector<idx_t> node(s.slots(), -1);
  std::vector<TetId> tet_of_node;
  for (TetId t = 0; t < s.slots(); ++t)
    if (s.is_alive(t) && s.vertex(t, 3) < kFirstSpecialVertex) {  // finite: no ghost, no proxy
      node[t] = static_cast<idx_t>(tet_of_node.size());
      tet_of_node.push_back(t);
    }
  const std::size_t n = tet_of_node.size();
  if (parts < 1 || parts > n)
    throw std::invalid_argument("partition: " + std::to_string(parts) + " parts for " +
                                std::to_string(n) + " tets");
  // METIS sums the weights (and counts 4 adjacencies per tet) in 32-bit idx_t.
  if (n > static_cast<std::size_t>(std::numeric_limits<idx_t>::max() / kInsideWeight))
    throw std::length_error("partition: " + std::to_string(n) +
                            " tets are too many for METIS's 32-bit indices; partition a "
                            "coarser initial mesh (--initial-tets)");
  std::vector<idx_t> xadj{0}, adjncy, vwgt;
  xadj.reserve(n + 1);
  adjncy.reserve(4 * n);
  vwgt.reserve(n);
  for (const TetId t : tet_of_node) {
    for (int f = 0; f < 4; ++f) {
      const TetId u = s.neighbour(t, f);
      if (node[u] >= 0) adjncy.push_back(node[u]);
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
    options[METIS_OPTION_SEED] = static_cast<idx_t>(seed & 0x7FFFFFFF);
    const auto run = [&](bool contiguous) {
      options[METIS_OPTION_CONTIG] = contiguous ? 1 : 0;
      return METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), vwgt.data(),
                                 nullptr, nullptr, &nparts, nullptr, nullptr, options, &cut,
                                 where.data());
    };
    // Contiguous parts need a connected graph (METIS refuses otherwise); a store whose
    // finite tets fall apart gets parts that may be disconnected too.
    const bool connected = is_connected(xadj, adjncy);
    p.contiguous = connected;
    const int rc = run(connected);
    if (rc != METIS_OK)
      throw std::runtime_error("partition: METIS_PartGraphKway failed (code " +
                               std::to_string(rc) + ") for " + std::to_string(n) + " tets into " +
                               std::to_string(parts) + " parts");
  }
  if (std::any_of(where.begin(), where.end(), [&](idx_t k) { return k < 0 || k >= static_cast<idx_t>(parts); }))
    throw std::runtime_error("partition: METIS returned a part number out of range");
  p.tets.assign(parts, 0);
  p.weight.assign(parts, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t k = static_cast<std::uint32_t>(where[i]);
    p.part[tet_of_node[i]] = k;
    ++p.tets[k];
    p.weight[k] += static_cast<std::uint64_t>(vwgt[i]);
  }
  for (std::uint32_t k = 0; k < parts; ++k)
    if (p.tets[k] == 0)
      throw std::invalid_argument("partition: METIS left part " + std::to_string(k) + " of " +
                                  std::to_string(parts) + " empty (" + std::to_string(n) +
                                  " tets); ask for fewer submeshes or a finer initial mesh");
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t) || s.is_proxy(t)) continue;
    if (s.is_ghost(t)) {
      p.part[t] = p.part[s.neighbour(t, 3)];  // the finite tet across its hull face
      continue;
    }
    for (int f = 0; f < 4; ++f) {
      const TetId u = s.neighbour(t, f);
      if (u > t && node[u] >= 0 && p.part[u] != p.part[t]) ++p.interface_faces;
    }
  }
  return p;
}

}  // namespace pdr::par
