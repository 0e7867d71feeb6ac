// The entry points of pdr_io: read a mesh or a domain by file name, write a mesh in a set
// of formats. Format-specific readers and writers (tetgen.hpp, gmsh.hpp, medit.hpp,
// vtu.hpp) document each format's layout and orientation convention; every reader returns
// pdr's conventions (0-based indices, det[b-a, c-a, d-a] > 0 for a tet the file stores as
// positive, outward face normals where the format has a face convention) and never repairs
// individual elements: the checker sees what the file says.
//
// Errors: malformed input throws InputError ("file:line: problem; what to do"); output
// failures throw std::system_error; an inconsistent MeshData given to a writer throws
// std::invalid_argument before any file is created. Output is atomic per file (and per
// TetGen file set): a failed write leaves no partial file and no temporary behind.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/error.hpp"
#include "io/read_info.hpp"
#include "io/vtu.hpp"
#include "mesh/mesh_data.hpp"
#include "mesh/plc.hpp"

namespace pdr::io {

// `path` is a file with extension .ele or .node (TetGen: PREFIX.node + PREFIX.ele
// [+ PREFIX.face]), .msh (Gmsh 2.2/4.1), .mesh (medit) or .vtu (VTK XML); or a prefix
// PREFIX for which PREFIX.ele and PREFIX.node exist.
MeshData read_mesh(const std::string& path, ReadInfo* info = nullptr);

// `path` is a .poly or .smesh file (a PLC), a .node file (a bare point set, no facets), or
// a closed surface (.off, .stl, .ply, .obj, .mesh, .msh), converted by surface_to_plc
// (surface.hpp) with `planarity_tolerance` (the domain analysis's, domain::PlcOptions).
Plc read_domain(const std::string& path, double planarity_tolerance = 1e-9);

enum class MeshFormat { TetGen, Vtu, Msh, Medit };

// "node" (or "tetgen", "ele"), "vtu", "msh", "mesh" (or "medit"); throws
// std::invalid_argument naming the accepted names otherwise.
MeshFormat parse_mesh_format(std::string_view name);

// The file(s) write_mesh writes for `format`: PREFIX.node/.ele/.face, PREFIX.vtu,
// PREFIX.msh, PREFIX.mesh.
std::vector<std::string> output_paths(const std::string& prefix, MeshFormat format);

// Writes `mesh` in each of `formats` under `prefix`. Cell fields (one value per tet) and
// point fields go to the .vtu output only. The mesh and the fields are checked before any
// file is written (std::invalid_argument). The formats, and TetGen's three files, are
// formatted concurrently (io/tasks.hpp); the first failure is rethrown once all ended.
void write_mesh(const MeshData& mesh, const std::string& prefix,
                std::span<const MeshFormat> formats,
                const std::vector<CellField>& cell_fields = {},
                const std::vector<PointField>& point_fields = {});

}  // namespace pdr::io
