// Property (issue #11): for a valid closed domain OUTSIDE the theory (acute and reflex
// corners, re-entrant edges above 270 degrees, tilted walls from random rotations, thin
// slabs, regions split by facet walls; tests/support/outside_fixtures.hpp), `pdr mesh` ends without an error in exit 0 or
// 3, with a mesh that passes every exact check of validity, Delaunay, conformity and
// volume; only quality.ratio and encroachment.* may fail, and only with exit 3, which then
// lists why (leftovers, unsplit). A second property runs rotated tori of triangle facets
// (triangulated surfaces whose neighbours are coplanar only within rounding).
//
// Cases: 60 by default (PDR_OUTSIDE_CASES=N for more), from seed 1 (PDR_OUTSIDE_SEED=S or
// RC_PARAMS=seed=S for others); corners down to 15 degrees (PDR_OUTSIDE_MIN_CORNER=D for
// others; before the protecting cylinders the suite stopped at 45). A failing case
// is written to PDR_REFINE_COUNTEREXAMPLE (default refine-counterexample.poly) after every
// shrinking step (and every case to <that>.running before it runs); keep the shrunk one as tests/regress/outside-<what>.poly, which the
// replay below runs from then on.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "domain/analysis.hpp"
#include "io/mesh_io.hpp"
#include "refine/property_support.hpp"
#include "support/admissible_fixtures.hpp"
#include "support/outside_fixtures.hpp"
#include "support/outside_verdict.hpp"
#include "support/plc_fixtures.hpp"
#include "support/union_fixtures.hpp"

