#include "io/detail/CapturedStderr.h"

#include <cstdio>
#include <iostream>

#include <sys/mman.h>
#include <unistd.h>

namespace solidtex::io::detail {
namespace {

constexpr std::size_t kMaxCaptured = 4096;  // bytes kept: the gist, not a flood of warnings

std::recursive_mutex& captureMutex() {
  static std::recursive_mutex mutex;
  return mutex;
}

// What is written before the switch must reach the real stderr, and what is written during the
// capture must not leak out after it.
void flushStderr() {
  std::cerr.flush();
  std::fflush(stderr);
}

int anonymousFile() {
  const int fd = ::memfd_create("solidtex-stderr", MFD_CLOEXEC);
  if (fd >= 0) return fd;
  std::FILE* file = std::tmpfile();  // kernels without memfd: an unlinked temporary file
  if (!file) return -1;
  const int dup = ::dup(::fileno(file));
  std::fclose(file);
  return dup;
}

std::string readAll(int fd) {
  std::string text(kMaxCaptured, '\0');
  std::size_t got = 0;
  while (got < text.size()) {
    const ssize_t n = ::pread(fd, text.data() + got, text.size() - got, off_t(got));
    if (n <= 0) break;
    got += std::size_t(n);
  }
  text.resize(got);
  return text;
}

// Lines joined with "; ", blank ones dropped, whitespace trimmed.
std::string oneLine(const std::string& text) {
  std::string line, current;
  const auto flushLine = [&] {
    const auto first = current.find_first_not_of(" \t\r");
    const auto last = current.find_last_not_of(" \t\r");
    if (first != std::string::npos)
      line += (line.empty() ? "" : "; ") + current.substr(first, last - first + 1);
    current.clear();
  };
  for (char c : text) c == '\n' ? flushLine() : current.push_back(c);
  flushLine();
  return line;
}

}  // namespace

CapturedStderr::CapturedStderr() : lock_(captureMutex()) {
  flushStderr();
  capture_ = anonymousFile();
  if (capture_ < 0) return;
  saved_ = ::dup(STDERR_FILENO);
  if (saved_ < 0 || ::dup2(capture_, STDERR_FILENO) < 0) {
    if (saved_ >= 0) ::close(saved_);
    ::close(capture_);
    saved_ = capture_ = -1;
  }
}

CapturedStderr::~CapturedStderr() {
  restore();
  if (capture_ >= 0) ::close(capture_);
}

void CapturedStderr::restore() {
  if (saved_ < 0) return;
  flushStderr();
  ::dup2(saved_, STDERR_FILENO);
  ::close(saved_);
  saved_ = -1;
}

std::string CapturedStderr::finish() {
  restore();
  return capture_ >= 0 ? oneLine(readAll(capture_)) : std::string();
}

}  // namespace solidtex::io::detail
