#include "pipeline/jobSupport.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <tbb/info.h>

#include "common/Error.h"
#include "common/secondsSince.h"

namespace solidtex {

void checkOutputPath(const std::string& path, const std::string& extension) {
  namespace fs = std::filesystem;
  const fs::path out(path);
  if (out.extension() != extension) throw InputError("output " + path + " must end in " + extension);
  const fs::path parent = out.has_parent_path() ? out.parent_path() : fs::path(".");
  if (!fs::is_directory(parent))
    throw InputError("cannot write " + path + ": folder " + parent.string() + " does not exist");
}

void writeJsonFile(const std::string& path, const nlohmann::json& json) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path temp = target.parent_path() / ("." + target.filename().string() + ".partial");
  {
    std::ofstream out(temp);
    if (!out) throw InputError("cannot write report " + path);
    out << json.dump(2) << '\n';
    if (!out) throw InputError("cannot write report " + path);
  }
  std::error_code ec;
  fs::rename(temp, target, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw InputError("cannot write report " + path);
  }
}

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

namespace {

std::size_t checkedThreads(int threads) {
  if (threads < 0) throw InputError("--threads must not be negative (0 = all cores)");
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

void ProgressLine::update(const std::string& text) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const bool terminal = isatty(STDERR_FILENO);
  const auto interval = terminal ? std::chrono::milliseconds(100) : std::chrono::milliseconds(2000);
  if (dirty_ && now - last_ < interval) return;
  last_ = now;
  std::fprintf(stderr, terminal ? "\r\033[K%s" : "%s\n", text.c_str());
  dirty_ = terminal;
}

void ProgressLine::done() {
  if (dirty_) std::fputc('\n', stderr);
  dirty_ = false;
}

}  // namespace solidtex
