// Step 4 of build_domain: the plane and the triangulation of every face (paper §1.1:
// "planar, segment-bounded, polygonal facets", not necessarily convex, with holes).
//
// Per face, with the plane step 4a fitted (domain/coplanar.cpp): project the facet's
// vertices by the plane's chart (exact: a projection only drops a coordinate); build the
// constrained triangulation of its polygons' edges (domain/ctri.hpp), which detects edges
// through vertices and crossing edges; remove the part outside the polygons and the parts
// marked by facet hole points. The facet's region is then a set of triangles whose corners
// are input vertices, counter-clockwise in the chart.
#include <algorithm>
#include <cstdio>
#include <unordered_map>

#include "domain/ctri.hpp"
#include "domain/steps.hpp"

namespace pdr::domain::detail {

namespace {

void triangulate_face(const FacetPolys& fp, std::size_t f, PlcDomain& dom) {
  const Plc& plc = dom.plc;
  const PlcFacet& facet = plc.facets[f];
  auto here = [&](const std::string& m) { fail(plc, facet.line, m); };
  const double tol = dom.options.planarity_tolerance;

  const std::vector<std::uint32_t> verts = face_vertices(fp);
  DomainFacet& F = dom.facets[f];  // plane fitted by step 4a (domain/coplanar.cpp)

  std::unordered_map<std::uint32_t, std::uint32_t> local;
  std::vector<P2> p2(verts.size());
  for (std::uint32_t i = 0; i < verts.size(); ++i) {
    local[verts[i]] = i;
    p2[i] = F.plane.projection(plc.points[verts[i]]);
  }
  std::vector<std::array<std::uint32_t, 2>> cons;
  for (const auto& loop : fp.loops)
    for (std::size_t i = 0; i < loop.size(); ++i)
      cons.push_back({local[loop[i]], local[loop[(i + 1) % loop.size()]]});
  for (const auto& s : fp.segs) cons.push_back({local[s[0]], local[s[1]]});

  Ct2 ct;
  const Ct2Outcome r = ct.build(p2, cons);
  auto V = [&](std::uint32_t l) { return vertex_name(plc, verts[l]); };
  switch (r.status) {
    case Ct2Status::Ok: break;
    case Ct2Status::Duplicate:
      here("non-degenerate facet: " + V(r.a) + " and " + V(r.b) +
           " of this facet differ only across the facet's plane (within the planarity "
           "tolerance); merge them");
      break;
    case Ct2Status::Collinear:
      here("non-degenerate facet: the vertices of this facet are collinear in its plane; "
           "remove the facet or fix it");
      break;
    case Ct2Status::ThroughVertex:
      here("simple facet polygons: the edge from " + V(r.a) + " to " + V(r.b) +
           " of this facet passes through " + V(r.c) +
           "; split the edge at that vertex or fix the coordinates");
      break;
    case Ct2Status::Crossing:
      here("simple facet polygons: the edge from " + V(r.a) + " to " + V(r.b) +
           " crosses the edge from " + V(r.c) + " to " + V(r.d) +
           " of this facet; polygons must be simple and meet only at shared vertices");
      break;
  }

  std::vector<std::int32_t> seeds;
  for (std::size_t h = 0; h < facet.holes.size(); ++h) {
    const std::string which = "facet hole point " + std::to_string(h + 1) + " of this facet";
    const double dev = relative_deviation(F.plane, facet.holes[h]);
    if (!(dev * F.plane.diameter <= dom.tolerance.admitted(F.plane.diameter)))
      here("facet hole in plane: " + which + " lies " + number(dev) +
           " facet diameters off the facet's plane (tolerance " + number(tol) +
           "); move it into the facet");
    const Ct2Location loc = ct.locate(F.plane.projection(facet.holes[h]));
    if (loc.tri < 0)
      here("facet hole inside facet: " + which +
           " lies outside the facet's polygons; move it into the region it should remove");
    const Ct2Tri& T = ct.tris()[loc.tri];
    if (loc.zeros == 2 || (loc.zeros == 1 && T.fixed[loc.edge]))
      here("facet hole off edges: " + which +
           " lies on an edge or vertex of the facet's polygons; move it into the region it "
           "should remove");
    seeds.push_back(loc.tri);
  }
  const std::vector<Ct2Region> region = ct.regions(seeds);
  for (std::size_t h = 0; h < seeds.size(); ++h)
    if (region[seeds[h]] == Ct2Region::Outside)
      here("facet hole inside facet: facet hole point " + std::to_string(h + 1) +
           " of this facet lies outside the facet's polygons; move it into the region it "
           "should remove");

  std::vector<std::int32_t> index(ct.tris().size(), -1);
  std::vector<bool> covered(verts.size(), false);
  for (std::size_t t = 0; t < ct.tris().size(); ++t)
    if (region[t] == Ct2Region::Inside) {
      index[t] = static_cast<std::int32_t>(F.tris.size());
      F.tris.emplace_back();
      for (std::uint32_t l : ct.tris()[t].v) covered[l] = true;
    }
  if (F.tris.empty())
    here("non-empty facet: the facet hole points of this facet remove all of it; remove "
         "the facet or its holes");
  for (std::size_t t = 0; t < ct.tris().size(); ++t) {
    if (index[t] < 0) continue;
    const Ct2Tri& T = ct.tris()[t];
    FacetTri& out = F.tris[index[t]];
    for (int i = 0; i < 3; ++i) {
      out.v[i] = verts[T.v[i]];
      out.nbr[i] = T.n[i] >= 0 ? index[T.n[i]] : -1;
      out.on_segment[i] = T.fixed[i];
    }
  }
  for (std::uint32_t l = 0; l < verts.size(); ++l)
    if (!covered[l])
      here("polygons inside facet: " + V(l) +
           " of this facet lies outside the facet's region (outside its polygons or in a "
           "facet hole); remove it or fix the polygons");
  // A constraint edge with no region triangle on either side lies outside the region.
  for (std::size_t t = 0; t < ct.tris().size(); ++t) {
    if (index[t] >= 0) continue;
    const Ct2Tri& T = ct.tris()[t];
    for (int i = 0; i < 3; ++i)
      if (T.fixed[i] && (T.n[i] < 0 || index[T.n[i]] < 0))
        here("polygons inside facet: the edge from " + V(T.v[(i + 1) % 3]) + " to " +
             V(T.v[(i + 2) % 3]) +
             " of this facet lies outside the facet's region (outside its polygons or in "
             "a facet hole); remove it or fix the polygons");
  }
}

}  // namespace

void triangulate_faces(const std::vector<FacetPolys>& polys, PlcDomain& dom) {
  for (std::size_t f = 0; f < polys.size(); ++f)
    if (!polys[f].loops.empty()) triangulate_face(polys[f], f, dom);
}

}  // namespace pdr::domain::detail
