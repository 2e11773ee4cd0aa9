#include <cmath>

#include <gtest/gtest.h>

#include "common/ProgressLine.h"

namespace solidtex {
namespace {

TEST(ProgressText, ABarThePercentAndTheTimeLeft) {
  EXPECT_EQ(progressText("placing", 0.5, 83), "placing [############------------]  50% 1m 23s left");
  EXPECT_EQ(progressText("level 3/3", 1, 0), "level 3/3 [########################] 100% 0s left");
  EXPECT_EQ(progressText("level 1/3", 0.01, 7300), "level 1/3 [------------------------]   1% 2h 01m left");
}

TEST(ProgressText, NoBarWithoutAFractionNoEstimateWithoutARate) {
  EXPECT_EQ(progressText("rebuilding", -1, 10), "rebuilding");
  EXPECT_EQ(progressText("rebuilding", std::nan(""), 10), "rebuilding");
  EXPECT_EQ(progressText("placing", 0.25, -1), "placing [######------------------]  25%");
  EXPECT_EQ(progressText("placing", 1.5, -1), "placing [########################] 100%");
}

}  // namespace
}  // namespace solidtex
