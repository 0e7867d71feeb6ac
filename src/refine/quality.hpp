// Exact tetrahedron tests of the refinement loop (paper §1.1 "radius-edge ratio"; §3,
// Fig. 2 "while ∃t: ratio(t) >= 2"; §3 "a slight modification ... to make sure that
// tetrahedra larger than the value of the size function are refined").
//
//   ratio_at_least   R^2 >= B^2 lmin^2          (skinny: Fig. 2's loop condition)
//   radius_above     R^2 >  L^2                 (size control, --size L)
//   volume_above     volume6 > 6 V              (size control, --max-volume V, and the
//                                               regional bounds: domain/cells.hpp)
// With u = b-a, v = c-a, w = d-a, D = det[u,v,w] and X = |u|^2 v x w + |v|^2 w x u +
// |w|^2 u x v, the circumcenter is a + X / (2D), so R^2 = |X|^2 / (4 D^2): every test is a
// sign of a polynomial in the input doubles. Evaluation: the filters of
// geom/filter_kit.hpp (tet_measures: X and D with their derived bounds, 13u and 9u, carried
// as Brackets through the squares and products, every rounding and underflow covered)
// decide when the two sides' brackets are separated; otherwise, and when a coordinate
// difference is outside the kit's range, GMP rationals (geom/exact.hpp) do. The doubles of
// the filter never decide alone a case the bound does not cover. Precondition: the tet is
// positive (orient3d > 0, as every live tet of the kernel).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>

#include "domain/cells.hpp"
#include "geom/point.hpp"

namespace pdr::refine {

// The bounds of SeqRefinement's loop (refine/seq_refinement.hpp): B, and L and V when given.
struct TetBounds {
  double ratio = 2.0;
  std::optional<double> size;
  std::optional<double> max_volume;
  const domain::RegionVolumes* regions = nullptr;  // regional volume bounds, when any
};

bool ratio_at_least(const Point& a, const Point& b, const Point& c, const Point& d,
                    double bound);
bool radius_above(const Point& a, const Point& b, const Point& c, const Point& d,
                  double size);
bool volume_above(const Point& a, const Point& b, const Point& c, const Point& d,
                  double max_volume);
// ratio_at_least || radius_above || volume_above (V, then the bound of the tet's region),
// the measures computed once. A tet is located in its region only when its volume exceeds
// the smallest regional bound.
bool is_bad(const Point& a, const Point& b, const Point& c, const Point& d,
            const TetBounds& bounds);

// Display only (summaries): the radius-edge ratio (R / shortest edge).
double ratio_of(const Point& a, const Point& b, const Point& c, const Point& d);

// Display only: the extremes of ratio_of, of the dihedral angles and of the edge lengths
// over a set of tets. Each tet's figures depend on its points alone, and min and max on
// no order, so the figures of a mesh are those of any split of its tets, merged (the
// parallel run's ranks each take their own, par/par_refinement.hpp). The dihedral angles
// are kept as the extreme dot products of unit outward face normals (the angle at an edge
// is pi - acos(dot), increasing with it) and turned into degrees once.
struct QualityRange {
  double ratio_min = std::numeric_limits<double>::infinity(), ratio_max = 0;
  double dot_lo = std::numeric_limits<double>::infinity();
  double dot_hi = -std::numeric_limits<double>::infinity();
  double shortest2 = std::numeric_limits<double>::infinity();  // the shortest edge, squared
  std::uint64_t tets = 0;
  void add(const Point& a, const Point& b, const Point& c, const Point& d);
  void merge(const QualityRange& o);
  double dihedral_min_deg() const;  // 180 for no tets
  double dihedral_max_deg() const;  // 0 for no tets
};

}  // namespace pdr::refine
