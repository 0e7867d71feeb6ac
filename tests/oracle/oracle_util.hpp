// Helpers for the oracle tests: an independent verdict on a foreign mesh (brute force, GMP
// rationals only: no grid, no filter, no shared code with src/check beyond geom/exact),
// and the comparison of pdr check's report with it.
//
// The independent verdict, for every tet with exact orientation o:
//   orientation   o <= 0 is a violation (validity.orientation);
//   Delaunay      every other vertex p with insphere(tet, p) * o > 0 (all pairs;
//                 check/mesh_gen.hpp's delaunay_oracle), o = 0 tets skipped;
//   ratio         R^2 >= B^2 lmin^2 (exact circumradius and edge lengths), o = 0 skipped.
#pragma once

#include <gtest/gtest.h>

#include <gmpxx.h>

#include <cstdint>
#include <set>
#include <string>

#include "check/check.hpp"
#include "check/check_test_util.hpp"
#include "check/mesh_gen.hpp"
#include "geom/exact.hpp"
#include "io/io_test_util.hpp"

namespace pdr::oracle::test {

using pdr::io::test::have_tool;
using pdr::io::test::run_in;
using pdr::io::test::ScratchDir;
using pdr::io::test::write_text;

struct Verdict {
  std::uint64_t non_positive = 0;         // tets with orient3d <= 0
  check::test::OracleVerdict delaunay;    // tets with a vertex strictly inside
  std::set<std::uint64_t> ratio_at_least; // tets with R >= B lmin
};

// with_delaunay = false skips the O(#tets x #points) GMP Delaunay part (large meshes).
inline Verdict independent_verdict(const MeshData& m, double B, bool with_delaunay = true) {
  Verdict v;
  if (with_delaunay) v.delaunay = check::test::delaunay_oracle(m);
  const mpq_class b2 = mpq_class(B) * mpq_class(B);
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    const Tet& k = m.tets[t];
    const Point &a = m.points[k[0]], &b = m.points[k[1]], &c = m.points[k[2]],
                &d = m.points[k[3]];
    const Sign o = exact::orient3d(a, b, c, d);
    if (o != Sign::Positive) ++v.non_positive;
    if (o == Sign::Zero) continue;
    const std::array<const Point*, 4> p{&a, &b, &c, &d};
    mpq_class l2 = exact::squared_distance(a, b);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const mpq_class q = exact::squared_distance(*p[i], *p[j]);
        if (q < l2) l2 = q;
      }
    if (exact::circumradius2(a, b, c, d) >= b2 * l2) v.ratio_at_least.insert(t);
  }
  return v;
}

// pdr check (all findings kept) against the independent verdict, check by check.
inline check::Report expect_same_verdict(const MeshData& m, double B, const std::string& label,
                                         bool with_delaunay = true) {
  SCOPED_TRACE(label);
  check::Options o;
  o.ratio_bound = B;
  o.max_reported = m.tets.size() + m.points.size();
  const check::Report r = check::test::run(m, o);
  const Verdict v = independent_verdict(m, B, with_delaunay);
  using check::test::count;
  using check::test::result;
  EXPECT_EQ(result(r, "validity.orientation").violations, v.non_positive);
  const check::CheckResult& q = result(r, "quality.ratio");
  std::set<std::uint64_t> qids;
  for (const check::Finding& f : q.findings) qids.insert(f.id);
  EXPECT_EQ(qids, v.ratio_at_least);
  EXPECT_EQ(q.violations, v.ratio_at_least.size());
  if (!with_delaunay) return r;
  const check::CheckResult& d = result(r, "delaunay.empty_sphere");
  EXPECT_EQ(d.violations, v.delaunay.violating_tets.size());
  EXPECT_EQ(count(r, "delaunay.empty_sphere", "violating_pairs"), v.delaunay.violating_pairs);
  EXPECT_EQ(count(r, "delaunay.empty_sphere", "cospherical"), v.delaunay.cospherical);
  std::set<std::uint64_t> ids;
  for (const check::Finding& f : d.findings) ids.insert(f.id);
  EXPECT_EQ(ids, v.delaunay.violating_tets);
  return r;
}

inline std::string data(const std::string& name) {
  return std::string(PDR_DATA_DIR) + "/" + name;
}
inline std::string oracle_data(const std::string& name) {
  return std::string(PDR_SOURCE_DIR) + "/tests/oracle/data/" + name;
}

}  // namespace pdr::oracle::test
