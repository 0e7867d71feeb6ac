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
#include <cstdlib>

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

// The CPUs this thread may run on now (at least 1): the checker's default thread count,
// read when the check starts (after use_every_cpu() on rank 0 of a parallel run).
inline unsigned usable_cpus() {
  cpu_set_t mine;
  CPU_ZERO(&mine);
  if (sched_getaffinity(0, sizeof mine, &mine) != 0) return 1;
  return static_cast<unsigned>(std::max(1, CPU_COUNT(&mine)));
}

}  // namespace pdr::par
