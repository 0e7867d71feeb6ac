// Subfacets a tet of T asks to refine (issue #3: facets a few ulps off their planes).
//
// 1. Flat tets on a facet: a tet whose four vertices all lie on one facet of D, or on
//    facets of one coplanar group (domain/coplanar.cpp: facets across a segment coplanar
//    within the planarity tolerance form one group). On an exactly
//    planar facet with exactly coplanar vertices such a tet cannot exist (its orientation
//    would be zero). On a tilted facet rounding puts constructed vertices a few ulps off the
//    plane, and a near-cocircular quadruple a, b, c, d of the facet may then be a Delaunay
//    sliver of T: two of its faces are subfacets (the facet's choice of diagonal,
//    surface/chart.hpp), the other two lie on the facet too. On the domain's side it is a
//    tet of the mesh with volume within rounding of zero and faces on the facet that are not
//    subfacets.
// 2. Encroached subfacet faces: a subfacet face abc of the tet whose equatorial ball
//    strictly holds the tet's fourth vertex x. In exact arithmetic Lemma 1 excludes it; a
//    vertex rounded onto a tilted facet can end a hair inside the equatorial sphere of a
//    subfacet of a neighbouring facet that it is exactly on in the unrounded geometry.
//    Completeness: if abc is a face of T and a vertex x off abc's plane is strictly inside
//    its equatorial ball, x is the apex of the tet on abc on x's side (every sphere through
//    a, b, c centred on that side holds the part of the equatorial ball on that side, so
//    the tet's circumsphere would hold x otherwise); scanning the tets therefore finds
//    every such pair.
// Either way the refinement treats the tet as bad and refines the subfacet at its
// circumcenter (Fig. 2 Refine(f) for an encroached subfacet). For (1) that point is within
// rounding of the centre of the subfacet's equatorial sphere, so strictly inside the
// sliver's circumsphere (centred on the subfacet's axis): the sliver is gone. For (2) the
// subfacet is gone. Refinement repairs (2) at once, within each insertion step and before
// its Lemma 1 audit (refine/seq_refinement.cpp), and through the bad-tet queue as a fallback. Each
// step inserts a vertex; the refinement's vertex cap bounds them.
// The protected length (refine/split.hpp) does not stop a repair of (1): it ends the
// encroachment cascade between features that meet at a small angle, a geometric cause,
// while a flat tet is rounding's (a near-cocircular quadruple of one plane). Near an acute
// vertex the quadruple's circumcenter may encroach a subsegment already at the protected
// length; refusing that split left the sliver in the mesh, inside the domain with two
// faces on the facet that are not subfacets (a rotated torus of triangle facets:
// tests/regress/outside-*torus*). The repair's splits keep the concentric shells. (2)
// can be geometric too (subfacets of two facets at a sharp dihedral encroach each other
// at every scale), so the floor applies to it.
// A repair of (1) is refused below the facet's planarity gap (SurfaceFacet::gap: how far
// its input vertices lie off the plane its new vertices go on; 0 on exact facets). The
// facet's segments run up to the gap off that plane, so at that scale the subfacets next to
// a segment are tilted by gap / size: a tet with its four vertices on the facet is then the
// facet's own bend, not rounding, and each repair made another beside the last (a 3-degree
// notch printed with 7 digits: 72,000 repairs around a few vertices of one wall at
// circumradii of 1e-9 to 4e-12, and no end). Such a tet stays, listed.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "refine/volume_mesh.hpp"

namespace pdr::refine {

// The subfacet of largest circumradius among the faces of finite tet t that are
// subfacets of a facet f with (1) the fourth vertex a vertex of the triangulation of f or
// of a facet in f's coplanar group, or (2)
// the fourth vertex strictly inside the subfacet's equatorial ball; nullopt if none.
std::optional<std::uint32_t> subfacet_to_refine(const VolumeMesh& m, TetId t);
// The same for (2) alone.
std::optional<std::uint32_t> encroached_subfacet_face(const VolumeMesh& m, TetId t);
// The same for (1) alone: t is a flat tet on a facet (or coplanar group).
std::optional<std::uint32_t> flat_subfacet_face(const VolumeMesh& m, TetId t);
// Both in one scan: `flat` as flat_subfacet_face, `any` as subfacet_to_refine.
struct SubfacetPicks {
  std::optional<std::uint32_t> flat, any;
};
SubfacetPicks subfacets_to_refine(const VolumeMesh& m, TetId t);

// Why the repair of a flat tet on subfacet f is refused: f's circumradius is below its
// facet's planarity gap (above); empty when it may go in.
std::string within_planarity_gap(const SurfaceMesh& s, std::uint32_t f);

}  // namespace pdr::refine
