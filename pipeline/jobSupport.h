#pragma once
#include <chrono>
#include <string>

#include <tbb/global_control.h>
#include <nlohmann/json.hpp>

namespace solidtex {

/// Refuses (InputError) an output path without the given extension (".vdb") or in a missing folder.
void checkOutputPath(const std::string& path, const std::string& extension);

/// Writes JSON to `path` through a temporary name, so no partial report is ever left.
void writeJsonFile(const std::string& path, const nlohmann::json& json);

/// Peak resident memory of this process so far, in MiB.
double peakMemoryMiB();

/// Sets the number of worker threads for the rest of the process (0 = all cores).
class ThreadLimit {
public:
  explicit ThreadLimit(int threads);

private:
  tbb::global_control control_;
};

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

/// A progress line on stderr that rewrites itself on a terminal and prints sparse lines otherwise.
class ProgressLine {
public:
  explicit ProgressLine(bool enabled) : enabled_(enabled) {}
  void update(const std::string& text);
  void done();

private:
  bool enabled_;
  bool dirty_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace solidtex
