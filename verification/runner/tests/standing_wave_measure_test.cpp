#include "standing_wave_measure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace lituya::verify {
namespace {

// A damped cosine sampled as the solver's output is (every 0.01 s): its period and decay come
// back to within what the sampling allows.
TEST(FitStandingWave, RecoversPeriodAndDecayOfASampledDampedCosine) {
  const double period = 0.9326, lost_per_period = 0.03;
  const double rate = -std::log(1 - lost_per_period) / period;
  std::vector<double> t, a;
  for (int k = 0; k <= 300; ++k) {
    t.push_back(0.01 * k);
    a.push_back(0.01 * std::exp(-rate * t.back()) *
                std::cos(2 * std::numbers::pi * t.back() / period));
  }
  const StandingWaveFit fit = fit_standing_wave(t, a);
  EXPECT_NEAR(fit.period, period, 1e-4);
  EXPECT_NEAR(fit.decay_per_period, lost_per_period, 1e-3);
  // Crossings at T/4, 3T/4, ..., 11T/4 (13T/4 is past 3 s): the release's extreme and the five
  // half cycles between crossings; the one from 11T/4 on is cut by the end of the record.
  ASSERT_EQ(fit.extreme_time.size(), 6u);
  EXPECT_NEAR(fit.extreme_time[3], 1.5 * period, 2e-3);
  EXPECT_NEAR(fit.extreme_amplitude[2], 0.01 * std::exp(-rate * period), 2e-6);
}

TEST(FitStandingWave, RefusesARecordWithoutTwoCrossings) {
  EXPECT_THROW(fit_standing_wave({0, 0.01, 0.02}, {1, 0.5, -0.1}), std::runtime_error);
}

// The cosine moment of a water body whose surface is h + a cos(pi x / L): points on a fine
// lattice, each holding its column's share, give back a.
TEST(ModalAmplitude, IsTheAmplitudeOfTheSurfaceMode) {
  const double length = 0.5, depth = 0.15, a = 0.01, dx = 0.001, dy = 0.001;
  const int columns = 500;  // dx = 1 mm
  std::vector<double> x, v;
  for (int i = 0; i < columns; ++i) {
    const double xc = (i + 0.5) * dx;
    const double top = depth + a * std::cos(std::numbers::pi * xc / length);
    for (int j = 0; j * dy < top; ++j) {
      const double height = std::min(dy, top - j * dy);
      x.insert(x.end(), {xc, j * dy + 0.5 * height, 0.0});
      v.push_back(dx * height);
    }
  }
  EXPECT_NEAR(modal_amplitude(x, v, length), a, 1e-6);
  // A flat surface has no mode.
  std::vector<double> flat_x, flat_v;
  for (int i = 0; i < columns; ++i)
    for (int j = 0; j < 150; ++j) {
      flat_x.insert(flat_x.end(), {(i + 0.5) * dx, (j + 0.5) * dy, 0.0});
      flat_v.push_back(dx * dy);
    }
  EXPECT_NEAR(modal_amplitude(flat_x, flat_v, length), 0.0, 1e-9);
  // Its volume centroid is at half the depth; the displaced surface raises it by the mode's
  // potential energy, a^2 / 4 h.
  EXPECT_NEAR(volume_centroid_height(flat_x, flat_v), 0.5 * depth, 1e-12);
  EXPECT_NEAR(volume_centroid_height(x, v), 0.5 * depth + a * a / (4 * depth), 1e-7);
}

}  // namespace
}  // namespace lituya::verify
