// SurfaceMesh: the conforming surface triangulation D of paper §1.1 / §2.1 ("a Delaunay
// surface triangulation D(∂Ω) consisting of the refined segments and facets of ∂Ω").
//
// Contents:
//   - vertices: the input vertices first, with the same ids as the Plc, then the added
//     ones; each has a Home: the input vertex itself, the interior of segment s, or the
//     interior of facet f;
//   - subsegments: each segment (domain::DomainSegment, same ids) is a chain of subsegments from
//     its vertex a to its vertex b; a subsegment id is stable: splitting s = (u, w) at m
//     turns s into (u, m) and appends (m, w);
//   - subfacets: per face (domain::DomainFacet with is_face, same ids) a triangulation of the
//     facet's vertices restricted to the facet, each subfacet counter-clockwise in the
//     facet's chart (surface/chart.hpp), with neighbours across its edges in the same facet
//     and a mark on the edges that are subsegments (a facet cavity never crosses those).
//     Dead subfacets stay in the array (alive = false) and their slots are reused.
// Invariants kept by the operations (surface/split.hpp, surface/insert.hpp) and checked by
// audit_surface (surface/audit.hpp): chains cover their segments; each facet's subfacets
// tile the facet and conform to its subsegments; neighbours agree; the incidence lists
// below list exactly the live subfacets and the subsegments at each vertex.
// The mesh holds no reference to the domain: it copies what the operations and the audit
// need (segments with their facets, facet charts and boundaries, source lines).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "domain/distance.hpp"
#include "geom/point.hpp"
#include "surface/chart.hpp"

namespace pdr::surface {

// A failure of the surface mesh construction (the guard, or a degenerate case the exact
// arguments exclude); the message starts with the name of the invariant or step.
class SurfaceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The surface mesh reached its vertex cap (surface/init.hpp): a resource limit, not a bug;
// the command line reports it as a run that could not be finished (exit 3).
class SurfaceCapError : public SurfaceError {
 public:
  using SurfaceError::SurfaceError;
};

enum class HomeKind : std::uint8_t { Input, Segment, Facet };

struct Home {
  HomeKind kind = HomeKind::Input;
  std::uint32_t id = 0;  // Input: the vertex id; Segment: segment id; Facet: facet id
};

struct Subsegment {
  std::array<std::uint32_t, 2> v{};  // v[0] is nearer the segment's vertex a
  std::uint32_t segment = 0;
};

struct Subfacet {
  std::array<std::uint32_t, 3> v{};             // counter-clockwise in the facet's chart
  std::array<std::int32_t, 3> nbr{-1, -1, -1};  // across the edge opposite v[i]; -1: none
  std::array<bool, 3> constrained{};            // the edge opposite v[i] is a subsegment
  std::uint32_t facet = 0;
  bool alive = true;
};

struct SurfaceSegment {
  std::uint32_t a = 0, b = 0;          // input vertices, a < b
  std::vector<std::uint32_t> facets;   // faces containing the segment, sorted
};

// A boundary edge of a facet's region: segment `segment`, traversed from a to b when
// `forward` (else b to a) with the facet on its left in the chart.
struct BoundarySide {
  std::uint32_t segment = 0;
  bool forward = true;
};

struct SurfaceFacet {
  bool is_face = false;                 // facets without area have no subfacets
  FacetChart chart;                     // valid when is_face
  std::uint32_t plane_group = 0;        // domain::DomainFacet::plane_group: facets of one
                                        // group are one plane to refine/flat.hpp's rule 1
  std::vector<std::uint32_t> segments;  // segments contained in the facet, sorted
  std::vector<BoundarySide> boundary;   // the region's boundary, as segments
  std::size_t line = 0;                 // source line of the facet, for diagnostics
  bool separates = true;                // domain::DomainFacet::separates: Ω on one side
                                        // only (false: an internal facet, Ω on both)
  double gap = 0;                       // the largest distance of its input vertices from
                                        // the chart's plane (0 when exactly planar)
};

class SurfaceMesh {
 public:
  std::string source;                    // input file name, for diagnostics
  double d = 0;                          // paper §2.1 d the mesh was refined for (0: none)
  // The graded initial mesh (surface/init.hpp): the d each segment and each facet was
  // refined for; empty when the mesh is uniform (every one is d).
  std::vector<double> segment_d, facet_d;
  double segment_size(std::uint32_t s) const { return segment_d.empty() ? d : segment_d[s]; }
  double facet_size(std::uint32_t f) const { return facet_d.empty() ? d : facet_d[f]; }
  // Graded by position (surface/init.hpp): where the sizes at a point come from; null for
  // a uniform mesh. subsegment_size and subfacet_size are the d an element is refined for:
  // at its midpoint or circumcenter when graded, else d.
  std::shared_ptr<const domain::UnrelatedDistance> sizer;
  double subsegment_size(std::uint32_t s) const;
  double subfacet_size(std::uint32_t t) const;
  std::vector<SurfaceSegment> segments;  // parallel to domain::PlcDomain::segments
  std::vector<SurfaceFacet> facets;      // parallel to domain::PlcDomain::facets

