// Surface domains: a closed polygonal surface as the surface readers return it (OFF, STL,
// PLY, OBJ, the triangles and quadrilaterals of medit .mesh and Gmsh .msh files), and its
// conversion to the Plc that pdr meshes (paper §1.1: a polyhedral domain bounded by planar
// polygonal facets).
//
// surface_to_plc, in this order, throwing InputError at the first failure (a file without
// faces is one):
//   0. repeated faces: a face whose corners are, as a set, an earlier face's (a face that
//      two closed bodies of an assembly share, each giving it) is read once;
//   0b. non-planar faces: a face of four or more corners that is not planar within half the
//      planarity tolerance (a bilinear quad of a modelling tool) is split into triangles, a
//      quad along its shorter diagonal inside it as seen along its normal, a larger face by
//      the triangulation of its diagonals of largest smallest angle in its plane's
//      projection (exact orient2d; ear clipping above 96 corners); one that cannot be split (three corners on a line,
//      a projection that is not simple) is an error (surface_split.cpp). The triangles
//      keep the face's line, marker and number;
//   1. duplicate vertices: vertices with exactly equal coordinates (STL repeats every
//      corner; -0 equals 0) become one; a coordinate that is not finite is an error;
//   2. non-degenerate faces: a face has at least 3 corners, no vertex twice (after step 1)
//      and not all corners on one line (exact, orient2d in the three axis projections);
//   3. closed surface: every edge joins two or more faces (an open edge is an error naming
//      the edge and the face that uses it); an edge of three or more (a wall between two
//      bodies, or bodies touching along it) joins no faces in the steps below, and becomes
//      a segment of the facets around it;
//   4. orientation: faces are reoriented, per connected piece, so that the two faces of
//      every edge of exactly two run along it in opposite directions (pdr's Plc has no face orientation;
//      this only lets step 5 tell a flat joint from a fold); a non-orientable surface is an
//      error;
//   5. coplanar facets: two faces sharing an edge with the same marker, each exactly planar,
//      are merged when every corner of one lies exactly on the plane of the other (exact
//      orient3d, no tolerance) and they lie on opposite sides of the edge (exact orient2d);
//      coplanar faces folded onto each other are an error. Each merged region becomes one
//      facet: its boundary loops as polygons (split at vertices a loop visits twice), and,
//      for each inner loop (one that runs against the region's orientation), a facet hole
//      point strictly inside an ear of that loop, verified exactly in every axis projection
//      in which the ear is not degenerate;
//   5b. faces coplanar within the planarity tolerance: merged regions (and single faces)
//      that share an edge and a marker, are not folded onto each other, and whose vertices
//      all lie within an eighth of the planarity tolerance (relative to the union's
//      bounding-box diagonal) of one plane are merged too, greedily in face order (the two
//      triangles of a planar quad in a rotated file are a few ulps off each other's planes;
//      kept apart they would be two facets with a segment and small angles between them).
//      This classifies imprecise input, as the domain's planarity tolerance does, which then
//      judges each facet;
//   5c. repeated facets: a facet whose boundary loops are an earlier facet's (a face two
//      bodies share, each triangulating it its own way) is read once;
//   6. vertices left only inside a merged facet (the centre of a fan, the inner vertices of
//      a finely triangulated plane) are not part of the domain and are dropped, unless
//      another facet uses them, in which case they become 1-vertex polygons of the facet.
// The Plc keeps the file order of the remaining vertices and numbers facets in the order of
// their first face. Facet lines are the lines of their first face; the facet marker is the
// faces' marker.
//
// Messages: text formats report file:line of the face or vertex; binary ones report line 0
// and the face's number. Faces are numbered from 1 in file order (medit: Triangles, then
// Quadrilaterals; Gmsh: the order of $Elements); vertices as the file numbers them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mesh/plc.hpp"

namespace pdr::io {

struct Surface {
  std::string source;                    // file name, for diagnostics
  std::vector<Point> points;
  std::vector<std::size_t> point_lines;  // one per point; 0 in binary files
  std::vector<std::int64_t> point_ids;   // the file's number of each point (messages)
  std::vector<std::uint32_t> corners;    // the faces' corners, concatenated
  std::vector<std::size_t> face_start{0};  // face f is corners[face_start[f], face_start[f+1])
  std::vector<std::size_t> face_lines;   // one per face; 0 in binary files
  std::vector<int> face_markers;         // one per face (0: none)
  std::vector<std::size_t> face_numbers;  // the file's number of each face (messages);
                                          // empty: f + 1

  std::size_t face_count() const { return face_start.size() - 1; }
  std::span<const std::uint32_t> face(std::size_t f) const {
    return {corners.data() + face_start[f], face_start[f + 1] - face_start[f]};
  }
  void add_point(const Point& p, std::size_t line, std::int64_t id) {
    points.push_back(p);
    point_lines.push_back(line);
    point_ids.push_back(id);
  }
  // The same source and points, no faces (for a step that rewrites the faces).
  Surface points_only() const {
    Surface out;
    out.source = source;
    out.points = points;
    out.point_lines = point_lines;
    out.point_ids = point_ids;
    return out;
  }
  // The file's number of face f (messages).
  std::size_t face_number(std::size_t f) const {
    return f < face_numbers.size() ? face_numbers[f] : f + 1;
  }
  void add_face(std::span<const std::uint32_t> c, std::size_t line, int marker) {
    corners.insert(corners.end(), c.begin(), c.end());
    face_start.push_back(corners.size());
    face_lines.push_back(line);
    face_markers.push_back(marker);
  }
};

// The Plc of a closed surface (every edge of two or more faces); see the steps above.
// planarity_tolerance: step 5b's (the domain analysis's default, PlcOptions).
Plc surface_to_plc(const Surface& surface, double planarity_tolerance = 1e-9);

// Surface readers, one per format; each documents its format in its file header.
Surface read_off(const std::string& path);  // off_read.cpp
Surface read_stl(const std::string& path);  // stl_read.cpp
Surface read_ply(const std::string& path);  // ply_read.cpp
Surface read_obj(const std::string& path);  // obj_read.cpp
// Gmsh .msh 2.2/4.1, ASCII or binary (gmsh.hpp): the triangles (types 2, 9, 20-25) and
// quadrilaterals (3, 10, 16) by their corners, in $Elements order, with their physical tags
// as markers; node tags number the vertices in messages. Other elements are ignored.
Surface read_gmsh_surface(const std::string& path);  // gmsh_read.cpp
// medit .mesh (medit.hpp): the Triangles, then the Quadrilaterals, with their refs as
// markers; vertices numbered from 1 in messages.
Surface read_medit_surface(const std::string& path);  // medit_read.cpp

}  // namespace pdr::io
