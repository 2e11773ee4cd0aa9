#pragma once
/// @file Communicator.h
/// @brief The processes of one run: MPI's world when mpirun started several, else this one alone.
#include <cstdint>
#include <string>
#include <vector>

namespace solidtex {

/// Where mpirun put this process, read from the environment it set (OpenMPI's, or PMI's for
/// other launchers) without starting MPI; {0, 1, 1} for a process started otherwise.
struct LaunchedAs {
  int rank = 0;
  int size = 1;
  int localSize = 1;  ///< processes on this machine, sharing its cores
};
LaunchedAs launchedAs();

/// Threads for this process: `asked`, or when it is 0 the process's share of the machine's cores,
/// and no more than mpirun bound it to (one core each for up to two processes, a socket beyond):
/// more threads than bound cores only take turns.
int threadsPerProcess(int asked);

/// Throws OptionError when mpirun started several processes for `what`, which runs as one.
void requireOneProcess(const std::string& what);

/// The processes of this run. MPI starts with the first call to world() in a process mpirun
/// started among several, and ends when the process exits.
class Communicator {
public:
  /// Throws InputError when mpirun started several processes and this build has no MPI.
  static const Communicator& world();

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// On rank 0: every rank's bytes in rank order (its own moved in). Elsewhere: sends its own to
  /// rank 0 and returns nothing. Parts of any size: larger than MPI's int counts too.
  std::vector<std::string> gatherToRoot(std::string bytes) const;
  /// On every rank: every rank's bytes in rank order. Parts of any size.
  std::vector<std::string> allGather(std::string bytes) const;
  /// On every rank: the first non-empty `text` in rank order (empty when all are), for agreeing
  /// on a failure before work that every rank must share.
  std::string firstOf(const std::string& text) const;

private:
  Communicator(int rank, int size) : rank_(rank), size_(size) {}
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace solidtex
