// physical_memory_bytes: the machine's physical memory, which the derived vertex caps of the
// surface phase (surface/init.hpp) and of the refinement (refine/budget.hpp) stay under, so
// that a run that would not end stops with exit 3 and a report instead of exhausting memory.
// A resource limit, never a geometric decision.
#pragma once

#include <unistd.h>

namespace pdr {

// In bytes; 0 when the system does not say.
inline double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 0;
  return static_cast<double>(pages) * static_cast<double>(page);
}

}  // namespace pdr
