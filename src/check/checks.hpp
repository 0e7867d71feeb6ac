// The individual checkers, each a pure function over a read-only Context (docs/design.md §8), named
// after the invariant it encodes and returning a CheckResult (violations as data).
//
// A Context holds what several checkers share, computed once by check_mesh (check.cpp):
// the exact orientation of every tet, the topology, the vertex grid and, with a domain, the
// DomainMap. Each checker judges one invariant and stays silent about the others where it
// can: e.g. checks that need a tet's geometry use its exact orientation to be independent
// of the vertex order, so a tet recorded with two vertices swapped fails
// validity.orientation only; degenerate (zero-volume) tets are skipped by the geometric
// checks and reported by validity.orientation only.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "check/check.hpp"
#include "check/domain.hpp"
#include "check/grid.hpp"
#include "check/interval.hpp"
#include "check/topology.hpp"

namespace pdr::check {

struct Context {
  MeshView mesh;
  const Plc* domain = nullptr;
  Options options;
  std::vector<Sign> orientation;  // exact orient3d of each tet as recorded
  Topology topology;
  PointGrid grid;
  std::optional<DomainMap> domain_map;
  // Each tet's squared circumradius, enclosed (circumball.hpp): kept by
  // delaunay.empty_sphere for quality.ratio, which would compute the same enclosure; empty
  // until then (degenerate tets' entries are not set: both checks skip them).
  std::vector<Interval> circum_r2;
  // delaunay.empty_sphere's on-sphere pairs (Report::on_sphere), per worker; beyond
  // Report::kMaxOnSphere in all, on_sphere_overflow is set and the lists are dropped.
  std::vector<std::vector<std::pair<std::uint64_t, std::uint32_t>>> on_sphere;
  bool on_sphere_overflow = false;
};

// orient3d(face key a<b<c, apex) from the holder's exact orientation: the sorted face and
// the apex are an even permutation of the tet exactly when the face is listed oddly
// (FaceRef::odd). Two holders of a face lie on its opposite sides when theirs differ.
inline int apex_side(const Context& c, const FaceRef& r) {
  return to_int(c.orientation[r.tet]) * (r.odd ? 1 : -1);
}

// A result with the id, its invariant text (table in check.cpp), status Skipped.
CheckResult make_result(std::string_view id);
// Sets Pass/Fail from the violation count (Fail if any).
void conclude(CheckResult& r);
// A finding naming mesh vertices `vs` (coordinates filled in from the mesh).
Finding make_finding(const MeshView& mesh, std::string kind, std::uint64_t id,
                     std::vector<std::uint32_t> vs, std::string message);
// A finding for tet t (its four vertices).
Finding tet_finding(const MeshView& mesh, std::uint64_t t, std::string message);

// validity.cpp — the mesh is a tetrahedralization.
CheckResult check_indices(const MeshView& mesh, const Options& o);     // validity.indices
CheckResult check_coordinates(const MeshView& mesh, const Options& o);  // validity.coordinates
CheckResult check_orientation(const MeshView& mesh, const Options& o,
                              std::vector<Sign>& orientation);          // validity.orientation
CheckResult check_duplicate_vertices(const Context& c);     // validity.duplicate_vertices
CheckResult check_unreferenced_vertices(const Context& c);  // validity.unreferenced_vertices
CheckResult check_face_sharing(const Context& c);           // validity.face_sharing
CheckResult check_boundary_closed(const Context& c);        // validity.boundary_closed
CheckResult check_listed_faces(const Context& c);           // validity.faces

// overlap.cpp
CheckResult check_overlap(const Context& c);  // validity.overlap
// degree.cpp: the degree argument's verdict on disjoint interiors (counts go to r).
enum class DegreeVerdict { Disjoint, Overlap, PremisesFail };
DegreeVerdict overlap_by_degree(const Context& c, CheckResult& r);

// delaunay_empty.cpp
// delaunay.empty_sphere; fills c.circum_r2. By default the Delaunay lemma spares the vertex
// query of tets far from the boundary when its premises hold; that verdict also assumes
// validity.overlap, so the caller runs it again with `by_lemma` false if that fails.
CheckResult check_empty_circumspheres(Context& c, bool by_lemma = true);
// Whether a result of check_empty_circumspheres relied on validity.overlap.
bool used_lemma(const CheckResult& empty_sphere);

// quality.cpp — Theorem 1.
CheckResult check_radius_edge_ratio(const Context& c);  // quality.ratio
CheckResult check_shortest_edge(const Context& c);      // quality.shortest_edge

// conformity.cpp — §1.1, §2.1 property 1.
CheckResult check_input_vertices(const Context& c);     // conformity.vertices
CheckResult check_segments(const Context& c);           // conformity.segments
CheckResult check_facets(const Context& c);             // conformity.facets
CheckResult check_domain_volume(const Context& c);      // conformity.volume

// encroachment.cpp — §1.1, Lemma 1 invariant 1.
CheckResult check_subsegments_unencroached(const Context& c);  // encroachment.subsegments
CheckResult check_subfacets_unencroached(const Context& c);    // encroachment.subfacets

// Outward orientation of boundary face `face` (a topology face held by one tet), from the
// holder's exact orientation; nullopt if the holder is degenerate.
std::optional<Tri> outward_boundary_face(const Context& c, std::uint32_t face);

}  // namespace pdr::check
