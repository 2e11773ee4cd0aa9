#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace solidtex::test {

struct Outcome {
  int exitCode = -1;  ///< -1 when killed by a signal
  std::vector<std::string> errLines;
};

/// This build's scratch folder for `name`, emptied.
std::filesystem::path emptyScratch(const std::string& name);

/// Runs solidtex with `arguments` (shell words) through the shell, as a user's script would.
Outcome runSolidtex(const std::string& arguments);

/// A path as one shell word.
std::string word(const std::filesystem::path& path);

/// Every file under `folder`, hidden ones included, one path per entry.
std::vector<std::string> filesUnder(const std::filesystem::path& folder);

}  // namespace solidtex::test
