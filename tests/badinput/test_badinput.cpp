#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "runCommand.h"
#include "tests/pngBytes.h"

namespace fs = std::filesystem;
using namespace solidtex::test;

namespace {

Bytes readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const fs::path& path, const Bytes& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

Bytes damaged(Bytes bytes, std::size_t at, std::size_t count, bool zero) {
  for (std::size_t i = at; i < at + count && i < bytes.size(); ++i) bytes[i] = zero ? 0 : bytes[i] ^ 0x5a;
  return bytes;
}

class BadInput : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    // ctest runs each test in its own process, several at once: each has its own folders.
    inputs_ = emptyScratch("inputs-" + std::to_string(getpid()));
    const fs::path coins = fs::path(SOLIDTEX_DATA_DIR) / "particles/coins.png";
    fs::copy_file(coins, inputs_ / "coins.png");
    fs::copy_file(fs::path(SOLIDTEX_DATA_DIR) / "volumes/ct_stent_64.vdb", inputs_ / "ct.vdb");
    const Bytes png = readBytes(coins);
    writeBytes(inputs_ / "empty.png", {});
    writeBytes(inputs_ / "text.png", Bytes{'n', 'o', 't', ' ', 'a', 'n', ' ', 'i', 'm', 'a', 'g', 'e', '\n'});
    writeBytes(inputs_ / "truncated.png", Bytes(png.begin(), png.begin() + long(png.size() / 2)));
    writeBytes(inputs_ / "idat.png", damaged(png, png.size() / 2, 64, false));
    writeBytes(inputs_ / "tiny.png", flatPng(1, 1, {128, 128, 128}));
    writeBytes(inputs_ / "black.png", flatPng(64, 64, {0, 0, 0}));
    writeBytes(inputs_ / "white.png", flatPng(64, 64, {255, 255, 255}));
    writeBytes(inputs_ / "clear.png", flatPng(64, 64, {200, 100, 50, 0}));
    writeBytes(inputs_ / "huge.png", flatPng(1, 1, {0, 0, 0}, 20000, 20000));
    fs::create_directories(inputs_ / "folder.png");

    const fs::path good = inputs_ / "good.vdb";
    ASSERT_EQ(runSolidtex("particles " + word(coins) + " --size 24 --quiet -o " + word(good)).exitCode, 0);
    const Bytes vdb = readBytes(good);
    writeBytes(inputs_ / "truncated.vdb", Bytes(vdb.begin(), vdb.begin() + long(vdb.size() / 2)));
    writeBytes(inputs_ / "header.vdb", Bytes(vdb.begin(), vdb.begin() + 100));
    writeBytes(inputs_ / "xored.vdb", damaged(vdb, vdb.size() / 2, 300, false));
    writeBytes(inputs_ / "zeroed.vdb", damaged(vdb, vdb.size() / 3, 300, true));
    writeBytes(inputs_ / "metadata.vdb", damaged(vdb, 150, 300, true));
    writeBytes(inputs_ / "empty.vdb", {});
    writeBytes(inputs_ / "foreign.vdb", png);
    // Fuzz findings: a value chunk longer than its node (a heap overflow inside OpenVDB 10.0), a
    // tree that makes OpenVDB print a warning of its own.
    const fs::path corpus = fs::path(SOLIDTEX_DATA_DIR) / "../tests/fuzz/corpus/vdb";
    fs::copy_file(corpus / "260948a0269240db913d6b232da60d8347309a15", inputs_ / "chunk.vdb");
    fs::copy_file(corpus / "8e6a0dd8b4de22509717e15714e9283a5d28c535", inputs_ / "warning.vdb");
  }

  /// Runs `arguments` (with IN standing for the inputs folder and OUT for an empty output folder):
  /// it must exit with `exitCode`, print one `solidtex: error:` line and leave no file anywhere.
  std::string expectRefused(const std::string& arguments, int exitCode) {
    const fs::path out = emptyScratch("out-" + std::to_string(getpid()));
    const auto before = filesUnder(inputs_);
    std::string line = arguments;
    for (const auto& [key, value] :
         {std::pair{std::string("IN/"), inputs_}, std::pair{std::string("OUT/"), out}})
      for (std::size_t at = line.find(key); at != std::string::npos; at = line.find(key))
        line.replace(at, key.size(), (value / "").string());
    const Outcome outcome = runSolidtex(line);
    EXPECT_EQ(outcome.exitCode, exitCode) << arguments;
    if (outcome.errLines.size() != 1u) {
      ADD_FAILURE() << arguments << " printed " << outcome.errLines.size() << " lines on stderr";
      return {};
    }
    EXPECT_EQ(outcome.errLines[0].rfind("solidtex: error: ", 0), 0u) << outcome.errLines[0];
    EXPECT_TRUE(filesUnder(out).empty()) << arguments << " left " << filesUnder(out).front();
    EXPECT_EQ(filesUnder(inputs_), before) << arguments << " wrote beside its inputs";
    return outcome.errLines[0];
  }

  static void TearDownTestSuite() { fs::remove_all(inputs_); }

  static fs::path inputs_;
};