  // Read access.
  std::size_t vertex_count() const { return points_.size(); }
  const Point& point(std::uint32_t v) const { return points_[v]; }
  const std::vector<Point>& points() const { return points_; }
  Home home(std::uint32_t v) const { return homes_[v]; }
  const std::vector<Subsegment>& subsegments() const { return subsegments_; }
  const Subsegment& subsegment(std::uint32_t s) const { return subsegments_[s]; }
  const std::vector<Subfacet>& subfacets() const { return subfacets_; }
  const Subfacet& subfacet(std::uint32_t t) const { return subfacets_[t]; }
  std::size_t live_subfacets() const { return subfacets_.size() - free_.size(); }
  // Incidences (unordered).
  const std::vector<std::uint32_t>& vertex_subsegments(std::uint32_t v) const { return vsegs_[v]; }
  const std::vector<std::uint32_t>& vertex_subfacets(std::uint32_t v) const { return vtris_[v]; }

  // The subsegment with endpoints u and w, if any.
  std::optional<std::uint32_t> find_subsegment(std::uint32_t u, std::uint32_t w) const;
  // The live subfacet with vertices {a, b, c} (any facet), if any.
  std::optional<std::uint32_t> find_subfacet(std::uint32_t a, std::uint32_t b, std::uint32_t c) const;
  // The live subfacets of facet f having edge {u, w} (one or two).
  std::vector<std::uint32_t> subfacets_on_edge(std::uint32_t f, std::uint32_t u,
                                               std::uint32_t w) const;
  // The vertices of segment s in order from its a to its b (follows the chain).
  std::vector<std::uint32_t> chain(std::uint32_t s) const;
  // The live subfacets of facet f, in increasing id (linear in their number).
  std::vector<std::uint32_t> facet_subfacets(std::uint32_t f) const;
  // "facet 3 (box.poly:40)".
  std::string facet_name(std::uint32_t f) const;
  std::string segment_name(std::uint32_t s) const;

  // Mutation, for the operations (they keep the invariants above).
  std::uint32_t add_vertex(const Point& p, Home home);
  std::uint32_t add_subsegment(std::uint32_t u, std::uint32_t w, std::uint32_t segment);
  // Turns subsegment s = (u, w) into (u, m) and appends (m, w); returns the new id.
  std::uint32_t split_subsegment_record(std::uint32_t s, std::uint32_t m);
  // Stores t (alive) in a free slot and lists it at its vertices; neighbours are the
  // caller's business.
  std::uint32_t add_subfacet(const Subfacet& t);
  void kill_subfacet(std::uint32_t t);
  Subfacet& subfacet_mut(std::uint32_t t) { return subfacets_[t]; }

 private:
  std::vector<Point> points_;
  std::vector<Home> homes_;
  std::vector<Subsegment> subsegments_;
  std::vector<Subfacet> subfacets_;
  std::vector<std::uint32_t> free_;  // dead subfacet slots
  std::vector<std::vector<std::uint32_t>> vsegs_, vtris_;
  // Per facet its live subfacets (unordered), and per subfacet slot its index there: a
  // scan of every subfacet per facet made the build of a scanned bust's 100K triangles,
  // and each walk that left a non-convex facet, linear in the whole surface.
  std::vector<std::vector<std::uint32_t>> ftris_;
  std::vector<std::uint32_t> fpos_;
};

// The index of vertex v in subfacet t (precondition: v is a vertex of t).
int vertex_index(const Subfacet& t, std::uint32_t v);
// The index i such that the edge opposite v[i] is {u, w}, or -1.
int edge_index(const Subfacet& t, std::uint32_t u, std::uint32_t w);

}  // namespace pdr::surface
