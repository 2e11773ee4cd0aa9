#include <gtest/gtest.h>

#include "cli/commandLine.h"

using solidtex::cli::volumeCommandLine;

TEST(VolumeCommandLine, KeepsTheArgumentsThatDecideTheVolume) {
  EXPECT_EQ(volumeCommandLine({"particles", "p.png", "--size", "64", "--seed=3", "--placer", "delaunay"}),
            "solidtex particles p.png --size 64 --seed=3 --placer delaunay");
  EXPECT_EQ(volumeCommandLine({}), "solidtex");
}

TEST(VolumeCommandLine, DropsOutputsThreadsAndQuietInEverySpelling) {
  EXPECT_EQ(volumeCommandLine({"particles", "p.png", "-o", "a.vdb", "--threads", "2", "--report", "r.json",
                               "--preview", "dir", "--quiet", "--size", "32"}),
            "solidtex particles p.png --size 32");
  EXPECT_EQ(volumeCommandLine({"particles", "p.png", "-oa.vdb", "--output=a.vdb", "--threads=8",
                               "--report=r.json", "--size", "32"}),
            "solidtex particles p.png --size 32");
  EXPECT_EQ(volumeCommandLine({"particles", "p.png", "--tiff", "t", "--npy=n", "--vti", "v.vti",
                               "--max-memory", "8G", "--size", "32"}),
            "solidtex particles p.png --size 32");
  EXPECT_EQ(volumeCommandLine({"analyze", "p.png", "--labels", "l.png"}), "solidtex analyze p.png");
  EXPECT_EQ(volumeCommandLine({"synthesize", "e.png", "--no-quality", "--size", "32"}),
            "solidtex synthesize e.png --size 32");
  EXPECT_EQ(volumeCommandLine({"compare", "p.png", "v.vdb", "--plot", "c.png"}),
            "solidtex compare p.png v.vdb");
}

TEST(VolumeCommandLine, KeepsOptionsThatOnlyStartLikeADroppedOne) {
  EXPECT_EQ(volumeCommandLine({"particles", "p.png", "--threads-x", "--outputs"}),
            "solidtex particles p.png --threads-x --outputs");
}
