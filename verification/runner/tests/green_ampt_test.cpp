#include "green_ampt.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace lituya::verify {
namespace {

// The scene's sand and water (verification/infiltration): n = 0.4, D_p = 1 mm.
GreenAmptColumn darcy_column(bool falling_head) {
  GreenAmptColumn c;
  c.sand.forchheimer = false;
  c.falling_head = falling_head;
  return c;
}

// Hydraulic conductivity K = kappa rho_w g / mu_w = n^2 rho_w g / a (m/s).
double conductivity(const SeepageColumn& sand) {
  return sand.porosity * sand.porosity * sand.density * sand.gravity / sand.darcy_coefficient();
}

// Darcy's law under a constant head d: n dL/dt = K (d + L) / L, so
// t = (n / K) (L - d ln(1 + L / d)) (Green and Ampt 1911 with zero suction head). Checked at
// the depths the closed form gives for three times; 20 000 Simpson intervals in sqrt(L) are
// accurate far beyond the 1e-6 asked.
TEST(GreenAmpt, DarcyFrontUnderAConstantHeadFollowsTheClosedForm) {
  const GreenAmptColumn c = darcy_column(false);
  const double n = c.sand.porosity, k = conductivity(c.sand), d = 0.1;
  for (const double depth : {0.01, 0.05, 0.2}) {
    const double t = n / k * (depth - d * std::log(1 + depth / d));
    EXPECT_NEAR(c.front_depth(d, {t}, 0.3)[0], depth, 1e-6 * depth) << "L = " << depth;
  }
}

// Darcy's law under the falling head d = d0 - n L: n dL/dt = K (d0 + (1 - n) L) / L, so
// t = (n / K) (L / (1 - n) - d0 / (1 - n)^2 ln(1 + (1 - n) L / d0)).
TEST(GreenAmpt, DarcyFrontUnderAFallingHeadFollowsTheClosedForm) {
  const GreenAmptColumn c = darcy_column(true);
  const double n = c.sand.porosity, k = conductivity(c.sand), d0 = 0.1, m = 1 - n;
  for (const double depth : {0.01, 0.05, 0.2}) {
    const double t = n / k * (depth / m - d0 / (m * m) * std::log(1 + m * depth / d0));
    EXPECT_NEAR(c.front_depth(d0, {t}, 0.3)[0], depth, 1e-6 * depth) << "L = " << depth;
    EXPECT_NEAR(c.pond_depth(d0, depth), d0 - n * depth, 1e-15);
  }
}

// Ergun's inertial term only resists, so the front lags Darcy's. At the scene's speeds the
// term is b v / a = 0.4 of Darcy's at 1 s (v = 0.05 m/s in the pores) and more before, so the
// conductivity the front sees is at most 1 / 1.4 of Darcy's and, the front going as the root
// of it, it lags by at least 10 % (0.0702 against 0.0883 m).
TEST(GreenAmpt, ForchheimerTermSlowsTheFront) {
  GreenAmptColumn ergun;
  const double with = ergun.front_depth(0.1, {1.0}, 0.3)[0];
  const double without = darcy_column(true).front_depth(0.1, {1.0}, 0.3)[0];
  EXPECT_LT(with, 0.9 * without);
}

// A time after the front has reached the column's bottom has no reading.
TEST(GreenAmpt, TimeBeyondTheColumnIsAnError) {
  const GreenAmptColumn c;
  EXPECT_THROW(c.front_depth(0.1, {1000.0}, 0.3), std::runtime_error);
}

}  // namespace
}  // namespace lituya::verify
