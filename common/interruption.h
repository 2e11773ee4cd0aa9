#pragma once
/// @file interruption.h
/// @brief Stopping long work early at the request of whoever started it (Python's Ctrl-C).
#include <functional>

namespace solidtex {

/// While it lives, checkInterruption() on the thread that made it calls `check` (at most every
/// 50 ms); `check` throws to stop the work. Calls on other threads (TBB's workers) do nothing: the
/// making thread takes part in every parallel loop it starts, so it still checks.
class InterruptionCheck {
public:
  explicit InterruptionCheck(std::function<void()> check);
  ~InterruptionCheck();
  InterruptionCheck(const InterruptionCheck&) = delete;
  InterruptionCheck& operator=(const InterruptionCheck&) = delete;
};

/// Called by long loops between units of work: runs the check of this thread, if one is installed.
void checkInterruption();

}  // namespace solidtex
