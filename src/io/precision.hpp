// How precisely a domain's coordinates are given, read off their values, and the planarity
// tolerance that follows (input classification only: it never steers the mesher).
//
// Files written by other tools round their coordinates: ASCII STL and OFF writers print 6
// to 9 significant digits, binary STL stores floats. A rotated box written so has facets
// planar only to about the rounding, and faces of one plane split into triangles that are
// coplanar only to the rounding. A tolerance relative to a facet's diameter (the
// documented default 1e-9) cannot read these for small faces, whose rounding is large next
// to their size, so the rounding itself is inferred from the values:
//   - a coordinate's digits: the fewest significant decimal digits that give it back
//     exactly (std::to_chars' shortest form); the file's precision is the most over every
//     nonzero coordinate;
//   - at most kExactDigits (5) digits everywhere: short decimals such as 0.5 or 2.25, read
//     as the exact values they are (a hand-written or generated exact domain);
//   - more than 9 digits but every coordinate a float: float32 (binary STL), relative
//     rounding 2^-24;
//   - 6 to 15 digits: relative rounding 5 * 10^-digits (half a unit of the last digit);
//   - 16 or 17: full double precision, coordinates computed in double (a rotation): a few
//     units in the last place, kComputedRounding relative (negligible next to the relative
//     tolerance, except far from the origin: a part at 1e7 has its coordinates to 2e-9).
// The uncertainty of a point is then sqrt(3) times the rounding of the largest coordinate:
// the relative rounding times the place of its leading digit (0.95 printed with 6 digits
// is rounded to 5e-7, not 5e-6 times 0.95: a scanned model's small triangles then read
// as coplanar within 10 times their actual rounding, and their real bends of a degree as
// creases of one plane); how far rounding may have moved any vertex; but at most
// kMaxUncertainty (1e-5) times the domain's diameter (its bounding box's diagonal). The
// digits cannot tell exact values from rounded ones: integers from 100000 to 100010 have
// 6 digits, as a 6-digit print of a part at 1e5 would, and read as rounded they would make
// the whole part uncertain. A rounding coarser than 1e-5 of the part is no precision a
// tolerance should read; beyond it the input is taken as given.
#pragma once

#include <algorithm>
#include <span>

#include "geom/point.hpp"
#include "mesh/plc.hpp"

namespace pdr::io {

inline constexpr int kExactDigits = 5;
inline constexpr double kComputedRounding = 0x1p-51;  // four half units in the last place
inline constexpr double kMaxUncertainty = 1e-5;       // of the domain's diameter

// digits: 17 for full doubles; 0 when no coordinate is nonzero.
CoordinatePrecision infer_precision(std::span<const Point> points);

// The planarity classification: a face (a facet, or a polygon of a surface file) of
// diameter d (its bounding box's diagonal) is planar when its vertices lie within
// admitted(d) of a plane: the relative tolerance times d, or kPlanarShare times the
// uncertainty of the coordinates, whichever admits more. kPlanarShare bounds how far off
// the least-squares plane of a polygon whose vertices each lie within u of some plane they
// may lie (2u for a quad; 4u covers up to 16 vertices in the worst case).
struct PlanarityTolerance {
  static constexpr double kPlanarShare = 4;
  double relative = 1e-9;
  CoordinatePrecision precision;  // none (uncertainty 0) when relative is 0
  double uncertainty() const { return precision.uncertainty; }
  double admitted(double diameter) const {
    return std::max(relative * diameter, kPlanarShare * uncertainty());
  }
};

// The tolerance for a domain with these points under the relative tolerance `relative`:
// with relative == 0 (exact classification) nothing is inferred.
PlanarityTolerance planarity_tolerance_of(std::span<const Point> points, double relative);
// The same for a domain: its reader's inference (Plc::precision) when it made one, else
// one from its points.
PlanarityTolerance planarity_tolerance_of(const Plc& plc, double relative);

}  // namespace pdr::io
