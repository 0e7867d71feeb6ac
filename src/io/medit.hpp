// medit / INRIA .mesh files (libMeshb's ASCII form, as written by Gmsh, MMG, TetGen -g),
// read and written.
//
// Layout: "MeshVersionFormatted <1|2>", "Dimension 3", then sections "<Keyword> <n>"
// followed by n entities: Vertices "x y z ref", Triangles "a b c ref", Tetrahedra
// "a b c d ref" (1-based indices), ..., and "End". Keywords are case-insensitive; tokens may
// be split over lines freely; '#' starts a comment. TetrahedraP2 and TrianglesP2 are read
// by their corners (the mid-edge nodes dropped, ReadInfo); Edges, Quadrilaterals, Hexahedra,
// Prisms, Pyramids and the Corners/Ridges/Required*/Normals/Tangents lists are skipped
// (elements counted in ReadInfo). A file with no tetrahedra but other elements is rejected.
// As a surface domain (read_medit_surface, surface.hpp) the Triangles and then the
// Quadrilaterals are the faces, their refs the markers, and tetrahedra are ignored.
// Binary .meshb is not supported.
//
// Markers: a vertex ref is the point marker, a triangle ref the face marker, a tet ref the
// region; MeshData gets them only when one is non-zero (medit always stores a ref).
//
// Orientation: the format states none. Found by experiment: Gmsh 4.8.4's `-format mesh`
// output of a box has det[b-a, c-a, d-a] > 0 for all 1125 tets (and MMG requires positive
// volumes), pdr's convention: tets are read and written unchanged; triangles likewise (no
// convention; Gmsh's followed its surfaces' orientation).
//
// Writing: "MeshVersionFormatted 2" (double precision), shortest round-trip doubles, refs 0
// where MeshData has no markers; Triangles only when there are faces.
#pragma once

#include <string>

#include "io/read_info.hpp"
#include "mesh/mesh_data.hpp"

namespace pdr::io {

MeshData read_medit(const std::string& path, ReadInfo* info = nullptr);

void write_medit(const MeshData& mesh, const std::string& path);

}  // namespace pdr::io
