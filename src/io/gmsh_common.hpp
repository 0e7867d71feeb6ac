// Parts shared by the Gmsh 2.2 and 4.1 readers (internal to pdr_io): the element type
// table, the node tag -> point index map, and the element sink that builds MeshData (or,
// for a surface domain, a Surface of the triangles and quadrilaterals).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "io/mesh_assembly.hpp"
#include "io/read_info.hpp"
#include "io/surface.hpp"
#include "mesh/mesh_data.hpp"

namespace pdr::io {

enum class GmshKind : std::uint8_t { Unknown, Tet, Tri, Quad, Other };

struct GmshType {
  GmshKind kind = GmshKind::Unknown;
  int nodes = 0;  // nodes per element; 0 when the type is unknown
};

// The kind and node count of Gmsh element type `type` (Gmsh manual, §10.2 node ordering).
GmshType gmsh_type(std::int64_t type);

// Maps node tags (any positive integers, in any order) to point indices 0..n-1 in the
// order they were added.
class GmshNodes {
 public:
  void reserve(std::size_t n);
  // `where` is the line (ASCII) or byte offset (binary) of the node, for diagnostics.
  void add(std::uint64_t tag, const Point& p, std::size_t where);
  // Builds the lookup. Returns the index of a node whose tag repeats an earlier one, or
  // size() when all tags are distinct.
  std::size_t finish();
  static constexpr std::uint32_t kMissing = 0xffffffffu;
  std::uint32_t find(std::uint64_t tag) const;

  std::size_t size() const { return tags_.size(); }
  std::uint64_t tag(std::size_t i) const { return tags_[i]; }
  std::size_t where(std::size_t i) const { return where_[i]; }
  std::vector<Point>& points() { return points_; }

 private:
  std::vector<std::uint64_t> tags_;
  std::vector<std::size_t> where_;
  std::vector<Point> points_;
  std::vector<std::uint32_t> dense_;                               // tag -> index
  std::vector<std::pair<std::uint64_t, std::uint32_t>> sparse_;  // sorted (tag, index)
  bool use_dense_ = true;
};

// (dimension, physical tag) -> the marker a group named "pdr marker <marker>" stands for.
using GmshMarkerNames = std::map<std::pair<int, int>, int>;

// Collects elements into a MeshData (tets and triangles), or with `surface` into a Surface
// (triangles and quadrilaterals, in file order). Node indices must already be mapped.
class GmshSink {
 public:
  GmshSink(std::vector<Point>&& points, bool surface);
  // Whether elements of this kind are read (the others are skipped).
  bool wants(GmshKind kind) const {
    return surface_mode_ ? kind == GmshKind::Tri || kind == GmshKind::Quad
                         : kind == GmshKind::Tet || kind == GmshKind::Tri;
  }
  // Physical tags that stand for other markers, from $PhysicalNames.
  void set_marker_names(GmshMarkerNames names) { names_ = std::move(names); }
  // Adds an element of `type` with mapped nodes `idx[0..n)`, physical tag, source line (0
  // in binary files) and element tag.
  void add(const GmshType& type, const std::uint32_t* idx, int physical, std::size_t line,
           std::int64_t tag);
  void skip() { ++skipped_; }
  // Finishes the mesh, tets and faces each in the order of their element tags (the file's
  // order when it lists them by tag); `problem` is set when the file has no tets but other
  // elements.
  MeshData finish(ReadInfo* info, std::string& problem);
  // Finishes the surface: points with the nodes' tags and (ASCII) lines.
  Surface finish_surface(const std::string& path, const GmshNodes& nodes, bool binary);

 private:
  MeshData mesh_;
  std::vector<std::int64_t> tet_tags_, face_tags_;
  GmshMarkerNames names_;
  Surface surface_;
  PointRoles roles_;
  std::size_t skipped_ = 0;
  bool surface_mode_;
};

}  // namespace pdr::io
