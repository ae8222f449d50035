// The error figures of a simulated series against its reference: RMS over the reference
// samples, peak and arrival-time errors, on series whose errors are known analytically.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "lituya/post/reference_error.hpp"

namespace lituya::post {
namespace {

constexpr double kPi = std::numbers::pi;

// A sine of period 1 s sampled every 5 ms over one period (the reference), against the same
// sine 1.2 times as high and 0.05 s late, sampled every 0.5 ms over [0, 1] (the simulation).
TEST(ReferenceError, ShiftedHigherSineAgainstASine) {
  std::vector<double> ref_t, ref_v, sim_t, sim_v;
  for (int k = 0; k < 200; ++k) {
    ref_t.push_back(k / 200.0);
    ref_v.push_back(std::sin(2 * kPi * ref_t.back()));
  }
  const double shift = 0.05, amplitude = 1.2;
  for (int j = 0; j <= 2000; ++j) {
    sim_t.push_back(j / 2000.0);
    sim_v.push_back(amplitude * std::sin(2 * kPi * (sim_t.back() - shift)));
  }
  const ReferenceError e = compare_with_reference(sim_t, sim_v, ref_t, ref_v);

  EXPECT_DOUBLE_EQ(e.span_start, 0.0);
  EXPECT_DOUBLE_EQ(e.span_end, 0.995);
  EXPECT_EQ(e.samples, 200);
  // Over whole periods, mean((A sin(a - phi) - sin a)^2) = (A^2 + 1 - 2 A cos phi) / 2; the
  // linear interpolation of the simulation adds at most A (2 pi dt)^2 / 8 = 1.5e-6.
  const double phi = 2 * kPi * shift;
  const double rms = std::sqrt((amplitude * amplitude + 1 - 2 * amplitude * std::cos(phi)) / 2);
  EXPECT_NEAR(rms, 0.280592, 1e-6);  // the formula itself, against a hand computation
  EXPECT_NEAR(e.rms, rms, 1e-5);

  EXPECT_NEAR(e.simulated_peak, 1.2, 1e-9);  // at t = 0.3, a sample of the simulation
  EXPECT_NEAR(e.reference_peak, 1.0, 1e-9);  // at t = 0.25, a reference sample
  EXPECT_NEAR(e.peak_error, 0.2, 1e-9);
  EXPECT_NEAR(e.peak_error_relative, 0.2, 1e-9);

  // Threshold: 10 % of the reference peak. The sine crosses it at asin(0.1) / 2 pi; the
  // higher, later one at 0.05 + asin(0.1 / 1.2) / 2 pi. The reference, sampled every 5 ms,
  // is interpolated linearly: its crossing is off by < 4e-5 s.
  EXPECT_NEAR(e.threshold, 0.1, 1e-9);
  const double ref_arrival = std::asin(0.1) / (2 * kPi);
  const double sim_arrival = shift + std::asin(0.1 / amplitude) / (2 * kPi);
  EXPECT_NEAR(e.reference_arrival, ref_arrival, 4e-5);
  EXPECT_NEAR(e.simulated_arrival, sim_arrival, 1e-6);
  EXPECT_NEAR(e.arrival_error, sim_arrival - ref_arrival, 4e-5);
  EXPECT_NEAR(e.arrival_error, 0.04734, 1e-4);
}

// Reference samples outside the simulated span, or in a gap of the simulation (next to a
// sample without a value), do not count; the span is what both cover.
TEST(ReferenceError, OnlyReferenceSamplesTheSimulationCoversCount) {
  std::vector<double> sim_t, sim_v;
  for (int j = 0; j <= 10; ++j) {
    sim_t.push_back(0.1 * j);
    sim_v.push_back(j == 5 ? NAN : 0.1 * j);  // v = t, but no value at t = 0.5
  }
  const std::vector<double> ref_t{0.25, 0.45, 0.75, 1.5};
  const std::vector<double> ref_v{0.35, 0.0, 0.75, 0.75};
  const ReferenceError e = compare_with_reference(sim_t, sim_v, ref_t, ref_v);
  EXPECT_DOUBLE_EQ(e.span_start, 0.25);
  EXPECT_DOUBLE_EQ(e.span_end, 1.0);
  EXPECT_EQ(e.samples, 2);                         // 0.25 and 0.75
  EXPECT_NEAR(e.rms, std::sqrt(0.01 / 2), 1e-12);  // errors -0.1 and 0
  EXPECT_NEAR(e.simulated_peak, 1.0, 1e-12);       // at the span's end
  EXPECT_NEAR(e.reference_peak, 0.75, 1e-12);
  EXPECT_NEAR(e.peak_error_relative, 0.25 / 0.75, 1e-12);
  // Both are above 10 % of 0.75 at the span's start: no arrival.
  EXPECT_TRUE(std::isnan(e.simulated_arrival));
  EXPECT_TRUE(std::isnan(e.arrival_error));
}

TEST(ReferenceError, FallingSeriesHasPeakAndRmsButNoArrival) {
  const std::vector<double> sim_t{0, 0.5, 1.0}, sim_v{0.14, 0.10, 0.06};
  const std::vector<double> ref_t{0, 0.32, 0.64}, ref_v{0.14, 0.125, 0.08};
  const ReferenceError e = compare_with_reference(sim_t, sim_v, ref_t, ref_v);
  // Simulation at 0.32: 0.14 - 0.08 * 0.32 = 0.1144; at 0.64: 0.10 - 0.08 * 0.14 = 0.0888.
  EXPECT_NEAR(e.rms, std::sqrt((0.0 + 0.0106 * 0.0106 + 0.0088 * 0.0088) / 3), 1e-12);
  EXPECT_NEAR(e.peak_error, 0.0, 1e-12);
  EXPECT_NEAR(e.threshold, 0.014, 1e-12);
  EXPECT_TRUE(std::isnan(e.reference_arrival));
}

TEST(ReferenceError, NoOverlapOrNoValuesGiveNoFigures) {
  const ReferenceError apart = compare_with_reference({0, 1}, {0, 1}, {2, 3}, {0, 1});
  EXPECT_EQ(apart.samples, 0);
  EXPECT_TRUE(std::isnan(apart.rms));
  EXPECT_TRUE(std::isnan(apart.peak_error));
  const ReferenceError empty = compare_with_reference({0, 1}, {NAN, NAN}, {0, 1}, {0, 1});
  EXPECT_TRUE(std::isnan(empty.rms));
  // A reference that never rises above zero has no arrival threshold.
  const ReferenceError flat = compare_with_reference({0, 1}, {0, 1}, {0, 1}, {0, -1});
  EXPECT_NEAR(flat.rms, std::sqrt(4.0 / 2), 1e-12);
  EXPECT_TRUE(std::isnan(flat.threshold));
  EXPECT_TRUE(std::isnan(flat.arrival_error));
}

TEST(ReferenceError, InterpolationIsLinearAndStopsAtGapsAndEnds) {
  const std::vector<double> t{0, 1, 2, 3}, v{0, 2, NAN, 5};
  EXPECT_DOUBLE_EQ(interpolate_series(t, v, 0.25), 0.5);
  EXPECT_DOUBLE_EQ(interpolate_series(t, v, 1.0), 2.0);
  EXPECT_DOUBLE_EQ(interpolate_series(t, v, 3.0), 5.0);
  EXPECT_TRUE(std::isnan(interpolate_series(t, v, 1.5)));
  EXPECT_TRUE(std::isnan(interpolate_series(t, v, 2.5)));
  EXPECT_TRUE(std::isnan(interpolate_series(t, v, -0.1)));
  EXPECT_TRUE(std::isnan(interpolate_series(t, v, 3.1)));
}

TEST(ReferenceError, ArrivalIsTheFirstUpCrossingInTheWindow) {
  const std::vector<double> t{0, 1, 2, 3, 4}, v{0, 0.5, 0, 2, 0};
  EXPECT_DOUBLE_EQ(arrival_time(t, v, 0.25, 0, 4), 0.5);
  EXPECT_DOUBLE_EQ(arrival_time(t, v, 1.0, 0, 4), 2.5);        // the first bump stays below 1
  EXPECT_DOUBLE_EQ(arrival_time(t, v, 0.25, 1.5, 4), 2.125);   // from the window's start on
  EXPECT_TRUE(std::isnan(arrival_time(t, v, 0.25, 0.75, 4)));  // above at the start
  EXPECT_TRUE(std::isnan(arrival_time(t, v, 3.0, 0, 4)));      // never reached
}

TEST(ReferenceError, TitleLineIsShortWithSignsAndUnits) {
  ReferenceError e;
  e.unit = "m";
  e.rms = 0.00213;
  e.peak_error = 0.0013;
  e.peak_error_relative = 0.052;
  e.arrival_error = -0.021;
  EXPECT_EQ(error_summary(e, "X1"), "X1: RMS 0.00213 m, peak +0.0013 m (+5.2 %), arrival -0.021 s");
  e.arrival_error = NAN;
  e.peak_error_relative = NAN;
  EXPECT_EQ(error_summary(e), "RMS 0.00213 m, peak +0.0013 m, arrival -");
}

}  // namespace
}  // namespace lituya::post
