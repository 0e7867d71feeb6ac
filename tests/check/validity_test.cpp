// validity.*: valid meshes pass; each planted corruption fails its own check (and, where
// the invariants allow, only that one).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "check_test_util.hpp"
#include "mesh_gen.hpp"

namespace pdr::check::test {
namespace {

using Ids = std::set<std::string>;

TEST(Validity, KuhnGridPassesEveryCheck) {
  const MeshData m = kuhn_grid(3);
  Options o;
  o.ratio_bound = 2.0;
  o.min_edge = 0.5;
  const Report r = run(m, o);
  EXPECT_TRUE(r.ok()) << to_text(r);
  EXPECT_EQ(r.tets, 27u * 6);
  EXPECT_EQ(r.boundary_faces, 6u * 9 * 2);
  for (const char* id : {"validity.orientation", "validity.face_sharing", "validity.boundary_closed",
                         "validity.overlap", "validity.duplicate_vertices", "delaunay.empty_sphere",
                         "quality.ratio", "quality.shortest_edge"})
    EXPECT_EQ(result(r, id).status, Status::Pass) << id;
  EXPECT_EQ(result(r, "validity.faces").status, Status::Skipped);
  EXPECT_EQ(result(r, "conformity.facets").status, Status::Skipped);
  EXPECT_GT(count(r, "delaunay.empty_sphere", "cospherical"), 0u);
  // Decided from the boundary surface: its face pairs tested, one outer cell probed.
  EXPECT_GT(count(r, "validity.overlap", "degree.boundary_pairs_examined"), 0u);
  EXPECT_EQ(count(r, "validity.overlap", "degree.outer_cells_probed"), 1u);
}

TEST(Validity, SmallHandMadeMeshesPass) {
  MeshData one;
  one.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  one.tets = {{0, 1, 2, 3}};
  EXPECT_TRUE(run(one).ok()) << to_text(run(one));
  MeshData two = one;  // two tets on either side of face (1,2,3)
  two.points.push_back({1, 1, 1});
  two.tets.push_back({1, 4, 2, 3});
  const Report r = run(two);
  EXPECT_TRUE(r.ok()) << to_text(r);
  EXPECT_EQ(r.boundary_faces, 6u);
}

TEST(Validity, FlippedTetFailsOnlyOrientation) {
  MeshData m = kuhn_grid(3);
  std::swap(m.tets[40][1], m.tets[40][2]);
  std::swap(m.tets[0][0], m.tets[0][3]);  // a boundary tet
  const Report r = run(m);
  EXPECT_EQ(failed(r), Ids{"validity.orientation"}) << to_text(r);
  EXPECT_EQ(result(r, "validity.orientation").violations, 2u);
  EXPECT_EQ(result(r, "validity.orientation").findings.at(0).id, 0u);
  EXPECT_EQ(count(r, "validity.orientation", "negative"), 2u);
}

TEST(Validity, DegenerateTetFailsOrientation) {
  MeshData m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.tets = {{0, 1, 2, 3}};
  const Report r = run(m);
  EXPECT_TRUE(failed(r).count("validity.orientation"));
  EXPECT_EQ(count(r, "validity.orientation", "zero_volume"), 1u);
}

TEST(Validity, DuplicatedVertexFailsOnlyDuplicates) {
  MeshData m = kuhn_grid(2);
  m.points.push_back(m.points[13]);
  const Report r = run(m);
  EXPECT_EQ(failed(r), Ids{"validity.duplicate_vertices"}) << to_text(r);
  EXPECT_EQ(result(r, "validity.unreferenced_vertices").status, Status::Warn);
  const Finding& f = result(r, "validity.duplicate_vertices").findings.at(0);
  EXPECT_EQ(f.vertices, (std::vector<std::uint32_t>{13, 27}));
}

// Three vertices at one point and two at another: each later copy is reported against the
// copy before it (the next smaller id), in id order, whatever the thread count.
TEST(Validity, EveryLaterCopyOfAPointIsADuplicateOfThePreviousOne) {
  MeshData m = kuhn_grid(2);
  m.points.push_back(m.points[13]);  // 27
  m.points.push_back(m.points[5]);   // 28
  m.points.push_back(m.points[13]);  // 29
  for (const unsigned threads : {1u, 2u, 3u}) {
    Options o;
    o.threads = threads;
    const Report r = run(m, o);
    const CheckResult& d = result(r, "validity.duplicate_vertices");
    EXPECT_EQ(d.violations, 3u);
    ASSERT_EQ(d.findings.size(), 3u);
    EXPECT_EQ(d.findings[0].vertices, (std::vector<std::uint32_t>{13, 27}));
    EXPECT_EQ(d.findings[1].vertices, (std::vector<std::uint32_t>{5, 28}));
    EXPECT_EQ(d.findings[2].vertices, (std::vector<std::uint32_t>{27, 29}));
  }
}

TEST(Validity, DeletedInteriorTetLeavesAValidMeshWithACavity) {
  MeshData m = kuhn_grid(3);
  m.tets.erase(m.tets.begin() + 13 * 6 + 2);  // a tet of the central cube
  const Report r = run(m);
  EXPECT_TRUE(r.ok()) << to_text(r);  // a cavity is a boundary: only a domain tells
  EXPECT_EQ(r.boundary_faces, 6u * 9 * 2 + 4);
}

TEST(Validity, ExtraOverlappingTetFailsOnlyOverlap) {
  MeshData m = kuhn_grid(3);
  // A corner tet of the central cube: not a Kuhn tet, no face in common with the mesh.
  m.tets.push_back({grid_id(3, 1, 1, 1), grid_id(3, 2, 1, 1), grid_id(3, 1, 2, 1), grid_id(3, 1, 1, 2)});
  const Report r = run(m);
  EXPECT_EQ(failed(r), Ids{"validity.overlap"}) << to_text(r);
  EXPECT_GT(count(r, "validity.overlap", "overlapping_pairs"), 0u);
  EXPECT_EQ(result(r, "validity.boundary_closed").status, Status::Pass);
}

TEST(Validity, PartiallyOverlappingCoplanarFacesFailOverlap) {
  MeshData m;
  m.points = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1}, {0.5, 0.5, 0}, {2.5, 0.5, 0}, {0.5, 2.5, 0}, {0, 0, -1}};
  m.tets = {{0, 1, 2, 3}, {4, 6, 5, 7}};
  const Report r = run(m);
  EXPECT_TRUE(failed(r).count("validity.overlap")) << to_text(r);
  EXPECT_EQ(count(r, "validity.overlap", "coplanar_overlaps"), 1u);
  EXPECT_EQ(result(r, "validity.orientation").status, Status::Pass);
}

