// The guards of SeqRefinement for domains outside the theory (refine/seq_refinement.hpp,
// refine/guard.hpp, refine/split.hpp): the encroachment pass, concentric shells,
// protected lengths. The tee (70° corners and dihedrals) meshes at several sizes with no
// encroached subsegment or subfacet and every ratio < 2, by the exact checker; domains
// with sharper angles terminate with quality or a report, never a hang or a throw.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include "check/check.hpp"
#include "delaunay/export.hpp"
#include "domain/analysis.hpp"
#include "domain/distance.hpp"
#include "io/mesh_io.hpp"
#include "refine/flat.hpp"
#include "refine/initial.hpp"
#include "refine/seq_refinement.hpp"
#include "refine/split.hpp"
#include "support/outside_fixtures.hpp"
#include "support/plc_fixtures.hpp"
#include "surface/init.hpp"

namespace pdr::refine {
using namespace pdr::test;
using namespace pdr::domain;
using namespace pdr::surface;
namespace {

struct Sizes {
  std::optional<double> max_volume, size;
};

struct GuardRun {
  bool admissible = true;
  RefineResult rr;
  check::Report report;
  MeshData data;
  std::size_t tets = 0;
};

GuardRun mesh(const Plc& plc, const Sizes& sz) {
  DomainAnalysis an = analyze(plc);
  GuardRun r;
  r.admissible = an.report.admissible;
  VolumeMesh vm = build_initial(init_surface(an).mesh, an.domain.plc.holes);
  RefineOptions o;
  o.max_volume = sz.max_volume;
  o.size = sz.size;
  set_domain(o, an);
  r.rr = refine(vm, o);
  r.data = to_mesh_data(vm.dt, vm.inside);
  r.tets = r.data.tets.size();
  check::Options co;
  co.ratio_bound = 2.0;
  r.report = check::check_mesh(check::view_of(r.data), an.domain.plc, co);
  return r;
}

TEST(RefineGuard, AcuteVerticesOfTheTee) {
  const DomainAnalysis an = analyze(test::read_data("tee.poly"));
  ASSERT_FALSE(an.report.admissible);
  // The flange tips (3,10,z) and (-3,10,z), z = 0, 20: Plc vertices 3, 4, 9, 10.
  EXPECT_EQ(acute_vertices(an.report), (std::vector<std::uint32_t>{3, 4, 9, 10}));
}

TEST(RefineGuard, TeeMeshesWithoutEncroachmentAtSeveralSizes) {
  const Plc tee = test::read_data("tee.poly");
  for (const Sizes sz : {Sizes{}, Sizes{1.0, {}}, Sizes{0.1, {}}, Sizes{{}, 1.0}}) {
    SCOPED_TRACE(sz.max_volume ? "max_volume " + std::to_string(*sz.max_volume)
                               : sz.size ? "size " + std::to_string(*sz.size) : "default");
    const GuardRun r = mesh(tee, sz);
    EXPECT_FALSE(r.admissible);
    EXPECT_TRUE(r.rr.stop_reason.empty()) << r.rr.stop_reason;
    EXPECT_TRUE(r.rr.leftovers.empty()) << r.rr.leftovers.front().reason;
    EXPECT_TRUE(r.rr.unsplit.empty()) << r.rr.unsplit.front();
    // Every exact check passes, encroachment.* and quality.ratio (B = 2) included.
    EXPECT_TRUE(r.report.ok()) << check::to_text(r.report);
    ASSERT_NE(r.report.find("encroachment.subfacets"), nullptr);
    EXPECT_GT(r.report.find("encroachment.subfacets")->checked, 0u);
    EXPECT_GT(r.tets, 0u);
  }
}

// A prism over a right triangle with the angle `deg` at the origin: a wedge of dihedral
// `deg` along the z axis, and `deg` corners in the caps.
Plc wedge(double deg) {
  const double t = std::tan(deg * std::numbers::pi / 180);
  return test::prism({{0, 0}, {10, 0}, {10, 10 * t}}, 0, 4);
}

// A run the vertex cap stops may leave flat tets on a facet inside the domain (rounding on
// a tilted facet; their repair waited in the queue): each is counted (flat_left), and the
// mesh still conforms: a flat tet's faces that are subfacets are faces of T, the inside
// flags follow them, and its other faces lie within the facet's slab without being in the
// facet (the exact check keeps one layer, check/domain.cpp). A 5-degree blade (a wedge 3
// long, 1 high; tilted faces) stopped at 5,000 vertices leaves two. Its protecting
// cylinder ends the refinement at about 130 vertices, so this run leaves it out (the
// cascade then runs to the cap, as it did before the cylinders).
TEST(RefineGuard, CapStopLeavesFlatTetsInAConformingMesh) {
  const double t = 3 * std::tan(2.5 * std::numbers::pi / 180);
  const Plc blade = test::prism({{0, 0}, {3, -t}, {3, t}}, 0, 1);
  DomainAnalysis an = analyze(blade);
  // The paper's uniform surface mesh (the graded one sized by position starts coarser and
  // the cascade takes another course).
  VolumeMesh vm = build_initial(init_surface(an, {0, SurfaceSizing::Uniform}).mesh,
                                an.domain.plc.holes);
  RefineOptions o;
  set_domain(o, an);
  o.cylinders.clear();
  o.max_vertices = 5000;
  const RefineResult rr = refine(vm, o);
  ASSERT_FALSE(rr.stop_reason.empty());
  std::size_t flat = 0;
  const TetStore& s = vm.dt.store();
  for (TetId x = 0; x < s.slots(); ++x)
    if (s.is_alive(x) && !s.is_ghost(x) && vm.is_inside(x) && flat_subfacet_face(vm, x)) ++flat;
  EXPECT_GT(flat, 0u);
  EXPECT_EQ(rr.stats.flat_left, flat);
  const MeshData data = to_mesh_data(vm.dt, vm.inside);
  check::Options co;
  co.ratio_bound = 2.0;
  const check::Report report = check::check_mesh(check::view_of(data), an.domain.plc, co);
  for (const char* id : {"validity.orientation", "validity.overlap", "conformity.vertices",
                         "conformity.segments", "conformity.facets", "conformity.volume",
                         "delaunay.empty_sphere"})
    EXPECT_EQ(check::to_string(report.find(id)->status), "pass") << id << "\n"
                                                                 << check::to_text(report);
}

// The paper's tee (data/tee-paper.poly: re-entrant edges at 290.56 deg, tips at 69.44
// deg). Across the re-entrant edges a new subfacet can have a vertex of the other facet in
// its equatorial ball, so it is not a face of T when made: refine/conformity.hpp refines it
// until it is, and recomputes the flags. Before that, V = 0.1 ended in an internal error
// (volume.conformity). Every exact check passes; the recovery path ran.
TEST(RefineGuard, PaperTeeRecoversConformity) {
  const Plc tee = test::read_data("tee-paper.poly");
  std::size_t breaks = 0;
  for (const double v : {0.1, 0.02}) {
    SCOPED_TRACE("max_volume " + std::to_string(v));
    const GuardRun r = mesh(tee, Sizes{v, {}});
    EXPECT_FALSE(r.admissible);
    EXPECT_TRUE(r.rr.stop_reason.empty()) << r.rr.stop_reason;
    EXPECT_TRUE(r.rr.unsplit.empty()) << r.rr.unsplit.front();
    EXPECT_TRUE(r.report.ok()) << check::to_text(r.report);
    EXPECT_EQ(r.rr.stats.conformity_refused, 0u);  // every missing element came back
    breaks += r.rr.stats.conformity_breaks;
  }
  EXPECT_GT(breaks, 0u);
}

// Whatever a wedge ends with, the mesh is a valid, Delaunay, conforming tetrahedralization
// of the domain (every validity.*, delaunay.* and conformity.* check passes), and a tet
// left with ratio >= 2 has a vertex next to the wedge's sharp edge (the z axis; "next to":
// in its protecting cylinder, or near an acute vertex): the guards give up only there.
TEST(RefineGuard, SharpWedgesTerminateWithQualityOrAReport) {
  for (const double deg : {30.0, 20.0, 15.0}) {
    for (const Sizes sz : {Sizes{}, Sizes{0.5, {}}}) {
      SCOPED_TRACE(std::to_string(deg) + " deg, V " + std::to_string(sz.max_volume.value_or(0)));
      // Where the guards may give up: in the protecting cylinder of the sharp edge (half its
      // distance to the far face, at most cbrt(V)), or within 1% of the wedge's 10-unit legs
      // from an acute vertex (about 5 global protected lengths).
      const DomainAnalysis an = analyze(wedge(deg));
      double near = 0;
      for (const double c : protecting_cylinders(an)) near = std::max(near, c);
      if (sz.max_volume) near = std::min(near, std::cbrt(*sz.max_volume));
      near = std::max(near, 0.1);
      GuardRun r;
      ASSERT_NO_THROW(r = mesh(wedge(deg), sz));
      EXPECT_FALSE(r.admissible);
      EXPECT_GT(r.tets, 0u);
      for (const auto& c : r.report.checks) {
        if (c.id.rfind("validity.", 0) != 0 && c.id.rfind("delaunay.", 0) != 0 &&
            c.id.rfind("conformity.", 0) != 0)
          continue;
        EXPECT_EQ(c.status, check::Status::Pass) << c.id;
      }
      for (const char* id : {"validity.overlap", "delaunay.empty_sphere", "conformity.facets"}) {
        ASSERT_NE(r.report.find(id), nullptr) << id;
        EXPECT_GT(r.report.find(id)->checked, 0u) << id;
      }
      for (const auto& l : r.rr.leftovers) {
        double to_axis = std::numeric_limits<double>::infinity();
        for (const Point& q : l.p) to_axis = std::min(to_axis, std::hypot(q[0], q[1]));
        EXPECT_LE(to_axis, near) << "leftover tet " << l.tet << " (" << l.reason << ")";
      }
      if (r.report.ok()) continue;  // quality reached
      // Otherwise a well-formed report: every tet with ratio >= 2 is a listed leftover with
      // a reason, and only quality and encroachment checks fail; what the guards refused is
      // listed with the reason.
      EXPECT_TRUE(!r.rr.leftovers.empty() || !r.rr.unsplit.empty() || !r.rr.stop_reason.empty());
      for (const auto& l : r.rr.leftovers) EXPECT_FALSE(l.reason.empty());
      for (const auto& why : r.rr.unsplit) EXPECT_FALSE(why.empty());
      for (const auto& c : r.report.checks) {
        if (c.status != check::Status::Fail) continue;
        EXPECT_TRUE(c.id == "quality.ratio" || c.id.rfind("encroachment.", 0) == 0) << c.id;
        if (c.id == "quality.ratio") {
          EXPECT_EQ(c.violations, r.rr.leftovers.size());
        }
      }
    }
  }
}

TEST(RefineGuard, ProtectedLengthRefusesWithAReason) {
  // A protected length larger than the wedge: no subsegment of a guarded segment may be
  // split, and the run still ends, listing why.
  const DomainAnalysis an = analyze(wedge(15));
  const SurfaceInit si = init_surface(an);
  const SplitGuard g(si.mesh, acute_vertices(an.report), [](double) { return 1e3; });
  ASSERT_TRUE(g.active());
  bool refused = false;
  for (std::uint32_t s = 0; s < si.mesh.subsegments().size(); ++s) {
    const SplitGuard::Plan p = g.plan(si.mesh, s);
    if (p.ok) continue;
    refused = true;
    EXPECT_NE(p.reason.find("refine.protected"), std::string::npos) << p.reason;
  }
  EXPECT_TRUE(refused);
}

// A tee whose flange tips are sharper than the paper's (about 30 degrees; re-entrant
// web/flange edges about 330), 20 long.
Plc sharp_tee() { return test::prism(tee_profile(1.5, 6, 2.5, 8, 4.3), 0, 20); }

// The protecting cylinders lie along exactly the segments where two facets meet at an
// inadmissible dihedral: the four long edges at the tips and at the web.
TEST(RefineGuard, CylindersLieAlongTheSharpDihedrals) {
  const DomainAnalysis an = analyze(sharp_tee());
  ASSERT_FALSE(an.report.admissible);
  const std::vector<double> radius = protecting_cylinders(an);
  ASSERT_EQ(radius.size(), an.domain.segments.size());
  std::size_t sharp = 0;
  for (std::size_t s = 0; s < radius.size(); ++s) {
    const auto& g = an.domain.segments[s];
    const Point &a = an.domain.plc.points[g.a], &b = an.domain.plc.points[g.b];
    const bool along_z = a[0] == b[0] && a[1] == b[1];
    const bool sharp_edge = along_z && a[1] != 8 && !(a[1] == 0);  // tips and web joints
    EXPECT_EQ(radius[s] > 0, sharp_edge) << "segment " << s;
    if (radius[s] > 0) {
      ++sharp;
      EXPECT_LT(radius[s], 2.0);  // half the distance to an unrelated facet, at most
    }
  }
  EXPECT_EQ(sharp, 4u);
  // An admissible domain has none, nor a dihedral at or above arccos(1/3) (about 70.53
  // degrees, where Shewchuk's refinement terminates without one); below it, the wedge's
  // sharp edge has one.
  EXPECT_TRUE(protecting_cylinders(analyze(test::read_data("cube-in-cube.poly"))).empty());
  // A prism over a parallelogram with corners deg and 180 - deg: two dihedrals of deg.
  const auto cylinders = [](double deg) {
    const double c = 2 * std::cos(deg * std::numbers::pi / 180);
    const double h = 2 * std::sin(deg * std::numbers::pi / 180);
    const DomainAnalysis a = analyze(test::prism({{0, 0}, {4, 0}, {4 + c, h}, {c, h}}, 0, 3));
    EXPECT_FALSE(a.report.admissible) << deg;
    const std::vector<double> r = protecting_cylinders(a);
    return std::count_if(r.begin(), r.end(), [](double x) { return x > 0; });
  };
  EXPECT_EQ(cylinders(80), 0);
  EXPECT_EQ(cylinders(71), 0);
  EXPECT_EQ(cylinders(70), 2);
  EXPECT_EQ(cylinders(40), 2);
}

// A subfacet of a facet along a sharp segment, whose circumcenter lies in the segment's
// cylinder and whose circumradius is below the cylinder's floor, is refused with the
// reason; subfacets of facets along no sharp segment are not (the global protected length
// is 0 here).
TEST(RefineGuard, CylinderRefusesSubfacetsNearTheSharpSegment) {
  const DomainAnalysis an = analyze(sharp_tee());
  const SurfaceInit si = init_surface(an);
  std::vector<double> radius = protecting_cylinders(an);
  for (double& r : radius)
    if (r > 0) r = 1e3;  // every subfacet of those facets lies in its cylinder
  const SplitGuard g(si.mesh, acute_vertices(an.report), [](double) { return 0.0; }, radius);
  std::size_t refused = 0, free = 0;
  for (std::uint32_t f = 0; f < si.mesh.subfacets().size(); ++f) {
    if (!si.mesh.subfacet(f).alive) continue;
    bool along_sharp = false;
    for (const std::uint32_t s : si.mesh.facets[si.mesh.subfacet(f).facet].segments)
      along_sharp = along_sharp || radius[s] > 0;
    const std::string why = g.refuse_subfacet(si.mesh, f);
    EXPECT_EQ(!why.empty(), along_sharp) << why;
    if (why.empty()) {
      ++free;
      continue;
    }
    ++refused;
    EXPECT_NE(why.find("protecting cylinder"), std::string::npos) << why;
  }
  EXPECT_GT(refused, 0u);
  EXPECT_GT(free, 0u);
}

// The cascade of mutual encroachment between the two facets of a sharp dihedral stops at
// the cylinder's floor, a size proportional to the local feature size. With the global
// protected length alone (resolution / 64) this tee at V = 1 ran to 320,563 tets, a band
// along the 20-unit edges refined down to it, and left 20 tets with ratio >= 2; with the
// cylinders, 6,779 tets and 2 left. The mesh is valid, Delaunay and conforming; a tet left
// with ratio >= 2 has a vertex in a cylinder, and what the cylinders refused is listed.
TEST(RefineGuard, CylindersStopTheCascadeAtASharpDihedral) {
  const Plc tee = sharp_tee();
  const DomainAnalysis an = analyze(tee);
  const std::vector<double> radius = protecting_cylinders(an);
  const GuardRun r = mesh(tee, Sizes{1.0, {}});
  EXPECT_FALSE(r.admissible);
  EXPECT_TRUE(r.rr.stop_reason.empty()) << r.rr.stop_reason;
  EXPECT_LT(r.tets, 30000u);
  EXPECT_TRUE(std::any_of(r.rr.unsplit.begin(), r.rr.unsplit.end(), [](const std::string& u) {
    return u.find("protecting cylinder") != std::string::npos;
  }));
  for (const auto& l : r.rr.leftovers) {
    bool in_cylinder = false;
    for (std::size_t s = 0; s < radius.size(); ++s) {
      const Point& a = an.domain.plc.points[an.domain.segments[s].a];
      const Point& b = an.domain.plc.points[an.domain.segments[s].b];
      for (const Point& q : l.p)
        in_cylinder = in_cylinder || dist2_point_segment(q, a, b) <= radius[s] * radius[s];
    }
    EXPECT_TRUE(in_cylinder) << "leftover tet " << l.tet << " (" << l.reason << ")";
  }
  for (const auto& c : r.report.checks) {
    if (c.status != check::Status::Fail) continue;
    EXPECT_TRUE(c.id == "quality.ratio" || c.id.rfind("encroachment.", 0) == 0) << c.id;
    if (c.id == "quality.ratio") {
      EXPECT_EQ(c.violations, r.rr.leftovers.size());
    }
  }
}


// The protected length at an acute vertex follows the local feature size, as protecting
// balls do: a void 0.002 above the base of a pyramid 6 high makes the surface fine next to
// it (graded by position), and the apex, 6 away, is refined no finer than for itself. With
// the domain's d (0.0014) as every guarded element's d, the apex was refined down to edges
// of 3.5e-6 (pieces of the shells refused below 1.1e-5); with the local d, the shells stop
// at cbrt(V) / 64 there.
TEST(RefineGuard, ProtectedLengthIsLocalToTheAcuteVertex) {
  Plc plc = merge(pyramid(4, 6), box({-0.05, -0.05, 0.002}, {0.05, 0.05, 0.102}));
  plc.holes.push_back({0, 0, 0.05});
  relabel(plc);
  const GuardRun r = mesh(plc, Sizes{0.001, {}});
  EXPECT_FALSE(r.admissible);
  EXPECT_TRUE(r.rr.stop_reason.empty()) << r.rr.stop_reason;
  for (const auto& c : r.report.checks) {
    if (c.status != check::Status::Fail) continue;
    EXPECT_TRUE(c.id == "quality.ratio" || c.id.rfind("encroachment.", 0) == 0) << c.id;
  }
  double near_apex = std::numeric_limits<double>::infinity();
  const MeshData m = r.data;
  for (const auto& t : m.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Point& a = m.points[t[i]];
        const Point& b = m.points[t[j]];
        if (a[2] < 5 && b[2] < 5) continue;
        near_apex = std::min(near_apex, std::sqrt(dist2_point_point(a, b)));
      }
  EXPECT_GT(near_apex, 1e-4);
  for (const auto& l : r.rr.leftovers)
    EXPECT_NE(l.reason.find("refine.protected"), std::string::npos) << l.reason;
}

}  // namespace
}  // namespace pdr::refine
