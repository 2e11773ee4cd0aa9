#pragma once
#include <chrono>
#include <string>

#include <nlohmann/json.hpp>

namespace solidtex {

/// Wall time of named phases, collected into a report.
class PhaseTimer {
public:
  /// Ends the running phase (if any) and starts `name`.
  void start(const std::string& name);
  /// Ends the running phase; returns {phase: seconds, ..., "total": seconds}.
  nlohmann::json finish();

private:
  using Clock = std::chrono::steady_clock;
  nlohmann::json phases_ = nlohmann::json::object();
  std::string current_;
  Clock::time_point begin_ = Clock::now(), phaseBegin_ = begin_;
};

}  // namespace solidtex