TEST(Validity, FaceInThreeTetsFailsFaceSharing) {
  MeshData m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {0.1, 0.1, 2}};
  m.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}};
  const Report r = run(m);
  EXPECT_TRUE(failed(r).count("validity.face_sharing")) << to_text(r);
}

TEST(Validity, TetsOnTheSameSideOfASharedFaceFailFaceSharing) {
  MeshData m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2, 0.2, 2}};
  m.tets = {{0, 1, 2, 3}, {0, 1, 2, 4}};
  const Report r = run(m);
  EXPECT_TRUE(failed(r).count("validity.face_sharing")) << to_text(r);
  EXPECT_EQ(result(r, "validity.orientation").status, Status::Pass);
}

// Many shared faces, few listed: the same first ones in face order, and the same counts,
// whatever the number of threads (the faces are checked in blocks on each thread).
TEST(Validity, FaceSharingReportDoesNotDependOnThreads) {
  MeshData m = kuhn_grid(12);
  const std::size_t n = m.tets.size();
  for (std::size_t t = 0; t < n; t += 3) m.tets.push_back(m.tets[t]);  // each face thrice held
  Options o;
  o.max_reported = 4;
  std::string first;
  for (const nlohmann::json& j : reports_for_threads(m, o)) {
    nlohmann::json sharing;
    for (const auto& c : j["checks"])
      if (c["id"] == "validity.face_sharing") sharing = c;
    ASSERT_FALSE(sharing.is_null());
    EXPECT_EQ(sharing["findings"].size(), 4u);
    EXPECT_GT(sharing["violations"].get<std::uint64_t>(), 1000u);
    sharing.erase("seconds");
    if (first.empty()) first = sharing.dump();
    EXPECT_EQ(sharing.dump(), first);
  }
}

TEST(Validity, IndexOutOfRangeSkipsTheRest) {
  MeshData m = kuhn_grid(1);
  m.tets[2][3] = 99;
  const Report r = run(m);
  EXPECT_EQ(failed(r), Ids{"validity.indices"});
  EXPECT_EQ(result(r, "delaunay.empty_sphere").status, Status::Skipped);
  EXPECT_EQ(r.checks.size(), 18u);
}

TEST(Validity, NonFiniteCoordinateFails) {
  MeshData m = kuhn_grid(1);
  m.points[3][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(failed(run(m)), Ids{"validity.coordinates"});
}

TEST(Validity, ListedFacesAreCompared) {
  MeshData m = kuhn_grid(1);
  const Report bare = run(m);
  // The outward boundary, from a valid mesh: list it, then corrupt the list.
  std::vector<Tri> boundary, interior;
  {
    for (const Tet& t : m.tets)
      for (const auto& f : std::array<Tri, 4>{{{t[1], t[2], t[3]}, {t[0], t[3], t[2]}, {t[0], t[1], t[3]}, {t[0], t[2], t[1]}}}) {
        int holders = 0;
        for (const Tet& u : m.tets) {
          int shared = 0;
          for (auto v : f) shared += std::count(u.begin(), u.end(), v) ? 1 : 0;
          holders += shared == 3 ? 1 : 0;
        }
        (holders == 1 ? boundary : interior).push_back(f);
      }
  }
  ASSERT_EQ(boundary.size(), bare.boundary_faces);
  m.faces = boundary;
  EXPECT_EQ(result(run(m), "validity.faces").status, Status::Pass);
  m.faces.push_back(interior.at(0));  // interior face: allowed
  const Report with_interior = run(m);
  EXPECT_EQ(result(with_interior, "validity.faces").status, Status::Pass);
  EXPECT_EQ(count(with_interior, "validity.faces", "interior_listed"), 1u);
  m.faces = boundary;
  std::swap(m.faces[0][1], m.faces[0][2]);  // inward
  EXPECT_EQ(result(run(m), "validity.faces").status, Status::Warn);
  m.faces = boundary;
  m.faces.pop_back();  // missing
  EXPECT_EQ(failed(run(m)), Ids{"validity.faces"});
  m.faces = boundary;
  m.faces.push_back({1, 2, 4});  // not a face of any tet (every Kuhn tet holds 0 and 7)
  EXPECT_EQ(failed(run(m)), Ids{"validity.faces"});
}

TEST(Validity, ArraysEntryPointMatchesMeshData) {
  const MeshData m = kuhn_grid(2);
  std::vector<double> xyz;
  for (const Point& p : m.points) xyz.insert(xyz.end(), p.begin(), p.end());
  std::vector<std::uint32_t> tets;
  for (const Tet& t : m.tets) tets.insert(tets.end(), t.begin(), t.end());
  const Report a = check_arrays(xyz, tets);
  EXPECT_EQ(to_json(a).dump(), to_json(run(m)).dump());
}

}  // namespace
}  // namespace pdr::check::test
