#include "common/writeFileBytes.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "common/Error.h"

namespace solidtex {
namespace {

[[noreturn]] void fail(const std::string& path, int error) {
  throw InputError("cannot write " + path + ": " + std::strerror(error));
}

void writeAll(int fd, const std::string& path, ByteSpan part) {
  const auto* bytes = static_cast<const char*>(part.data);
  std::size_t size = part.size;
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      const int error = written < 0 ? errno : ENOSPC;
      ::close(fd);
      fail(path, error);
    }
    bytes += written;
    size -= std::size_t(written);
  }
}

}  // namespace

void writeFileBytes(const std::string& path, const void* data, std::size_t size) {
  writeFileBytes(path, {ByteSpan{data, size}});
}

void writeFileBytes(const std::string& path, const std::vector<ByteSpan>& parts) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(path, errno);
  for (const ByteSpan& part : parts) writeAll(fd, path, part);
  if (::close(fd) != 0) fail(path, errno);
}

}  // namespace solidtex
