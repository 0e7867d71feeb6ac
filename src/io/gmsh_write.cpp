// Gmsh MSH 4.1 ASCII writer. See gmsh.hpp for the layout: one surface entity per distinct
// face marker, one volume entity per distinct tet region (physical tag = the value, none for
// 0), nodes on volume entity 1, elements in MeshData order in blocks of equal markers.
#include <algorithm>
#include <map>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/gmsh.hpp"
#include "io/mesh_assembly.hpp"
#include "io/text_sink.hpp"

namespace pdr::io {

namespace {

// Distinct values in first-appearance order, and value -> entity tag (1-based).
struct Entities {
  std::vector<int> values;
  std::map<int, int> tag_of;
  explicit Entities(const std::vector<int>& markers, bool always_one) {
    for (int m : markers)
      if (tag_of.emplace(m, static_cast<int>(values.size()) + 1).second) values.push_back(m);
    if (values.empty() && always_one) {
      values.push_back(0);
      tag_of[0] = 1;
    }
  }
};

int marker_at(const std::vector<int>& markers, std::size_t i) {
  return markers.empty() ? 0 : markers[i];
}

// Number of maximal runs of equal markers among n elements.
std::size_t count_runs(const std::vector<int>& markers, std::size_t n) {
  if (n == 0) return 0;
  if (markers.empty()) return 1;
  std::size_t runs = 1;
  for (std::size_t i = 1; i < n; ++i) runs += markers[i] != markers[i - 1];
  return runs;
}

template <class Elem>
void write_blocks(TextSink& out, int dim, int type, const std::vector<Elem>& elems,
                  const std::vector<int>& markers, const Entities& ent, std::uint64_t& id) {
  std::size_t i = 0;
  while (i < elems.size()) {
    const int m = marker_at(markers, i);
    std::size_t j = i + 1;
    while (j < elems.size() && marker_at(markers, j) == m) ++j;
    out.put_int(dim).put(' ').put_int(ent.tag_of.at(m)).put(' ').put_int(type).put(' ');
    out.put_uint(j - i).put('\n');
    for (; i < j; ++i) {
      out.put_uint(id++);
      for (std::uint32_t v : elems[i]) out.put(' ').put_uint(std::uint64_t{v} + 1);
      out.put('\n');
    }
  }
}

}  // namespace

void write_gmsh(const MeshData& mesh, const std::string& path) {
  check_writable(mesh, path);
  std::vector<int> face_markers = mesh.face_markers;
  if (face_markers.empty()) face_markers.assign(mesh.faces.size(), 0);
  std::vector<int> regions = mesh.tet_regions;
  if (regions.empty()) regions.assign(mesh.tets.size(), 0);
  const Entities surfaces(face_markers, false);
  const Entities volumes(regions, true);

  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  if (!mesh.points.empty()) {
    for (int k = 0; k < 3; ++k) lo[k] = hi[k] = mesh.points[0][k];
    for (const Point& p : mesh.points)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
  }

  AtomicFile file(path);
  TextSink out(file);
  out.put("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");

  out.put("$Entities\n0 0 ").put_uint(surfaces.values.size()).put(' ');
  out.put_uint(volumes.values.size()).put('\n');
  auto entity = [&](const Entities& ent) {
    for (std::size_t e = 0; e < ent.values.size(); ++e) {
      out.put_uint(e + 1);
      for (double b : lo) out.put(' ').put_double(b);
      for (double b : hi) out.put(' ').put_double(b);
      if (ent.values[e] != 0) out.put(" 1 ").put_int(ent.values[e]);
      else out.put(" 0");
      out.put(" 0\n");  // no bounding entities
    }
  };
  entity(surfaces);
  entity(volumes);
  out.put("$EndEntities\n");

  const std::size_t n = mesh.points.size();
  out.put("$Nodes\n");
  if (n == 0) {
    out.put("0 0 0 0\n");
  } else {
    out.put("1 ").put_uint(n).put(" 1 ").put_uint(n).put('\n');
    out.put("3 1 0 ").put_uint(n).put('\n');
    for (std::size_t i = 0; i < n; ++i) out.put_uint(i + 1).put('\n');
    for (const Point& p : mesh.points)
      out.put_double(p[0]).put(' ').put_double(p[1]).put(' ').put_double(p[2]).put('\n');
  }
  out.put("$EndNodes\n");

  const std::size_t ne = mesh.faces.size() + mesh.tets.size();
  const std::size_t blocks = count_runs(face_markers, mesh.faces.size()) +
                             count_runs(regions, mesh.tets.size());
  out.put("$Elements\n").put_uint(blocks).put(' ').put_uint(ne).put(' ');
  out.put_uint(ne == 0 ? 0 : 1).put(' ').put_uint(ne).put('\n');
  std::uint64_t id = 1;
  write_blocks(out, 2, 2, mesh.faces, face_markers, surfaces, id);
  write_blocks(out, 3, 4, mesh.tets, regions, volumes, id);
  out.put("$EndElements\n");
  out.flush();
  file.commit();
}

}  // namespace pdr::io
