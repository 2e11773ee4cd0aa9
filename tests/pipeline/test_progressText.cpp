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

TEST(ProgressText, ALogSaysTheShareAndTheTimeLeft) {
  EXPECT_EQ(shareText(0.425, 83), "42%, 1m 23s left");
  EXPECT_EQ(shareText(1.2, -1), "100%");
}

TEST(TimeLeftEstimate, TheRateSoFarGivesTheTimeLeft) {
  TimeLeftEstimate estimate;
  EXPECT_LT(estimate.update(100, 0.2), 0);
  EXPECT_LT(estimate.update(101, 0.3), 0);  // under two seconds: too little to go by
  EXPECT_DOUBLE_EQ(estimate.update(110, 0.6), 10 * 0.4 / 0.4);
  EXPECT_LT(estimate.update(111, -1), 0);  // no share: no estimate, and the stage goes on
  EXPECT_DOUBLE_EQ(estimate.update(120, 1), 0);
}

// The next stage of a job reports its own share from 0: its rate is its own.
TEST(TimeLeftEstimate, AFallingShareStartsANewStage) {
  TimeLeftEstimate estimate;
  estimate.update(0, 0);
  EXPECT_DOUBLE_EQ(estimate.update(10, 0.9), 10 * 0.1 / 0.9);
  EXPECT_LT(estimate.update(12, 0.1), 0);
  EXPECT_DOUBLE_EQ(estimate.update(16, 0.3), 4 * 0.7 / 0.2);
  estimate.restart();
  EXPECT_LT(estimate.update(30, 0.5), 0);
  EXPECT_LT(estimate.update(31, 0.505), 0);  // under a hundredth gained
}

}  // namespace
}  // namespace solidtex
