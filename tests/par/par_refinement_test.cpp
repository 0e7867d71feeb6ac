// ParRefinement's parallel phase (par/par_refinement.hpp) on the simulator: a refined
// cube-in-cube cut into one submesh per rank, every rank refining its bad tets with
// RefinementRules (every other seed with Refine(s) in the phase), every message delivered
// in a seeded random order. When termination is detected:
//   - no message is in flight, every store is valid, no relink notice waits;
//   - the ranks together hold exactly M_o plus the committed points, as inserting them
//     builds it (the Delaunay tetrahedralization is unique; the midpoints split D as the
//     sequential Refine(s) does), with the same inside tets, and assemble() glues their
//     tets into exactly that mesh, every tet with its flag, and D a part of T;
//   - every edge and face the ranks hold has the label of rank 0's D (Submesh M4);
//   - no work was left behind: every bad inside tet of that mesh is marked deferred, and
//     without the steps on ∂Ω every one is a step the rules defer (checked on the whole
//     mesh with the same rules; with them, D changes after a deferral, so a few may be
//     steps to commit by then: counted, the completion takes them);
//   - the sequential completion then ends in a mesh the exact checker passes: valid,
//     Delaunay, conforming, ratio < 2.
// And the rules decide alike with and without the vertex tags that spare them most
// lookups in D.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <set>

#include "check/check.hpp"
#include "delaunay/spatial_sort.hpp"
#include "par/assembly.hpp"
#include "refine/audit.hpp"
#include "refine/flat.hpp"
#include "refine/guard.hpp"
#include "refine/quality.hpp"
#include "surface/locate.hpp"
#include "surface/split.hpp"
#include "mesh/tables.hpp"
#include "delaunay/export.hpp"
#include "par/insertion_actor.hpp"
#include "par/mesh_parts.hpp"
#include "par/par_meshes.hpp"
#include "par/par_refinement.hpp"
#include "par/partition.hpp"
#include "par/point_tets.hpp"
#include "par/sim_network.hpp"
#include "par/sim_run.hpp"

namespace pdr::par {
namespace {

constexpr double kTargetVolume = 0.05;

// A tet as its four points, sorted (the same for any numbering of the same tet).
test::PointTet point_tet(const Point& a, const Point& b, const Point& c, const Point& d) {
  std::array<Point, 4> p{a, b, c, d};
  std::sort(p.begin(), p.end());
  test::PointTet q;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t k = 0; k < 3; ++k) q[3 * i + k] = p[i][k];
  return q;
}

// A mesh's inside tets as sorted point tuples, and its boundary faces as their points,
// rotated so the smallest comes first (the orientation kept), each with its marker: the
// same lists for any numbering of the same mesh.
using PointFace = std::pair<std::array<Point, 3>, int>;
std::pair<std::vector<test::PointTet>, std::vector<PointFace>> canonical(const MeshData& m) {
  std::vector<test::PointTet> tets;
  for (const Tet& t : m.tets) tets.push_back(point_tet(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]));
  std::sort(tets.begin(), tets.end());
  std::vector<PointFace> faces;
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    std::array<Point, 3> p{m.points[m.faces[i][0]], m.points[m.faces[i][1]], m.points[m.faces[i][2]]};
    std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
    faces.emplace_back(p, m.face_markers.empty() ? 0 : m.face_markers[i]);
  }
  std::sort(faces.begin(), faces.end());
  return {tets, faces};
}

