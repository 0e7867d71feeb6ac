// The resolution and the vertex cap of SeqRefinement; see budget.hpp.
#include "refine/budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include <unistd.h>

#include "mesh/physical_memory.hpp"
#include "refine/seq_refinement.hpp"

namespace pdr::refine {

namespace {

double box_volume(std::span<const Point> pts) {
  Point lo = pts[0], hi = pts[0];
  for (const Point& p : pts)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
}

}  // namespace

std::size_t memory_vertex_limit() {
  const double memory = physical_memory_bytes();
  if (memory <= 0) return 2000000000;
  return static_cast<std::size_t>(std::min(2.0e9, memory / 2 / kRefineVertexBytes));
}

VertexBudget::VertexBudget(std::span<const Point> points, const RefineOptions& o) {
  const double box = box_volume(points);
  box_share_ = std::cbrt(box) / 8;
  without_d_ = std::numeric_limits<double>::infinity();
  if (o.size) without_d_ = std::min(without_d_, *o.size / 2);
  if (const auto v = smallest_volume(o)) without_d_ = std::min(without_d_, std::cbrt(*v));
  const double u = resolution_at(o.d);
  resolution_ = u;
  user_cap_ = o.max_vertices != 0;
  if (user_cap_) {
    cap_ = o.max_vertices;
  } else {
    const double cap = 1000.0 + 64.0 * static_cast<double>(points.size()) + 16.0 * box / (u * u * u);
    cap_ = std::min(static_cast<std::size_t>(std::min(cap, 2.0e9)), memory_vertex_limit());
  }
  memory_limit_ = physical_memory_bytes() / 2;
}

double resident_bytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (f == nullptr) return 0;
  unsigned long size = 0, resident = 0;
  const int read = std::fscanf(f, "%lu %lu", &size, &resident);
  std::fclose(f);
  const long page = sysconf(_SC_PAGE_SIZE);
  if (read != 2 || page <= 0) return 0;
  return static_cast<double>(resident) * static_cast<double>(page);
}

double VertexBudget::resolution_at(double d) const {
  return std::min(d > 0 && std::isfinite(d) ? d / 2 : box_share_, without_d_);
}

bool VertexBudget::reached(std::size_t vertices, std::string& why) const {
  if (memory_why_.empty() && memory_limit_ > 0 && (++calls_ & 0xFFF) == 0) {
    const double resident = resident_bytes();
    if (resident > memory_limit_) {
      std::ostringstream os;
      os.precision(3);
      os << "refine.memory: the run holds " << resident / (1 << 30) << " GiB at " << vertices
         << " vertices, past half the machine's memory (" << memory_limit_ / (1 << 30)
         << " GiB); the domain is probably outside the theory, or the sizes ask for more "
            "than the machine holds";
      memory_why_ = os.str();
    }
  }
  if (!memory_why_.empty()) {
    why = memory_why_;
    return true;
  }
  if (vertices < cap_) return false;
  why = "refine.cap: " + std::to_string(vertices) + " vertices reached the cap of " +
        std::to_string(cap_) +
        (user_cap_ ? std::string(" (--max-vertices)")
                   : std::string(" (derived from the input size, its bounding box, d, "
                                 "B and the size bounds, and at most what half the "
                                 "machine's memory holds); the domain is probably outside "
                                 "the theory, or the sizes ask for more than the machine "
                                 "holds"));
  return true;
}

}  // namespace pdr::refine
