#include "common/PhaseTimer.h"

#include "common/secondsSince.h"

namespace solidtex {

void PhaseTimer::start(const std::string& name) {
  const auto now = Clock::now();
  if (!current_.empty()) phases_[current_] = std::chrono::duration<double>(now - phaseBegin_).count();
  current_ = name;
  phaseBegin_ = now;
}

nlohmann::json PhaseTimer::finish() {
  start("");
  phases_["total"] = secondsSince(begin_);
  return phases_;
}

}  // namespace solidtex
