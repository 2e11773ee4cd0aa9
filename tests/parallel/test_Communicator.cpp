#include <cstdlib>

#include <gtest/gtest.h>

#include "common/Error.h"
#include "parallel/Communicator.h"

namespace solidtex {
namespace {

// The variables mpirun sets, for as long as it lives.
struct LaunchedByMpirun {
  LaunchedByMpirun(const char* rank, const char* size, const char* local) {
    setenv("OMPI_COMM_WORLD_RANK", rank, 1);
    setenv("OMPI_COMM_WORLD_SIZE", size, 1);
    setenv("OMPI_COMM_WORLD_LOCAL_SIZE", local, 1);
  }
  ~LaunchedByMpirun() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_LOCAL_SIZE"})
      unsetenv(name);
  }
};

TEST(Communicator, AProcessStartedAloneIsRankZeroOfOne) {
  const LaunchedAs launched = launchedAs();
  EXPECT_EQ(launched.rank, 0);
  EXPECT_EQ(launched.size, 1);
  EXPECT_NO_THROW(requireOneProcess("particles"));
  const Communicator& world = Communicator::world();
  EXPECT_EQ(world.size(), 1);
  const std::vector<std::string> parts = world.gatherToRoot("abc");
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0], "abc");
  EXPECT_EQ(world.firstOf("a failure"), "a failure");
  EXPECT_EQ(world.allGather("xyz"), std::vector<std::string>{"xyz"});
}

TEST(Communicator, ReadsWhereMpirunPutIt) {
  const LaunchedByMpirun launched("3", "8", "4");
  const LaunchedAs as = launchedAs();
  EXPECT_EQ(as.rank, 3);
  EXPECT_EQ(as.size, 8);
  EXPECT_EQ(as.localSize, 4);
  EXPECT_THROW(requireOneProcess("particles"), OptionError);
}

TEST(Communicator, IgnoresWhatIsNoRank) {
  const LaunchedByMpirun launched("x", "-2", "9");
  const LaunchedAs as = launchedAs();
  EXPECT_EQ(as.rank, 0);
  EXPECT_EQ(as.size, 1);
  EXPECT_EQ(as.localSize, 1);
}

}  // namespace
}  // namespace solidtex