namespace pdr::refine::test {
using namespace pdr::test;
namespace {

// The smallest corner of the generated profiles (PDR_OUTSIDE_MIN_CORNER=D for others).
double min_corner() {
  const char* env = std::getenv("PDR_OUTSIDE_MIN_CORNER");
  return env ? std::atof(env) : 15;
}

// The suite's cases are fixed (seed 1; PDR_OUTSIDE_SEED=S or RC_PARAMS for others): longer
// runs with other seeds still find counterexamples (issue #11), which must not make the
// suite flaky.
std::uint64_t seed() {
  const char* env = std::getenv("PDR_OUTSIDE_SEED");
  return env ? std::strtoull(env, nullptr, 10) : 1;
}

int cases() {
  const char* env = std::getenv("PDR_OUTSIDE_CASES");
  return env ? std::max(1, std::atoi(env)) : 60;
}

// None, or a volume bound that splits the bounding box into 4 k^3 pieces, k in [1, 12]
// (meshes of up to some 10^5 tets: fine enough for the refinement to meet the corners).
rc::Gen<Sizing> gen_fine_sizing(const Plc& plc) {
  const Point e = box_extent(plc);
  const double vol = e[0] * e[1] * e[2];
  return rc::gen::exec([vol] {
    Sizing z;
    const int k = *rc::gen::elementOf(std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12});
    if (k > 0) z.max_volume = vol / (4.0 * k * k * k);
    return z;
  });
}

// Runs `pdr mesh` in process (no files, check on, B = 2); "" when the run ends as the
// property says, else why not.
std::string outside_failure(const Plc& plc, const Sizing& z, bool* admissible = nullptr) {
  nlohmann::json j;
  std::string error;
  const int code = run_mesh(plc, z, false, j, &error);
  if (code < 0) return error;
  if (admissible) *admissible = j.value("admissible", false);
  return outside_verdict(code, j);
}

// judge_case with outside_failure: a case of the generator test `name` of OutsideProperty.
void judge_outside(const std::string& name, const Plc& plc, const Sizing& z,
                   const std::string& what) {
  judge_case("OutsideProperty." + name, plc, z, what, [&] { return outside_failure(plc, z); });
}

TEST(OutsideProperty, EndsInExit0Or3WithAConformingDelaunayMesh) {
  check_property("EndsInExit0Or3WithAConformingDelaunayMesh", cases(), [] {
    const Plc plc = *gen_outside_domain(min_corner());
    const Sizing z = *gen_fine_sizing(plc);
    bool admissible = true;
    judge_case("OutsideProperty.EndsInExit0Or3WithAConformingDelaunayMesh", plc, z,
               "a domain outside the theory does not end in a conforming Delaunay mesh",
               [&] { return outside_failure(plc, z, &admissible); });
    RC_CLASSIFY(!admissible, "outside the theory");
    RC_CLASSIFY(plc.enclosure == Enclosure::HolePoints, "regions split by facet walls");
  }, seed());
}

// The same property on rotated tori of triangle facets (a third of the cases, default
// sizing): facets coplanar within rounding across every quad's diagonal, every input vertex
// acute. Before the rounding and conformity repairs went below the protected length
// (refine/flat.hpp, refine/conformity.hpp), 7 of 16 such tori ended in exit 1.
TEST(OutsideProperty, RotatedToriOfTriangleFacetsEndConforming) {
  check_property("RotatedToriOfTriangleFacetsEndConforming", std::max(1, cases() / 3), [] {
    const Plc plc = *gen_rotated_torus_of_triangles();
    judge_outside("RotatedToriOfTriangleFacetsEndConforming", plc, Sizing{},
                  "a rotated torus of triangle facets does not end in a conforming Delaunay mesh");
  }, seed());
}

// The same property on pyramids (a sharp apex) and twisted prisms of triangle facets
// (dihedrals of 55-80 degrees along twisted edges, skinny facets, neighbours coplanar within
// a small twist), with a random volume bound.
TEST(OutsideProperty, PyramidsAndTwistedPrismsEndConforming) {
  check_property("PyramidsAndTwistedPrismsEndConforming", std::max(1, cases() / 3), [] {
    const Plc plc = *gen_pyramid_or_twisted_prism();
    const Sizing z = *gen_fine_sizing(plc);
    judge_outside("PyramidsAndTwistedPrismsEndConforming", plc, z,
                  "a pyramid or twisted prism does not end in a conforming Delaunay mesh");
  }, seed());
}

// The same property on spiky star-shaped polyhedra of triangle facets, turned, with a
// random volume bound (a fifteenth of the cases): spikes and pits at every angle, acute
// vertices everywhere. 262 runs of a script version (2026-11-27, after the protecting balls;
// some turned balls on) and 100 cases at seed 11 all ended conforming.
TEST(OutsideProperty, SpikyPolyhedraEndConforming) {
  check_property("SpikyPolyhedraEndConforming", std::max(1, cases() / 15), [] {
    const Plc plc = *gen_spiky();
    const Sizing z = *gen_fine_sizing(plc);
    judge_outside("SpikyPolyhedraEndConforming", plc, z,
                  "a spiky polyhedron does not end in a conforming Delaunay mesh");
  }, seed());
}

// The same property on tucked flaps (a cap triangle folded onto the top at 0.8 to 3
// degrees), default sizing: a fifteenth of the cases, each one to two seconds. Before the repair
// floor went to 2^-24 of the protected length, 6 of 6 such flaps (folds of 0.3 to 1.2
// degrees) ended NOT CONFORMING; before the one-pass closure scan (refine/closure.hpp
// ClosureScan) a flap took 6 to 70 s.
TEST(OutsideProperty, TuckedFlapsEndConforming) {
  check_property("TuckedFlapsEndConforming", std::max(1, cases() / 15), [] {
    const Plc plc = *gen_tucked_flap();
    judge_outside("TuckedFlapsEndConforming", plc, Sizing{},
                  "a tucked flap does not end in a conforming Delaunay mesh");
  }, seed());
}

// The same property on crumpled tops (tests/support/outside_fixtures.hpp crumpled_top, 4 x 4
// to 8 x 8 grids; tops that cross themselves are discarded): folds of needle triangles at
// sharp dihedrals, where repairs cascaded towards one input vertex. Before the protecting
// balls (refine/vertex_zones.hpp) 3 to 5 of every 66 valid tops ended NOT CONFORMING
// (tests/regress/outside-crumpled-top-*.off); with them 200 cases pass (seed 7, 347 s),
// and 66 (the default seed). A twentieth of the cases here: one to twenty seconds each.
TEST(OutsideProperty, CrumpledTopsEndConforming) {
  check_property("CrumpledTopsEndConforming", std::max(1, cases() / 20), [] {
    const int n = *rc::gen::inRange(4, 9);
    const auto seed = *rc::gen::inRange<std::uint32_t>(0, 1u << 30);
    const Plc plc = crumpled_top(n, 0.08 + *rc::gen::inRange(0, 8) / 100.0, seed);
    RC_PRE(pdr::test::error_of(plc).empty());
    judge_outside("CrumpledTopsEndConforming", plc, Sizing{},
                  "a crumpled top does not end in a conforming Delaunay mesh");
  }, seed());
}

// The same property on stacked unions of rotated boxes (tests/support/union_fixtures.hpp):
// parts a CAD tool builds by Boolean operations, with through-holes (facets with holes),
// ledges between layers (facets whose sides are cut by the walls of the next layer),
// walls at every dihedral and, half the time, a random rotation and 17, 9 or 7 digits;
// with a random volume bound, a fifth of the cases. A script version of this generator
// (corners down to 1 degree, features down to 0.001) found the runaway replayed as a known
// bug below.
TEST(OutsideProperty, StackedUnionsOfRotatedBoxesEndConforming) {
  check_property("StackedUnionsOfRotatedBoxesEndConforming", std::max(1, cases() / 5), [] {
    const Plc plc = *gen_stacked_union();
    const Sizing z = *gen_fine_sizing(plc);
    judge_outside("StackedUnionsOfRotatedBoxesEndConforming", plc, z,
                  "a stacked union of rotated boxes does not end in a conforming Delaunay mesh");
  }, seed());
}

// A square prism [-1,1]^2 x [0,1] with a slot of A degrees (1 to 10) cut D deep into one
// side, exact coordinates, each slot wall given as two triangles (either diagonal) and the
// bottom and top as polygons or as fans from the slot's corner: what an STL of a slotted
// part gives, turned by a signed permutation of the axes (exact). A wall's triangles are
// one wall of the slot's edge for the rotation copies (refine/axis_zones.hpp); when each
// triangle was a wall of its own, 5 of 6 such slots with both diagonals from one corner
// ended NOT CONFORMING. Half of them are turned by any rotation and printed with 17, 9 or
// 7 digits instead: those found a runaway and a NOT CONFORMING run at the apexes'
// protecting balls (tests/regress/outside-slot-*-rotated-*).
Plc slot_with_triangle_walls(double angle_deg, double depth, bool diag_low, bool diag_high,
                             bool fans) {
  const double h = depth * std::tan(angle_deg * std::numbers::pi / 360);
  const double tip = 1 - depth;
  std::vector<Point> pts;
  for (const double z : {0.0, 1.0})
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{
             {-1, -1}, {1, -1}, {1, -h}, {tip, 0}, {1, h}, {1, 1}, {-1, 1}})
      pts.push_back({x, y, z});
  std::vector<FacetSpec> facets;
  for (const std::uint32_t base : {0u, 7u}) {
    if (!fans) {
      facets.push_back({{base, base + 1, base + 2, base + 3, base + 4, base + 5, base + 6}});
      continue;
    }
    for (const std::uint32_t k : {4u, 5u, 6u, 0u, 1u})
      facets.push_back({{base + 3, base + k, base + (k + 1) % 7}});
  }
  for (std::uint32_t i = 0; i < 7; ++i) {
    const std::uint32_t j = (i + 1) % 7;
    const bool wall = i == 2 || i == 3;
    if (!wall) {
      facets.push_back({{i, j, j + 7, i + 7}});
      continue;
    }
    if (i == 2 ? diag_low : diag_high) {  // the diagonal from i to j + 7
      facets.push_back({{i, j, j + 7}});
      facets.push_back({{i, j + 7, i + 7}});
    } else {  // from j to i + 7
      facets.push_back({{i, j, i + 7}});
      facets.push_back({{j, j + 7, i + 7}});
    }
  }
  return make_plc(pts, facets);
}

