// Gmsh MSH files (Gmsh reference manual, §10 "MSH file format"): versions 2.2 and 4.1,
// ASCII and binary, read; version 4.1 ASCII written.
//
// Reading: tetrahedra are the elements of types 4 (4-node), 11 (10-node), 29, 30, 31
// (higher order); their first four nodes are the corners, the other nodes are dropped
// (ReadInfo::dropped_high_order_nodes). Boundary triangles are types 2, 9, 20-25 (first three
// nodes). Every other type (points, lines, quads, hexes, prisms, pyramids) is counted in
// ReadInfo::skipped_elements; a file with no tetrahedra but other elements is rejected.
// Node tags may be sparse and in any order: points are numbered in the order of $Nodes.
// Markers: a triangle's face marker and a tet's region are the first physical tag of its
// elementary entity ($Entities in 4.1, the first element tag in 2.2), or 0 when it has
// none; MeshData gets markers only when one is non-zero. Point markers are not represented.
// Binary files must be in the host's byte order (the file's int 1 marker is checked).
// As a surface domain (read_gmsh_surface, surface.hpp) the same sections give the
// triangles and quadrilaterals (types 3, 10, 16) instead, and tetrahedra are ignored.
// Other sections ($NodeData, $Periodic, ...) are skipped.
//
// Orientation, found by experiment with Gmsh 4.8.4 (`gmsh -3` on an OpenCASCADE box and on
// a built-in-kernel box with second-order elements, in msh22, msh41, mesh and vtk formats,
// checked with a determinant on every element): every tet (a,b,c,d) of types 4 and 11 has
// det[b-a, c-a, d-a] > 0 (1125/1125, 375/375), pdr's convention, so tets are read and
// written unchanged. Triangles follow the orientation of their CAD surface (on the built-in
// box, surface 1 defined with a +z normal at z=0 gave 42/42 inward triangles while the other
// five surfaces were outward): MSH has no face convention, so faces are read as they are.
//
// Tets and triangles are returned each in the order of their element tags (the file order
// when, as Gmsh and pdr write them, the tags increase through the file). A physical group
// named "pdr marker <m>" in $PhysicalNames (placed before $Elements, as Gmsh writes it)
// stands for marker m instead of its tag.
//
// Writing (4.1 ASCII, "4.1 0 8"), in the form meshio and Gmsh both read: one surface
// entity per distinct face marker and one volume entity per distinct tet region (at least
// one), each in a physical group of its own named "pdr marker <value>" in $PhysicalNames,
// whose tag is the value when positive and otherwise the smallest positive tag that no
// other group of that dimension has (Gmsh wants positive tags; the name brings the value
// back); every node on volume entity 1; one element block per entity and element type,
// holding that entity's elements in MeshData order; element tags 1.. over the faces, then
// the tets, in MeshData order, so the reader restores MeshData's order. Point markers are
// not written.
#pragma once

#include <string>

#include "io/read_info.hpp"
#include "mesh/mesh_data.hpp"

namespace pdr::io {

MeshData read_gmsh(const std::string& path, ReadInfo* info = nullptr);

void write_gmsh(const MeshData& mesh, const std::string& path);

}  // namespace pdr::io
