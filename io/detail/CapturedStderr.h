#pragma once
#include <mutex>
#include <string>

namespace solidtex::io::detail {

// While alive, whatever anything in the process writes to file descriptor 2 (libpng, libjpeg,
// libtiff print their own complaints there) goes to an anonymous file instead of the terminal, so
// a command's error stays one line. One capture at a time across threads (a mutex), since fd 2 is
// shared; other threads' stderr output during a capture is captured too. If no anonymous file can
// be made, nothing is captured and stderr is left as it was.
class CapturedStderr {
public:
  CapturedStderr();
  ~CapturedStderr();
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;

  // Restores fd 2 and returns what was written meanwhile, as one trimmed line ("" if nothing).
  std::string finish();

private:
  void restore();

  std::unique_lock<std::recursive_mutex> lock_;
  int saved_ = -1;    // the real fd 2
  int capture_ = -1;  // the anonymous file
};

}  // namespace solidtex::io::detail