// The reference for assemble(): inserts `points` into m as the sequential kernel would:
// the steps on ∂Ω first, the splits before the subfacet circumcenters, each once the
// vertices of its element are there (a subsegment split in D at the point; a subfacet's
// circumcenter by the facet cavity of the subfacet of D that holds it; then the point in
// T, mapped to its D vertex), then the others in Hilbert order, off ∂Ω (commit_point
// flags the new tets). Returns how many were new.
std::size_t absorb(refine::VolumeMesh& m, std::span<const Point> all,
                   std::span<const SurfaceStep> steps = {}) {
  Cavity c;
  std::vector<TetId> star;
  std::size_t added = 0;
  std::vector<Point> split_points;
  // An element's vertex by point: an M_o vertex, or the point of an earlier step.
  std::map<Gid, Point> made;
  for (const SurfaceStep& r : steps) made[r.m] = r.p, split_points.push_back(r.p);
  const auto where = [&](Gid g) { return g < m.dt.num_points() ? m.dt.point(static_cast<VertexId>(g)) : made.at(g); };
  std::vector<const SurfaceStep*> left;
  for (const SurfaceStep& r : steps)
    if (r.c == kNoGid) left.push_back(&r);
  for (const SurfaceStep& r : steps)
    if (r.c != kNoGid) left.push_back(&r);
  std::map<Point, VertexId> vertex_at;
  for (VertexId v = 0; v < m.dt.num_points(); ++v) vertex_at[m.dt.point(v)] = v;
  while (!left.empty()) {
    std::vector<const SurfaceStep*> later;
    for (const SurfaceStep* r : left) {
      std::vector<std::uint32_t> dv;
      for (const Gid g : {r->a, r->b, r->c})
        if (g != kNoGid)
          if (const auto it = vertex_at.find(where(g)); it != vertex_at.end()) dv.push_back(m.d2s[it->second]);
      if (dv.size() != (r->c == kNoGid ? 2u : 3u) ||
          (r->c != kNoGid && std::any_of(later.begin(), later.end(), [](const SurfaceStep* x) {
             return x->c == kNoGid;
           }))) {
        later.push_back(r);
        continue;
      }
      std::uint32_t surf_vertex = 0;
      if (r->c == kNoGid) {
        const auto sub = m.surf.find_subsegment(dv[0], dv[1]);
        EXPECT_TRUE(sub.has_value()) << "a split of a subsegment D does not have";
        if (!sub) return added;
        surf_vertex = surface::split_subsegment_at(m.surf, *sub, r->p).vertex;
      } else {
        const auto at = surface::locate_in_facet(m.surf, r->facet, r->p, dv[0]);
        EXPECT_TRUE(at.has_value()) << "a subfacet circumcenter outside its facet";
        if (!at) return added;
        const surface::FacetCavity fc =
            surface::build_facet_cavity(m.surf, r->facet, r->p, {at->subfacet}, std::nullopt);
        EXPECT_EQ(fc.status, surface::CavityStatus::Ok);
        if (fc.status != surface::CavityStatus::Ok) return added;
        surf_vertex = m.surf.add_vertex(r->p, {surface::HomeKind::Facet, r->facet});
        surface::commit_facet_cavity(m.surf, fc, surf_vertex);
      }
      const Location loc = m.dt.locate(r->p, m.dt.last_tet());
      m.dt.build_cavity(r->p, loc.tet, c);
      vertex_at[r->p] = commit_point(m, c, surf_vertex, star);
      ++added;
    }
    EXPECT_LT(later.size(), left.size()) << "steps whose elements never appear";
    if (later.size() == left.size()) return added;
    left.swap(later);
  }
  std::sort(split_points.begin(), split_points.end());
  std::vector<Point> points;
  for (const Point& p : all)
    if (!std::binary_search(split_points.begin(), split_points.end(), p)) points.push_back(p);
  std::vector<std::uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0u);
  Point lo = m.dt.point(0), hi = lo;
  for (const Point& p : points)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  hilbert_sort(order, std::span<const Point>(points), lo, hi);
  for (const std::uint32_t i : order) {
    const Location loc = m.dt.locate(points[i], m.dt.last_tet());
    if (loc.kind == Location::Kind::OnVertex) continue;
    m.dt.build_cavity(points[i], loc.tet, c);
    commit_point(m, c, refine::kNone, star);
    ++added;
  }
  return added;
}

// Every tet of m (outside ones and ghosts too), as points, with its flag (bit 0) and
// whether it is a ghost (bit 1; its ghost vertex stands as the origin).
std::vector<std::pair<test::PointTet, int>> all_tets(const refine::VolumeMesh& m) {
  std::vector<std::pair<test::PointTet, int>> out;
  const TetStore& s = m.dt.store();
  for (TetId t = 0; t < s.slots(); ++t) {
    if (!s.is_alive(t)) continue;
    const VertexId* v = s.vertices(t);
    const Point o{0, 0, 0};
    const auto pt = [&](int i) { return v[i] == kGhostVertex ? o : m.dt.point(v[i]); };
    out.emplace_back(point_tet(pt(0), pt(1), pt(2), pt(3)),
                     (m.is_inside(t) ? 1 : 0) | (s.is_ghost(t) ? 2 : 0));
  }
  std::sort(out.begin(), out.end());
  return out;
}

