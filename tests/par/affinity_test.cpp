// use_every_cpu() (par/affinity.hpp): a thread bound to one CPU, as mpirun binds a rank,
// gets back every CPU the process was allowed, and a thread it starts afterwards has them
// too; usable_cpus() counts the mask.
#include "par/affinity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace pdr::par {
namespace {

int allowed_cpus() {
  cpu_set_t s;
  CPU_ZERO(&s);
  EXPECT_EQ(sched_getaffinity(0, sizeof s, &s), 0);
  return CPU_COUNT(&s);
}

// Binds the calling thread to the first CPU of `mask`, as mpirun binds a rank.
void bind_to_first(const cpu_set_t& mask) {
  int first = 0;
  while (!CPU_ISSET(first, &mask)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
}

TEST(Affinity, BoundThreadGetsEveryAllowedCpuBack) {
  const int before = allowed_cpus();
  cpu_set_t all;
  ASSERT_EQ(sched_getaffinity(0, sizeof all, &all), 0);
  bind_to_first(all);
  ASSERT_EQ(allowed_cpus(), 1);
  EXPECT_TRUE(use_every_cpu());
  EXPECT_GE(allowed_cpus(), before);
  int in_thread = 0;
  std::thread([&] { in_thread = allowed_cpus(); }).join();
  EXPECT_GE(in_thread, before);
}

// The checker's default threads: the CPUs of the mask (within a quota), 1 when bound to one.
TEST(Affinity, UsableCpusFollowsTheMask) {
  cpu_set_t saved;
  ASSERT_EQ(sched_getaffinity(0, sizeof saved, &saved), 0);
  EXPECT_GE(usable_cpus(), 1u);
  EXPECT_LE(usable_cpus(), static_cast<unsigned>(std::min(CPU_COUNT(&saved), 256)));
  bind_to_first(saved);
  EXPECT_EQ(usable_cpus(), 1u);
  ASSERT_EQ(sched_setaffinity(0, sizeof saved, &saved), 0);
}

// PDR_KEEP_BINDING: the binding a user asked for stays.
TEST(Affinity, KeepBindingLeavesTheMask) {
  cpu_set_t saved;
  ASSERT_EQ(sched_getaffinity(0, sizeof saved, &saved), 0);
  bind_to_first(saved);
  setenv("PDR_KEEP_BINDING", "1", 1);
  EXPECT_FALSE(use_every_cpu());
  unsetenv("PDR_KEEP_BINDING");
  EXPECT_EQ(allowed_cpus(), 1);
  ASSERT_EQ(sched_setaffinity(0, sizeof saved, &saved), 0);
}

}  // namespace
}  // namespace pdr::par