TEST(OutsideProperty, SlotsWithTriangleWallsEndConforming) {
  check_property("SlotsWithTriangleWallsEndConforming", std::max(1, cases() / 10), [] {
    const double angle = *rc::gen::inRange(10, 101) / 10.0;
    const double depth = *rc::gen::inRange(5, 19) / 10.0;
    Plc plc = slot_with_triangle_walls(angle, depth, *rc::gen::arbitrary<bool>(),
                                       *rc::gen::arbitrary<bool>(),
                                       *rc::gen::arbitrary<bool>());
    if (*rc::gen::arbitrary<bool>()) {
      // Turned by a signed permutation of the axes: exact, so the walls stay exactly
      // coplanar.
      const auto perm = *rc::gen::elementOf(std::vector<std::array<int, 3>>{
          {0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}});
      const auto signs = *rc::gen::inRange(0, 8);
      for (Point& p : plc.points) {
        const Point q = p;
        for (int k = 0; k < 3; ++k) p[k] = (signs >> k & 1 ? -1 : 1) * q[perm[k]];
      }
    } else {
      // Turned by any rotation and printed with 17, 9 or 7 digits: a wall's triangles are
      // then coplanar only within the tolerance.
      const auto turn = [] { return *rc::gen::inRange(0, 628) / 100.0; };
      const double a = turn(), b = turn(), c = turn();
      const int digits = *rc::gen::elementOf(std::vector<int>{17, 9, 7});
      plc = printed(rotated(std::move(plc), a, b, c), digits);
    }
    const Sizing z = *gen_fine_sizing(plc);
    judge_outside("SlotsWithTriangleWallsEndConforming", plc, z,
                  "a slot with triangle walls does not end in a conforming Delaunay mesh");
  }, seed());
}

