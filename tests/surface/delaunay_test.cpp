// The point of the facet in-circle test (surface/chart.hpp): every subfacet of the surface
// mesh D_o is a face of the 3D Delaunay tetrahedralization of D_o's vertices built by
// src/delaunay (insphere_sos), paper §2.1 step 3 "add the vertices in D_o by Delaunay
// insertion" and property 1 "the facets appear as a union of subfacets in T_o".
// Exactly planar axis-parallel domains (all constructed points exactly on their facets,
// including cocircular grids) must conform fully; so must tilted facets, whose subfacets
// are restricted Delaunay faces (spheres centred on the facet's plane, surface/chart.hpp),
// checked here on fixed inputs and in tests/refine/tilted_test.cpp on random rotations.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "delaunay/bulk.hpp"
#include "delaunay/delaunay.hpp"
#include "delaunay/export.hpp"
#include "geom/predicates.hpp"
#include "support/plc_fixtures.hpp"
#include "support/surface_fixtures.hpp"

namespace pdr::surface::test {
using namespace pdr::test;
using namespace pdr::domain;
namespace {

// Subfacets of m that are not faces of the 3D Delaunay tetrahedralization of its vertices.
std::size_t missing_subfacets(const SurfaceMesh& m) {
  std::vector<Point> pts;
  std::map<Point, std::uint32_t> id_of;
  for (std::uint32_t v = 0; v < m.vertex_count(); ++v) {
    pts.push_back(m.point(v));
    id_of[m.point(v)] = v;
  }
  Delaunay dt(pts);
  const BulkResult r = bulk_insert(dt);
  EXPECT_EQ(r.status, BulkStatus::Ok) << r.message;
  // Faces by coordinates: bulk_insert may store the points in another order.
  const MeshData md = to_mesh_data(dt);
  std::set<std::array<std::uint32_t, 3>> faces;
  for (const Tet& t : md.tets)
    for (int k = 0; k < 4; ++k) {
      std::array<std::uint32_t, 3> f{};
      for (int i = 0, j = 0; i < 4; ++i)
        if (i != k) f[j++] = id_of.at(md.points[t[i]]);
      std::sort(f.begin(), f.end());
      faces.insert(f);
    }
  std::size_t missing = 0;
  for (const Subfacet& t : m.subfacets()) {
    if (!t.alive) continue;
    std::array<std::uint32_t, 3> f = t.v;
    std::sort(f.begin(), f.end());
    missing += faces.count(f) == 0;
  }
  return missing;
}

TEST(SurfaceDelaunay, DataDomainsConform) {
  for (const char* name : {"box.poly", "cube-in-cube.poly", "l-prism.poly", "tee-admissible.poly"}) {
    SCOPED_TRACE(name);
    const SurfaceInit init = init_surface(analyze(read_data(name)));
    EXPECT_EQ(missing_subfacets(init.mesh), 0u);
  }
}

TEST(SurfaceDelaunay, FrameAndInteriorSegmentConform) {
  for (const Plc& plc : {frame_box(), box_with_interior_segment()}) {
    const SurfaceInit init = init_surface(analyze(plc));
    EXPECT_EQ(missing_subfacets(init.mesh), 0u);
  }
}

TEST(SurfaceDelaunay, CocircularGridConforms) {
  for (const int n : {4, 8}) {
    const SurfaceInit init = init_surface(analyze(grid_facet_box(n)));
    EXPECT_EQ(missing_subfacets(init.mesh), 0u) << n;
  }
}

TEST(SurfaceDelaunay, TiltedFacetsConformOnTheseInputs) {
  // Vertices a few ulps off their facets' planes (their audit finds closed-ball violations
  // by near-cocircular vertices): every subfacet's plane-centred sphere is empty, so it is
  // a face of the 3D triangulation (surface/chart.hpp, restricted Delaunay).
  for (const Plc& plc : {rotated_box(8, 6, 1), tumbled_box(8, 6, 1), tumbled_box(16, 16, 1)}) {
    const SurfaceInit init = init_surface(analyze(plc));
    EXPECT_EQ(missing_subfacets(init.mesh), 0u);
  }
}

RC_GTEST_PROP(SurfaceDelaunay, BoxUnionsConform, ()) {
  const SurfaceInit init = init_surface(analyze(*gen_box_union()));
  RC_ASSERT(missing_subfacets(init.mesh) == 0u);
}

}  // namespace
}  // namespace pdr::surface::test
