#include "common/OutputFiles.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "common/Error.h"

namespace solidtex {
namespace fs = std::filesystem;
namespace {

// What an interrupt must remove, kept where a signal handler may read it: fixed arrays, published
// by an atomic count after each path is complete.
constexpr int kSlots = 256;
constexpr std::size_t kPathBytes = 4096;
char slotPath[kSlots][kPathBytes];
std::atomic<bool> slotLive[kSlots];
std::atomic<bool> slotIsFolder[kSlots];
std::atomic<int> slotCount{0};
std::atomic<bool> committing{false};
// The thread that writes the outputs. A signal delivered to any other thread is passed on to it, so
// that no output is created or reopened between the handler's unlinks and its _exit.
std::atomic<pid_t> outputThread{0};
std::atomic<bool> interruptOnTerminal{false};
// The real stderr, kept apart from fd 2, which may be pointed elsewhere for a while to capture a
// library's own messages (CapturedStderr): the interrupt's line must still reach the user.
std::atomic<int> interruptStderr{STDERR_FILENO};
OutputFiles* current = nullptr;

void registerSlot(const std::string& path, bool folder) {
  const int slot = slotCount.load();
  if (slot >= kSlots) throw std::logic_error("OutputFiles: more outputs than the interrupt table holds");
  if (path.size() >= kPathBytes) throw InputError("output path too long: " + path);
  std::memcpy(slotPath[slot], path.c_str(), path.size() + 1);
  slotIsFolder[slot] = folder;
  slotLive[slot] = true;
  slotCount = slot + 1;
}

void forgetSlot(const std::string& path) {
  for (int i = 0; i < slotCount.load(); ++i)
    if (slotLive[i] && path == slotPath[i]) slotLive[i] = false;
}

void clearSlots() {
  for (int i = 0; i < slotCount.load(); ++i) slotLive[i] = false;
  slotCount = 0;
}

fs::path absolutePath(const std::string& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  if (ec)
    throw InputError("cannot use " + path + ": the current folder no longer exists (cd to one that does, " +
                     "or give an absolute path)");
  return absolute;
}

std::string canonical(const std::string& path) { return fs::weakly_canonical(absolutePath(path)).string(); }

fs::path folderOf(const fs::path& path) {
  return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

std::string temporaryName(const fs::path& target) {
  return (folderOf(target) /
          ("." + target.filename().string() + ".solidtex-" + std::to_string(::getpid()) + ".partial"))
      .string();
}

// Temporaries of this target that a killed run (SIGKILL, power loss) left behind.
void removeStaleTemporaries(const fs::path& target) {
  const std::string prefix = "." + target.filename().string() + ".solidtex-";
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folderOf(target), ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || name.size() < prefix.size() + 9 || !name.ends_with(".partial"))
      continue;
    const std::string pid = name.substr(prefix.size(), name.size() - prefix.size() - 8);
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos || pid.size() > 9) continue;
    if (::kill(pid_t(std::stol(pid)), 0) != 0 && errno == ESRCH) fs::remove(entry.path(), ec);
  }
}

void syncFile(const std::string& path, const std::string& shownAs) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int error = errno;
    if (fd >= 0) ::close(fd);
    throw InputError("cannot write " + shownAs + ": " + std::strerror(error));
  }
  ::close(fd);
}

void syncFolder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);  // some file systems refuse to sync folders; the files themselves are synced
  ::close(fd);
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

void writeAll(int fd, const char* text) {
  for (std::size_t size = std::strlen(text); size > 0;) {
    const ssize_t n = ::write(fd, text, size);
    if (n <= 0) return;
    text += n;
    size -= std::size_t(n);
  }
}

extern "C" void onInterrupt(int signal) {
  if (const pid_t writer = outputThread.load(); writer != 0 && ::gettid() != writer) {
    const int savedErrno = errno;
    ::syscall(SYS_tgkill, ::getpid(), writer, signal);
    errno = savedErrno;
    return;
  }
  if (committing.load()) return;  // the outputs are being renamed into place: let it finish
  // `timeout` signals the command and then its process group: the second signal waits, blocked by
  // the handler's mask, until the _exit below.
  const int count = slotCount.load();
  for (int i = 0; i < count; ++i)
    if (slotLive[i] && !slotIsFolder[i]) ::unlink(slotPath[i]);
  for (int i = count - 1; i >= 0; --i)
    if (slotLive[i] && slotIsFolder[i]) ::rmdir(slotPath[i]);
  const int err = interruptStderr.load();
  if (interruptOnTerminal.load()) writeAll(err, "\r\033[K");
  writeAll(err, signal == SIGINT    ? "solidtex: error: interrupted (SIGINT), no output written\n"
                : signal == SIGTERM ? "solidtex: error: terminated (SIGTERM), no output written\n"
                                    : "solidtex: error: hung up (SIGHUP), no output written\n");
  ::_exit(128 + signal);
}

}  // namespace

OutputFiles::OutputFiles() {
  if (current) throw std::logic_error("OutputFiles: one command's outputs at a time");
  current = this;
  clearSlots();
}

