// Region attributes of the output (TetGen's -A): each tet of the mesh is labelled with the
// region it lies in. A region is a connected part of Ω: the tets inside Ω joined across
// faces that are no subfacets (the refined facets separate regions). A region holding a
// region point of the input gets that point's attribute (rounded to an integer; the first
// such point wins); one holding none gets the next integer above the largest attribute
// given, the regions ordered by the sorted lists of facets they touch (a property of the
// domain, not of the mesh, so every run numbers them alike; two regions bounded by the
// very same facets, which walls inside facets can make, are ordered by their tets). TetGen gives unnamed regions
// the numbers above the largest attribute too.
#pragma once

#include <span>
#include <vector>

#include "mesh/plc.hpp"
#include "refine/volume_mesh.hpp"

namespace pdr::app {

// The label of every live inside tet of m, by tet slot (0 elsewhere).
std::vector<int> region_labels(const refine::VolumeMesh& m, std::span<const PlcRegion> regions);

}  // namespace pdr::app
