#include "common/memoryBudget.h"

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "common/Error.h"

namespace solidtex {
namespace {

constexpr std::uint64_t kUnlimited = std::numeric_limits<std::uint64_t>::max();
std::atomic<std::uint64_t> userLimit{0};

// The first number after `key` in a /proc file, in the file's units (times `unit`).
std::uint64_t procField(const char* file, const std::string& key, std::uint64_t unit) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) {
      std::istringstream fields(line.substr(key.size()));
      std::uint64_t value = 0;
      if (fields >> value) return value * unit;
    }
  return kUnlimited;
}

std::uint64_t readNumber(const char* file) {
  std::ifstream in(file);
  std::string text;
  if (!(in >> text) || text == "max") return kUnlimited;
  try {
    return std::stoull(text);
  } catch (const std::exception&) {
    return kUnlimited;
  }
}

// cgroup v2 (memory.max) or v1 (memory.limit_in_bytes) of this process, less what the group uses.
std::uint64_t cgroupHeadroom() {
  std::ifstream in("/proc/self/cgroup");
  std::string line, path;
  while (std::getline(in, line)) {
    if (line.rfind("0::", 0) == 0) path = "/sys/fs/cgroup" + line.substr(3);
  }
  for (const std::string& dir : {path, std::string("/sys/fs/cgroup")}) {
    if (dir.empty()) continue;
    const std::uint64_t limit = readNumber((dir + "/memory.max").c_str());
    if (limit != kUnlimited) {
      const std::uint64_t used = readNumber((dir + "/memory.current").c_str());
      return used == kUnlimited ? limit : limit - std::min(limit, used);
    }
  }
  const std::uint64_t v1 = readNumber("/sys/fs/cgroup/memory/memory.limit_in_bytes");
  if (v1 >= (std::uint64_t(1) << 60)) return kUnlimited;  // v1 reports "no limit" as a huge number
  const std::uint64_t used = readNumber("/sys/fs/cgroup/memory/memory.usage_in_bytes");
  return used == kUnlimited ? v1 : v1 - std::min(v1, used);
}

std::uint64_t rlimitHeadroom(int resource, std::uint64_t used) {
  rlimit limit{};
  if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kUnlimited;
  return std::uint64_t(limit.rlim_cur) - std::min<std::uint64_t>(limit.rlim_cur, used);
}

}  // namespace

std::uint64_t availableMemoryBytes() {
  std::uint64_t available = procField("/proc/meminfo", "MemAvailable:", 1024);
  available = std::min(available, cgroupHeadroom());
  const std::uint64_t mapped = procField("/proc/self/status", "VmSize:", 1024);
  const std::uint64_t data = procField("/proc/self/status", "VmData:", 1024);
  available = std::min(available, rlimitHeadroom(RLIMIT_AS, mapped == kUnlimited ? 0 : mapped));
  available = std::min(available, rlimitHeadroom(RLIMIT_DATA, data == kUnlimited ? 0 : data));
  if (const std::uint64_t cap = userLimit.load(); cap > 0) {
    const std::uint64_t resident = procField("/proc/self/status", "VmRSS:", 1024);
    available = std::min(available, cap - std::min(cap, resident == kUnlimited ? 0 : resident));
  }
  return available;
}

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

MemoryCap::MemoryCap(std::uint64_t bytes) {
  rlimit limit{};
  const std::uint64_t mapped = procField("/proc/self/status", "VmSize:", 1024);
  if (kSanitized || mapped == kUnlimited || getrlimit(RLIMIT_AS, &limit) != 0) return;
  const std::uint64_t cap = mapped + bytes;
  if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur <= cap) return;
  previous_ = limit.rlim_cur;
  limit.rlim_cur = cap;
  active_ = setrlimit(RLIMIT_AS, &limit) == 0;
}

MemoryCap::~MemoryCap() {
  rlimit limit{};
  if (!active_ || getrlimit(RLIMIT_AS, &limit) != 0) return;
  limit.rlim_cur = previous_;
  setrlimit(RLIMIT_AS, &limit);
}

void setMemoryLimit(std::uint64_t bytes) { userLimit.store(bytes); }

std::uint64_t parseMemorySize(const std::string& text) {
  double value = 0;
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  std::string unit = text.substr(used);
  if (!unit.empty() && unit.back() == 'B') unit.pop_back();
  if (unit.size() == 2 && unit[1] == 'i') unit.pop_back();
  const std::string units = "KMGT";
  double scale = 1;
  if (unit.size() == 1 && units.find(char(std::toupper(unit[0]))) != std::string::npos)
    scale = std::pow(1024.0, double(units.find(char(std::toupper(unit[0]))) + 1));
  else if (!unit.empty())
    used = 0;
  const double bytes = value * scale;
  if (used == 0 || !std::isfinite(bytes) || bytes < 1 || bytes > 1e18)
    throw InputError("cannot read the memory size '" + text + "': use a number with K, M, G or T (8G)");
  return std::uint64_t(bytes);
}

std::string formatBytes(double bytes) {
  char text[32];
  if (bytes >= 1024.0 * 1024 * 1024)
    std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024 * 1024));
  else
    std::snprintf(text, sizeof text, "%.0f MiB", std::ceil(bytes / (1024.0 * 1024)));
  return text;
}

void requireMemory(const std::string& what, double bytes) {
  const std::uint64_t available = availableMemoryBytes();
  if (bytes > double(available))
    throw InputError(what + " needs about " + formatBytes(bytes) + " of memory, " +
                     formatBytes(double(available)) + " available" +
                     (userLimit.load() > 0 ? " under --max-memory" : ""));
}

void requireVolumeMemory(const std::string& what, const Dims& dims, double bytesPerVoxel) {
  constexpr double kEveryRun = 160.0 * 1024 * 1024;
  requireVolumeBytes(what, dims,
                     double(dims.x) * double(dims.y) * double(dims.z) * bytesPerVoxel + kEveryRun);
}

void requireVolumeBytes(const std::string& what, const Dims& dims, double bytes) {
  if (dims.x <= 0 || dims.y <= 0 || dims.z <= 0) return;  // the command's own checks say what is wrong
  const double voxels = double(dims.x) * double(dims.y) * double(dims.z);
  const std::string size =
      std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z);
  if (voxels > 4294967295.0)
    throw OptionError(what + " of " + size + " voxels: more than 2^32 - 1 voxels, the most a volume holds");
  requireMemory(what + " of " + size + " voxels", bytes);
}

void returnFreedMemory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

}  // namespace solidtex