OutputFiles::~OutputFiles() {
  if (!committed_) {
    std::error_code ec;
    for (const Staged& file : staged_) fs::remove(file.temporary, ec);
    for (auto it = createdFolders_.rbegin(); it != createdFolders_.rend(); ++it) fs::remove(*it, ec);
  }
  clearSlots();
  current = nullptr;
}

void OutputFiles::addInput(const std::string& path) { inputs_.push_back(canonical(path)); }

void OutputFiles::checkNotClaimed(const std::string& option, const std::string& path) const {
  const std::string id = canonical(path);
  if (std::find(inputs_.begin(), inputs_.end(), id) != inputs_.end())
    throw InputError(option + " " + path + " is an input of this command: it would be overwritten");
  if (std::find(claimed_.begin(), claimed_.end(), id) != claimed_.end() ||
      std::find(folders_.begin(), folders_.end(), id) != folders_.end())
    throw InputError(option + " " + path + " is already another output of this command");
}

void OutputFiles::addFile(const std::string& option, const std::string& path,
                          const std::vector<std::string>& extensions) {
  const fs::path target(path);
  if (!extensions.empty() &&
      std::find(extensions.begin(), extensions.end(), target.extension().string()) == extensions.end()) {
    std::string list = extensions.front();
    for (std::size_t i = 1; i < extensions.size(); ++i) list += " or " + extensions[i];
    throw InputError(option + " " + path + " must end in " + list);
  }
  std::error_code ec;
  if (!fs::is_directory(folderOf(target), ec))
    throw InputError("cannot write " + path + ": folder " + folderOf(target).string() + " does not exist");
  if (fs::is_directory(target, ec)) throw InputError("cannot write " + path + ": it is a folder");
  checkNotClaimed(option, path);
  claimed_.push_back(canonical(path));
  stage(path);
}

void OutputFiles::addFolder(const std::string& option, const std::string& path) {
  std::error_code ec;
  if (fs::exists(path, ec) && !fs::is_directory(path, ec))
    throw InputError(option + " " + path + " is a file, not a folder");
  checkNotClaimed(option, path);
  std::vector<fs::path> missing;
  for (fs::path p = absolutePath(path).lexically_normal(); !p.empty() && !fs::exists(p, ec);
       p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, ec) && ec)
      throw InputError("cannot create folder " + path + ": " + ec.message());
    registerSlot(it->string(), true);
    createdFolders_.push_back(it->string());
  }
  // A file made and removed now proves the folder takes new files before any work is done.
  const std::string probe =
      (fs::path(path) / (".solidtex-" + std::to_string(::getpid()) + ".probe")).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw InputError("cannot write into folder " + path + ": " + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
  folders_.push_back(canonical(path));
}

std::string OutputFiles::stage(const std::string& target) {
  removeStaleTemporaries(target);
  const std::string temporary = temporaryName(target);
  registerSlot(temporary, false);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int error = errno;
    forgetSlot(temporary);
    throw InputError("cannot write " + target + ": " + std::strerror(error));
  }
  ::close(fd);
  staged_.push_back({target, temporary});
  return temporary;
}

void OutputFiles::write(const std::string& path,
                        const std::function<void(const std::string& temporary)>& writer) {
  const std::string id = canonical(path);
  auto it = std::find_if(staged_.begin(), staged_.end(),
                         [&](const Staged& file) { return canonical(file.target) == id; });
  if (it == staged_.end()) {
    const std::string folder = canonical(folderOf(fs::path(path)).string());
    if (std::find(folders_.begin(), folders_.end(), folder) == folders_.end())
      throw std::logic_error("OutputFiles: " + path + " was not declared as an output");
    checkNotClaimed("output", path);
    claimed_.push_back(id);
    stage(path);
    it = staged_.end() - 1;
  }
  try {
    writer(it->temporary);
  } catch (const InputError& e) {
    throw InputError(replaceAll(e.what(), it->temporary, path));
  }
  it->written = true;
}

void OutputFiles::commit() {
  for (const Staged& file : staged_) {
    if (!file.written) throw std::logic_error("OutputFiles: nothing was written to " + file.target);
    syncFile(file.temporary, file.target);
  }
  committing = true;
  for (const Staged& file : staged_) {
    std::error_code ec;
    fs::rename(file.temporary, file.target, ec);
    if (ec) {
      committing = false;
      throw InputError("cannot write " + file.target + ": " + ec.message());
    }
    forgetSlot(file.temporary);
  }
  std::vector<fs::path> folders;
  for (const Staged& file : staged_) folders.push_back(folderOf(file.target));
  std::sort(folders.begin(), folders.end());
  folders.erase(std::unique(folders.begin(), folders.end()), folders.end());
  for (const auto& folder : folders) syncFolder(folder);
  committed_ = true;
  committing = false;
}

void installInterruptHandlers() {
  outputThread = ::gettid();
  interruptOnTerminal = ::isatty(STDERR_FILENO) != 0;
  if (const int err = ::fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3); err >= 0) interruptStderr = err;
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, signal);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal, &action, nullptr);
}

}  // namespace solidtex
