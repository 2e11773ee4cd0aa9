#pragma once
/// @file OutputFiles.h
/// @brief Every file one command writes, checked before work starts and put in place together.
#include <functional>
#include <string>
#include <vector>

namespace solidtex {

/// The outputs of one command, all or none. Each output is checked when it is added, before any
/// work: its folder exists and takes a new file, it is not a folder, not an input and not another
/// output. Each file is written under a temporary name unique to this process beside its target
/// and renamed into place only by commit(), after every file was written and synced. Destroyed
/// uncommitted (an error, an exception), it removes its temporaries and the folders it created;
/// so does an interrupt (installInterruptHandlers). At most one exists at a time.
class OutputFiles {
public:
  OutputFiles();
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  /// An input of the command: no output may replace it.
  void addInput(const std::string& path);
  /// A file output given by `option` (named in messages), ending in one of `extensions`.
  void addFile(const std::string& option, const std::string& path,
               const std::vector<std::string>& extensions);
  /// A folder output (created now if missing): files written into it are staged one by one.
  void addFolder(const std::string& option, const std::string& path);

  /// Calls writer(temporary) for `path`, a declared file or a file in a declared folder; errors
  /// name `path`, not the temporary.
  void write(const std::string& path, const std::function<void(const std::string& temporary)>& writer);

  /// Syncs every written file to disk and renames each into place. Interrupts wait until it ends.
  void commit();

private:
  struct Staged {
    std::string target, temporary;
    bool written = false;
  };
  std::string stage(const std::string& target);
  void checkNotClaimed(const std::string& option, const std::string& path) const;

  std::vector<std::string> inputs_, claimed_, folders_;
  std::vector<Staged> staged_;
  std::vector<std::string> createdFolders_;
  bool committed_ = false;
};

/// SIGINT, SIGTERM and SIGHUP remove the current OutputFiles' temporaries and created folders, print
/// one line and exit 128 + the signal's number (130, 143, 129).
void installInterruptHandlers();

}  // namespace solidtex
