// pdr.read and pdr.write (api.hpp): the io layer's readers (io::read_mesh, io::read_domain)
// and the command line's writer (app::write_outputs: every file atomic, the prefix's
// folder created), on numpy arrays.
//
// read's kind "auto" decides by the file name: .poly, .smesh, .off, .stl, .ply, .obj are
// domains; a .node file is a mesh's points when PREFIX.ele exists beside it, else a
// domain (a point set); .msh and .mesh are meshes, or surface domains when they hold no
// tet; anything else (.ele, .vtu, a bare PREFIX) is a mesh.
#include <array>
#include <filesystem>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "api.hpp"
#include "app/pipeline.hpp"
#include "arrays.hpp"
#include "io/mesh_io.hpp"

namespace pdr::python {

namespace {

namespace fs = std::filesystem;

bool is_domain_extension(const std::string& ext) {
  for (const char* e : {".poly", ".smesh", ".off", ".stl", ".ply", ".obj"})
    if (ext == e) return true;
  return false;
}

py::dict mesh_dict(const MeshData& mesh, const std::string& path, const io::ReadInfo& info) {
  py::dict d = from_mesh(mesh);
  d["kind"] = "mesh";
  d["source"] = path;
  d["skipped_elements"] = info.skipped_elements;
  d["dropped_high_order_nodes"] = info.dropped_high_order_nodes;
  return d;
}

}  // namespace

py::dict read(const py::object& path_obj, const std::string& kind) {
  if (kind != "auto" && kind != "mesh" && kind != "domain")
    throw py::value_error("read: kind is 'auto', 'mesh' or 'domain', not '" + kind + "'");
  const std::string path = to_path(path_obj);
  if (kind == "domain") return from_plc(io::read_domain(path));
  const fs::path p(path);
  const std::string ext = p.extension().string();
  if (kind == "auto" && (is_domain_extension(ext) ||
                         (ext == ".node" && !fs::exists(fs::path(p).replace_extension(".ele")))))
    return from_plc(io::read_domain(path));
  io::ReadInfo info;
  const MeshData mesh = io::read_mesh(path, &info);
  if (kind == "auto" && mesh.tets.empty() && (ext == ".msh" || ext == ".mesh"))
    return from_plc(io::read_domain(path));
  return mesh_dict(mesh, path, info);
}

py::list write(const py::object& path_or_prefix, const py::object& points,
               const py::object& tets, const py::object& faces, const py::object& formats,
               const py::object& face_markers) {
  std::string prefix = to_path(path_or_prefix);
  std::vector<std::string> names;
  if (!formats.is_none()) {
    if (py::isinstance<py::str>(formats)) {
      // "node,vtu", as --formats takes it.
      std::istringstream s(formats.cast<std::string>());
      for (std::string name; std::getline(s, name, ',');) names.push_back(name);
    } else {
      for (const py::handle f : py::iter(formats)) names.push_back(py::str(f));
    }
  } else {
    // The format from the file name, or the command's default formats for a bare prefix.
    static const std::array<std::pair<const char*, const char*>, 5> by_extension{
        {{".node", "node"}, {".ele", "node"}, {".vtu", "vtu"}, {".msh", "msh"}, {".mesh", "mesh"}}};
    fs::path p(prefix);
    for (const auto& [ext, name] : by_extension)
      if (p.extension() == ext) names.push_back(name);
    if (names.empty()) {
      names = app::MeshArgs{}.formats;
    } else {
      prefix = p.replace_extension().string();
    }
  }
  const auto fmts = app::parse_formats(names);

  MeshData mesh;
  mesh.points = to_points(points, "points");
  mesh.tets = to_tets(tets, "tets");
  mesh.faces = to_tris(faces, "faces");
  mesh.face_markers = to_ints(face_markers, "face_markers");
  app::PhaseTimer timer;
  app::Summary summary;
  {
    py::gil_scoped_release unlocked;
    app::write_outputs(mesh, prefix, fmts, timer, summary);
  }
  return from_json(summary.to_json().at("written"));
}

}  // namespace pdr::python
