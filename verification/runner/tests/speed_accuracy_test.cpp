#include "lituya/verify/speed_accuracy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace lituya::verify {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// A small study: the fastest run overall (courant 0.9, 2.0 s) is too inaccurate for 5 %, the
// fastest run within 5 % is a points-per-cell run listed after slower ones.
std::vector<TradeRun> study() {
  return {
      {"cell_size", 0.04, 0.120, 1.0},           // 0: cheapest of all, error 12 %
      {"cell_size", 0.02, 0.048, 4.0},           // 1
      {"cell_size", 0.01, 0.041, 30.0},          // 2: the most accurate
      {"courant", 0.9, 0.080, 2.0},              // 3
      {"courant", 0.2, 0.049, 9.0},              // 4
      {"points_per_cell", 1, 0.050, 3.5},        // 5: exactly at 5 %: taken
      {"points_per_cell", 16, 0.0501, 3.0},      // 6: just above 5 %
      {"bulk_modulus", 2e4, kNaN, 0.5},          // 7: failed run, fastest of all
      {"bulk_modulus", 2e5, 0.030, 0.8, false},  // 8: accurate and fast, but not admissible
  };
}

TEST(CheapestWithin, PicksTheFastestRunWhoseErrorIsWithinTheBound) {
  const auto runs = study();
  ASSERT_TRUE(cheapest_within(runs, 0.05).has_value());
  EXPECT_EQ(*cheapest_within(runs, 0.05), 5u);  // 3.5 s at 0.050, not 6 (3.0 s at 0.0501)
  EXPECT_EQ(*cheapest_within(runs, 0.10), 3u);  // courant 0.9: 2.0 s at 0.080
  EXPECT_EQ(*cheapest_within(runs, 0.20), 0u);  // cell_size 0.04: 1.0 s at 0.120
}

TEST(CheapestWithin, SkipsFailedRunsAndHonoursTheKnob) {
  const auto runs = study();
  EXPECT_EQ(*cheapest_within(runs, 0.05, "cell_size"), 1u);
  EXPECT_EQ(*cheapest_within(runs, 0.05, "courant"), 4u);
  EXPECT_EQ(*cheapest_within(runs, 0.045, "cell_size"), 2u);
  // The failed run (NaN error) is never taken, however large the bound.
  EXPECT_FALSE(cheapest_within(runs, 1e9, "bulk_modulus").has_value());
  EXPECT_FALSE(cheapest_within(runs, 0.04).has_value());  // nothing is that accurate
  EXPECT_FALSE(cheapest_within(runs, 0.05, "no_such_knob").has_value());
  // The inadmissible run is never taken either.
  EXPECT_FALSE(cheapest_within(runs, 1e9, "bulk_modulus").has_value());
  auto admitted = runs;
  admitted[8].admissible = true;
  EXPECT_EQ(*cheapest_within(admitted, 0.05), 8u);
  EXPECT_EQ(*cheapest_within(admitted, 0.03, "bulk_modulus"), 8u);
}

TEST(CheapestWithin, TiesGoToTheMoreAccurateRun) {
  const std::vector<TradeRun> runs = {
      {"a", 1, 0.04, 2.0}, {"a", 2, 0.03, 2.0}, {"a", 3, 0.01, 2.5}, {"a", 4, 0.03, kNaN}};
  EXPECT_EQ(*cheapest_within(runs, 0.05), 1u);
}

TEST(Median, OddEvenAndEmpty) {
  EXPECT_DOUBLE_EQ(median({5.0, 1.0, 3.0}), 3.0);
  EXPECT_DOUBLE_EQ(median({4.0, 1.0, 10.0, 2.0}), 3.0);
  EXPECT_TRUE(std::isnan(median({})));
}

TEST(LogLogSlope, RecoversThePowerLawExponent) {
  // t = 3 h^-3 over a decade: slope -3 exactly.
  EXPECT_NEAR(
      log_log_slope({0.005, 0.01, 0.02, 0.05}, {3 / 1.25e-7, 3 / 1e-6, 3 / 8e-6, 3 / 1.25e-4}),
      -3.0, 1e-12);
  // sqrt law, with a failed run (NaN) and a non-positive value left out.
  EXPECT_NEAR(log_log_slope({1e7, 1e8, 1e9, 5e8, -1.0}, {1.0, std::sqrt(10.0), 10.0, kNaN, 2.0}),
              0.5, 1e-12);
  // Least squares, not the end points: y = x^1 at x = 1, 2, 4 with the middle point doubled.
  // log2 y = 0, 2, 2 against log2 x = 0, 1, 2: slope (0*-1 + 2*0 + 2*1) / 2 = 1.
  EXPECT_NEAR(log_log_slope({1, 2, 4}, {1, 4, 4}), 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(log_log_slope({2, 2}, {1, 3})));
  EXPECT_TRUE(std::isnan(log_log_slope({1}, {1})));
}

// f(h) = 0.05 + 0.3 h^1.5 sampled at h = 0.02, 0.01, 0.005: the estimate recovers the order 1.5
// and the limit 0.05 to rounding.
TEST(Richardson, RecoversTheOrderAndTheLimitOfAPowerLaw) {
  auto f = [](double h) { return 0.05 + 0.3 * std::pow(h, 1.5); };
  const RichardsonEstimate e = richardson(f(0.02), f(0.01), f(0.005), 2.0);
  EXPECT_NEAR(e.order, 1.5, 1e-9);
  EXPECT_NEAR(e.limit, 0.05, 1e-12);
  // A value that decreases toward its limit works the same way (the differences are negative).
  const RichardsonEstimate d = richardson(-f(0.02), -f(0.01), -f(0.005), 2.0);
  EXPECT_NEAR(d.order, 1.5, 1e-9);
  EXPECT_NEAR(d.limit, -0.05, 1e-12);
}

TEST(Richardson, NoEstimateWhenTheDifferencesChangeSign) {
  EXPECT_TRUE(std::isnan(richardson(45.0, 49.8, 46.8, 2.0).order));
  EXPECT_TRUE(std::isnan(richardson(45.0, 49.8, 46.8, 2.0).limit));
  EXPECT_TRUE(std::isnan(richardson(1.0, 1.0, 1.0, 2.0).order));  // converged already: no order
}

}  // namespace
}  // namespace lituya::verify
