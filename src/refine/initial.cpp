// The initial tetrahedralization T_o (paper §2.1 step 3); see refine/initial.hpp.
#include "refine/initial.hpp"

#include "delaunay/bulk.hpp"
#include "mesh/tables.hpp"

namespace pdr::refine {

VolumeMesh build_initial(SurfaceMesh surf, std::span<const Point> holes, std::uint64_t seed) {
  VolumeMesh m;
  std::vector<Point> pts;
  m.s2d.assign(surf.vertex_count(), kNone);
  for (std::uint32_t v = 0; v < surf.vertex_count(); ++v) {
    m.s2d[v] = static_cast<std::uint32_t>(pts.size());
    m.d2s.push_back(v);
    pts.push_back(surf.point(v));
  }
  m.surf = std::move(surf);
  for (const std::uint32_t v : m.d2s)
    m.vclass.push_back(m.surf.home(v).kind == HomeKind::Facet ? VertexClass::Facet
                                                              : VertexClass::Segment);
  m.dt = Delaunay(std::move(pts));
  BulkOptions bo;
  bo.seed = seed;
  bo.renumber = false;
  const BulkResult r = bulk_insert(m.dt, bo);
  if (r.status != BulkStatus::Ok) throw RefineError("volume.initial: " + r.message);
  if (!r.duplicates.empty())
    throw RefineError("volume.initial: surface vertex " + std::to_string(m.d2s[r.duplicates[0].id]) +
                      " duplicates vertex " + std::to_string(m.d2s[r.duplicates[0].kept]));

  // Conformity: the subfacets that are faces and the subsegments that are edges of T_o.
  const TetStore& s = m.dt.store();
  std::vector<std::uint8_t> found(m.surf.subfacets().size(), 0);
  std::vector<std::uint8_t> found_seg(m.surf.subsegments().size(), 0);
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t) || s.is_ghost(t)) continue;
    const VertexId* v = s.vertices(t);
    for (int f = 0; f < 4; ++f)
      if (const auto sf = m.face_subfacet(t, f)) found[*sf] = 1;
    for (const auto& [i, j] : tables::kEdgeVertex)
      if (const auto sub = m.subsegment(v[i], v[j])) found_seg[*sub] = 1;
  }
  for (std::uint32_t t = 0; t < m.surf.subfacets().size(); ++t)
    if (m.surf.subfacet(t).alive && !found[t]) m.missing_subfacets.push_back(t);
  for (std::uint32_t t = 0; t < m.surf.subsegments().size(); ++t)
    if (!found_seg[t]) m.missing_subsegments.push_back(t);
  const bool conforms = m.missing_subfacets.empty() && m.missing_subsegments.empty();

  // Flood fill with parity from a ghost tet. When T_o does not conform the flags are
  // provisional (the refinement recomputes them once it does): the first one reached wins.
  m.inside.assign(s.slots(), 0);
  std::vector<std::uint8_t> seen(s.slots(), 0);
  std::vector<TetId> queue;
  for (TetId t = 0; t < s.slots() && queue.empty(); ++t)
    if (s.is_alive(t) && s.is_ghost(t)) queue.push_back(t);
  if (queue.empty()) throw RefineError("volume.initial: no ghost tet");
  seen[queue[0]] = 1;
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const TetId t = queue[i];
    for (int f = 0; f < 4; ++f) {
      const TetId n = s.neighbour(t, f);
      const std::uint8_t want = s.is_ghost(n) ? 0 : static_cast<std::uint8_t>(m.inside[t] ^ (m.face_flips(t, f) ? 1 : 0));
      if (!seen[n]) {
        seen[n] = 1;
        m.inside[n] = want;
        queue.push_back(n);
      } else if (m.inside[n] != want && conforms) {
        throw RefineError("volume.parity: tets " + std::to_string(t) + " and " +
                          std::to_string(n) + " disagree on the side of their common face");
      }
    }
  }
  if (!conforms) return m;

  for (std::size_t i = 0; i < holes.size(); ++i) {
    const Location loc = m.dt.locate(holes[i]);
    if (loc.kind == Location::Kind::InTet && m.is_inside(loc.tet))
      throw RefineError("volume.hole: hole point " + std::to_string(i) +
                        " lies in a tet classified inside the domain");
  }
  return m;
}

}  // namespace pdr::refine
