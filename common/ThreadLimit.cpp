#include "common/ThreadLimit.h"

#include <tbb/info.h>

#include "common/Error.h"

namespace solidtex {
namespace {

std::size_t checkedThreads(int threads) {
  if (threads < 0) throw OptionError("--threads must not be negative (0 = all cores)");
  return std::size_t(threads > 0 ? threads : tbb::info::default_concurrency());
}

}  // namespace

ThreadLimit::ThreadLimit(int threads)
    : control_(tbb::global_control::max_allowed_parallelism, checkedThreads(threads)) {}

}  // namespace solidtex
