// PREFIX.pvtu and its pieces (see partitioned_output.hpp).
#include "app/partitioned_output.hpp"

#include <algorithm>
#include <bit>
#include <filesystem>
#include <memory>

#include "io/atomic_file.hpp"
#include "io/vtu.hpp"

namespace pdr::app {

std::size_t PointHash::operator()(const Point& p) const {
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for (double x : p) h = (h ^ std::bit_cast<std::uint64_t>(x)) * 0x100000001B3ull + (h >> 29);
  return static_cast<std::size_t>(h);
}

std::vector<std::uint32_t> tet_owners(const MeshData& mesh, const VertexOwners& owners) {
  std::vector<std::uint32_t> owner(mesh.tets.size(), 0);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const Point* best[2] = {nullptr, nullptr};  // smallest committed, smallest initial
    std::uint32_t rank[2] = {0, 0};
    for (std::uint32_t v : mesh.tets[t]) {
      const Point& p = mesh.points[v];
      for (int k = 0; k < 2; ++k) {
        const auto& map = k == 0 ? owners.committed : owners.initial;
        const auto it = map.find(p);
        if (it != map.end() && (!best[k] || p < *best[k])) best[k] = &p, rank[k] = it->second;
      }
    }
    owner[t] = best[0] ? rank[0] : (best[1] ? rank[1] : 0);
  }
  return owner;
}

std::vector<std::string> write_partitioned_vtu(const MeshData& mesh,
                                               const std::vector<std::uint32_t>& owner,
                                               int parts, const std::string& prefix) {
  const std::string name = std::filesystem::path(prefix).filename().string();
  std::vector<std::string> paths;
  std::vector<std::unique_ptr<io::AtomicFile>> files;
  // A piece: the tets of one rank, their points renumbered; written through write_vtu to a
  // temporary path, renamed with the rest.
  for (int r = 0; r < parts; ++r) {
    MeshData piece;
    std::vector<std::uint32_t> local(mesh.points.size(), UINT32_MAX);
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      if (owner[t] != static_cast<std::uint32_t>(r)) continue;
      Tet k = mesh.tets[t];
      for (auto& v : k) {
        if (local[v] == UINT32_MAX) {
          local[v] = static_cast<std::uint32_t>(piece.points.size());
          piece.points.push_back(mesh.points[v]);
        }
        v = local[v];
      }
      piece.tets.push_back(k);
    }
    const std::string path = prefix + "_p" + std::to_string(r) + ".vtu";
    files.push_back(std::make_unique<io::AtomicFile>(path));
    files.back()->close();  // the temporary exists; write_vtu fills it
    io::write_vtu(piece, files.back()->temp_path(),
                  {{"owner", std::vector<double>(piece.tets.size(), static_cast<double>(r))}});
    paths.push_back(path);
  }
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <PUnstructuredGrid GhostLevel=\"0\">\n"
      "    <PCellData Scalars=\"owner\">\n"
      "      <PDataArray type=\"Float64\" Name=\"owner\"/>\n"
      "    </PCellData>\n"
      "    <PPoints>\n"
      "      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n"
      "    </PPoints>\n";
  for (int r = 0; r < parts; ++r) xml += "    <Piece Source=\"" + name + "_p" + std::to_string(r) + ".vtu\"/>\n";
  xml += "  </PUnstructuredGrid>\n</VTKFile>\n";
  files.push_back(std::make_unique<io::AtomicFile>(prefix + ".pvtu"));
  files.back()->write(xml);
  paths.push_back(prefix + ".pvtu");
  std::vector<io::AtomicFile*> all;
  for (auto& f : files) all.push_back(f.get());
  io::commit_all(all);
  return paths;
}

}  // namespace pdr::app
