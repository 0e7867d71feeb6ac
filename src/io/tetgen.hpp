// TetGen file formats (TetGen 1.6 manual, §5.2): domains (.node, .poly, .smesh) and meshes
// (.node + .ele + optional .face).
//
// Index base: the first point index in a .node section (0 or 1) fixes the base of every
// index in the .node/.poly/.smesh/.ele/.face files that refer to it (TetGen's own rule;
// `tetgen -z` writes 0-based files, plain `tetgen` 1-based). Points must be numbered
// consecutively. Everything returned is 0-based.
//
// Orientation, found by experiment with TetGen 1.6 (`tetgen -pq1.4a0.05 box.poly`, also with
// -o2, -nn and a cube with a cubic void, checked with a determinant on every element):
//   - .ele: every tet (a,b,c,d) has det[b-a, c-a, d-a] > 0 (130/130, 562/562, 1454/1454):
//     the same as pdr's convention, so tets are read and written as they are.
//   - .face: for every boundary face (a,b,c) of tet t, the fourth vertex d of t has
//     det[b-a, c-a, d-a] > 0 (452 outer and 114 void faces of 566): the normal (b-a)x(c-a)
//     points INTO the mesh. pdr's faces point out, so the readers swap b and c of every
//     face and the writer swaps them back (format-wide mapping, never per face).
//
// Layout details read: .node "<#points> [3 [<#attributes> [<0|1 markers>]]]" then
// "<i> <x> <y> <z> <attributes...> [<marker>]"; attributes are skipped. .ele
// "<#tets> [<4|10> [<#attributes>]]" then "<i> <v1..v4|v1..v10> <attributes...>"; the first
// attribute becomes MeshData::tet_regions when every tet's first attribute is an integer
// (TetGen -A writes region numbers there), otherwise regions are left empty. .face
// "<#faces> [<0|1 markers>]" then "<i> <v1 v2 v3> [<v4 v5 v6> (-o2)] [<marker>] [<adj tet
// 1> <adj tet 2> (-nn)]". Mid-edge nodes of 10-node tets are dropped (ReadInfo).
// A polygon of a .poly facet must be on one line; '#' starts a comment.
//
// The writer writes 1-based files with a first index of 1, as `tetgen` does by default:
// .node with a marker column iff point_markers is non-empty, .ele with one attribute column
// iff tet_regions is non-empty, .face (always, with 0 faces when faces is empty, so that a stale .face never pairs with
// the new files) with a marker column iff face_markers is non-empty. The three files are committed together (AtomicFile).
#pragma once

#include <string>
#include <vector>

#include "io/read_info.hpp"
#include "mesh/mesh_data.hpp"
#include "mesh/plc.hpp"

namespace pdr::io {

// A .node file's points alone (attributes and markers are checked, then ignored).
std::vector<Point> read_tetgen_points(const std::string& node_path);

// A .node file as a domain: points and markers, no facets.
Plc read_tetgen_node_domain(const std::string& node_path);

// A .poly file: nodes (or, when its node section has 0 points, the sibling .node file),
// facets with polygons, facet holes and markers, volume holes, regions.
Plc read_tetgen_poly(const std::string& poly_path);

// A .smesh file: like .poly but each facet is one polygon "<n> <v1..vn> [<marker>]".
Plc read_tetgen_smesh(const std::string& smesh_path);

// PREFIX.node + PREFIX.ele (+ PREFIX.face when it exists).
MeshData read_tetgen_mesh(const std::string& prefix, ReadInfo* info = nullptr);

// Writes PREFIX.node, PREFIX.ele and PREFIX.face, all or none.
void write_tetgen_mesh(const MeshData& mesh, const std::string& prefix);

}  // namespace pdr::io
