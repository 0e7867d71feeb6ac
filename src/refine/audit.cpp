// Lemma 1 audit (paper §3); see refine/audit.hpp.
#include "refine/audit.hpp"

#include <gmpxx.h>

#include <sstream>

#include "geom/encroach.hpp"
#include "geom/exact.hpp"
#include "geom/point_text.hpp"
#include "mesh/tables.hpp"

namespace pdr::refine {
namespace {

// Invariant 1 on tet t: its subsegment edges and subfacet faces against its own vertices
// and `extra`. Returns an empty string when it holds.
std::string check_tet(const VolumeMesh& m, TetId t, VertexId extra) {
  const TetStore& s = m.dt.store();
  if (s.is_ghost(t)) return {};
  const VertexId* v = s.vertices(t);
  auto candidates = [&](auto&& f) -> std::string {
    for (int k = 0; k < 4; ++k)
      if (auto r = f(v[k]); !r.empty()) return r;
    if (extra != kNoVertex) return f(extra);
    return {};
  };
  for (const auto& e : tables::kEdgeVertex) {
    const VertexId a = v[e[0]], b = v[e[1]];
    if (!m.subsegment(a, b)) continue;
    auto r = candidates([&](VertexId w) -> std::string {
      if (w == a || w == b) return {};
      if (in_diametral_ball(m.dt.point(a), m.dt.point(b), m.dt.point(w)) != Sign::Positive)
        return {};
      return "lemma1.invariant1: subsegment " + std::to_string(a) + "-" + std::to_string(b) +
             " " + point_text(m.dt.point(a)) + "-" + point_text(m.dt.point(b)) +
             " is encroached by vertex " + std::to_string(w) + " " + point_text(m.dt.point(w));
    });
    if (!r.empty()) return r;
  }
  for (int f = 0; f < 4; ++f) {
    if (!m.face_subfacet(t, f)) continue;
    const VertexId a = v[tables::kFaceVertex[f][0]], b = v[tables::kFaceVertex[f][1]],
                   c = v[tables::kFaceVertex[f][2]];
    auto r = candidates([&](VertexId w) -> std::string {
      if (w == a || w == b || w == c) return {};
      if (in_equatorial_ball(m.dt.point(a), m.dt.point(b), m.dt.point(c), m.dt.point(w)) !=
          Sign::Positive)
        return {};
      return "lemma1.invariant1: subfacet " + std::to_string(a) + "," + std::to_string(b) +
             "," + std::to_string(c) + " " + point_text(m.dt.point(a)) + point_text(m.dt.point(b)) +
             point_text(m.dt.point(c)) + " is encroached by vertex " + std::to_string(w) + " " +
             point_text(m.dt.point(w));
    });
    if (!r.empty()) return r;
  }
  return {};
}

}  // namespace

void audit_encroachment(const VolumeMesh& m, VertexId v, const std::vector<TetId>& star,
                        const char* what) {
  const TetStore& s = m.dt.store();
  for (const TetId t : star) {
    if (auto r = check_tet(m, t, kNoVertex); !r.empty())
      throw RefineError(r + " (after refining a " + what + ")");
    int k = 0;
    while (s.vertex(t, k) != v) ++k;
    if (auto r = check_tet(m, s.neighbour(t, k), v); !r.empty())
      throw RefineError(r + " (after refining a " + what + ")");
  }
}

void audit_edges(const VolumeMesh& m, VertexId v, const std::vector<TetId>& star,
                 const char* what, double size2, double h) {
  const TetStore& s = m.dt.store();
  const mpq_class hb = mpq_class(h * (1 - 0x1p-40));
  const mpq_class h2 = hb * hb;
  for (const TetId t : star)
    for (int k = 0; k < 4; ++k) {
      const VertexId w = s.vertex(t, k);
      if (w == v || w == kGhostVertex) continue;
      if (exact::squared_distance(m.dt.point(v), m.dt.point(w)) < h2) {
        std::ostringstream os;
        os.precision(17);
        os << "lemma1.invariant" << (what[0] == 't' ? 4 : what[0] == 's' ? 2 : 3)
           << ": refining a " << what << " of squared size " << size2 << " created edge "
           << v << "-" << w << " " << point_text(m.dt.point(v)) << "-" << point_text(m.dt.point(w))
           << " shorter than h = " << h;
        throw RefineError(os.str());
      }
    }
}

std::vector<std::string> audit_volume(const VolumeMesh& m) {
  std::vector<std::string> out;
  const TetStore& s = m.dt.store();
  std::vector<std::uint8_t> found(m.surf.subfacets().size(), 0);
  for (TetId t = 0; t < s.slots() && out.size() < 20; ++t) {
    if (!s.is_alive(t)) continue;
    for (int f = 0; f < 4; ++f) {
      const auto sf = m.face_subfacet(t, f);
      if (sf) found[*sf] = 1;
      const TetId n = s.neighbour(t, f);
      const bool in_t = !s.is_ghost(t) && m.is_inside(t);
      const bool in_n = !s.is_ghost(n) && m.is_inside(n);
      if ((in_t != in_n) != m.face_flips(t, f))
        out.push_back("volume.parity: tets " + std::to_string(t) + " and " +
                      std::to_string(n) + " across face " + std::to_string(f));
    }
    if (auto r = check_tet(m, t, kNoVertex); !r.empty()) out.push_back(r);
  }
  for (std::uint32_t t = 0; t < found.size(); ++t)
    if (m.surf.subfacet(t).alive && !found[t])
      out.push_back("volume.conformity: subfacet " + std::to_string(t) + " of " +
                    m.surf.facet_name(m.surf.subfacet(t).facet) + " is not a face of T");
  return out;
}

}  // namespace pdr::refine
