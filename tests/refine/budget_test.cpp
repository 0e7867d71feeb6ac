// The vertex cap of SeqRefinement (refine/budget.hpp): derived from the input and the sizes
// asked for, and never above what half the machine's memory holds, so that a run that would
// not end (outside the theory) stops with exit 3 and a report instead of exhausting memory;
// a cap the user gives (--max-vertices) is kept as given.
#include <gtest/gtest.h>
#include <unistd.h>

#include <vector>

#include "refine/budget.hpp"
#include "refine/seq_refinement.hpp"

namespace pdr::refine {
namespace {

const std::vector<Point> kBox{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};

TEST(VertexBudget, DerivedCapIsBoundedByMemory) {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  ASSERT_GT(pages, 0);
  const double half = static_cast<double>(pages) * static_cast<double>(page) / 2;
  EXPECT_LE(static_cast<double>(memory_vertex_limit()), half / kRefineVertexBytes);
  EXPECT_GT(static_cast<double>(memory_vertex_limit()), half / kRefineVertexBytes - 1);

  RefineOptions o;
  o.d = 1e-6;  // 16 (box volume) / u^3 = 1.3e20 vertices: far past any machine
  const VertexBudget tiny(kBox, o);
  EXPECT_EQ(tiny.cap(), memory_vertex_limit());
  std::string why;
  EXPECT_TRUE(tiny.reached(tiny.cap(), why));
  EXPECT_NE(why.find("memory"), std::string::npos) << why;

  o.d = 0.25;  // a coarse run: the derived figure, far below the memory bound
  const VertexBudget coarse(kBox, o);
  EXPECT_LT(coarse.cap(), memory_vertex_limit());
  EXPECT_EQ(coarse.cap(), static_cast<std::size_t>(1000.0 + 64.0 * 5 + 16.0 / (0.125 * 0.125 * 0.125)));
}

TEST(VertexBudget, UserCapIsKept) {
  RefineOptions o;
  o.d = 1e-6;
  o.max_vertices = memory_vertex_limit() + 12345;
  const VertexBudget b(kBox, o);
  EXPECT_EQ(b.cap(), o.max_vertices);
  std::string why;
  EXPECT_FALSE(b.reached(o.max_vertices - 1, why));
  EXPECT_TRUE(b.reached(o.max_vertices, why));
  EXPECT_NE(why.find("--max-vertices"), std::string::npos) << why;
}

// A run can hold more than the cap's kRefineVertexBytes a vertex (outside the theory, the
// refused tets' reasons among it: a lateral repair cascade held 2.9 KB a vertex): the budget
// reads the resident memory every 4096th call and stops once it is past the limit, for good.
TEST(VertexBudget, ResidentMemoryPastTheLimitStops) {
  EXPECT_GT(resident_bytes(), 0.0);
  RefineOptions o;
  o.d = 0.25;
  VertexBudget b(kBox, o);
  std::string why;
  for (int i = 0; i < 5000; ++i) ASSERT_FALSE(b.reached(10, why)) << why;  // half the machine
  b.set_memory_limit(1);  // one byte: every process is past it
  bool stopped = false;
  for (int i = 0; i < 4096 && !stopped; ++i) stopped = b.reached(10, why);
  ASSERT_TRUE(stopped);
  EXPECT_NE(why.find("refine.memory"), std::string::npos) << why;
  std::string again;
  EXPECT_TRUE(b.reached(10, again));
  EXPECT_EQ(again, why);
}

}  // namespace
}  // namespace pdr::refine
