// Fig. 2's encroachment tests on a cavity's closure: which subsegment or subfacet of C_p
// a candidate point p encroaches (closed balls, exact: geom/encroach.hpp). The tets given
// are the closure of p's cavity (its conflict tets and ring), or a tet alone.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>

#include "refine/volume_mesh.hpp"

namespace pdr::refine {

using ClosureTets = std::initializer_list<std::span<const TetId>>;

// A subsegment that is an edge of the tets and whose closed diametral ball holds p (Fig. 2
// "p encroaches subsegment s ∈ C_p"); the first found.
std::optional<std::uint32_t> closure_encroached_subsegment(const VolumeMesh& m,
                                                           ClosureTets tets, const Point& p);

// The subfacet of largest circumradius among the faces of the tets whose closed
// equatorial ball holds p (Fig. 2 "f <- max radius(f) that p encroaches"), compared
// exactly (geom/encroach.hpp); equal radii: the smaller sorted vertex coordinates.
std::optional<std::uint32_t> closure_encroached_subfacet(const VolumeMesh& m,
                                                         ClosureTets tets, const Point& p);

}  // namespace pdr::refine
