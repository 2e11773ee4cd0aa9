#pragma once
/// @file ProgressLine.h
/// @brief The progress line long work shows on stderr.
#include <chrono>
#include <optional>
#include <string>

namespace solidtex {

/// A progress line on stderr. On a terminal it rewrites itself: the step, a bar, the share done and
/// an estimate of the time left; in a log it prints a plain line with the percentage every ten
/// seconds at most, and nothing for a step without one.
class ProgressLine {
public:
  explicit ProgressLine(bool enabled) : enabled_(enabled) {}
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ~ProgressLine();
  /// `fraction`: the share of the work done in [0, 1], negative when unknown (no bar).
  void update(const std::string& step, double fraction = -1);
  /// Ends the line; the next update starts a new estimate.
  void done();

private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool dirty_ = false;
  bool started_ = false;
  Clock::time_point last_{};
  std::optional<Clock::time_point> firstFraction_;  ///< when the current estimate began
  double fractionAtFirst_ = 0;                      ///< and the share done then
};

/// The terminal's progress line: "STEP [########------------] 42% 1m 23s left"; no bar for a
/// negative fraction, no estimate for a negative `secondsLeft`.
std::string progressText(const std::string& step, double fraction, double secondsLeft);

}  // namespace solidtex
