#pragma once
#include <tbb/global_control.h>

namespace solidtex {

/// Sets the number of worker threads while it lives (0 = all cores); throws OptionError for a
/// negative count.
class ThreadLimit {
public:
  explicit ThreadLimit(int threads);

private:
  tbb::global_control control_;
};

}  // namespace solidtex