fs::path BadInput::inputs_;

const char* const kBrokenPhotos[] = {"missing.png",   "folder.png", "empty.png", "text.png",
                                     "truncated.png", "idat.png",   "tiny.png",  "huge.png",
                                     "black.png",     "white.png",  "clear.png"};

TEST_F(BadInput, BrokenPhotosAreRefusedByEveryCommandThatReadsOne) {
  for (const char* photo : kBrokenPhotos) {
    const std::string in = std::string("IN/") + photo;
    expectRefused("analyze " + in + " --report OUT/r.json --labels OUT/l.png", 1);
    expectRefused("particles " + in + " --size 16 -o OUT/v.vdb --report OUT/r.json --preview OUT/p", 1);
    expectRefused("particles IN/coins.png --photo-yz " + in + " --size 16 -o OUT/v.vdb --report OUT/r.json",
                  1);
    expectRefused("compare " + in + " IN/good.vdb --report OUT/r.json --plot OUT/p.png", 1);
  }
  for (const char* photo : {"empty.png", "truncated.png", "idat.png", "huge.png"}) {
    const std::string in = std::string("IN/") + photo;
    expectRefused("synthesize " + in + " --size 16 -o OUT/v.vdb --report OUT/r.json", 1);
    expectRefused("synthesize IN/white.png --photo-xz " + in + " --size 16 -o OUT/v.vdb --report OUT/r.json",
                  1);
    expectRefused("synthesize2d " + in + " --size 16 16 -o OUT/t.png", 1);
    expectRefused("analyze IN/coins.png --mask " + in, 1);
  }
}

TEST_F(BadInput, BrokenVolumesAreRefused) {
  for (const char* volume : {"missing.vdb", "empty.vdb", "header.vdb", "truncated.vdb", "xored.vdb",
                             "zeroed.vdb", "metadata.vdb", "foreign.vdb", "chunk.vdb", "warning.vdb"}) {
    const std::string in = std::string("IN/") + volume;
    // compare reads a particle solid's ids alone, and checks what it reads: the damage in the
    // middle of xored and zeroed lies in the colour grid, refused when every grid is read.
    const bool colourOnly = std::string(volume) == "xored.vdb" || std::string(volume) == "zeroed.vdb";
    expectRefused(
        "compare IN/coins.png " + in + (colourOnly ? " --mode continuous" : "") + " --report OUT/r.json", 1);
    expectRefused("synthesize " + in + " --size 16 -o OUT/v.vdb", 1);
    expectRefused("synthesize IN/good.vdb --size 16 --field " + in + " -o OUT/v.vdb", 1);
  }
}

