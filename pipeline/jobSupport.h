#pragma once
#include <chrono>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/Grid.h"
#include "common/OutputFiles.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// Writes JSON to `path`, checking every write (commands write through OutputFiles).
void writeJsonFile(const std::string& path, const nlohmann::json& json);

/// Declares `--report`, when given, as one of the command's outputs (a .json file).
void addReport(OutputFiles& outputs, const std::optional<std::string>& report);
/// Declares a volume job's outputs: the .vdb, and the report and preview folder when given.
void addVolumeOutputs(OutputFiles& outputs, const std::string& vdb, const std::optional<std::string>& report,
                      const std::optional<std::string>& preview);

/// Writes the report, when asked for, through `outputs`.
void writeReport(OutputFiles& outputs, const std::optional<std::string>& report, const nlohmann::json& json);

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

/// A warning line on stderr, below the progress line when there is one, when most of what stood
/// out in the photo (by area) was dropped as smaller than the minimum area: the solid would miss it.
void warnOfDroppedRegions(const ExemplarStats& stats, ProgressLine* progress = nullptr);

/// The terminal's progress line: "STEP [########------------] 42% 1m 23s left"; no bar for a
/// negative fraction, no estimate for a negative `secondsLeft`.
std::string progressText(const std::string& step, double fraction, double secondsLeft);

}  // namespace solidtex
