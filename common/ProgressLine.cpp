#include "common/ProgressLine.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace solidtex {

namespace {

std::string timeLeftText(double secondsLeft) {
  const long seconds = std::lround(secondsLeft);
  char left[48];
  if (seconds >= 3600)
    std::snprintf(left, sizeof left, "%ldh %02ldm left", seconds / 3600, seconds / 60 % 60);
  else if (seconds >= 60)
    std::snprintf(left, sizeof left, "%ldm %02lds left", seconds / 60, seconds % 60);
  else
    std::snprintf(left, sizeof left, "%lds left", seconds);
  return left;
}

}  // namespace

std::string shareText(double fraction, double secondsLeft) {
  const std::string percent = std::to_string(int(std::clamp(fraction, 0.0, 1.0) * 100)) + "%";
  return secondsLeft >= 0 ? percent + ", " + timeLeftText(secondsLeft) : percent;
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
  return secondsLeft >= 0 ? text + " " + timeLeftText(secondsLeft) : text;
}

double TimeLeftEstimate::update(double seconds, double fraction) {
  if (!(fraction >= 0)) return -1;
  if (!started_ || fraction < lastFraction_) {
    started_ = true;
    startSeconds_ = seconds;
    startFraction_ = fraction;
  }
  lastFraction_ = fraction;
  const double elapsed = seconds - startSeconds_, gained = fraction - startFraction_;
  return gained > 0.01 && elapsed > 2 ? elapsed * std::max(0.0, 1 - fraction) / gained : -1;
}

void ProgressLine::update(const std::string& step, double fraction) {
  if (!enabled_) return;
  const auto now = Clock::now();
  const double left = timeLeft_.update(std::chrono::duration<double>(now - origin_).count(), fraction);
  const bool terminal = isatty(STDERR_FILENO), shared = fraction >= 0;
  // A log gets a line every ten seconds at most, with the percentage and the time left; a step
  // without a share shows only once the run has gone ten seconds without a line (a quick run or
  // failure stays quiet). A terminal sees the line rewritten ten times a second.
  const auto interval = terminal ? std::chrono::milliseconds(100) : std::chrono::milliseconds(10000);
  if (!terminal && !shared && now - (started_ ? last_ : origin_) < interval) return;
  if (started_ && shared && now - last_ < interval) return;  // a new step always shows
  started_ = true;
  last_ = now;
  if (!terminal) {
    if (shared)
      std::fprintf(stderr, "%s (%s)\n", step.c_str(), shareText(fraction, left).c_str());
    else
      std::fprintf(stderr, "%s\n", step.c_str());
    return;
  }
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
  timeLeft_.restart();
}

}  // namespace solidtex