TEST_F(BadInput, UnwritableOutputsAreRefusedBeforeAnyWork) {
  for (const std::string& output : {std::string("-o /proc/v.vdb"),
                                    std::string("-o OUT/missing/v.vdb"),
                                    std::string("-o OUT/"),
                                    std::string("-o OUT/v.png"),
                                    std::string("-o OUT/v.vdb --report /proc/r.json"),
                                    std::string("-o OUT/v.vdb --report OUT/missing/r.json"),
                                    std::string("-o OUT/v.vdb --report OUT/"),
                                    std::string("-o OUT/v.vdb --report OUT/v.vdb"),
                                    std::string("-o OUT/v.vdb --report OUT/r.txt"),
                                    std::string("-o OUT/v.vdb --preview IN/coins.png"),
                                    std::string("-o OUT/v.vdb --preview /proc/p"),
                                    std::string("-o IN/good.vdb --mask IN/good.vdb"),
                                    std::string("-o OUT/v.vdb --tiff /proc/t"),
                                    std::string("-o OUT/v.vdb --tiff IN/coins.png"),
                                    std::string("-o OUT/v.vdb --npy OUT/v.vdb"),
                                    std::string("-o OUT/v.vdb --vti OUT/v.vtk"),
                                    std::string("-o OUT/v.vdb --vti /proc/v.vti"),
                                    std::string("-o OUT/v.vdb --vti OUT/v.vdb"),
                                    std::string("-o OUT/v.vdb --meshes /proc/m.ply"),
                                    std::string("-o OUT/v.vdb --meshes OUT/m.stl"),
                                    std::string("-o OUT/v.vdb --meshes /proc/m"),
                                    std::string("-o OUT/v.vdb --meshes OUT/missing/m.obj"),
                                    std::string("-o OUT/v.vdb --meshes IN/coins.png"),
                                    std::string("-o OUT/v.vdb --periodic --meshes /proc/m.obj")})
    expectRefused("particles IN/coins.png --size 16 " + output, 1);
  expectRefused("analyze IN/coins.png --labels IN/coins.png", 1);
  expectRefused("analyze IN/coins.png --labels OUT/l.jpg", 1);
  expectRefused("analyze IN/coins.png --report /proc/r.json", 1);
  expectRefused("compare IN/coins.png IN/good.vdb --plot /proc/p.png", 1);
  expectRefused("compare IN/coins.png IN/good.vdb --report IN/good.vdb", 1);
  expectRefused("synthesize IN/coins.png --size 16 -o /proc/v.vdb", 1);
  expectRefused("synthesize IN/coins.png --size 16 -o OUT/v.vdb --npy /proc/n", 1);
  expectRefused("synthesize IN/good.vdb --size 16 -o OUT/v.vdb --tiff IN/good.vdb", 1);
  expectRefused("synthesize2d IN/coins.png --size 16 16 -o /proc/t.png", 1);
  expectRefused("spaciousness IN/coins.png --size 16 --plot /proc/p.png", 1);
  expectRefused("truth --dims 16 16 16 -o /proc/t", 1);
  expectRefused("truth --dims 16 16 16 -o IN/coins.png", 1);
}

TEST_F(BadInput, AbsurdValuesAreRefusedAsCommandLineErrors) {
  for (const std::string& option :
       {std::string("--seed -1"), std::string("--seed 18446744073709551616"), std::string("--scale nan"),
        std::string("--scale -1"), std::string("--min-area 1e12"), std::string("--size 2048"),
        std::string("--views 9"), std::string("--max-memory lots"), std::string("--boundary torus"),
        std::string("--periodic --boundary walls")})
    expectRefused("particles IN/coins.png -o OUT/v.vdb " + option, 2);
  for (const std::string& option :
       {std::string("--scale 0"), std::string("--scale 1e9"), std::string("--scale inf")})
    expectRefused("compare IN/coins.png IN/good.vdb " + option, 2);
}

