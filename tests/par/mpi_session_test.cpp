// single_host_pml() (par/mpi_transport.hpp): Open MPI's "ob1" for a run whose ranks all
// share one host, nothing for a run over several hosts, outside a launcher, or when the
// user chose a messaging layer.
#include "par/mpi_transport.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace pdr::par {
namespace {

// Sets (or, for nullptr, removes) the launcher's variables and the user's choice.
void launched(const char* size, const char* local, const char* pml) {
  const auto put = [](const char* name, const char* value) {
    if (value == nullptr)
      unsetenv(name);
    else
      setenv(name, value, 1);
  };
  put("OMPI_COMM_WORLD_SIZE", size);
  put("OMPI_COMM_WORLD_LOCAL_SIZE", local);
  put("OMPI_MCA_pml", pml);
}

TEST(SingleHostPml, Ob1WhenEveryRankIsOnThisHost) {
  launched("2", "2", nullptr);
  ASSERT_NE(single_host_pml(), nullptr);
  EXPECT_EQ(std::string(single_host_pml()), "ob1");
  launched("1", "1", nullptr);
  EXPECT_NE(single_host_pml(), nullptr);
}

TEST(SingleHostPml, NothingOverSeveralHostsOrOutsideALauncher) {
  launched("4", "2", nullptr);
  EXPECT_EQ(single_host_pml(), nullptr);
  launched(nullptr, nullptr, nullptr);
  EXPECT_EQ(single_host_pml(), nullptr);
  launched("2", nullptr, nullptr);
  EXPECT_EQ(single_host_pml(), nullptr);
  launched("garbage", "garbage", nullptr);
  EXPECT_EQ(single_host_pml(), nullptr);
}

TEST(SingleHostPml, TheUsersChoiceWins) {
  launched("2", "2", "ucx");
  EXPECT_EQ(single_host_pml(), nullptr);
  launched("2", "2", "");
  EXPECT_EQ(single_host_pml(), nullptr);
  launched(nullptr, nullptr, nullptr);
}

}  // namespace
}  // namespace pdr::par
