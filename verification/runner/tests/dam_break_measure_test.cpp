#include "dam_break_measure.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lituya::verify {
namespace {

TEST(RitterDepth, ReservoirFanAndDryBed) {
  const double g = 9.81, h0 = 0.2, c0 = std::sqrt(g * h0);
  EXPECT_DOUBLE_EQ(ritter_depth(-2 * c0, h0, g), h0);        // undisturbed reservoir
  EXPECT_NEAR(ritter_depth(-c0, h0, g), h0, 1e-15);          // fan starts at h0
  EXPECT_NEAR(ritter_depth(0.0, h0, g), 4 * h0 / 9, 1e-15);  // the dam site: 4 H / 9
  EXPECT_NEAR(ritter_depth(c0, h0, g), h0 / 9, 1e-15);       // (2 c0 - c0)^2 / 9 g
  EXPECT_DOUBLE_EQ(ritter_depth(2 * c0, h0, g), 0.0);        // the front
}

// One point per bin, its top (centre + half its spacing) on `depth(x)`.
void points_on(double (*depth)(double), std::vector<double>& x, std::vector<double>& v) {
  const DamBreakSetup s;
  const double volume = 1e-6;  // spacing 1 mm
  for (int b = 0; b < static_cast<int>(std::lround(s.length / s.bin)); ++b) {
    const double xc = (b + 0.5) * s.bin;
    x.insert(x.end(), {xc, depth(xc) - 0.5 * std::sqrt(volume), 0.0});
    v.push_back(volume);
  }
}

double exact_at(double x) {
  const DamBreakSetup s;
  return ritter_depth((x - s.x_dam) / 0.4, s.h0, s.g);
}

TEST(MeasureDamBreak, RitterProfileHasNoErrorAndItsInvariants) {
  std::vector<double> x, v;
  points_on(exact_at, x, v);
  const DamBreakMeasure m = measure_dam_break(x, v, 0.4);
  EXPECT_NEAR(m.rms_error, 0.0, 1e-12);
  // The dam site lies between two bin centres: linear interpolation of a parabola, 4 H / 9
  // plus (bin / 2)^2 / (9 g t^2) = 7.1e-6 m.
  EXPECT_NEAR(m.depth_at_dam, 4 * 0.2 / 9 + 0.0001 / (9 * 9.81 * 0.16), 1e-9);
  EXPECT_NEAR(m.tenth_position, 2 - std::sqrt(0.9), 0.01);
  EXPECT_EQ(m.profile.size(), 150u);
}

double raised(double x) {
  return exact_at(x) + 0.01;
}

TEST(MeasureDamBreak, UniformOffsetInTheFanIsTheRmsError) {
  std::vector<double> x, v;
  points_on(raised, x, v);
  // Every bin of the fan (|x - x_dam| <= c0 t) is 0.01 m too deep; outside it does not count.
  EXPECT_NEAR(measure_dam_break(x, v, 0.4).rms_error, 0.01, 1e-12);
}

}  // namespace
}  // namespace lituya::verify
