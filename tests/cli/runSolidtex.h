#pragma once
// The real executable run through the shell, as a user's script would, for the CLI's tests.
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace solidtex::testing {

namespace fs = std::filesystem;

struct Outcome {
  int exitCode = -1;
  std::string out;
  std::vector<std::string> errLines;
};

inline std::string readFile(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A path in this build's scratch folder.
inline fs::path scratch(const std::string& name) {
  fs::create_directories(SOLIDTEX_CLI_SCRATCH);
  return fs::path(SOLIDTEX_CLI_SCRATCH) / name;
}

/// A path as one shell word.
inline std::string shellWord(const fs::path& path) { return "'" + path.string() + "'"; }

/// Runs `program arguments` through the shell, as a user's script would. The captured streams are
/// named after the running test, since ctest runs tests in parallel.
inline Outcome runCommand(const std::string& program, const std::string& arguments) {
  std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::replace(test.begin(), test.end(), '/', '_');  // a parameterised test's "Name/3"
  const fs::path out = scratch(test + ".stdout"), err = scratch(test + ".stderr");
  const std::string command = program + " " + arguments + " >" + shellWord(out) + " 2>" + shellWord(err);
  const int status = std::system(command.c_str());
  Outcome outcome;
  outcome.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  outcome.out = readFile(out);
  std::istringstream lines(readFile(err));
  for (std::string line; std::getline(lines, line);) outcome.errLines.push_back(line);
  return outcome;
}

/// Runs the real executable, as runCommand.
inline Outcome runSolidtex(const std::string& arguments) {
  return runCommand(shellWord(SOLIDTEX_EXECUTABLE), arguments);
}

}  // namespace solidtex::testing
