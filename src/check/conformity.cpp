// conformity.*: the domain's boundary appears in the mesh (paper §1.1: "the subsegments and
// subfacets in D(dOmega) appear in T(Omega)"; §2.1 property 1: "the segments and facets in
// dOmega appear as a union of subsegments and subfacets").
//   vertices  every input vertex is a mesh vertex (exactly equal coordinates)
//   segments  every segment (polygon edge of a facet) is a union of mesh edges: the mesh
//             vertices on it (domain.hpp), in order, are joined by mesh edges
//   facets    every facet is exactly covered by mesh faces: the projected areas of the mesh
//             faces lying in it sum exactly (rationals) to the projected area of its region.
//             Faces in a facet do not overlap because tets meet only in common faces
//             (validity.overlap); so equal areas mean exact cover.
//   volume    the mesh fills the domain and nothing else, decided as: (a) every boundary
//             face of the mesh lies in a facet; (b) no volume hole point lies in a (closed)
//             tet; (c) every region point lies in a tet. Justification: by (a) the mesh's
//             boundary is inside the union of facets, so the mesh is a union of cells of
//             the facets' arrangement; it is bounded, so not the outer cell; (b) excludes
//             hole cells; facets adjacent to the outside or a hole are covered only if the
//             cell on their other side is meshed (facets); (c) covers cells named by region
//             points. Not detected: an unnamed bounded cell missing while every facet
//             around it is covered from neighbouring meshed cells.
// Segments and facets whose vertices are not mesh vertices are not judged (counted as
// skipped; conformity.vertices fails for them).
#include <algorithm>

#include "check/checks.hpp"
#include "check/signs.hpp"

