// read_mesh, read_domain and write_mesh: dispatch on the file extension; see mesh_io.hpp.
#include "io/mesh_io.hpp"

#include <functional>
#include <stdexcept>
#include <vector>

#include "io/file_bytes.hpp"
#include "io/gmsh.hpp"
#include "io/medit.hpp"
#include "io/surface.hpp"
#include "io/mesh_assembly.hpp"
#include "io/tasks.hpp"
#include "io/tetgen.hpp"

namespace pdr::io {

MeshData read_mesh(const std::string& path, ReadInfo* info) {
  const std::string ext = lower_extension(path);
  if (ext == ".ele" || ext == ".node") return read_tetgen_mesh(strip_extension(path), info);
  if (ext == ".msh") return read_gmsh(path, info);
  if (ext == ".mesh") return read_medit(path, info);
  if (ext == ".vtu") return read_vtu(path, info);
  if (is_regular_file(path + ".ele") && is_regular_file(path + ".node"))
    return read_tetgen_mesh(path, info);
  if (ext == ".meshb")
    throw InputError(path, 0, "binary medit (.meshb) is not supported; convert it to ASCII "
                              ".mesh (e.g. gmsh FILE.meshb -0 -o FILE.mesh)");
  if (ext == ".vtk")
    throw InputError(path, 0, "legacy VTK (.vtk) is not supported; save the mesh as .vtu or "
                              ".msh");
  throw InputError(path, 0, "unknown mesh format: expected PREFIX (with PREFIX.node and "
                            "PREFIX.ele), or a .ele, .node, .msh, .mesh or .vtu file");
}

Plc read_domain(const std::string& path, double planarity_tolerance) {
  const std::string ext = lower_extension(path);
  if (ext == ".poly") return read_tetgen_poly(path);
  if (ext == ".smesh") return read_tetgen_smesh(path);
  if (ext == ".node") return read_tetgen_node_domain(path);
  const double tol = planarity_tolerance;
  if (ext == ".off") return surface_to_plc(read_off(path), tol);
  if (ext == ".stl") return surface_to_plc(read_stl(path), tol);
  if (ext == ".ply") return surface_to_plc(read_ply(path), tol);
  if (ext == ".obj") return surface_to_plc(read_obj(path), tol);
  if (ext == ".msh") return surface_to_plc(read_gmsh_surface(path), tol);
  if (ext == ".mesh") return surface_to_plc(read_medit_surface(path), tol);
  throw InputError(path, 0, "unknown domain format: expected a .poly, .smesh, .node, .off, "
                            ".stl, .ply, .obj, .mesh or .msh file");
}

MeshFormat parse_mesh_format(std::string_view name) {
  if (name == "node" || name == "tetgen" || name == "ele") return MeshFormat::TetGen;
  if (name == "vtu") return MeshFormat::Vtu;
  if (name == "msh") return MeshFormat::Msh;
  if (name == "mesh" || name == "medit") return MeshFormat::Medit;
  throw std::invalid_argument("unknown mesh format '" + std::string(name) +
                              "'; use node, vtu, msh or mesh");
}

std::vector<std::string> output_paths(const std::string& prefix, MeshFormat format) {
  switch (format) {
    case MeshFormat::TetGen: return {prefix + ".node", prefix + ".ele", prefix + ".face"};
    case MeshFormat::Vtu: return {prefix + ".vtu"};
    case MeshFormat::Msh: return {prefix + ".msh"};
    case MeshFormat::Medit: return {prefix + ".mesh"};
  }
  return {};
}

void write_mesh(const MeshData& mesh, const std::string& prefix,
                std::span<const MeshFormat> formats, const std::vector<CellField>& cell_fields,
                const std::vector<PointField>& point_fields) {
  // Refuse an inconsistent mesh or field before any format is written.
  check_writable(mesh, prefix);
  for (const CellField& f : cell_fields)
    if (f.values.size() != mesh.tets.size())
      throw std::invalid_argument("cannot write '" + prefix + "': cell field '" + f.name +
                                  "' does not have one value per tet");
  for (const PointField& f : point_fields)
    if (f.values.size() != mesh.points.size())
      throw std::invalid_argument("cannot write '" + prefix + "': point field '" + f.name +
                                  "' does not have one value per point");
  // One task per format (io/tasks.hpp): the formats are independent files.
  std::vector<std::function<void()>> tasks;
  for (MeshFormat f : formats)
    tasks.emplace_back([&, f] {
      switch (f) {
        case MeshFormat::TetGen: write_tetgen_mesh(mesh, prefix); break;
        case MeshFormat::Vtu: write_vtu(mesh, prefix + ".vtu", cell_fields, point_fields); break;
        case MeshFormat::Msh: write_gmsh(mesh, prefix + ".msh"); break;
        case MeshFormat::Medit: write_medit(mesh, prefix + ".mesh"); break;
      }
    });
  run_tasks(tasks);
}

}  // namespace pdr::io
