#include "pipeline/jobSupport.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <tbb/info.h>

#include "common/Error.h"
#include "common/memoryBudget.h"
#include "common/secondsSince.h"
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

void requireVolumeMemory(const std::string& what, const Dims& dims, double bytesPerVoxel) {
  constexpr double kEveryRun = 160.0 * 1024 * 1024;
  if (dims.x <= 0 || dims.y <= 0 || dims.z <= 0) return;  // the command's own checks say what is wrong
  const double voxels = double(dims.x) * double(dims.y) * double(dims.z);
  const std::string size =
      std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z);
  if (voxels > 4294967295.0)
    throw OptionError(what + " of " + size + " voxels: more than 2^32 - 1 voxels, the most a volume holds");
  requireMemory(what + " of " + size + " voxels", voxels * bytesPerVoxel + kEveryRun);
}

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

namespace {

std::size_t checkedThreads(int threads) {
  if (threads < 0) throw OptionError("--threads must not be negative (0 = all cores)");
  return std::size_t(threads > 0 ? threads : tbb::info::default_concurrency());
}

}  // namespace

ThreadLimit::ThreadLimit(int threads)
    : control_(tbb::global_control::max_allowed_parallelism, checkedThreads(threads)) {}

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
