#include <signal.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "runCommand.h"

namespace fs = std::filesystem;
using namespace solidtex::test;

namespace {

const std::string kCoins = std::string(SOLIDTEX_DATA_DIR) + "/particles/coins.png";

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// solidtex with `arguments`, started without a shell so that its pid is ours to signal.
pid_t start(const std::vector<std::string>& arguments, const fs::path& stderrFile) {
  const pid_t pid = fork();
  if (pid == 0) {
    const FILE* err = std::freopen(stderrFile.c_str(), "w", stderr);
    const FILE* out = std::freopen("/dev/null", "w", stdout);
    if (!err || !out) _exit(127);
    std::vector<char*> argv{const_cast<char*>(SOLIDTEX_EXECUTABLE)};
    for (const auto& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(SOLIDTEX_EXECUTABLE, argv.data());
    _exit(127);
  }
  return pid;
}

// True once a temporary file with content appears in `folder`: the .vdb is being written.
bool writing(const fs::path& folder) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (entry.path().extension() == ".partial" && entry.path().string().find(".vdb.") != std::string::npos &&
        fs::file_size(entry.path(), ec) > 0)
      return true;
  return false;
}

/// `deliveries` signals back to back, as `timeout` sends one to the command and one to its group.
void expectInterruptedWhileWriting(int signal, int exitCode, int deliveries = 1) {
  // One folder per case: ctest runs the cases at once, and a case must not see another's files.
  const std::string name = "signal" + std::to_string(signal) + "x" + std::to_string(deliveries);
  const fs::path out = emptyScratch(name);
  const fs::path err = out.parent_path() / (name + ".stderr");
  const pid_t pid = start({"particles", kCoins, "--size", "160", "--quiet", "-o", (out / "v.vdb").string(),
                           "--report", (out / "r.json").string(), "--preview", (out / "p").string()},
                          err);
  ASSERT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(3);
  while (!writing(out) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  ASSERT_TRUE(writing(out)) << "the .vdb was never seen being written";
  for (int d = 0; d < deliveries; ++d) kill(pid, signal);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), exitCode);
  const std::string message = contents(err);
  EXPECT_EQ(message.rfind("solidtex: error: ", 0), 0u) << message;
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
  EXPECT_TRUE(filesUnder(out).empty()) << filesUnder(out).front();
}

}  // namespace

TEST(Signals, InterruptDuringTheWriteLeavesNothing) { expectInterruptedWhileWriting(SIGINT, 130); }

TEST(Signals, TerminateDuringTheWriteLeavesNothing) { expectInterruptedWhileWriting(SIGTERM, 143); }

TEST(Signals, TwoTerminationsAtOnceSayItOnce) { expectInterruptedWhileWriting(SIGTERM, 143, 2); }

TEST(FullDisk, IsAnErrorNeverATruncatedFile) {
  const fs::path disk = emptyScratch("fulldisk");
  if (getuid() != 0 || mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=96k") != 0)
    GTEST_SKIP() << "cannot mount a small tmpfs here (needs root)";
  struct Unmount {
    fs::path at;
    ~Unmount() { umount(at.c_str()); }
  } unmount{disk};
  for (const std::string& arguments :
       {"particles " + word(kCoins) + " --size 32 --quiet -o " + word(disk / "v.vdb"),
        "particles " + word(kCoins) + " --size 16 --quiet -o " + word(disk / "v.vdb") + " --preview " +
            word(disk / "p"),
        "analyze " + word(kCoins) + " --labels " + word(disk / "l.png"),
        "synthesize " + std::string(SOLIDTEX_DATA_DIR) + "/continuous/terra.png --size 32 --quiet -o " +
            word(disk / "v.vdb")}) {
    const Outcome outcome = runSolidtex(arguments);
    EXPECT_EQ(outcome.exitCode, 1) << arguments;
    ASSERT_EQ(outcome.errLines.size(), 1u) << arguments;
    EXPECT_NE(outcome.errLines[0].find("No space left on device"), std::string::npos) << outcome.errLines[0];
    EXPECT_TRUE(filesUnder(disk).empty()) << arguments << " left " << filesUnder(disk).front();
  }
}

TEST(ConcurrentWriters, OneOutputIsWhollyOneRun) {
  const fs::path dir = emptyScratch("concurrent");
  const auto command = [&](int seed, const fs::path& out) {
    return "particles " + word(kCoins) + " --size 32 --quiet --seed " + std::to_string(seed) + " -o " +
           word(out);
  };
  ASSERT_EQ(runSolidtex(command(1, dir / "one.vdb")).exitCode, 0);
  ASSERT_EQ(runSolidtex(command(2, dir / "two.vdb")).exitCode, 0);
  const std::string one = contents(dir / "one.vdb"), two = contents(dir / "two.vdb");
  for (int trial = 0; trial < 2; ++trial) {
    const fs::path shared = dir / "shared.vdb";
    std::thread first([&] { EXPECT_EQ(runSolidtex(command(1, shared)).exitCode, 0); });
    std::thread second([&] { EXPECT_EQ(runSolidtex(command(2, shared)).exitCode, 0); });
    first.join();
    second.join();
    const std::string result = contents(shared);
    EXPECT_TRUE(result == one || result == two) << "trial " << trial << ": the file is neither run's";
    for (const auto& file : filesUnder(dir)) EXPECT_EQ(file.find(".partial"), std::string::npos) << file;
  }
}

TEST(StaleTemporaries, OfAKilledRunAreRemovedByTheNext) {
  const fs::path dir = emptyScratch("stale");
  // A pid above the kernel's largest (pid_max is at most 2^22) belongs to no running process.
  const fs::path stale = dir / ".v.vdb.solidtex-99999999.partial";
  std::ofstream(stale) << "left by a run killed with SIGKILL";
  ASSERT_EQ(
      runSolidtex("particles " + word(kCoins) + " --size 16 --quiet -o " + word(dir / "v.vdb")).exitCode, 0);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(dir / "v.vdb"));
}
