// Step 4a of build_domain: every face's plane, and faces that share an edge and are coplanar
// within the planarity tolerance marked as one group (plane_group).
//
// Why. Two faces across an edge whose dihedral angle is 180 degrees to within rounding (the
// two triangles of a planar quad in a rotated STL or OFF file, a face split in two in a
// .poly) are, as the kernel sees them with a plane each, two planes a few ulps apart. Near
// the common edge the 3D Delaunay tetrahedralization then decides flat tets spanning both
// faces by those ulps, which the flat-tet repair of refine/flat.hpp must see as flat: its
// rule 1 takes four vertices of one group as lying on one plane. The input means one plane
// there, so the tolerance classifies it as one: this is input classification, like a facet
// planar within tolerance, and every later decision stays exact.
//
// Each face keeps its own plane (defining triple and chart): the new vertices of a face are
// rounded onto it, so they lie within rounding of the face's own plane, as an independent
// check of that face expects (check/domain.hpp). A plane shared by the group put them on
// the group's defining triple, up to the group's deviation times its diameter off a member
// face, beyond the check's tolerance relative to the face's diameter (a 10-degree wedge
// written with 9 digits: tests/regress/outside-wedge-printed-9-digits-facets-off-check.off).
//
// Rule. Faces are grouped greedily in index order: a group starts at its smallest face and
// grows across polygon edges shared with faces not yet grouped, taking a neighbour when the
// fitted plane of the group's vertices together with the neighbour's is within the planarity
// tolerance (relative to the union's diameter). Every face of a group gets `plane_group`, the
// group's smallest face; the segment between two faces of a group stays a segment.
#include <algorithm>
#include <cstdio>
#include <map>
#include <numeric>

#include "domain/steps.hpp"

namespace pdr::domain::detail {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

std::vector<std::uint32_t> face_vertices(const FacetPolys& fp) {
  std::vector<std::uint32_t> verts(fp.points);
  for (const auto& loop : fp.loops) verts.insert(verts.end(), loop.begin(), loop.end());
  for (const auto& s : fp.segs) verts.insert(verts.end(), s.begin(), s.end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  return verts;
}

namespace {

std::vector<std::uint32_t> merged(const std::vector<std::uint32_t>& a,
                                  const std::vector<std::uint32_t>& b) {
  std::vector<std::uint32_t> out;
  out.reserve(a.size() + b.size());
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

}  // namespace

void fit_planes(const std::vector<FacetPolys>& polys, PlcDomain& dom) {
  const Plc& plc = dom.plc;
  const io::PlanarityTolerance& tol = dom.tolerance;
  const std::size_t n = polys.size();
  std::vector<std::vector<std::uint32_t>> verts(n);
  for (std::size_t f = 0; f < n; ++f) {
    if (polys[f].loops.empty()) continue;
    verts[f] = face_vertices(polys[f]);
    const PlaneFit fit = fit_facet_plane(plc.points, verts[f], tol);
    auto here = [&](const std::string& m) { fail(plc, plc.facets[f].line, m); };
    if (fit.status == PlaneStatus::Collinear)
      here("non-degenerate facet: all " + std::to_string(verts[f].size()) +
           " vertices of this facet are collinear, so it has no area; remove it or fix it");
    if (fit.status == PlaneStatus::NotPlanar)
      here("planar facet: " + vertex_name(plc, fit.worst) + " lies " +
           number(fit.plane.max_deviation) +
           " facet diameters off the best-fit plane of this facet (tolerance " +
           number(tol.relative) +
           (tol.uncertainty() > 0 ? ", or " + number(tol.admitted(0) / fit.plane.diameter) +
                                      " for the rounding of the coordinates"
                                : std::string()) +
           "); fix the coordinates, split the facet into planar facets, or raise the "
           "planarity tolerance (pdr mesh --planarity-tolerance)");
    DomainFacet& F = dom.facets[f];
    F.is_face = true;
    F.plane = fit.plane;
    F.plane_group = static_cast<std::uint32_t>(f);
  }

  // Faces on each polygon edge (segments not split yet: the polygon edges as given, after
  // step 3, which is what the faces share).
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> on_edge;
  auto add_edge = [&](std::uint32_t a, std::uint32_t b, std::uint32_t f) {
    auto& list = on_edge[{std::min(a, b), std::max(a, b)}];
    if (list.empty() || list.back() != f) list.push_back(f);
  };
  for (std::uint32_t f = 0; f < n; ++f) {
    if (polys[f].loops.empty()) continue;
    for (const auto& loop : polys[f].loops)
      for (std::size_t i = 0; i < loop.size(); ++i) add_edge(loop[i], loop[(i + 1) % loop.size()], f);
    for (const auto& s : polys[f].segs) add_edge(s[0], s[1], f);
  }
  std::vector<std::vector<std::uint32_t>> neighbours(n);
  for (const auto& [edge, faces] : on_edge)
    for (std::uint32_t f : faces)
      for (std::uint32_t g : faces)
        if (f != g) neighbours[f].push_back(g);

  std::vector<bool> grouped(n, false);
  for (std::uint32_t seed = 0; seed < n; ++seed) {
    if (polys[seed].loops.empty() || grouped[seed]) continue;
    grouped[seed] = true;
    std::vector<std::uint32_t> members{seed}, group_verts = verts[seed];
    for (std::size_t i = 0; i < members.size(); ++i)
      for (std::uint32_t g : neighbours[members[i]]) {
        if (grouped[g]) continue;
        std::vector<std::uint32_t> u = merged(group_verts, verts[g]);
        PlaneFit fit = fit_facet_plane(plc.points, u, tol);
        if (fit.status != PlaneStatus::Ok) continue;
        grouped[g] = true;
        members.push_back(g);
        group_verts = std::move(u);
      }
    for (std::uint32_t f : members) dom.facets[f].plane_group = seed;
  }
  for (std::uint32_t f = 0; f < n; ++f)
    if (dom.facets[f].is_face && !dom.facets[f].plane.exact) dom.tolerance_facets.push_back(f);
}

}  // namespace pdr::domain::detail
