// The CPUs a rank may run on once the other ranks of its host are idle.
//
// mpirun binds each rank to a core by default (Open MPI: to a core for up to 2 ranks, to a
// socket above), which suits the parallel phase: one event loop per core. What follows the
// phase on rank 0 (the completion, the writers' threads, the checker's threads) runs while
// every other rank sleeps in a collective (par/mpi_collect.hpp), and a single-rank mpirun
// is the sequential command: bound to one core, their threads would take turns on it (a
// 2M-tet check took 5.1 s there instead of 2.8 s). use_every_cpu() lets the calling thread,
// and the threads it starts afterwards, run on every CPU of the host; the kernel keeps the
// mask within the CPUs the job's control group allows, and where it refuses, the binding
// stays as it was (only the speed differs).
#pragma once

#include <sched.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

namespace pdr::par {

// True when the mask was widened (false: refused, or PDR_KEEP_BINDING is set in the
// environment, for a user who pinned the ranks on purpose; the binding stays).
inline bool use_every_cpu() {
  if (std::getenv("PDR_KEEP_BINDING") != nullptr) return false;
  cpu_set_t all;
  CPU_ZERO(&all);
  for (int c = 0; c < CPU_SETSIZE; ++c) CPU_SET(c, &all);  // the kernel keeps the allowed
  return sched_setaffinity(0, sizeof all, &all) == 0;
}

// The CPUs this thread may run on now, within a cgroup v2 CPU quota (a container's
// --cpus), in 1..256: the checker's default thread count, read when the check starts
// (after use_every_cpu() on rank 0 of a parallel run).
inline unsigned usable_cpus() {
  unsigned n = std::thread::hardware_concurrency();  // when the mask cannot be read
  cpu_set_t mine;
  CPU_ZERO(&mine);
  if (sched_getaffinity(0, sizeof mine, &mine) == 0) n = static_cast<unsigned>(CPU_COUNT(&mine));
  if (std::ifstream max("/sys/fs/cgroup/cpu.max"); max) {  // "QUOTA PERIOD" or "max PERIOD"
    std::string quota;
    double period = 0;
    if (max >> quota >> period && quota != "max" && period > 0) {
      const double cpus = std::ceil(std::atof(quota.c_str()) / period);
      n = std::min(n, static_cast<unsigned>(std::clamp(cpus, 1.0, 256.0)));
    }
  }
  return std::clamp(n, 1u, 256u);
}

// The threads a user asked for (--threads), or usable_cpus() when none (0).
inline unsigned threads_or_usable(unsigned requested) {
  return requested > 0 ? requested : usable_cpus();
}

}  // namespace pdr::par