// The generator's domains are outside the theory by the domain analysis (else the property
// tests nothing new).
TEST(OutsideProperty, GeneratedProfilesHaveCornersOutside90To270) {
  check_property("GeneratedProfilesHaveCornersOutside90To270", 200, [] {
    const Plc plc = *gen_outside_domain(min_corner());
    RC_ASSERT(!domain::analyze(plc).report.admissible);
  });
  // The tee profile's corners: tips acute, web/underside edges re-entrant above 270.
  const std::vector<double> a = corner_angles(tee_profile(1, 5, 3, 10, 4.25));
  ASSERT_EQ(a.size(), 8u);
  EXPECT_NEAR(a[2], 290.56, 0.01);
  EXPECT_NEAR(a[3], 69.44, 0.01);
  EXPECT_NEAR(a[0], 90, 1e-9);
}

// Replays of tests/regress/outside-*.poly and outside-*.off, one test each; a known open bug
// is registered DISABLED_ with the bug named in its file.
const std::vector<std::string> kKnownBugs = {};
// Replays of more than about ten seconds (tests/refine/CMakeLists.txt runs them, labelled
// slow): crumpled tops whose folds make 560K tets (19 s) and 1.4M tets (about 35 s) of
// surface refinement.
const std::vector<std::string> kSlow = {"outside-crumpled-top-split-not-star.off",
                                        "outside-crumpled-top-seed-41-edge-cascade.poly"};

// Walls at sharp dihedrals around one axis: the repairs of subfacets missing from T took
// each other's subfacets out of T in turn, down towards the axis (60,000 vertices and an
// edge of 2.5e-32 at the file's volume bound, then NOT CONFORMING at the repair floor). With
// the rotation copies (refine/axis_zones.hpp) the run conforms with a few thousand vertices,
// its shortest edge far above the repair floor.
TEST(OutsideProperty, RepairCascadesEnd) {
  const std::string path = std::string(PDR_SOURCE_DIR) + "/tests/regress/outside-walls-star-axis-runaway.poly";
  nlohmann::json j;
  std::string error;
  Sizing z;
  z.max_volume = 0.02;  // coarser than the file's: the cascade is the same, the run shorter
  const int code = run_mesh(io::read_domain(path), z, false, j, &error);
  ASSERT_GE(code, 0) << error;
  EXPECT_LT(j.value("vertices", std::size_t{0}), 20000u) << j.dump(1);
  EXPECT_GT(j.value("shortest_edge", 0.0), 1e-6) << j.dump(1);
  EXPECT_FALSE(j.contains("conformity")) << j.dump(1);
  EXPECT_EQ(j["inserted"].value("conformity_refused", 1), 0) << j.dump(1);
}

// Rounding puts the split points of a rotated torus's tilted sides ulps off their facets'
// planes, and four vertices of one facet, nearly cocircular, then make a flat tet inside:
// the run refines it (refine/flat.hpp rule 1), counts it in inserted.flat_repairs, and ends
// conforming.
TEST(OutsideProperty, FlatTetsOnTiltedFacetsAreCountedRepairs) {
  const std::string path =
      std::string(PDR_SOURCE_DIR) + "/tests/regress/outside-rotated-torus-triangle-facets.poly";
  nlohmann::json j;
  std::string error;
  const int code = run_mesh(io::read_domain(path), sizing_of_file(path), false, j, &error);
  ASSERT_GE(code, 0) << error;
  EXPECT_GT(j["inserted"].value("flat_repairs", std::size_t{0}), 0u) << j.dump(1);
  EXPECT_FALSE(j.contains("conformity")) << j.dump(1);
}

// A 3-degree notch printed with 7 digits (replayed above: it conforms since the zone of
// its edge is kept, refine/axis_zones.hpp). Before, its flat-tet repairs went on around a few vertices of one wall at circumradii
// of 1e-9 to 4e-12 (72,000 of them by 80,000 vertices), each flag repair recomputed every
// flag, and the run never ended. Flat-tet repairs stop at the facet's planarity gap, so it
// ends by itself far below the cap: the phase is bounded even where the mesh is wrong.
TEST(OutsideProperty, NotchPrintedWithFewDigitsEndsBelowTheCap) {
  const std::string path = std::string(PDR_SOURCE_DIR) +
                           "/tests/regress/outside-notch-3-degrees-printed-7-digits-runaway.poly";
  nlohmann::json j;
  std::string error;
  Sizing z = sizing_of_file(path);
  z.max_vertices = 50000;
  const int code = run_mesh(io::read_domain(path), z, false, j, &error);
  ASSERT_GE(code, 0) << error;
  EXPECT_EQ(j.value("stop_reason", std::string()), "");
  EXPECT_LT(j.value("vertices", std::size_t{0}), z.max_vertices);
}

[[maybe_unused]] const bool kReplaysRegistered =
    register_replays("OutsideRegress", "outside-", kKnownBugs, [](const std::string& path) {
      return outside_failure(io::read_domain(path), sizing_of_file(path));
    }, kSlow);

}  // namespace
}  // namespace pdr::refine::test
