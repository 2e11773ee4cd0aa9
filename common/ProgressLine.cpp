#include "common/ProgressLine.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace solidtex {

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
