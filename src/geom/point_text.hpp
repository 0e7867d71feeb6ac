// A point as text for messages and reports: "(x, y, z)" with 17 significant digits, so
// the double read back is the same double.
#pragma once

#include <sstream>
#include <string>

#include "geom/point.hpp"

namespace pdr {

inline std::string point_text(const Point& p) {
  std::ostringstream os;
  os.precision(17);
  os << '(' << p[0] << ", " << p[1] << ", " << p[2] << ')';
  return os.str();
}

}  // namespace pdr