namespace pdr::check {
namespace {

bool in_closed_tet(const Context& c, std::size_t t, const Point& p) {
  const Tet& k = c.mesh.tets[t];
  std::array<const Point*, 4> v = {&c.mesh.points[k[0]], &c.mesh.points[k[1]], &c.mesh.points[k[2]],
                                   &c.mesh.points[k[3]]};
  for (int i = 0; i < 3; ++i)
    if (p[i] < std::min({(*v[0])[i], (*v[1])[i], (*v[2])[i], (*v[3])[i]}) ||
        p[i] > std::max({(*v[0])[i], (*v[1])[i], (*v[2])[i], (*v[3])[i]}))
      return false;
  if (c.orientation[t] == Sign::Negative) std::swap(v[1], v[2]);
  return signs::orient3d(p, *v[1], *v[2], *v[3]) != Sign::Negative &&
         signs::orient3d(*v[0], p, *v[2], *v[3]) != Sign::Negative &&
         signs::orient3d(*v[0], *v[1], p, *v[3]) != Sign::Negative &&
         signs::orient3d(*v[0], *v[1], *v[2], p) != Sign::Negative;
}

std::optional<std::size_t> tet_containing(const Context& c, const Point& p) {
  for (std::size_t t = 0; t < c.mesh.tets.size(); ++t)
    if (c.orientation[t] != Sign::Zero && in_closed_tet(c, t, p)) return t;
  return std::nullopt;
}

void warn_if_skipped(CheckResult& r, std::uint64_t skipped, const std::string& what) {
  if (r.status == Status::Pass && skipped > 0) {
    r.status = Status::Warn;
    r.reason = std::to_string(skipped) + " " + what + " not judged (see counts)";
  }
}

const char* skip_name(ItemStatus s) {
  switch (s) {
    case ItemStatus::MissingVertex: return "skipped_missing_vertex";
    case ItemStatus::Degenerate: return "skipped_degenerate";
    case ItemStatus::NonPlanar: return "skipped_nonplanar";
    case ItemStatus::Unsupported: return "skipped_crossing_polygons";
    case ItemStatus::Dropped: return "dropped";
    case ItemStatus::Ok: break;
  }
  return "ok";
}

}  // namespace

CheckResult check_input_vertices(const Context& c) {
  CheckResult r = make_result("conformity.vertices");
  const DomainMap& m = *c.domain_map;
  std::vector<std::uint8_t> may_miss(m.mesh_vertex.size(), 0);
  for (const std::uint32_t v : c.options.dropped_vertices)
    if (v < may_miss.size()) may_miss[v] = 1;
  for (std::size_t i = 0; i < m.mesh_vertex.size(); ++i) {
    ++r.checked;
    if (m.mesh_vertex[i] || may_miss[i]) continue;
    ++r.violations;
    if (r.findings.size() < c.options.max_reported)
      r.findings.push_back({"input_vertex", i, {}, {c.domain->points[i]}, std::nullopt,
                            "conformity.vertices: input vertex " + std::to_string(i) +
                                " is not a mesh vertex"});
  }
  conclude(r);
  return r;
}

CheckResult check_segments(const Context& c) {
  CheckResult r = make_result("conformity.segments");
  const DomainMap& m = *c.domain_map;
  std::uint64_t skipped = 0;
  for (std::size_t i = 0; i < m.segments.size(); ++i) {
    const SegmentMap& s = m.segments[i];
    if (s.status == ItemStatus::Dropped) continue;
    if (s.status != ItemStatus::Ok) {
      ++r.counts[skip_name(s.status)];
      ++skipped;
      continue;
    }
    ++r.checked;
    r.counts["tolerance_vertices"] += s.tolerance_vertices;
    r.counts["subsegments"] += s.vertices.size() - 1 - static_cast<std::size_t>(std::count(
        s.dropped.begin(), s.dropped.end(), std::uint8_t{1}));
    for (std::size_t k = 0; k + 1 < s.vertices.size(); ++k) {
      const std::uint32_t u = s.vertices[k], v = s.vertices[k + 1];
      if (c.topology.has_edge(u, v) || (!s.dropped.empty() && s.dropped[k])) continue;
      ++r.violations;
      if (r.findings.size() < c.options.max_reported)
        r.findings.push_back(make_finding(
            c.mesh, "segment", i, {u, v},
            "conformity.segments: segment " + std::to_string(i) + " (input vertices " +
                std::to_string(s.a) + "," + std::to_string(s.b) + "): consecutive vertices " +
                std::to_string(u) + "," + std::to_string(v) + " on it are not joined by a mesh edge"));
      break;
    }
  }
  conclude(r);
  warn_if_skipped(r, skipped, "segments");
  return r;
}

CheckResult check_facets(const Context& c) {
  CheckResult r = make_result("conformity.facets");
  const DomainMap& m = *c.domain_map;
  std::uint64_t skipped = 0;
  for (std::size_t i = 0; i < m.facets.size(); ++i) {
    const FacetMap& f = m.facets[i];
    if (f.status != ItemStatus::Ok) {
      ++r.counts[skip_name(f.status)];
      ++skipped;
      continue;
    }
    ++r.checked;
    r.counts["tolerance_vertices"] += f.tolerance_vertices;
    r.counts["ambiguous_faces"] += f.ambiguous_faces;
    r.counts["subfacets"] += f.faces.size();
    mpq_class covered = 0;
    for (std::uint32_t fid : f.faces) {
      const Tri& t = c.topology.faces[fid];
      covered += abs(area2(project(c.mesh.points[t[0]], f.drop), project(c.mesh.points[t[1]], f.drop),
                           project(c.mesh.points[t[2]], f.drop)));
    }
    mpq_class area = f.region->area2();
    for (const std::vector<P2>& tri : f.dropped) area -= abs(area2(tri));
    if (covered == area) continue;
    ++r.violations;
    if (r.findings.size() < c.options.max_reported) {
      const double frac = sgn(area) != 0 ? mpq_class(covered / area).get_d() : 0.0;
      Finding fd{"facet", i, {}, {}, frac,
                 "conformity.facets: facet " + std::to_string(i) + " is covered by " +
                     std::to_string(f.faces.size()) + " mesh faces of total area " +
                     std::to_string(frac) + " times its area"};
      r.findings.push_back(std::move(fd));
    }
  }
  conclude(r);
  warn_if_skipped(r, skipped, "facets");
  return r;
}

CheckResult check_domain_volume(const Context& c) {
  CheckResult r = make_result("conformity.volume");
  const DomainMap& m = *c.domain_map;
  for (std::uint32_t f : c.topology.boundary) {
    ++r.checked;
    if (m.face_in_facet[f]) continue;
    ++r.violations;
    ++r.counts["boundary_faces_off_facets"];
    if (r.findings.size() < c.options.max_reported) {
      const Tri& k = c.topology.faces[f];
      r.findings.push_back(make_finding(c.mesh, "face", kNoId, {k[0], k[1], k[2]},
                                        "conformity.volume: boundary face (" + std::to_string(k[0]) +
                                            "," + std::to_string(k[1]) + "," + std::to_string(k[2]) +
                                            ") lies in no facet"));
    }
  }
  for (std::size_t h = 0; h < c.domain->holes.size(); ++h) {
    ++r.checked;
    const auto t = tet_containing(c, c.domain->holes[h]);
    if (!t) continue;
    ++r.violations;
    ++r.counts["filled_holes"];
    if (r.findings.size() < c.options.max_reported)
      r.findings.push_back({"hole", h, {}, {c.domain->holes[h]}, static_cast<double>(*t),
                            "conformity.volume: hole point " + std::to_string(h) + " lies in tet " +
                                std::to_string(*t)});
  }
  for (std::size_t g = 0; g < c.domain->regions.size(); ++g) {
    ++r.checked;
    if (tet_containing(c, c.domain->regions[g].point)) continue;
    ++r.violations;
    ++r.counts["empty_regions"];
    if (r.findings.size() < c.options.max_reported)
      r.findings.push_back({"region", g, {}, {c.domain->regions[g].point}, std::nullopt,
                            "conformity.volume: region point " + std::to_string(g) + " lies in no tet"});
  }
  conclude(r);
  return r;
}

}  // namespace pdr::check
