#include "runCommand.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>

namespace solidtex::test {
namespace fs = std::filesystem;

fs::path emptyScratch(const std::string& name) {
  const fs::path dir = fs::path(SOLIDTEX_BADINPUT_SCRATCH) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string word(const fs::path& path) { return "'" + path.string() + "'"; }

Outcome runSolidtex(const std::string& arguments) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();  // null in a suite's set-up
  const std::string test = info ? info->name() : "setup";
  const fs::path err = fs::path(SOLIDTEX_BADINPUT_SCRATCH) / (test + ".stderr");
  const std::string command = word(SOLIDTEX_EXECUTABLE) + " " + arguments + " >/dev/null 2>" + word(err);
  const int status = std::system(command.c_str());
  Outcome outcome;
  outcome.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err);
  for (std::string line; std::getline(in, line);) outcome.errLines.push_back(line);
  return outcome;
}

std::vector<std::string> filesUnder(const fs::path& folder) {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) files.push_back(entry.path().string());
  return files;
}

}  // namespace solidtex::test
