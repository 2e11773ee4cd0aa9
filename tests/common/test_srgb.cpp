#include <gtest/gtest.h>

#include "common/srgb.h"

namespace solidtex {
namespace {

TEST(Srgb, RoundTripsEveryValue) {
  for (int i = 0; i <= 1000; ++i) {
    const float c = float(i) / 1000.0f;
    EXPECT_NEAR(linearToSrgb(srgbToLinear(c)), c, 2e-6f) << c;
    EXPECT_NEAR(srgbToLinear(linearToSrgb(c)), c, 2e-6f) << c;
  }
}

TEST(Srgb, MatchesTheStandardCurve) {
  EXPECT_FLOAT_EQ(srgbToLinear(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgbToLinear(1.0f), 1.0f);
  EXPECT_NEAR(srgbToLinear(0.5f), 0.214041f, 1e-5f);
  EXPECT_NEAR(srgbToLinear(0.04045f), 0.0031308f, 1e-6f);  // where the linear toe meets the power curve
  EXPECT_NEAR(linearToSrgb(0.18f), 0.461356f, 1e-5f);      // middle grey
}

TEST(Srgb, ClampsOutOfRangeValues) {
  EXPECT_FLOAT_EQ(srgbToLinear(-0.5f), 0.0f);
  EXPECT_FLOAT_EQ(srgbToLinear(2.0f), 1.0f);
  EXPECT_FLOAT_EQ(linearToSrgb(-1.0f), 0.0f);
  EXPECT_FLOAT_EQ(linearToSrgb(3.0f), 1.0f);
}

TEST(Srgb, IsMonotonic) {
  float previous = -1;
  for (int i = 0; i <= 4096; ++i) {
    const float v = srgbToLinear(float(i) / 4096.0f);
    EXPECT_GT(v, previous);
    previous = v;
  }
}

}  // namespace
}  // namespace solidtex