struct SimRun {
  std::vector<Piece> pieces;  // the submeshes' tets at the end
  std::vector<Point> points;
  std::vector<test::PointTet> inside_tets;  // the ranks' inside tets
  std::vector<SurfaceStep> steps;
  std::vector<std::vector<Point>> refused;  // elements whose step was refused, sorted
  // Every edge and face of the tets the ranks hold (ghosts aside), by its sorted points,
  // with the holder's label (kNoLabel for none).
  std::vector<std::pair<std::vector<Point>, std::uint32_t>> labels;
  InsertionStats stats;
  refine::QualityRange quality;  // the ranks' submesh_quality, merged
  // The ranks' own listing of the mesh (par/mesh_parts.hpp), their parts joined in rank
  // order, facet f's marker f + 1; whether every part was final; the parts' quality.
  MeshData listed;
  bool parts_final = true;
  refine::QualityRange listed_quality;
};

SimRun run_sim(const refine::VolumeMesh& m0, int ranks, std::uint64_t seed, bool surface = false) {
  SimRun out;
  const refine::TetBounds bounds{2.0, std::nullopt, kTargetVolume};
  const Partition part = partition_tets(m0.dt.store(), m0.inside, static_cast<std::uint32_t>(ranks), seed);
  SimNetwork net(ranks, seed);
  std::vector<std::unique_ptr<RefinementRules>> rules;
  std::vector<std::unique_ptr<InsertionActor>> actors;
  for (int r = 0; r < ranks; ++r) {
    rules.push_back(std::make_unique<RefinementRules>(m0, bounds, surface));
    Submesh sub = Submesh::extract(static_cast<ActorId>(r), m0.dt.store(), m0.dt.points(),
                                   m0.inside, part, rules.back()->vertex_tags(),
                                   /*dense=*/seed % 2 == 1);
    rules.back()->label(sub);
    actors.push_back(std::make_unique<InsertionActor>(net.endpoint(r), std::move(sub), seed,
                                                      rules.back().get()));
    actors.back()->add_wanted_tets();
  }
  const std::uint64_t steps = test::run_to_termination(net, actors, seed, 50'000'000u);
  if (steps == 0) return out;
  for (const auto& a : actors) {
    const Submesh& s = a->submesh();
    const auto problems = s.check();
    EXPECT_TRUE(problems.empty()) << "seed " << seed << ": " << problems.front();
    EXPECT_EQ(s.waiting_relinks(), 0u);
    out.pieces.push_back(piece_of(s));
    // Every vertex kept its tag across the migrations: M_o's class, or interior for the
    // committed points, segment for the midpoints, facet for the subfacet circumcenters.
    std::map<Gid, std::uint8_t> on_surface;
    for (const auto& rr : rules)
      for (const SurfaceStep& x : rr->surface_steps())
        on_surface[x.m] = 1 + static_cast<int>(x.c == kNoGid ? refine::VertexClass::Segment
                                                             : refine::VertexClass::Facet);
    for (VertexId v = 0; v < s.points().size(); ++v) {
      const Gid g = s.gid(v);
      const std::uint8_t want = g < m0.dt.num_points() ? rules.front()->vertex_tags()[g]
                                : on_surface.count(g) != 0 ? on_surface[g]
                                                           : rules.front()->new_vertex_tag();
      EXPECT_EQ(s.tag(v), want) << "seed " << seed << ": vertex " << g;
      if (s.tag(v) != want) break;
    }
    out.points.insert(out.points.end(), a->committed_points().begin(), a->committed_points().end());
    out.quality.merge(submesh_quality(s));
    {
      const TetStore& st = s.store();
      const auto pts = s.points();
      for (TetId t = 0; t < st.slots(); ++t) {
        if (!st.is_alive(t) || st.is_proxy(t) || st.is_ghost(t)) continue;
        const VertexId* v = st.vertices(t);
        for (const auto& e : tables::kEdgeVertex) {
          std::vector<Point> k{pts[v[e[0]]], pts[v[e[1]]]};
          std::sort(k.begin(), k.end());
          out.labels.emplace_back(k, s.edge_label(v[e[0]], v[e[1]]));
        }
        for (const auto& f : tables::kFaceVertex) {
          std::vector<Point> k{pts[v[f[0]]], pts[v[f[1]]], pts[v[f[2]]]};
          std::sort(k.begin(), k.end());
          out.labels.emplace_back(k, s.face_label(v[f[0]], v[f[1]], v[f[2]]));
        }
      }
    }
    const TetStore& st = s.store();
    std::vector<test::PointTet> tets;
    for (TetId t = 0; t < st.slots(); ++t)
      if (st.is_alive(t) && !st.is_proxy(t) && !st.is_ghost(t) && s.inside(t)) {
        const VertexId* v = st.vertices(t);
        const auto pts = s.points();
        out.inside_tets.push_back(point_tet(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]]));
      }
    out.stats.commits += a->stats().commits;
    out.stats.splits += a->stats().splits;
    out.stats.facet_points += a->stats().facet_points;
    out.stats.deferred += a->stats().deferred;
    out.stats.deferred_early += a->stats().deferred_early;
    out.stats.fetches_rejected += a->stats().fetches_rejected;
    out.stats.setbacks += a->stats().setbacks;
    out.stats.tets_sent += a->stats().tets_sent;
  }
  {
    std::vector<std::uint64_t> made;
    for (const auto& a : actors) made.push_back(a->committed_points().size());
    const VertexNumbers num(m0.dt.num_points(), made, ranks);
    std::vector<int> markers(m0.surf.facets.size());
    std::iota(markers.begin(), markers.end(), 1);
    out.listed.points.assign(m0.dt.points().begin(), m0.dt.points().end());
    for (const auto& a : actors)
      out.listed.points.insert(out.listed.points.end(), a->committed_points().begin(),
                               a->committed_points().end());
    EXPECT_EQ(out.listed.points.size(), num.total());
    for (const auto& a : actors) {
      out.parts_final = out.parts_final && part_is_final(a->submesh());
      add_part(a->submesh(), num, markers, out.listed, out.listed_quality);
    }
  }
  for (const auto& rr : rules) {
    out.steps.insert(out.steps.end(), rr->surface_steps().begin(), rr->surface_steps().end());
    for (const auto& k : rr->refused()) {
      std::vector<Point> e;
      for (const Gid g : k) {
        if (g == kNoGid) continue;
        for (const auto& x : actors)
          if (const VertexId v = x->submesh().find_vertex(g); v != kNoVertex) {
            e.push_back(x->submesh().points()[v]);
            break;
          }
      }
      EXPECT_EQ(e.size(), k[2] == kNoGid ? 2u : 3u) << "a refused element's vertices are nowhere";
      std::sort(e.begin(), e.end());
      out.refused.push_back(e);
    }
  }
  std::printf("seed %llu, %d ranks: %llu commits (%llu splits, %llu facet points, %zu refused), "
              "%llu deferred (%llu early, %llu at another rank), %llu setbacks, %llu tets migrated, "
              "%llu sim steps\n",
              static_cast<unsigned long long>(seed), ranks,
              static_cast<unsigned long long>(out.stats.commits),
              static_cast<unsigned long long>(out.stats.splits),
              static_cast<unsigned long long>(out.stats.facet_points), out.refused.size(),
              static_cast<unsigned long long>(out.stats.deferred),
              static_cast<unsigned long long>(out.stats.deferred_early),
              static_cast<unsigned long long>(out.stats.fetches_rejected),
              static_cast<unsigned long long>(out.stats.setbacks),
              static_cast<unsigned long long>(out.stats.tets_sent),
              static_cast<unsigned long long>(steps));
  return out;
}

