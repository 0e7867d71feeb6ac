// Gmsh MSH 4.1 ASCII writer. See gmsh.hpp for the layout: one surface entity per distinct
// face marker and one volume entity per distinct tet region, each in a physical group of its
// own (named "pdr marker <value>"), nodes on volume entity 1, one element block per entity
// with its elements in MeshData order, element tags in MeshData order (faces, then tets).
#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/gmsh.hpp"
#include "io/mesh_assembly.hpp"
#include "io/text_sink.hpp"

namespace pdr::io {

namespace {

// The entities of one dimension: distinct marker values in first-appearance order (entity
// tag e + 1 holds values[e]), the elements of each, and each one's physical tag: the value
// itself when positive, otherwise the smallest positive tag no other entity has.
struct Entities {
  std::vector<int> values;
  std::vector<int> physical;
  std::vector<std::vector<std::uint32_t>> members;
  Entities(const std::vector<int>& markers, std::size_t n, bool always_one) {
    std::map<int, std::size_t> index;
    for (std::size_t i = 0; i < n; ++i) {
      const int m = markers.empty() ? 0 : markers[i];
      const auto [it, added] = index.emplace(m, values.size());
      if (added) {
        values.push_back(m);
        members.emplace_back();
      }
      members[it->second].push_back(static_cast<std::uint32_t>(i));
    }
    if (values.empty() && always_one) {
      values.push_back(0);
      members.emplace_back();
    }
    std::set<int> taken;
    for (int v : values)
      if (v > 0) taken.insert(v);
    int next = 1;
    for (int v : values) {
      if (v > 0) {
        physical.push_back(v);
        continue;
      }
      while (taken.count(next)) ++next;
      physical.push_back(next++);
    }
  }
  std::size_t blocks() const {
    return static_cast<std::size_t>(std::count_if(
        members.begin(), members.end(), [](const auto& m) { return !m.empty(); }));
  }
};

// One block per non-empty entity; element tag = first_tag + index in MeshData.
template <class Elem>
void write_blocks(TextSink& out, int dim, int type, const std::vector<Elem>& elems,
                  const Entities& ent, std::uint64_t first_tag) {
  for (std::size_t e = 0; e < ent.values.size(); ++e) {
    if (ent.members[e].empty()) continue;
    out.put_int(dim).put(' ').put_uint(e + 1).put(' ').put_int(type).put(' ');
    out.put_uint(ent.members[e].size()).put('\n');
    for (std::uint32_t i : ent.members[e]) {
      out.put_uint(first_tag + i);
      for (std::uint32_t v : elems[i]) out.put(' ').put_uint(std::uint64_t{v} + 1);
      out.put('\n');
    }
  }
}

}  // namespace

void write_gmsh(const MeshData& mesh, const std::string& path) {
  check_writable(mesh, path);
  const Entities surfaces(mesh.face_markers, mesh.faces.size(), false);
  const Entities volumes(mesh.tet_regions, mesh.tets.size(), true);

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
  out.put("$PhysicalNames\n").put_uint(surfaces.values.size() + volumes.values.size());
  out.put('\n');
  for (const auto& [dim, ent] : {std::pair{2, &surfaces}, std::pair{3, &volumes}})
    for (std::size_t e = 0; e < ent->values.size(); ++e) {
      out.put_int(dim).put(' ').put_int(ent->physical[e]).put(" \"pdr marker ");
      out.put_int(ent->values[e]).put("\"\n");
    }
  out.put("$EndPhysicalNames\n");

  out.put("$Entities\n0 0 ").put_uint(surfaces.values.size()).put(' ');
  out.put_uint(volumes.values.size()).put('\n');
  auto entity = [&](const Entities& ent) {
    for (std::size_t e = 0; e < ent.values.size(); ++e) {
      out.put_uint(e + 1);
      for (double b : lo) out.put(' ').put_double(b);
      for (double b : hi) out.put(' ').put_double(b);
      out.put(" 1 ").put_int(ent.physical[e]);
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
  out.put("$Elements\n").put_uint(surfaces.blocks() + volumes.blocks()).put(' ').put_uint(ne);
  out.put(' ').put_uint(ne == 0 ? 0 : 1).put(' ').put_uint(ne).put('\n');
  write_blocks(out, 2, 2, mesh.faces, surfaces, 1);
  write_blocks(out, 3, 4, mesh.tets, volumes, 1 + mesh.faces.size());
  out.put("$EndElements\n");
  out.flush();
  file.commit();
}

}  // namespace pdr::io
