// medit .mesh writer (MeshVersionFormatted 2, ASCII); see medit.hpp.
#include "io/atomic_file.hpp"
#include "io/medit.hpp"
#include "io/mesh_assembly.hpp"
#include "io/text_sink.hpp"

namespace pdr::io {

void write_medit(const MeshData& mesh, const std::string& path) {
  check_writable(mesh, path);
  AtomicFile file(path);
  TextSink out(file);
  auto ref = [](const std::vector<int>& m, std::size_t i) { return m.empty() ? 0 : m[i]; };
  out.put("MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n").put_uint(mesh.points.size());
  out.put('\n');
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    const Point& p = mesh.points[i];
    out.put_double(p[0]).put(' ').put_double(p[1]).put(' ').put_double(p[2]).put(' ');
    out.put_int(ref(mesh.point_markers, i)).put('\n');
  }
  if (!mesh.faces.empty()) {
    out.put("\nTriangles\n").put_uint(mesh.faces.size()).put('\n');
    for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
      for (std::uint32_t v : mesh.faces[i]) out.put_uint(std::uint64_t{v} + 1).put(' ');
      out.put_int(ref(mesh.face_markers, i)).put('\n');
    }
  }
  out.put("\nTetrahedra\n").put_uint(mesh.tets.size()).put('\n');
  for (std::size_t i = 0; i < mesh.tets.size(); ++i) {
    for (std::uint32_t v : mesh.tets[i]) out.put_uint(std::uint64_t{v} + 1).put(' ');
    out.put_int(ref(mesh.tet_regions, i)).put('\n');
  }
  out.put("\nEnd\n");
  out.flush();
  file.commit();
}

}  // namespace pdr::io
