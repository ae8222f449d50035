// The lock exchange's measures (src/lock_exchange_measure.hpp).
#include "lock_exchange_measure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace lituya::verify {
namespace {

TEST(LockExchange, BoussinesqSpeedOfTheCaseIsAQuarterMetrePerSecond) {
  // g' = 9.81 * 120 / 1000 = 1.1772 m/s2, sqrt(g' 0.2) = 0.48522 m/s, U = 0.24261 m/s.
  EXPECT_NEAR(lock_exchange_speed(9.81, 0.2, 1120.0, 1000.0), 0.24261, 1e-5);
  // Four times the depth or the reduced gravity doubles it.
  EXPECT_NEAR(lock_exchange_speed(9.81, 0.8, 1120.0, 1000.0), 2 * 0.24261, 2e-5);
}

TEST(LockExchange, FrontSpeedIsTheSlopeOverTheWindowOnly) {
  // A front that accelerates over the first samples, then runs at 0.2 m/s from x = 0.3 m on.
  std::vector<double> time, front;
  for (int k = 0; k <= 30; ++k) {
    const double t = 0.1 * k;
    time.push_back(t);
    front.push_back(t < 1.0 ? 0.2 + 0.1 * t * t : 0.3 + 0.2 * (t - 1.0));
  }
  EXPECT_NEAR(front_speed(time, front, 0.3, 0.7), 0.2, 1e-12);
  // Fewer than three samples in the window: no speed.
  EXPECT_TRUE(std::isnan(front_speed(time, front, 0.695, 0.705)));
}

TEST(LockExchange, FrontSetsStrayPointsAsideAndLooksOnlyNearTheBed) {
  // (x, y, z) triples: the current reaches 0.5 m; one point thrown to 0.9 m; one high point at
  // 1.0 m is not on the bed.
  const std::vector<double> positions = {0.1, 0.01, 0,    0.3, 0.02, 0,    0.5, 0.01,
                                         0,   0.9,  0.01, 0,   1.0,  0.15, 0};
  EXPECT_DOUBLE_EQ(current_front(positions, 0.05, 0), 0.9);
  EXPECT_DOUBLE_EQ(current_front(positions, 0.05, 1), 0.5);
  EXPECT_TRUE(std::isnan(current_front(positions, 0.005, 0)));
}

}  // namespace
}  // namespace lituya::verify
