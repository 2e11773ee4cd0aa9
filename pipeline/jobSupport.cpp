#include "pipeline/jobSupport.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/Error.h"
#include "common/writeFileBytes.h"

namespace solidtex {

void writeJsonFile(const std::string& path, const nlohmann::json& json) {
  const std::string text = json.dump(2) + '\n';
  writeFileBytes(path, text.data(), text.size());
}

void addReport(OutputFiles& outputs, const std::optional<std::string>& report) {
  if (report) outputs.addFile("--report", *report, {".json"});
}

void addVolumeOutputs(OutputFiles& outputs, const std::string& vdb, const std::optional<std::string>& report,
                      const std::optional<std::string>& preview) {
  outputs.addFile("-o", vdb, {".vdb"});
  addReport(outputs, report);
  if (preview) outputs.addFolder("--preview", *preview);
}

void writeReport(OutputFiles& outputs, const std::optional<std::string>& report, const nlohmann::json& json) {
  if (report) outputs.write(*report, [&](const std::string& path) { writeJsonFile(path, json); });
}

std::string progressText(const std::string& step, double fraction, double secondsLeft) {
  if (!(fraction >= 0)) return step;  // unknown, or NaN
  constexpr int kBarWidth = 24;
  fraction = std::min(fraction, 1.0);
  const int filled = int(fraction * kBarWidth + 0.5);
  char percent[16];
  std::snprintf(percent, sizeof percent, "%3d%%", int(fraction * 100));
  std::string text = step + " [" + std::string(std::size_t(filled), '#') +
                     std::string(std::size_t(kBarWidth - filled), '-') + "] " + percent;
  if (secondsLeft >= 0) {
    const long seconds = std::lround(secondsLeft);
    char left[48];
    if (seconds >= 3600)
      std::snprintf(left, sizeof left, " %ldh %02ldm left", seconds / 3600, seconds / 60 % 60);
    else if (seconds >= 60)
      std::snprintf(left, sizeof left, " %ldm %02lds left", seconds / 60, seconds % 60);
    else
      std::snprintf(left, sizeof left, " %lds left", seconds);
    text += left;
  }
  return text;
}

void warnOfDroppedRegions(const ExemplarStats& stats, ProgressLine* progress) {
  if (stats.areaShareBelowMinArea <= 0.5) return;
  if (progress) progress->done();
  std::fprintf(stderr,
               "solidtex: warning: %s: %d regions, %.0f%% of the area that stands out, are smaller than the "
               "minimum area of %g pixels and were dropped (see --min-area)\n",
               stats.name.c_str(), stats.regionsBelowMinArea, 100 * stats.areaShareBelowMinArea,
               stats.minArea);
}

void ProgressLine::update(const std::string& step, double fraction) {
  if (!enabled_) return;
  const auto now = Clock::now();
  if (fraction >= 0 && !firstFraction_) {
    firstFraction_ = now;
    fractionAtFirst_ = fraction;
  }
  const bool terminal = isatty(STDERR_FILENO);
  // A log gets a line with a percentage every ten seconds at most, and nothing for a step without
  // one (a quick failure stays one line); a terminal sees the line rewritten ten times a second.
  if (!terminal && !(fraction >= 0)) return;
  const auto interval = terminal ? std::chrono::milliseconds(100) : std::chrono::milliseconds(10000);
  if (started_ && fraction >= 0 && now - last_ < interval) return;  // a new step always shows
  started_ = true;
  last_ = now;
  if (!terminal) {
    std::fprintf(stderr, "%s (%d%%)\n", step.c_str(), int(std::min(fraction, 1.0) * 100));
    return;
  }
  // The rate so far, once there is enough of it to go by, gives the time left.
  const double elapsed = firstFraction_ ? std::chrono::duration<double>(now - *firstFraction_).count() : 0;
  const double gained = fraction - fractionAtFirst_;
  const double left = gained > 0.01 && elapsed > 2 ? elapsed * (1 - fraction) / gained : -1;
  std::fprintf(stderr, "\r\033[K%s", progressText(step, fraction, left).c_str());
  dirty_ = true;
}

// Unwound by an error: the line goes, so that the error's message stands alone.
ProgressLine::~ProgressLine() {
  if (dirty_) std::fputs("\r\033[K", stderr);
}

void ProgressLine::done() {
  if (dirty_) std::fputc('\n', stderr);
  dirty_ = false;
  firstFraction_.reset();
}

}  // namespace solidtex
