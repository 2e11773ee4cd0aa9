#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include "common/Error.h"
#include "phaseFixtures.h"
#include "validation/tortuosity.h"

namespace solidtex {
namespace {

using testing::fieldWhere;

TEST(Tortuosity, OfStraightChannelsIsOne) {
  const PhaseField channels =
      fieldWhere({30, 20, 20}, [](double, double y, double z) { return int(y) % 5 < 2 && int(z) % 4 != 0; });
  const Tortuosity t = tortuosityFactor(channels, 0);
  EXPECT_NEAR(t.factor, 1.0, 1e-5);
  EXPECT_NEAR(t.effectiveDiffusivity, channels.fraction(), 1e-6);
  EXPECT_NEAR(t.connectedFraction, 1.0, 1e-12);
  EXPECT_LT(t.fluxMismatch, 1e-5);
  EXPECT_THROW(tortuosityFactor(channels, 1), InputError);  // the channels never cross y
}

// A one-voxel path of P voxels between the faces has resistance P (P - 1 links and two half
// voxels), so tau = phi / D_eff = (P / (L W)) / (L / (P W)) = (P / L)^2.
TEST(Tortuosity, OfAStaircaseIsTheSquaredPathRatio) {
  const int L = 24;
  const PhaseField stairs =
      fieldWhere({L, L, 1}, [](double x, double y, double) { return (y == x && x < L - 1) || y == x - 1; });
  const Tortuosity t = tortuosityFactor(stairs, 0);
  const double P = 2 * L - 2;  // one voxel on each face
  EXPECT_NEAR(t.factor, (P / L) * (P / L), 1e-4);
  EXPECT_LT(t.residual, 1e-6);
}

TEST(Tortuosity, IgnoresDeadEndsAndIsolatedPores) {
  // A straight channel with a dead-end branch and an isolated pore: the same flux as the channel.
  const PhaseField f = fieldWhere({20, 12, 1}, [](double x, double y, double) {
    return y == 5 || (x == 8 && y > 5 && y < 10) || (x == 15 && y == 1);
  });
  const Tortuosity t = tortuosityFactor(f, 0);
  EXPECT_NEAR(t.effectiveDiffusivity, 1.0 / 12, 1e-6);
  EXPECT_NEAR(t.connectedFraction, 24.0 / 25, 1e-12);
}

// Large enough for the multigrid cycle to have levels: the same sums at one thread and at two.
TEST(Tortuosity, IsTheSameAtAnyThreadCount) {
  double intensity = 0;
  const PhaseField matrix = testing::booleanBallsMatrix(40, 4.0, 0.55, 5, &intensity);
  const auto at = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    return tortuosityFactor(matrix, 2);
  };
  const Tortuosity one = at(1), two = at(2);
  EXPECT_EQ(one.factor, two.factor);
  EXPECT_EQ(one.iterations, two.iterations);
  EXPECT_LT(one.residual, 1e-6);
  EXPECT_LT(one.fluxMismatch, 1e-4);
  EXPECT_GT(one.factor, 1.0);
}

}  // namespace
}  // namespace solidtex
