// Parts shared by the Gmsh readers; see gmsh_common.hpp.
#include "io/gmsh_common.hpp"

#include <algorithm>

namespace pdr::io {

GmshType gmsh_type(std::int64_t type) {
  using K = GmshKind;
  // Gmsh element types 1..31 (manual §10.2): node counts, and which are tets, triangles,
  // quadrilaterals (3, 10, 16; the higher-order quadrilaterals above 31 are Other).
  static constexpr GmshType kTable[] = {
      {K::Unknown, 0},                                                         // 0
      {K::Other, 2},  {K::Tri, 3},    {K::Quad, 4},   {K::Tet, 4},   {K::Other, 8},   // 1-5
      {K::Other, 6},  {K::Other, 5},  {K::Other, 3},  {K::Tri, 6},   {K::Quad, 9},    // 6-10
      {K::Tet, 10},   {K::Other, 27}, {K::Other, 18}, {K::Other, 14}, {K::Other, 1},  // 11-15
      {K::Quad, 8},   {K::Other, 20}, {K::Other, 15}, {K::Other, 13}, {K::Tri, 9},    // 16-20
      {K::Tri, 10},   {K::Tri, 12},   {K::Tri, 15},   {K::Tri, 15},  {K::Tri, 21},    // 21-25
      {K::Other, 4},  {K::Other, 5},  {K::Other, 6},  {K::Tet, 20},  {K::Tet, 35},    // 26-30
      {K::Tet, 56},                                                            // 31
  };
  if (type >= 0 && type < static_cast<std::int64_t>(std::size(kTable)))
    return kTable[type];
  if (type == 92) return {K::Other, 64};   // 64-node hexahedron
  if (type == 93) return {K::Other, 125};  // 125-node hexahedron
  return {};
}

void GmshNodes::reserve(std::size_t n) {
  tags_.reserve(n);
  where_.reserve(n);
  points_.reserve(n);
}

void GmshNodes::add(std::uint64_t tag, const Point& p, std::size_t where) {
  tags_.push_back(tag);
  where_.push_back(where);
  points_.push_back(p);
}

std::size_t GmshNodes::finish() {
  const std::size_t n = tags_.size();
  const std::uint64_t max_tag = n ? *std::max_element(tags_.begin(), tags_.end()) : 0;
  use_dense_ = max_tag <= 4 * static_cast<std::uint64_t>(n) + 1024;
  if (use_dense_) {
    dense_.assign(static_cast<std::size_t>(max_tag) + 1, kMissing);
    for (std::size_t i = 0; i < n; ++i) {
      std::uint32_t& slot = dense_[static_cast<std::size_t>(tags_[i])];
      if (slot != kMissing) return i;
      slot = static_cast<std::uint32_t>(i);
    }
    return n;
  }
  sparse_.resize(n);
  for (std::size_t i = 0; i < n; ++i) sparse_[i] = {tags_[i], static_cast<std::uint32_t>(i)};
  std::sort(sparse_.begin(), sparse_.end());
  for (std::size_t i = 1; i < n; ++i)
    if (sparse_[i].first == sparse_[i - 1].first)
      return std::max(sparse_[i].second, sparse_[i - 1].second);
  return n;
}

std::uint32_t GmshNodes::find(std::uint64_t tag) const {
  if (use_dense_) return tag < dense_.size() ? dense_[static_cast<std::size_t>(tag)] : kMissing;
  const auto it = std::lower_bound(sparse_.begin(), sparse_.end(),
                                   std::pair<std::uint64_t, std::uint32_t>{tag, 0});
  return (it != sparse_.end() && it->first == tag) ? it->second : kMissing;
}

namespace {

// Puts elements and their markers in the order of their tags (stable for equal tags).
template <class Elem>
void sort_by_tag(std::vector<Elem>& elems, std::vector<int>& markers,
                 const std::vector<std::int64_t>& tags) {
  if (std::is_sorted(tags.begin(), tags.end())) return;
  std::vector<std::uint32_t> order(tags.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return tags[a] < tags[b]; });
  std::vector<Elem> e(elems.size());
  std::vector<int> m(markers.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    e[i] = elems[order[i]];
    m[i] = markers[order[i]];
  }
  elems = std::move(e);
  markers = std::move(m);
}

}  // namespace

GmshSink::GmshSink(std::vector<Point>&& points, bool surface)
    : roles_(points.size()), surface_mode_(surface) {
  mesh_.points = std::move(points);
}

void GmshSink::add(const GmshType& type, const std::uint32_t* idx, int physical,
                   std::size_t line, std::int64_t tag) {
  if (!wants(type.kind)) {
    ++skipped_;
    return;
  }
  int marker = physical;
  if (!names_.empty()) {
    const auto it = names_.find({type.kind == GmshKind::Tet ? 3 : 2, physical});
    if (it != names_.end()) marker = it->second;
  }
  if (surface_mode_) {
    const std::size_t corners = type.kind == GmshKind::Tri ? 3 : 4;
    surface_.add_face({idx, corners}, line, marker);
  } else if (type.kind == GmshKind::Tet) {
    mesh_.tets.push_back({idx[0], idx[1], idx[2], idx[3]});
    mesh_.tet_regions.push_back(marker);
    tet_tags_.push_back(tag);
    for (int k = 0; k < 4; ++k) roles_.corner(idx[k]);
    for (int k = 4; k < type.nodes; ++k) roles_.high_order(idx[k]);
  } else {
    mesh_.faces.push_back({idx[0], idx[1], idx[2]});
    mesh_.face_markers.push_back(marker);
    face_tags_.push_back(tag);
    for (int k = 0; k < 3; ++k) roles_.corner(idx[k]);
    for (int k = 3; k < type.nodes; ++k) roles_.high_order(idx[k]);
  }
}

Surface GmshSink::finish_surface(const std::string& path, const GmshNodes& nodes,
                                 bool binary) {
  surface_.source = path;
  for (std::size_t i = 0; i < mesh_.points.size(); ++i)
    surface_.add_point(mesh_.points[i], binary ? 0 : nodes.where(i),
                       static_cast<std::int64_t>(nodes.tag(i)));
  return std::move(surface_);
}

MeshData GmshSink::finish(ReadInfo* info, std::string& problem) {
  if (mesh_.tets.empty() && (skipped_ > 0 || !mesh_.faces.empty())) {
    problem = "the file has no tetrahedra (" + std::to_string(mesh_.faces.size()) +
              " triangles, " + std::to_string(skipped_) + " other elements); pdr reads "
              "volume meshes: mesh the volume (gmsh -3) and export again";
    return {};
  }
  sort_by_tag(mesh_.tets, mesh_.tet_regions, tet_tags_);
  sort_by_tag(mesh_.faces, mesh_.face_markers, face_tags_);
  drop_if_all_zero(mesh_.tet_regions);
  drop_if_all_zero(mesh_.face_markers);
  const std::size_t dropped = roles_.drop_high_order_only(mesh_);
  if (info) *info = ReadInfo{skipped_, dropped};
  return std::move(mesh_);
}

}  // namespace pdr::io