TEST(ParRefinement, ParallelPhaseThenCompletionGiveACheckedMesh) {
  const Plc plc = io::read_domain(std::string(PDR_DATA_DIR) + "/cube-in-cube.poly");
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const int ranks = 2 + static_cast<int>(seed % 3);
    // Odd seeds take the steps on ∂Ω in the phase (Refine(s), Refine(f)), even ones defer
    // them.
    const bool surface = seed % 2 == 1;
    refine::VolumeMesh m = test::cube_in_cube();
    const SimRun run = run_sim(m, ranks, seed, surface);
    if (HasFailure()) return;
    EXPECT_GT(run.stats.commits, 100u);
    if (surface) {
      EXPECT_GT(run.stats.splits, 0u) << "seed " << seed;
      EXPECT_GT(run.stats.facet_points, 0u) << "seed " << seed;
      EXPECT_EQ(run.stats.deferred_early, 0u) << "seed " << seed;  // Fig. 2 needs the closure
      EXPECT_EQ(run.stats.fetches_rejected, 0u) << "seed " << seed;
    } else {
      // Without steps on ∂Ω every refusal is a deferral, decided at the first conflict tet
      // that shows one (outside Ω, or an element of D it encroaches): the rest of the
      // cavity is neither built nor fetched, also when that tet is at the rank asked for
      // the tets behind the root's proxies (fetches_rejected: nothing migrates). The checks
      // below hold all the same.
      EXPECT_GT(run.stats.deferred_early, 0u) << "seed " << seed;
      EXPECT_GT(run.stats.fetches_rejected, 0u) << "seed " << seed;
      EXPECT_LT(run.stats.fetches_rejected, run.stats.deferred_early) << "seed " << seed;
    }
    // The submeshes' tets assembled (through the wire format) are M_o plus the points,
    // every tet with its flag: what inserting the points gives.
    refine::VolumeMesh g = m;
    WireWriter w;
    for (const Piece& p : run.pieces) put_piece(w, p);
    const Bytes bytes = w.take();
    WireReader r(bytes);
    std::vector<Piece> back;
    while (!r.done()) back.push_back(get_piece(r));
    const Assembled assembled = assemble(g, back, run.steps);
    EXPECT_EQ(assembled.added, run.points.size());
    EXPECT_EQ(absorb(m, run.points, run.steps), run.points.size());
    EXPECT_TRUE(g.missing_subfacets.empty() && g.missing_subsegments.empty())
        << "seed " << seed << ": the phase's steps on ∂Ω left D out of T";
    // Submesh M4 at the end: every edge and face the ranks hold has the label of rank 0's
    // D, the phase's changes included.
    {
      std::map<Point, VertexId> at;
      for (VertexId v = 0; v < g.dt.num_points(); ++v) at[g.dt.point(v)] = v;
      std::size_t wrong = 0, labelled = 0;
      for (const auto& [k, label] : run.labels) {
        std::uint32_t want = kNoLabel;
        if (k.size() == 2) {
          if (const auto d = g.subsegment(at.at(k[0]), at.at(k[1]))) want = g.surf.subsegment(*d).segment;
        } else if (const auto d = g.subfacet(at.at(k[0]), at.at(k[1]), at.at(k[2]))) {
          want = g.surf.subfacet(*d).facet;
        }
        wrong += label != want;
        labelled += label != kNoLabel;
      }
      EXPECT_EQ(wrong, 0u) << "seed " << seed << ": labels that are not D's";
      EXPECT_GT(labelled, 100u) << "seed " << seed;
    }
    EXPECT_TRUE(g.dt.check_topology().empty());
    EXPECT_TRUE(refine::audit_volume(g).empty());
    // The ranks' quality figures are those of the assembled mesh's inside tets, exactly
    // (what `pdr mesh` reports when the completion changes nothing).
    {
      const MeshData exported = to_mesh_data(g.dt, g.inside);
      refine::QualityRange whole;
      for (const auto& t : exported.tets)
        whole.add(exported.points[t[0]], exported.points[t[1]], exported.points[t[2]],
                  exported.points[t[3]]);
      EXPECT_EQ(run.quality.tets, whole.tets) << "seed " << seed;
      EXPECT_EQ(run.quality.ratio_min, whole.ratio_min) << "seed " << seed;
      EXPECT_EQ(run.quality.ratio_max, whole.ratio_max) << "seed " << seed;
      EXPECT_EQ(run.quality.dot_lo, whole.dot_lo) << "seed " << seed;
      EXPECT_EQ(run.quality.dot_hi, whole.dot_hi) << "seed " << seed;
      EXPECT_EQ(run.quality.shortest2, whole.shortest2) << "seed " << seed;
    }
    // No element of D is encroached after the phase (each point went in only where it
    // encroached no element of its closure): what lets the completion skip its scan
    // (refine::RefineOptions::resumed_h).
    {
      std::vector<TetId> every;
      for (TetId t = 0; t < g.dt.store().slots(); ++t)
        if (g.dt.store().is_alive(t) && !g.dt.store().is_ghost(t)) every.push_back(t);
      refine::EncroachedLists enc;
      refine::find_encroached(g, every, enc);
      EXPECT_TRUE(enc.subsegments.empty() && enc.subfacets.empty())
          << "seed " << seed << ": " << enc.subsegments.size() << " subsegments and "
          << enc.subfacets.size() << " subfacets encroached after the phase";
      EXPECT_EQ(assembled.encroached, 0u) << "seed " << seed;
    }
    // The ranks' own listing (par/mesh_parts.hpp): final exactly when the completion has
    // nothing to do (no deferred step, nothing encroached around the phase's points on
    // ∂Ω), and then the assembled mesh's export, tet for tet and face for face, each
    // boundary face with its facet's marker; the same quality figures.
    EXPECT_EQ(run.parts_final, assembled.deferred.empty() && assembled.encroached == 0) << "seed " << seed;
    if (surface) {
      EXPECT_TRUE(run.parts_final) << "seed " << seed;
    }
    if (run.parts_final) {
      MeshData exported = to_mesh_data(g.dt, g.inside);
      exported.face_markers.clear();
      for (const Tri& f : exported.faces) {
        const auto sf = g.subfacet(f[0], f[1], f[2]);
        exported.face_markers.push_back(sf ? static_cast<int>(g.surf.subfacet(*sf).facet) + 1 : 0);
      }
      const auto [tets, faces] = canonical(exported);
      const auto [listed_tets, listed_faces] = canonical(run.listed);
      EXPECT_EQ(listed_tets.size(), tets.size()) << "seed " << seed;
      EXPECT_TRUE(listed_tets == tets) << "seed " << seed << ": the listed tets are not the assembled mesh's";
      EXPECT_EQ(listed_faces.size(), faces.size()) << "seed " << seed;
      EXPECT_TRUE(listed_faces == faces) << "seed " << seed << ": the listed faces are not the assembled mesh's";
      std::vector<Point> a = run.listed.points, b(g.dt.points().begin(), g.dt.points().end());
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      EXPECT_TRUE(a == b) << "seed " << seed << ": the listed points are not the assembled mesh's";
      EXPECT_EQ(run.listed_quality.tets, run.quality.tets);
      EXPECT_EQ(run.listed_quality.ratio_max, run.quality.ratio_max);
      EXPECT_EQ(run.listed_quality.dot_lo, run.quality.dot_lo);
      EXPECT_EQ(run.listed_quality.shortest2, run.quality.shortest2);
    }
    EXPECT_TRUE(all_tets(g) == all_tets(m)) << "seed " << seed << ": assembly differs from insertion";
    EXPECT_EQ(g.dt.num_points(), m.dt.num_points());
    EXPECT_EQ(g.vclass.size(), g.dt.num_points());
    {
      const TetStore& gs = g.dt.store();
      const TetId last = g.dt.last_tet();
      const VertexId newest = static_cast<VertexId>(g.dt.num_points() - 1);
      ASSERT_TRUE(last < gs.slots() && gs.is_alive(last) && !gs.is_ghost(last));
      EXPECT_TRUE(std::find(gs.vertices(last), gs.vertices(last) + 4, newest) != gs.vertices(last) + 4);
    }
    // The tets marked deferred are exactly the assembled mesh's tets that the sequential
    // refinement would queue (bad, or flat on a facet): the completion starts from them.
    {
      std::vector<TetId> queued;
      const TetStore& gs = g.dt.store();
      const refine::TetBounds b{2.0, std::nullopt, kTargetVolume};
      for (TetId t = 0; t < gs.slots(); ++t) {
        if (!gs.is_alive(t) || gs.is_ghost(t) || !g.is_inside(t)) continue;
        const VertexId* v = gs.vertices(t);
        if (refine::is_bad(g.dt.point(v[0]), g.dt.point(v[1]), g.dt.point(v[2]), g.dt.point(v[3]), b) ||
            refine::subfacet_to_refine(g, t))
          queued.push_back(t);
      }
      if (!surface) {
        EXPECT_GT(queued.size(), 0u);  // not vacuous: some steps were deferred
      }
      std::vector<TetId> marked = assembled.deferred;
      std::sort(marked.begin(), marked.end());  // queued is sorted already
      EXPECT_TRUE(queued == marked)
          << "seed " << seed << ": " << queued.size() << " tets to queue, "
          << assembled.deferred.size() << " marked deferred";
    }
    // The union of the submeshes is M_o plus the points.
    std::vector<test::PointTet> want;
    const TetStore& s = m.dt.store();
    for (TetId t = 0; t < s.slots(); ++t)
      if (s.is_alive(t) && !s.is_ghost(t) && m.is_inside(t)) {
        const VertexId* v = s.vertices(t);
        want.push_back(point_tet(m.dt.point(v[0]), m.dt.point(v[1]), m.dt.point(v[2]), m.dt.point(v[3])));
      }
    EXPECT_TRUE(test::sorted(run.inside_tets) == test::sorted(want))
        << "seed " << seed << ": the submeshes are not M_o plus the committed points";
    // Nothing left that the rules would commit: every bad inside tet is deferred (or
    // needs a split that was refused).
    RefinementRules whole(m, {2.0, std::nullopt, kTargetVolume}, surface);
    Submesh one = Submesh::extract(0, s, m.dt.points(), m.inside,
                                   partition_tets(s, m.inside, 1, seed));
    whole.label(one);
    Cavity c;
    CavityBuilder builder;
    std::size_t bad = 0, stale = 0;
    for (TetId t = 0; t < one.store().slots(); ++t) {
      const TetStore& os = one.store();
      if (!os.is_alive(t) || os.is_ghost(t) || os.is_proxy(t) || !one.inside(t)) continue;
      if (!whole.wants(one, t)) continue;
      ++bad;
      const Point p = whole.point(one, t);
      WalkRng rng;
      const Location loc = locate(os, one.points(), p, t, rng);
      if (loc.kind == Location::Kind::OnVertex) continue;
      builder.build(os, one.points(), p, loc.tet, c);
      const Verdict v = whole.accept(one, c);
      // With steps on ∂Ω, D changes after a step was deferred: a subfacet that a tet's
      // point encroached may since have been refined, and the step be one to commit now.
      // Such a tet is marked deferred all the same (checked above), so the completion
      // takes it.
      if (surface && v.kind == Verdict::Kind::Commit) {
        ++stale;
        continue;
      }
      EXPECT_NE(v.kind, Verdict::Kind::Commit) << "seed " << seed << ": a bad tet was left undeferred";
      if (v.kind == Verdict::Kind::Split || v.kind == Verdict::Kind::Facet) {
        std::vector<Point> e;
        for (const Gid g : {v.a, v.b, v.c})
          if (g != kNoGid) e.push_back(one.points()[one.find_vertex(g)]);
        std::sort(e.begin(), e.end());
        EXPECT_TRUE(std::find(run.refused.begin(), run.refused.end(), e) != run.refused.end())
            << "seed " << seed << ": an element a bad tet encroaches was left unrefined";
      }
    }
    std::printf("  %zu bad tets left to the completion (%zu deferred before a split changed D)\n",
                bad, stale);
    EXPECT_LT(stale * 20, bad + 20) << "seed " << seed;
    // The sequential completion, from every tet (on the inserted mesh) and from the
    // deferred ones (on the assembled mesh, as `mpirun pdr mesh` does).
    refine::RefineOptions o;
    o.max_volume = kTargetVolume;
    o.d = 2;  // cube-in-cube's d (the derived cap only)
    refine::RefineOptions from_deferred = o;
    from_deferred.start_tets = assembled.deferred;
    // Resumed from M_o (unencroached, checked above), so Lemma 1 runs from it: every edge
    // made since, the completion's included, is longer than M_o's h.
    const double h = refine::theorem_h(refine::shortest_inside_edge(test::cube_in_cube()), o);
    from_deferred.resumed_h = h;
    for (const auto& [mesh_of, opts] : {std::pair{&m, &o}, std::pair{&g, &from_deferred}}) {
      const refine::RefineResult rr = refine::refine(*mesh_of, *opts);
      EXPECT_TRUE(rr.leftovers.empty());
      const MeshData mesh = to_mesh_data(mesh_of->dt, mesh_of->inside);
      check::Options co;
      co.ratio_bound = 2.0;
      if (opts->resumed_h) {
        EXPECT_EQ(rr.stats.h_theorem, h);
        co.min_edge = h;  // quality.shortest_edge, which fails on a shorter edge
      }
      const check::Report report = check::check_mesh(check::view_of(mesh), plc, co);
      for (const auto& ch : report.checks)
        EXPECT_NE(ch.status, check::Status::Fail) << "seed " << seed << ": " << ch.id;
    }
  }
}

