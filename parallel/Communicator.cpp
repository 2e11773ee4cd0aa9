#include "parallel/Communicator.h"

#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <thread>

#ifdef SOLIDTEX_WITH_MPI
#include <mpi.h>
#endif

#include "common/Error.h"

namespace solidtex {
namespace {

int environmentInt(const char* name, int fallback) {
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  return *end == '\0' && value >= 0 && value <= std::numeric_limits<int>::max() ? int(value) : fallback;
}

#ifdef SOLIDTEX_WITH_MPI
// MPI's counts are ints: a part goes in pieces of at most 1 GiB. MPI's errors end the run (its
// default handler), so calls are not checked.
constexpr std::size_t kPiece = std::size_t(1) << 30;
constexpr int kSizeTag = 1, kPieceTag = 2;

void finalizeMpi() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}
#endif

}  // namespace

LaunchedAs launchedAs() {
  LaunchedAs launched;
  launched.size = environmentInt("OMPI_COMM_WORLD_SIZE", environmentInt("PMI_SIZE", 1));
  launched.rank = environmentInt("OMPI_COMM_WORLD_RANK", environmentInt("PMI_RANK", 0));
  launched.localSize = environmentInt("OMPI_COMM_WORLD_LOCAL_SIZE", environmentInt("MPI_LOCALNRANKS", 1));
  launched.size = std::max(launched.size, 1);
  launched.localSize = std::clamp(launched.localSize, 1, launched.size);
  return launched;
}

int threadsPerProcess(int asked) {
  if (asked != 0) return asked;
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  const int share = std::max(1, cores / launchedAs().localSize);
  cpu_set_t set;
  CPU_ZERO(&set);
  const int bound = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 0;
  return bound > 0 ? std::min(bound, share) : share;
}

void requireOneProcess(const std::string& what) {
  const int size = launchedAs().size;
  if (size > 1)
    throw OptionError(
        what + " runs as one process, but mpirun started " + std::to_string(size) +
        "; only the --bricks of particle solids and volume exemplars are shared among processes");
}

const Communicator& Communicator::world() {
  static const Communicator world = [] {
    const LaunchedAs launched = launchedAs();
    if (launched.size == 1) return Communicator(0, 1);
#ifdef SOLIDTEX_WITH_MPI
    // Only this thread calls MPI; TBB's workers never do.
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    std::atexit(finalizeMpi);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return Communicator(rank, size);
#else
    throw InputError("this solidtex was built without MPI, so each of the " + std::to_string(launched.size) +
                     " processes mpirun started would make the whole volume; rebuild it with "
                     "libopenmpi-dev installed");
#endif
  }();
  return world;
}

std::vector<std::string> Communicator::gatherToRoot(std::string bytes) const {
  std::vector<std::string> parts;
  if (size_ == 1) {
    parts.push_back(std::move(bytes));
    return parts;
  }
#ifdef SOLIDTEX_WITH_MPI
  if (rank_ != 0) {
    const std::uint64_t length = bytes.size();
    MPI_Send(&length, 1, MPI_UINT64_T, 0, kSizeTag, MPI_COMM_WORLD);
    for (std::size_t at = 0; at < bytes.size(); at += kPiece)
      MPI_Send(bytes.data() + at, int(std::min(kPiece, bytes.size() - at)), MPI_BYTE, 0, kPieceTag,
               MPI_COMM_WORLD);
    return parts;
  }
  parts.push_back(std::move(bytes));
  for (int from = 1; from < size_; ++from) {
    std::uint64_t length = 0;
    MPI_Recv(&length, 1, MPI_UINT64_T, from, kSizeTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    std::string part(length, '\0');
    for (std::size_t at = 0; at < part.size(); at += kPiece)
      MPI_Recv(part.data() + at, int(std::min(kPiece, part.size() - at)), MPI_BYTE, from, kPieceTag,
               MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    parts.push_back(std::move(part));
  }
#endif
  return parts;
}

std::vector<std::string> Communicator::allGather(std::string bytes) const {
  std::vector<std::string> parts;
  if (size_ == 1) {
    parts.push_back(std::move(bytes));
    return parts;
  }
#ifdef SOLIDTEX_WITH_MPI
  const std::uint64_t length = bytes.size();
  std::vector<std::uint64_t> lengths(std::size_t(size_), 0);
  MPI_Allgather(&length, 1, MPI_UINT64_T, lengths.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD);
  for (int from = 0; from < size_; ++from) {
    std::string part = from == rank_ ? std::move(bytes) : std::string(lengths[std::size_t(from)], '\0');
    for (std::size_t at = 0; at < part.size(); at += kPiece)
      MPI_Bcast(part.data() + at, int(std::min(kPiece, part.size() - at)), MPI_BYTE, from, MPI_COMM_WORLD);
    parts.push_back(std::move(part));
  }
#endif
  return parts;
}

std::string Communicator::firstOf(const std::string& text) const {
  if (size_ == 1) return text;
#ifdef SOLIDTEX_WITH_MPI
  // Texts are one-line messages: their lengths fit MPI's ints.
  const int length = int(std::min<std::size_t>(text.size(), 1 << 16));
  std::vector<int> lengths(std::size_t(size_), 0), offsets(std::size_t(size_), 0);
  MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (std::size_t r = 1; r < lengths.size(); ++r) offsets[r] = offsets[r - 1] + lengths[r - 1];
  std::string all(std::size_t(offsets.back() + lengths.back()), '\0');
  MPI_Allgatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
                 MPI_COMM_WORLD);
  for (std::size_t r = 0; r < lengths.size(); ++r)
    if (lengths[r] > 0) return all.substr(std::size_t(offsets[r]), std::size_t(lengths[r]));
#endif
  return {};
}

}  // namespace solidtex
