// The initial tetrahedralization T_o (paper §2.1 step 3); see refine/initial.hpp.
#include "refine/initial.hpp"

#include <sstream>

#include "delaunay/bulk.hpp"

namespace pdr::refine {
namespace {

std::string describe_subfacet(const SurfaceMesh& m, std::uint32_t t) {
  std::ostringstream os;
  const Subfacet& f = m.subfacet(t);
  os << "subfacet " << t << " of " << m.facet_name(f.facet) << ", vertices";
  for (int i = 0; i < 3; ++i) {
    const Point& p = m.point(f.v[i]);
    os << ' ' << f.v[i] << " (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  }
  return os.str();
}

}  // namespace

VolumeMesh build_initial(SurfaceMesh surf, std::span<const Point> holes, std::uint64_t seed) {
  VolumeMesh m;
  std::vector<Point> pts;
  m.s2d.assign(surf.vertex_count(), kNone);
  for (std::uint32_t v = 0; v < surf.vertex_count(); ++v) {
    if (surf.home(v).kind == HomeKind::Unused) continue;
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

  // Flood fill with parity from a ghost tet.
  const TetStore& s = m.dt.store();
  m.inside.assign(s.slots(), 0);
  std::vector<std::uint8_t> seen(s.slots(), 0);
  std::vector<std::uint8_t> found(m.surf.subfacets().size(), 0);
  std::vector<TetId> queue;
  for (TetId t = 0; t < s.slots() && queue.empty(); ++t)
    if (s.is_alive(t) && s.is_ghost(t)) queue.push_back(t);
  if (queue.empty()) throw RefineError("volume.initial: no ghost tet");
  seen[queue[0]] = 1;
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const TetId t = queue[i];
    for (int f = 0; f < 4; ++f) {
      const auto sf = m.face_subfacet(t, f);
      if (sf) found[*sf] = 1;
      const TetId n = s.neighbour(t, f);
      const std::uint8_t want = s.is_ghost(n) ? 0 : static_cast<std::uint8_t>(m.inside[t] ^ (sf ? 1 : 0));
      if (!seen[n]) {
        seen[n] = 1;
        m.inside[n] = want;
        queue.push_back(n);
      } else if (m.inside[n] != want) {
        throw RefineError("volume.parity: tets " + std::to_string(t) + " and " +
                          std::to_string(n) + " disagree on the side of their common face");
      }
    }
  }
  for (std::uint32_t t = 0; t < m.surf.subfacets().size(); ++t)
    if (m.surf.subfacet(t).alive && !found[t])
      throw RefineError("volume.conformity: " + describe_subfacet(m.surf, t) +
                        " is not a face of the initial Delaunay tetrahedralization (an "
                        "encroached subfacet: the domain is probably inadmissible)");

  for (std::size_t i = 0; i < holes.size(); ++i) {
    const Location loc = m.dt.locate(holes[i]);
    if (loc.kind == Location::Kind::InTet && m.is_inside(loc.tet))
      throw RefineError("volume.hole: hole point " + std::to_string(i) +
                        " lies in a tet classified inside the domain");
  }
  return m;
}

}  // namespace pdr::refine