// The tags only skip lookups that would find nothing: on every bad tet of a mesh whose
// boundary layer is refined, accept() says the same, for the same reason, with and without
// them.
TEST(ParRefinement, VertexTagsChangeNoDecision) {
  const refine::VolumeMesh& m = test::cube_in_cube();
  const TetStore& s = m.dt.store();
  const refine::TetBounds bounds{2.0, std::nullopt, kTargetVolume};
  RefinementRules tagged(m, bounds), plain(m, bounds);
  const Partition whole = partition_tets(s, m.inside, 1, 1);
  Submesh with = Submesh::extract(0, s, m.dt.points(), m.inside, whole, tagged.vertex_tags());
  Submesh without = Submesh::extract(0, s, m.dt.points(), m.inside, whole);
  tagged.label(with);
  plain.label(without);
  // Element by element: the same lookups, and a tet the filter passes over has none.
  std::size_t skipped = 0, in_d = 0;
  for (TetId t = 0; t < with.store().slots(); ++t) {
    const TetStore& os = with.store();
    if (!os.is_alive(t) || os.is_ghost(t) || os.is_proxy(t)) continue;
    const VertexId* v = os.vertices(t);
    bool touches = false;
    for (const auto& e : tables::kEdgeVertex) {
      const refine::MaybeId a = tagged.subsegment(with, v[e[0]], v[e[1]]);
      ASSERT_EQ(a, plain.subsegment(without, v[e[0]], v[e[1]])) << "tet " << t;
      touches = touches || a;
    }
    for (const auto& f : tables::kFaceVertex) {
      const refine::MaybeId a = tagged.subfacet(with, v[f[0]], v[f[1]], v[f[2]]);
      ASSERT_EQ(a, plain.subfacet(without, v[f[0]], v[f[1]], v[f[2]])) << "tet " << t;
      touches = touches || a;
    }
    if (!RefinementRules::may_touch_d(with, v)) {
      ++skipped;
      EXPECT_FALSE(touches) << "tet " << t << " has an element of D but is passed over";
    }
    in_d += touches;
  }
  EXPECT_GT(skipped, 1000u);
  EXPECT_GT(in_d, 100u);
  Cavity c;
  CavityBuilder builder;
  std::size_t accepted = 0, refused = 0;
  for (TetId t = 0; t < with.store().slots(); ++t) {
    const TetStore& os = with.store();
    if (!os.is_alive(t) || os.is_ghost(t) || os.is_proxy(t) || !with.inside(t)) continue;
    if (!tagged.wants(with, t)) continue;
    const Point p = tagged.point(with, t);
    WalkRng rng;
    const Location loc = locate(os, with.points(), p, t, rng);
    if (loc.kind == Location::Kind::OnVertex) continue;
    builder.build(os, with.points(), p, loc.tet, c);  // the stores are alike slot by slot
    const bool a = tagged.accept(with, c).kind == Verdict::Kind::Commit;
    const bool b = plain.accept(without, c).kind == Verdict::Kind::Commit;
    ASSERT_EQ(a, b) << "tet " << t;
    (a ? accepted : refused) += 1;
  }
  const DeferCounts &x = tagged.deferred(), &y = plain.deferred();
  EXPECT_EQ(x.outside, y.outside);
  EXPECT_EQ(x.subsegment, y.subsegment);
  EXPECT_EQ(x.subfacet, y.subfacet);
  EXPECT_EQ(x.removed, y.removed);
  // Not vacuous: both outcomes, and refusals by D.
  EXPECT_GT(accepted, 100u);
  EXPECT_GT(x.subsegment + x.subfacet + x.removed, 10u);
  std::printf("%zu accepted, %zu refused (%llu subsegment, %llu subfacet, %llu removed)\n",
              accepted, refused, static_cast<unsigned long long>(x.subsegment),
              static_cast<unsigned long long>(x.subfacet), static_cast<unsigned long long>(x.removed));
}

}  // namespace
}  // namespace pdr::par