TEST_F(BadInput, ValuesOutOfRangeAreCommandLineErrorsNamingTheOption) {
  const std::pair<std::string, std::string> cases[] = {
      {"truth -o OUT/t --dims 64 64 16 --fraction 0.99", "--fraction"},
      {"truth -o OUT/t --dims 64 64 16 --fraction 0", "--fraction"},
      {"truth -o OUT/t --dims 64 64 16 --large-share 2", "--large-share"},
      {"truth -o OUT/t --dims 64 64 16 --spread 5", "--spread"},
      {"truth -o OUT/t --dims 64 64 16 --exponent 0.5", "--exponent"},
      {"truth -o OUT/t --dims 64 64 16 --elongation 0.5", "--elongation"},
      {"truth -o OUT/t --dims 64 64 16 --flatten 0.01", "--flatten"},
      {"truth -o OUT/t --dims 64 64 16 --blur -1", "--blur"},
      {"truth -o OUT/t --dims 64 64 16 --noise -1", "--noise"},
      {"truth -o OUT/t --dims 64 64 16 --anisotropy 3 1 0", "--anisotropy"},
      {"truth -o OUT/t --dims 64 64 16 --anisotropy 30 1 1", "--anisotropy"},
      {"truth -o OUT/t --dims 64 64 16 --small-radius 0", "--small-radius"},
      {"truth -o OUT/t --dims 64 64 16 --large-radius 40", "--large-radius"},
      {"truth -o OUT/t --dims 64 64 1", "--dims"},
      {"particles IN/coins.png -o OUT/a.vdb --size 16 --smoothing 0.9", "--smoothing"},
      {"particles IN/coins.png -o OUT/a.vdb --size 16 --body-form 1.5", "--body-form"},
      {"particles IN/coins.png -o OUT/a.vdb --size 16 --body-form disc", "--body-form"},
      {"particles IN/coins.png -o OUT/a.vdb --size 16 --phases 0", "--phases"},
      {"particles IN/coins.png -o OUT/a.vdb --size 16 --pixel-sizes 1 2 2", "--pixel-sizes"},
      {"particles IN/coins.png -o OUT/a.vdb --size 16 --photo-xz IN/coins.png --pixel-sizes 1 -2 2",
       "--pixel-sizes"},
      {"particles IN/coins.png -o OUT/a.vdb --size 16 --phases 9", "--phases"},
      {"analyze IN/coins.png --phases two", "--phases"},
      {"truth -o OUT/t --dims 64 64 16 --medium-share 0.9", "--medium-share"},
      {"truth -o OUT/t --dims 64 64 16 --medium-share 0.2 --medium-grain 1.5", "--medium-grain"},
      {"truth -o OUT/t --dims 64 64 16 --medium-share 0.2 --medium-srgb 1 2 0", "--medium-srgb"},
      {"compare IN/coins.png IN/good.vdb --plane zx", "--plane"},
      {"compare IN/coins.png IN/good.vdb --plane xy --measures s2", "--plane"},
      {"particles IN/coins.png -o OUT/a.vdb --size 16 --scale 1e-300", "--scale"},
      {"synthesize IN/ct.vdb -o OUT/a.vdb --size 16 --jitter 5", "--jitter"},
      {"synthesize IN/ct.vdb -o OUT/a.vdb --size 16 --exclusion -1", "--exclusion"},
      {"synthesize IN/ct.vdb -o OUT/a.vdb --size 16 --corrections -1", "--corrections"},
      {"synthesize IN/ct.vdb -o OUT/a.vdb --size 32 --region 0 0 0 40 40 40", "--region"},
      {"synthesize IN/ct.vdb -o OUT/a.vdb --size 16 --region 5 5 5 5 5 5", "--region"},
      {"synthesize IN/ct.vdb -o OUT/a.vdb --size 30 --periodic", "--periodic"},
      {"synthesize2d IN/coins.png -o OUT/a.png --threads -1", "--threads"},
      {"synthesize IN/ct.vdb -o OUT/a.vdb --size 16 --photo-xz IN/coins.png", "--photo-xz"},
      {"synthesize IN/coins.png -o OUT/a.vdb --size 512 --photo-yz IN/coins.png", "--photo-xz"}};
  for (const auto& [arguments, option] : cases) {
    const std::string line = expectRefused(arguments, 2);
    EXPECT_NE(line.find(option), std::string::npos) << arguments << ": " << line;
  }
}

TEST_F(BadInput, ADeletedCurrentFolderIsSaidInOneLine) {
  const fs::path gone = emptyScratch("gone-" + std::to_string(getpid()));
  const fs::path before = fs::current_path();
  fs::current_path(gone);
  fs::remove(gone);
  const Outcome outcome = runSolidtex("particles " + word(inputs_ / "coins.png") + " --size 16 -o a.vdb");
  fs::current_path(before);
  EXPECT_EQ(outcome.exitCode, 1);
  ASSERT_EQ(outcome.errLines.size(), 1u);
  EXPECT_NE(outcome.errLines[0].find("the current folder no longer exists"), std::string::npos)
      << outcome.errLines[0];
}

TEST_F(BadInput, PlaneExemplarsOfDifferentSizesAreRefused) {
  const std::string line = expectRefused(
      "synthesize IN/white.png --photo-xz IN/coins.png --size 32 -o OUT/v.vdb --report OUT/r.json", 1);
  EXPECT_NE(line.find("differ in size"), std::string::npos) << line;
}

TEST_F(BadInput, SizesBeyondMemoryAreRefusedUpFront) {
  expectRefused("particles IN/coins.png --size 1024 -o OUT/v.vdb --max-memory 1G", 1);
  expectRefused("truth --dims 1024 1024 1024 -o OUT/t --max-memory 1G", 1);
  expectRefused("synthesize IN/coins.png --size 1024 -o OUT/v.vdb --max-memory 1G", 1);
  expectRefused("synthesize IN/good.vdb --size 1024 -o OUT/v.vdb --max-memory 1G", 1);
}

}  // namespace
