#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/imageIO.h"
#include "io/vdbIO.h"
#include "tests/cli/runSolidtex.h"

namespace fs = std::filesystem;

namespace {

using namespace solidtex::testing;

/// An empty folder for one test's outputs.
fs::path emptyFolder(const std::string& name) {
  const fs::path dir = scratch(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

const std::string kPhotoPath = std::string(SOLIDTEX_DATA_DIR) + "/particles/leopard.png";
const std::string kPhoto = shellWord(kPhotoPath);

/// Each command line exits with `exitCode`, says why in one line on stderr and writes nothing in `dir`.
void expectRefused(const std::vector<std::string>& commandLines, int exitCode, const fs::path& dir) {
  for (const std::string& arguments : commandLines) {
    const Outcome outcome = runSolidtex(arguments);
    EXPECT_EQ(outcome.exitCode, exitCode) << arguments;
    ASSERT_EQ(outcome.errLines.size(), 1u) << arguments;
    EXPECT_EQ(outcome.errLines[0].rfind("solidtex: error: ", 0), 0u) << outcome.errLines[0];
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace

TEST(ExitCodes, HelpAndVersionSucceed) {
  const Outcome version = runSolidtex("--version");
  EXPECT_EQ(version.exitCode, 0);
  EXPECT_FALSE(version.out.empty());
  for (const char* command :
       {"analyze", "particles", "compare", "synthesize", "synthesize2d", "spaciousness", "truth"}) {
    const Outcome help = runSolidtex(std::string(command) + " --help");
    EXPECT_EQ(help.exitCode, 0) << command;
    EXPECT_NE(help.out.find("--help"), std::string::npos) << command;
    EXPECT_TRUE(help.errLines.empty()) << command;
  }
}

TEST(ExitCodes, ACommandLineThatDoesNotParseIsTwoWithOneLine) {
  const fs::path dir = emptyFolder("parse");
  const std::string out = " -o " + shellWord(dir / "a.vdb");
  expectRefused(
      {"", "bake", "particles " + kPhoto + out + " --size abc",
       "particles " + kPhoto + " --no-such-option" + out, "particles " + kPhoto,
       "particles " + kPhoto + out + " --size 1", "particles " + kPhoto + out + " --placer nearest",
       "particles " + kPhoto + out + " --threads -3", "particles " + kPhoto + out + " --outlines sharp",
       "analyze " + kPhoto + " --outlines sharp", "synthesize " + kPhoto + out + " --method none",
       "synthesize " + kPhoto + out + " --similarity-search fast",
       "synthesize2d " + kPhoto + " -o " + shellWord(dir / "a.png") + " --method none"},
      2, dir);
}

TEST(ExitCodes, AJobThatFailsIsOneWithOneLineAndNoOutput) {
  const fs::path dir = emptyFolder("fail");
  const std::string out = " -o " + shellWord(dir / "a.vdb") + " --report " + shellWord(dir / "r.json");
  expectRefused({"particles " + shellWord(dir / "missing.png") + out}, 1, dir);
  const std::string png = " -o " + shellWord(dir / "a.png") + " --report " + shellWord(dir / "r.json");
  expectRefused({"synthesize2d " + kPhoto + png + " --size 100 96",
                 "synthesize2d " + kPhoto + png + " --neighborhoods 64",
                 "synthesize " + kPhoto + out + " --method skeletal --wavelet-levels 3"},
                2, dir);
  expectRefused({"synthesize2d " + kPhoto + " -o " + shellWord(dir / "a.vdb")}, 1, dir);
}

TEST(ExitCodes, ASolidRecordsItsCommandLineAndIsTheSameAtAnyThreadCount) {
  const fs::path dir = emptyFolder("success");
  std::string bytes[2];
  for (int threads : {1, 2}) {
    const fs::path volume = dir / ("t" + std::to_string(threads) + ".vdb");
    const Outcome outcome =
        runSolidtex("particles " + kPhoto + " -o " + shellWord(volume) + " --size 24 --seed 5 --threads " +
                    std::to_string(threads) + " --quiet");
    ASSERT_EQ(outcome.exitCode, 0);
    EXPECT_TRUE(outcome.errLines.empty());
    const auto solid = solidtex::readVdb(volume.string());
    EXPECT_EQ(solid.metadata.at("command_line"), "solidtex particles " + kPhotoPath + " --size 24 --seed 5");
    bytes[threads - 1] = readFile(volume);
  }
  EXPECT_FALSE(bytes[0].empty());
  EXPECT_EQ(bytes[0], bytes[1]);
}

TEST(ExitCodes, SkeletalSynthesisIsTheSameAtAnyThreadCount) {
  const fs::path dir = emptyFolder("skeletal");
  const std::string exemplar = shellWord(fs::path(SOLIDTEX_DATA_DIR) / "continuous" / "terra.png");
  for (const std::string& command :
       {std::string("synthesize ") + exemplar + " --size 32 --method skeletal --distance wavelet -o ",
        std::string("synthesize2d ") + exemplar +
            " --size 32 32 --method skeletal --neighborhoods 8,6,4 -o "}) {
    std::string bytes[2];
    for (int threads : {1, 2}) {
      const fs::path output =
          dir / (std::to_string(threads) + (command.starts_with("synthesize2d") ? ".png" : ".vdb"));
      const Outcome outcome = runSolidtex(command + shellWord(output) + " --quiet --no-quality --threads " +
                                          std::to_string(threads));
      ASSERT_EQ(outcome.exitCode, 0) << command;
      bytes[threads - 1] = readFile(output);
    }
    EXPECT_FALSE(bytes[0].empty()) << command;
    EXPECT_EQ(bytes[0], bytes[1]) << command;
  }
}

TEST(ExitCodes, VolumeExemplarsRefuseWhatTheyCannotUse) {
  const fs::path dir = emptyFolder("volume");
  const std::string ct = shellWord(fs::path(SOLIDTEX_DATA_DIR) / "volumes" / "ct_stent_64.vdb");
  const std::string out = " -o " + shellWord(dir / "a.vdb") + " --report " + shellWord(dir / "r.json");
  expectRefused(
      {"synthesize " + ct + out + " --method kopf", "synthesize " + ct + out + " --iterations 3",
       "synthesize " + kPhoto + out + " --field circle", "synthesize " + kPhoto + out + " --jitter 0.5",
       "synthesize " + ct + out + " --field spiral", "synthesize " + ct + out + " --levels 9",
       "synthesize " + ct + out + " --size 16 --region 0 0 0 17 4 4",
       "synthesize " + ct + out + " --size 100 --periodic",  // sides multiples of 8
       "synthesize " + ct + out + " --size 96 --bricks 64",  // not dividing the sides
       "synthesize " + ct + out + " --size 64 --bricks 0",
       "synthesize " + ct + out + " --size 64 --bricks -32",
       "synthesize " + ct + out + " --size 64 --bricks 32 --region 0 0 0 8 8 8",
       "synthesize " + ct + out + " --size 64 --bricks 32 --npy " + shellWord(dir / "npy")},
      2, dir);
  expectRefused({"synthesize " + shellWord(dir / "missing.vdb") + out}, 1, dir);
}

TEST(ExitCodes, GrownSolidsRefuseWhatTheyCannotUse) {
  const fs::path dir = emptyFolder("grown");
  const std::string ct = shellWord(fs::path(SOLIDTEX_DATA_DIR) / "volumes" / "ct_stent_64.vdb");
  const std::string out = " -o " + shellWord(dir / "a.vdb") + " --report " + shellWord(dir / "r.json");
  expectRefused({"synthesize " + kPhoto + out + " --bricks 16",  // a 64^3 solid is not grown
                 "synthesize " + kPhoto + out + " --grow-from 300",
                 "synthesize " + kPhoto + out + " --dims 40 36 30 --region 0 0 0 4 4 4",
                 "synthesize " + kPhoto + out + " --dims 40 36 30 --bricks -4",
                 "synthesize " + ct + out + " --grow-from 32"},
                2, dir);
}

// --dims grows a photo's solid; bricks change the memory it takes, not the volume (the file's
// command line says which were used).
TEST(ExitCodes, GrownSolidsAreTheSameInBricks) {
  const fs::path dir = emptyFolder("grown_success");
  const std::string terra = shellWord(fs::path(SOLIDTEX_DATA_DIR) / "continuous" / "terra.png");
  std::vector<solidtex::SolidVolume> solids;
  for (const int edge : {0, 24}) {
    const fs::path output = dir / (std::to_string(edge) + ".vdb");
    const Outcome outcome =
        runSolidtex("synthesize " + terra + " --grow-from 32 --dims 100 20 18 --corrections 1 --bricks " +
                    std::to_string(edge) + " -o " + shellWord(output) + " --report " +
                    shellWord(dir / "r.json") + " --quiet");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.out;
    solids.push_back(solidtex::readVdb(output.string()));
  }
  EXPECT_EQ(solids[0].dims, (solidtex::Dims{100, 20, 18}));
  EXPECT_EQ(solids[0].color.size(), solids[0].dims.count());
  EXPECT_TRUE(solids[0].color == solids[1].color);
  EXPECT_EQ(solids[0].metadata.at("method"), "grown from chen-wang");
  const std::string report = readFile(dir / "r.json");
  EXPECT_NE(report.find("\"method\": \"grown\""), std::string::npos);
  EXPECT_NE(report.find("\"bricks\": 5"), std::string::npos);
}

TEST(ExitCodes, VolumeSynthesisIsTheSameAtAnyThreadCountAndKeepsTheDensityGrid) {
  const fs::path dir = emptyFolder("volume_success");
  const std::string ct = shellWord(fs::path(SOLIDTEX_DATA_DIR) / "volumes" / "ct_stent_64.vdb");
  std::string bytes[2];
  for (int threads : {1, 2}) {
    const fs::path output = dir / (std::to_string(threads) + ".vdb");
    const Outcome outcome =
        runSolidtex("synthesize " + ct + " --dims 24 20 16 --levels 1 --field slant -o " + shellWord(output) +
                    " --quiet --no-quality --threads " + std::to_string(threads));
    ASSERT_EQ(outcome.exitCode, 0);
    bytes[threads - 1] = readFile(output);
  }
  EXPECT_FALSE(bytes[0].empty());
  EXPECT_EQ(bytes[0], bytes[1]);
  const auto solid = solidtex::readVdb((dir / "1.vdb").string());
  EXPECT_EQ(solid.dims, (solidtex::Dims{24, 20, 16}));
  EXPECT_TRUE(solid.color.empty());
  EXPECT_EQ(solid.density.size(), solid.dims.count());
}

// Every file a command writes, reports aside (they hold times and paths), is the same bytes on a
// second run: volumes, every export, previews, labels and plots.
// Every export of every command, run twice: the same bytes. One case per command, each its own
// test, so that the slow ones (under the sanitizers) run side by side. "@" stands for the folder.
class TwoRuns : public testing::TestWithParam<std::vector<std::string>> {};

TEST_P(TwoRuns, WriteTheSameBytes) {
  std::map<std::string, std::string> first;
  for (int run = 0; run < 2; ++run) {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const fs::path dir = emptyFolder("bytes" + std::to_string(run) + "_" + test.substr(test.find('/') + 1));
    for (std::string command : GetParam()) {
      const std::string folder = shellWord(dir) + "/";
      for (std::size_t at = command.find('@'); at != std::string::npos;
           at = command.find('@', at + folder.size()))
        command.replace(at, 1, folder);
      const Outcome outcome = runSolidtex(command);
      ASSERT_EQ(outcome.exitCode, 0) << command << ": "
                                     << (outcome.errLines.empty() ? "" : outcome.errLines.back());
    }
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
      if (!entry.is_regular_file()) continue;
      const std::string name = fs::relative(entry.path(), dir).string(), bytes = readFile(entry.path());
      if (run == 0)
        first[name] = bytes;
      else
        EXPECT_TRUE(first.count(name) && first[name] == bytes) << name << " differs between two runs";
    }
  }
  EXPECT_FALSE(first.empty());
}

const std::string kExports = " --quiet --tiff @tif --npy @npy --vti @v.vti";
const std::string kCt = shellWord(fs::path(SOLIDTEX_DATA_DIR) / "volumes" / "ct_stent_64.vdb");
const std::string kTerra = shellWord(fs::path(SOLIDTEX_DATA_DIR) / "continuous" / "terra.png");

INSTANTIATE_TEST_SUITE_P(
    EveryCommand, TwoRuns,
    testing::Values(
        std::vector<std::string>{
            "particles " + kPhoto + " --size 24 -o @p.vdb" + kExports + " --meshes @m.obj --preview @pp",
            "compare " + kPhoto + " @p.vdb --plot @cmp.png"},
        std::vector<std::string>{"particles " + kPhoto +
                                 " --size 24 -o @p.vdb --quiet --particle-texture synthesized"},
        std::vector<std::string>{"synthesize " + kCt + " --size 16 --levels 1 -o @s.vdb" + kExports +
                                 " --no-quality --preview @sp"},
        std::vector<std::string>{"synthesize " + kTerra +
                                 " --size 32 -o @c.vdb --quiet --no-quality --tiff @ct"},
        std::vector<std::string>{"synthesize2d " + kTerra + " --size 32 32 -o @t.png --quiet --no-quality"},
        std::vector<std::string>{"analyze " + kPhoto + " --labels @l.png"},
        std::vector<std::string>{"spaciousness " + kPhoto + " --size 16 --plot @sp.png"},
        std::vector<std::string>{"truth -o @truth --dims 64 64 32 --small-radius 3 --large-radius 6"}));

TEST(ExitCodes, AMinimumAreaThatDropsMostOfWhatStandsOutIsWarnedOf) {
  const std::string gravel = shellWord(fs::path(SOLIDTEX_DATA_DIR) / "particles" / "gravel.png");
  const Outcome quiet = runSolidtex("analyze " + gravel);
  EXPECT_EQ(quiet.exitCode, 0);
  EXPECT_TRUE(quiet.errLines.empty());
  const Outcome dropped = runSolidtex("analyze " + gravel + " --min-area 1000");
  EXPECT_EQ(dropped.exitCode, 0);
  ASSERT_EQ(dropped.errLines.size(), 1u);
  EXPECT_EQ(dropped.errLines[0].rfind("solidtex: warning: ", 0), 0u) << dropped.errLines[0];
  EXPECT_NE(dropped.errLines[0].find("(see --min-area)"), std::string::npos) << dropped.errLines[0];
}

TEST(ExitCodes, ParticleBricksRefuseWhatTheyCannotUse) {
  const fs::path dir = emptyFolder("particle_bricks");
  const std::string out = " -o " + shellWord(dir / "a.vdb") + " --report " + shellWord(dir / "r.json");
  expectRefused(
      {"particles " + kPhoto + out + " --size 64 --bricks -8",
       "compare " + kPhoto + " " + shellWord(fs::path(SOLIDTEX_DATA_DIR) / "volumes" / "ct_stent_64.vdb") +
           " --mode continuous --bricks 32"},
      2, dir);
  // The particles' reach is known from the photo: bricks narrower than twice it fail after analysis
  // (--quiet: a slow build's log would get a progress line first).
  expectRefused(
      {"particles " + kPhoto + out + " --size 64 --bricks 8 --quiet",
       "particles " + kPhoto + out + " --size 120 --bricks 40 --periodic --quiet"},  // 3 bricks around
      1, dir);
}

// A solid placed in bricks: its report says the bricks, the processes and the seams, and `compare
// --bricks` measures the same seams on it.
TEST(ExitCodes, ParticleBricksReportTheirBricksAndSeams) {
  const fs::path dir = emptyFolder("particle_bricks_report");
  const fs::path out = dir / "a.vdb", report = dir / "r.json", compared = dir / "c.json";
  const Outcome run = runSolidtex("particles " + kPhoto + " -o " + shellWord(out) + " --size 96 --bricks 48" +
                                  " --quiet --report " + shellWord(report));
  ASSERT_EQ(run.exitCode, 0) << (run.errLines.empty() ? run.out : run.errLines[0]);
  EXPECT_NE(run.out.find("of 8 bricks"), std::string::npos) << run.out;
  const nlohmann::json bricks = nlohmann::json::parse(readFile(report))["bricks"];
  EXPECT_EQ(bricks["count"], 8);
  EXPECT_EQ(bricks["processes"], 1);
  EXPECT_EQ(bricks["per_brick"].size(), 8u);
  EXPECT_EQ(bricks["colour_seconds"].size(), 8u);
  EXPECT_EQ(bricks["bytes_exchanged"], 0);
  EXPECT_GT(bricks["seams"]["face_planes"].get<int>(), 0);
  ASSERT_EQ(
      runSolidtex("compare " + kPhoto + " " + shellWord(out) + " --bricks 48 --report " + shellWord(compared))
          .exitCode,
      0);
  EXPECT_EQ(nlohmann::json::parse(readFile(compared))["brick_seams"], bricks["seams"]);
}

// `compare --measures`: the materials descriptors of photo, sections and solid for both phases, in
// the report; a measure it does not know, or one asked of a continuous solid, is one line.
TEST(ExitCodes, CompareReportsTheMaterialsDescriptors) {
  const fs::path dir = emptyFolder("compare_measures");
  const fs::path out = dir / "a.vdb", report = dir / "c.json";
  ASSERT_EQ(runSolidtex("particles " + kPhoto + " -o " + shellWord(out) + " --size 48 --quiet").exitCode, 0);
  const Outcome run = runSolidtex("compare " + kPhoto + " " + shellWord(out) + " --measures all --report " +
                                  shellWord(report));
  ASSERT_EQ(run.exitCode, 0) << (run.errLines.empty() ? run.out : run.errLines[0]);
  EXPECT_NE(run.out.find("particles, sections vs photo: S2 rms"), std::string::npos) << run.out;
  const nlohmann::json materials = nlohmann::json::parse(readFile(report))["materials"];
  for (const char* phase : {"particles", "matrix"}) {
    const nlohmann::json& p = materials["phases"][phase];
    for (const char* field : {"photo", "sections", "solid"}) {
      EXPECT_EQ(p[field]["s2"]["radial"].size(), materials["max_distance"].get<std::size_t>() + 1) << phase;
      EXPECT_TRUE(p[field].contains("lineal_path") && p[field].contains("chords") &&
                  p[field].contains("local_thickness") && p[field].contains("minkowski"));
    }
    EXPECT_EQ(p["solid"]["tortuosity"].size(), 3u);
    EXPECT_TRUE(p["sections_vs_photo"].contains("s2_rms"));
  }
  const double photoFraction = materials["phases"]["particles"]["photo"]["fraction"];
  EXPECT_NEAR(materials["phases"]["matrix"]["photo"]["fraction"].get<double>(), 1 - photoFraction, 1e-12);
  const fs::path refused = emptyFolder("compare_measures_refused");
  expectRefused({"compare " + kPhoto + " " + shellWord(out) + " --measures s2,volume --report " +
                     shellWord(refused / "x.json"),
                 "compare " + kPhoto + " " + kCt + " --mode continuous --measures s2 --report " +
                     shellWord(refused / "x.json")},
                2, refused);
}

bool synthesizeTerra(const fs::path& out) {
  return runSolidtex("synthesize " + kTerra + " --size 32 -o " + shellWord(out) + " --quiet --no-quality")
             .exitCode == 0;
}

// `compare --phases K`: the photo's colour classes and the solid's voxels by class, for a
// continuous solid too; K out of range is one line.
TEST(ExitCodes, CompareMeasuresColourPhasesOfAContinuousSolid) {
  const fs::path dir = emptyFolder("compare_phases");
  const fs::path out = dir / "c.vdb", report = dir / "c.json";
  ASSERT_TRUE(synthesizeTerra(out));
  const Outcome run =
      runSolidtex("compare " + kTerra + " " + shellWord(out) + " --phases 3 --report " + shellWord(report));
  ASSERT_EQ(run.exitCode, 0) << (run.errLines.empty() ? run.out : run.errLines[0]);
  const nlohmann::json materials = nlohmann::json::parse(readFile(report))["materials"];
  ASSERT_EQ(materials["phases"].size(), 3u);
  ASSERT_EQ(materials["classes"]["centres_lab"].size(), 3u);
  double photo = 0, solid = 0;
  for (const auto& [name, phase] : materials["phases"].items()) {
    photo += phase["photo"]["fraction"].get<double>();
    solid += phase["solid"]["fraction"].get<double>();
  }
  EXPECT_NEAR(photo, 1.0, 1e-9);
  EXPECT_NEAR(solid, 1.0, 1e-9);
  const fs::path refused = emptyFolder("compare_phases_refused");
  expectRefused(
      {"compare " + kTerra + " " + shellWord(out) + " --phases 1 --report " + shellWord(refused / "x.json"),
       "compare " + kTerra + " " + shellWord(out) + " --measures s2 --report " +
           shellWord(refused / "x.json")},
      2, refused);
}

// A mask of three grey bands: three phases in the mask's order, each the photo's share of rows.
// Refused: a mask with more phases than --phases, one of another size, one with a single value.
TEST(ExitCodes, ComparePhasesFromAMask) {
  const fs::path dir = emptyFolder("compare_phase_mask");
  const fs::path out = dir / "c.vdb", report = dir / "c.json";
  ASSERT_TRUE(synthesizeTerra(out));
  const cv::Mat photo =
      solidtex::loadPhoto((fs::path(SOLIDTEX_DATA_DIR) / "continuous" / "terra.png").string());
  cv::Mat bands(photo.size(), CV_32FC3), small(photo.rows / 2, photo.cols, CV_32FC3, cv::Scalar::all(0.0));
  for (int y = 0; y < bands.rows; ++y) bands.row(y).setTo(cv::Scalar::all(0.5 * (3 * y / bands.rows)));
  small.row(0).setTo(cv::Scalar::all(1.0));
  const fs::path mask = dir / "bands.png", smallMask = dir / "small.png", flat = dir / "flat.png";
  solidtex::writeImage(mask.string(), bands);
  solidtex::writeImage(smallMask.string(), small);
  solidtex::writeImage(flat.string(), cv::Mat(photo.size(), CV_32FC3, cv::Scalar::all(0.3)));
  const Outcome run = runSolidtex("compare " + kTerra + " " + shellWord(out) + " --phase-mask " +
                                  shellWord(mask) + " --report " + shellWord(report));
  ASSERT_EQ(run.exitCode, 0) << (run.errLines.empty() ? run.out : run.errLines[0]);
  const nlohmann::json materials = nlohmann::json::parse(readFile(report))["materials"];
  ASSERT_EQ(materials["phases"].size(), 3u);
  EXPECT_NE(materials["classes"]["method"].get<std::string>().find("phase mask"), std::string::npos);
  for (const auto& [name, phase] : materials["phases"].items())
    EXPECT_NEAR(phase["photo"]["fraction"].get<double>(), 1.0 / 3, 0.02) << name;
  const fs::path refused = emptyFolder("compare_phase_mask_refused");
  const std::string to = " --report " + shellWord(refused / "x.json");
  expectRefused(
      {"compare " + kTerra + " " + shellWord(out) + " --phases 2 --phase-mask " + shellWord(mask) + to,
       "compare " + kTerra + " " + shellWord(out) + " --phase-mask " + shellWord(smallMask) + to,
       "compare " + kTerra + " " + shellWord(out) + " --phase-mask " + shellWord(flat) + to},
      1, refused);
}
