// Volume-exemplar synthesis in bricks under mpirun: the same bytes for any number of processes,
// the voxels of the unbricked volume, and nothing written when a process fails or is killed.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/vdbIO.h"
#include "runSolidtex.h"

namespace solidtex {
namespace {

using testing::Outcome;
using testing::readFile;
using testing::shellWord;
namespace fs = std::filesystem;

const std::string kStent = shellWord(fs::path(SOLIDTEX_DATA_DIR) / "volumes" / "ct_stent_64.vdb");

fs::path emptyFolder(const std::string& name) {
  const fs::path dir = testing::scratch(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// solidtex under mpirun with `processes` processes (--quiet: mpirun's own notices left out).
Outcome runUnderMpirun(int processes, const std::string& arguments) {
  return testing::runCommand(std::string(SOLIDTEX_MPIRUN) +
                                 " --allow-run-as-root --oversubscribe --quiet -np " +
                                 std::to_string(processes) + " " + shellWord(SOLIDTEX_EXECUTABLE),
                             arguments);
}

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// One fewer correction pass and smaller neighbourhoods than the defaults keep the runs short; the
// bricks' equality does not depend on them.
const std::string kOptions = " --size 128 --bricks 64 --corrections 1 --no-quality --quiet --seed 3";

TEST(MpiBricks, OneAndTwoProcessesWriteTheSameBytesAsTheUnbrickedVoxels) {
  const fs::path dir = emptyFolder("same_bytes");
  std::string bytes[2];
  for (const int processes : {1, 2}) {
    const fs::path out = dir / ("np" + std::to_string(processes) + ".vdb");
    const fs::path report = dir / ("np" + std::to_string(processes) + ".json");
    const Outcome run = runUnderMpirun(processes, "synthesize " + kStent + " -o " + shellWord(out) +
                                                      kOptions + " --report " + shellWord(report));
    ASSERT_EQ(run.exitCode, 0) << (run.errLines.empty() ? "" : run.errLines.front());
    bytes[processes - 1] = fileBytes(out);
    const nlohmann::json bricks = nlohmann::json::parse(readFile(report))["bricks"];
    EXPECT_EQ(bricks["count"], 8);
    EXPECT_EQ(bricks["processes"], processes);
    EXPECT_EQ(bricks["per_process"][processes - 1]["bricks"], 8 / processes);
    EXPECT_EQ(bricks["bytes_exchanged"] > 0, processes > 1);
  }
  EXPECT_FALSE(bytes[0].empty());
  EXPECT_TRUE(bytes[0] == bytes[1]);

  // The same options without bricks, as one process: another command line, the same voxels.
  const fs::path whole = dir / "whole.vdb";
  const std::string unbricked =
      kOptions.substr(0, kOptions.find(" --bricks")) + kOptions.substr(kOptions.find(" --corrections"));
  const Outcome run = testing::runSolidtex("synthesize " + kStent + " -o " + shellWord(whole) + unbricked);
  ASSERT_EQ(run.exitCode, 0);
  const SolidVolume a = readVdb(whole.string()), b = readVdb((dir / "np2.vdb").string());
  EXPECT_EQ(a.dims, b.dims);
  EXPECT_TRUE(a.density == b.density);
  EXPECT_TRUE(a.color == b.color);
}

const std::string kGravel = shellWord(fs::path(SOLIDTEX_DATA_DIR) / "particles" / "gravel.png");

// Particles: each colour's bricks are dealt to the processes, which exchange them before the next.
TEST(MpiBricks, OneAndTwoProcessesPlaceTheSameParticles) {
  const fs::path dir = emptyFolder("particles_same_bytes");
  std::string bytes[2];
  for (const int processes : {1, 2}) {
    const fs::path out = dir / ("np" + std::to_string(processes) + ".vdb");
    const fs::path report = dir / ("np" + std::to_string(processes) + ".json");
    const Outcome run = runUnderMpirun(processes, "particles " + kGravel + " -o " + shellWord(out) +
                                                      " --size 128 --bricks 64 --quiet --seed 2 --report " +
                                                      shellWord(report));
    ASSERT_EQ(run.exitCode, 0) << (run.errLines.empty() ? "" : run.errLines.front());
    bytes[processes - 1] = fileBytes(out);
    const nlohmann::json bricks = nlohmann::json::parse(readFile(report))["bricks"];
    EXPECT_EQ(bricks["processes"], processes);
    EXPECT_EQ(bricks["per_process_seconds"].size(), std::size_t(processes));
    EXPECT_EQ(bricks["bytes_exchanged"] > 0, processes > 1);
  }
  EXPECT_FALSE(bytes[0].empty());
  EXPECT_TRUE(bytes[0] == bytes[1]);
}

TEST(MpiBricks, AKilledProcessLeavesNothing) {
  const fs::path dir = emptyFolder("killed");
  const fs::path out = dir / "killed_run.vdb";
  // One of the two processes is killed once both have worked for two seconds.
  const std::string command = shellWord(fs::path(SOLIDTEX_TESTS_DIR) / "killOneRank.sh") + " " +
                              shellWord(out.filename()) + " & " + std::string(SOLIDTEX_MPIRUN) +
                              " --allow-run-as-root --oversubscribe --quiet -np 2 " +
                              shellWord(SOLIDTEX_EXECUTABLE);
  const Outcome run = testing::runCommand(command, "synthesize " + kStent + " -o " + shellWord(out) +
                                                       " --size 128 --bricks 64 --quiet --report " +
                                                       shellWord(dir / "r.json") + " --preview " +
                                                       shellWord(dir / "preview"));
  EXPECT_NE(run.exitCode, 0);
  EXPECT_TRUE(fs::is_empty(dir)) << fs::directory_iterator(dir)->path();

  const fs::path placed = dir / "killed_placement.vdb";
  const std::string placing = shellWord(fs::path(SOLIDTEX_TESTS_DIR) / "killOneRank.sh") + " " +
                              shellWord(placed.filename()) + " & " + std::string(SOLIDTEX_MPIRUN) +
                              " --allow-run-as-root --oversubscribe --quiet -np 2 " +
                              shellWord(SOLIDTEX_EXECUTABLE);
  const Outcome killed = testing::runCommand(placing, "particles " + kGravel + " -o " + shellWord(placed) +
                                                          " --size 128 --bricks 32 --quiet --report " +
                                                          shellWord(dir / "p.json"));
  EXPECT_NE(killed.exitCode, 0);
  EXPECT_TRUE(fs::is_empty(dir)) << fs::directory_iterator(dir)->path();
}

TEST(MpiBricks, BadInputIsOneLineFromOneProcess) {
  const fs::path dir = emptyFolder("bad");
  const std::string out = " -o " + shellWord(dir / "a.vdb");
  const std::string photo = shellWord(fs::path(SOLIDTEX_DATA_DIR) / "particles" / "gravel.png");
  for (const std::string& arguments :
       {"synthesize " + kStent + out + " --size 128 --bricks 48",
        "synthesize " + kStent + out + " --size 128 --bricks 64 --npy " + shellWord(dir / "npy"),
        "particles " + photo + out + " --size 64"}) {
    const Outcome run = runUnderMpirun(2, arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments;
    EXPECT_EQ(run.errLines.size(), 1u) << arguments;
  }
  // Found by every process after the photo's analysis (bricks too narrow for its particles), and
  // by rank 0 alone (a missing folder): either way one line, and no process waits for another
  // (--quiet: under load, a log gets a progress line once a run has gone ten seconds).
  for (const std::string& arguments : {"particles " + photo + out + " --size 64 --bricks 8 --quiet",
                                       "particles " + photo + " -o " + shellWord(dir / "missing" / "a.vdb") +
                                           " --size 64 --bricks 32 --quiet"}) {
    const Outcome run = runUnderMpirun(2, arguments);
    EXPECT_EQ(run.exitCode, 1) << arguments;
    EXPECT_EQ(run.errLines.size(), 1u) << arguments;
  }
  const Outcome missing =
      runUnderMpirun(2, "synthesize " + kStent + " -o " + shellWord(dir / "missing" / "a.vdb") + kOptions);
  EXPECT_EQ(missing.exitCode, 1);
  ASSERT_EQ(missing.errLines.size(), 1u);
  EXPECT_NE(missing.errLines[0].find("missing"), std::string::npos) << missing.errLines[0];
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
}  // namespace solidtex
