// Stacked unions of rotated boxes (issue #11 item 7): valid domains outside the theory as a
// CAD tool builds them, by Boolean operations on boxes.
//
// A part is a stack of layers; layer k is a prism over a profile P_k, the union of a few
// rectangles turned by random angles, minus a few more (notches, and through-holes when a
// cut lies inside: facets with holes, a part of genus > 0), over z in [z_k, z_{k+1}].
// The boundary of the stack is:
//   - P_0 at the bottom and P_{L-1} at the top;
//   - at each inner level z_k, the symmetric difference of P_{k-1} and P_k (the ledges where
//     one layer overhangs the other): polygons with holes, meeting the walls at 90 and 270
//     degrees;
//   - a vertical wall over every edge of every ring of every P_k, with the vertices of the
//     levels that lie on the edge inserted along its top and bottom sides (a wall meets the
//     ledges in several segments).
// The rectangles' corners meet at any angle, so the walls meet at acute and reflex
// dihedrals, and the ledges at vertices where many facets meet; Boolean operations in
// floating point (Boost.Geometry) place crossing points within rounding of the two edges
// they lie on, so walls are planar only to rounding, as a CAD export's are. The stack can
// close a cavity (a ring of one layer between two full ones): read as TetGen reads a .poly
// (Enclosure::HolePoints), the cavity is a second region and the ledges around it are
// internal facets.
#pragma once

#include <rapidcheck.h>

#include <cstdint>
#include <vector>

#include "mesh/plc.hpp"

namespace pdr::test {

struct TurnedBox {
  double cx = 0, cy = 0;  // centre
  double w = 1, h = 1;    // full width and height
  double angle = 0;       // radians, about the centre
};

struct UnionLayer {
  std::vector<TurnedBox> add;  // the profile is the union of these ...
  std::vector<TurnedBox> cut;  // ... minus these
  double top = 1;              // z of the layer's top (above the previous layer's)
};

// The stack over z0, or an empty Plc when some layer's profile is empty or the features
// are smaller than min_feature (an edge of a profile or a ledge shorter than it, a vertex
// of one level closer than it to an edge it does not lie on, corners sharper than
// min_corner_deg): such draws make thin slivers that a property would spend its time on.
Plc stacked_union(const std::vector<UnionLayer>& layers, double z0, double min_feature,
                  double min_corner_deg);

// Stacks of 1 to 3 layers of 1 to 4 boxes and 0 to 2 cuts each, corners of at least 8
// degrees, features of at least 0.02 on parts about 2 wide; half of them turned by a
// random rotation, and of those half printed with 17, 9 or 7 digits.
rc::Gen<Plc> gen_stacked_union();

}  // namespace pdr::test
