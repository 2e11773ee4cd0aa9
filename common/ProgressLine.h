#pragma once
/// @file ProgressLine.h
/// @brief The progress line long work shows on stderr.
#include <chrono>
#include <string>

namespace solidtex {

/// The time left of a stage of work, from the rate of its share done so far. A share below the one
/// before starts a new stage (the next step of a job reports its own share from 0).
class TimeLeftEstimate {
public:
  /// The seconds left when `fraction` in [0, 1] is done at `seconds` (any clock); negative until
  /// the stage has run two seconds and gained a hundredth, and for a negative fraction.
  double update(double seconds, double fraction);
  /// Starts a new stage at the next update.
  void restart() { started_ = false; }

private:
  bool started_ = false;
  double startSeconds_ = 0, startFraction_ = 0, lastFraction_ = 0;
};

/// A progress line on stderr. On a terminal it rewrites itself: the step, a bar, the share done and
/// an estimate of the time left; in a log it prints a plain line with the percentage and the time
/// left every ten seconds at most, and a step without a share only after ten quiet seconds.
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
  const Clock::time_point origin_ = Clock::now();
  TimeLeftEstimate timeLeft_;
};

/// A log's progress: "42%, 1m 23s left"; the percentage alone for a negative `secondsLeft`.
std::string shareText(double fraction, double secondsLeft);

/// The terminal's progress line: "STEP [########------------] 42% 1m 23s left"; no bar for a
/// negative fraction, no estimate for a negative `secondsLeft`.
std::string progressText(const std::string& step, double fraction, double secondsLeft);

}  // namespace solidtex
