// Order independence of the result (paper §3 Remark 1; §4 Remark 2 and Lemma 2 for the
// parallel layer): the mesh must be the Delaunay tetrahedralization of its own vertex set,
// restricted to the domain, whatever order the vertices were inserted in.
//
// Where the checker already found the mesh Delaunay, its report decides (order_implied,
// order_from_report below: one perturbed insphere per vertex found on a tet's sphere).
// Otherwise check_order_independence rebuilds DT(V) of the mesh's vertices from scratch by bulk
// insertion in a seeded BRIO order (not the order the mesher inserted them in) and looks up
// every mesh tet, as its sorted vertex quadruple, among DT(V)'s. Symbolic perturbation makes
// DT(V) unique (docs/design.md §5), so every mesh tet of pdr's must be found. With the
// checker's validity.* (the tets form a tetrahedralization) and conformity.volume (they fill
// exactly the domain), inclusion is equality with DT(V) restricted to the domain.
//
// Another mesher breaks ties among cospherical vertices its own way, so a missing tet is
// classified: a *tie* when a vertex of DT(V) next to it lies exactly on its circumsphere
// (exact insphere = 0). That classification is complete: a non-flat tet whose closed ball
// holds no vertex inside (delaunay.empty_sphere) but is not in DT(V) has a fifth vertex w on
// its sphere, and some tet of DT(V) at each of its vertices has such a w (the tets of DT(V)
// at a vertex v of the cospherical cell cover the cell near v, and they cannot all have only
// the four vertices of the missing tet). On a mesh that is not Delaunay a tet can have one
// vertex on its sphere and another strictly inside, so `pdr check` counts ties only where
// delaunay.empty_sphere passed: it passes with no missing tet, warns when every one is a
// tie (on a Delaunay mesh every one must be: a missing tet that is not is a disagreement
// between the two checks), and fails otherwise. pdr mesh requires no missing tet at all.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "check/check.hpp"
#include "mesh/mesh_data.hpp"

namespace pdr::app {

// The rebuild's BRIO seed in pdr mesh and pdr check: fixed (reproducible reports), and unlike
// the kernel's default, so the rebuild inserts in another order than the mesher did.
inline constexpr std::uint64_t kOrderCheckSeed = 0x0DE12;

struct OrderCheck {
  std::uint64_t seed = 0;
  bool rebuilt = false;                               // DT(V) was built (V spans space)
  std::size_t tets = 0;                               // mesh tets looked up
  std::size_t missing = 0;                            // not tets of the rebuilt DT(V)
  std::size_t ties = 0;                               // of those, with a vertex on the sphere
  std::vector<std::array<std::uint32_t, 4>> first;    // the first missing (sorted ids)
  std::vector<std::size_t> first_index;               // their indices in mesh.tets
  std::vector<std::int64_t> first_tie_vertex;         // a vertex on the sphere, or -1
  bool ok() const { return missing == 0; }
};

// DT(V) rebuilt from the points alone (its finite tets as sorted vertex quadruples), so it
// can run while the checker reads the tets: rebuilt is false when the points do not span
// space (or are not all finite: nothing is built then).
struct RebuiltDt {
  bool rebuilt = false;
  // Each finite tet as its sorted vertex quadruple, grouped by smallest vertex: those of
  // vertex v are tets[first[v]] .. tets[first[v + 1] - 1], sorted (a lookup searches one
  // short run instead of all of them).
  std::vector<std::array<std::uint32_t, 4>> tets;
  std::vector<std::uint32_t> first;  // points.size() + 1 offsets
  bool holds(const std::array<std::uint32_t, 4>& sorted_quad) const;
};
RebuiltDt rebuild_dt(std::span<const Point> points, std::uint64_t seed);

// Lists the first `max_listed` missing tets; classifies ties only with `find_ties` (on a
// mesh not known to be Delaunay they would mean nothing, and there may be many). The
// lookups run on `threads` threads; the result does not depend on their number.
OrderCheck check_order_independence(const MeshData& mesh, const RebuiltDt& dt,
                                     std::uint64_t seed, std::size_t max_listed = 10,
                                     bool find_ties = true, unsigned threads = 1);
OrderCheck check_order_independence(const MeshData& mesh, std::uint64_t seed,
                                     std::size_t max_listed = 10, bool find_ties = true);

// The check `order.independence` of `pdr check` and pdr.check, appended to `report` after
// the checker's own checks (its time as report.seconds["order"]): pass, warn (ties only),
// fail, or skipped; `violations` counts every missing tet (ties too, when it warns), and
// the findings list them when the vertex set cannot be rebuilt (indices out of range, duplicate
// or non-finite vertices: validity.* says why).
// Where order_implied(report) holds, the check is decided from the report without a
// rebuild (counts: implied 1); otherwise DT(V) is rebuilt here.
void add_order_check(check::Report& report, const MeshData& mesh, std::uint64_t seed);

// Whether the checker's own report decides order independence, so that nothing need be
// rebuilt: the mesh has tets, validity.indices, .coordinates, .duplicate_vertices and
// .orientation passed, and delaunay.empty_sphere passed and listed every vertex exactly on
// a tet's circumsphere (check::Report::on_sphere_complete). A tet whose closed ball holds
// no vertex but its own four is a tet of DT(V) under any perturbation (an empty sphere
// through exactly four vertices bounds a Delaunay cell that is a tet); one whose sphere
// also holds vertices v (none inside) is a tet of the perturbed DT(V) exactly when the
// perturbation puts every such v outside, insphere_sos(tet, v) < 0 (the perturbation is
// infinitesimal: every other vertex keeps its strict side). That is what the rebuild
// decides by building DT(V); here it costs one perturbed sign per pair. The rebuild
// remains where the mesh is not Delaunay (to list what differs) or the pairs are too many.
bool order_implied(const check::Report& report);
// The order check decided that way (precondition: order_implied(report)): the missing
// tets are those with a vertex on the sphere that the perturbation puts inside, each a
// tie (its first such vertex listed).
OrderCheck order_from_report(const MeshData& mesh, const check::Report& report, std::uint64_t seed,
                             std::size_t max_listed = 10, unsigned threads = 1);

}  // namespace pdr::app
