// Communicator as a build without MPI has it (compiled here without SOLIDTEX_WITH_MPI): bricks
// still run as one process, and a start by mpirun as several is refused with one line.
#include <cstdlib>

#include <gtest/gtest.h>

#include "common/Error.h"
#include "parallel/Communicator.h"

namespace solidtex {
namespace {

TEST(CommunicatorWithoutMpi, RunsAloneAndRefusesSeveralProcesses) {
  setenv("OMPI_COMM_WORLD_SIZE", "2", 1);
  try {
    Communicator::world();
    ADD_FAILURE() << "a build without MPI ran as one of several processes";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("built without MPI"), std::string::npos) << e.what();
  }
  unsetenv("OMPI_COMM_WORLD_SIZE");
}

}  // namespace
}  // namespace solidtex
