#include "common/interruption.h"

#include <chrono>
#include <utility>

namespace solidtex {
namespace {

constexpr auto kInterval = std::chrono::milliseconds(50);

struct Installed {
  std::function<void()> check;
  std::chrono::steady_clock::time_point last{};
};
thread_local Installed* installed = nullptr;

}  // namespace

InterruptionCheck::InterruptionCheck(std::function<void()> check) {
  installed = new Installed{std::move(check)};
}

InterruptionCheck::~InterruptionCheck() {
  delete installed;
  installed = nullptr;
}

void checkInterruption() {
  if (!installed) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - installed->last < kInterval) return;
  installed->last = now;
  installed->check();
}

}  // namespace solidtex
