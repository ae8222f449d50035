// The water surface measures on synthetic liquid clouds whose surface is known: still water,
// a sine wave, a leading crest ahead of a higher hump with noise on its flank.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "lituya/common/input_error.hpp"
#include "synthetic_output.hpp"

namespace lituya::post {
namespace {

using synthetic::add_water;

constexpr double kStill = 0.15;  // still water level, m
constexpr double kH = 0.005;     // point spacing, m

double gaussian(double x, double centre, double height, double width) {
  const double d = (x - centre) / width;
  return height * std::exp(-0.5 * d * d);
}

TEST(WaterSurface, StillWaterReadsZeroAtEveryGauge) {
  PointCloud water;
  add_water(water, 0.0, 1.0, 0.0, kH, [](double) { return kStill; });
  for (double x : {0.1, 0.4537, 0.9, 0.0025, 0.9975})
    EXPECT_NEAR(gauge_elevation(water, x, kH, kStill), 0.0, 1e-12) << "gauge at x = " << x;
  // Without the half spacing the surface would be the top row's centres, h/2 too low.
  PointCloud centres = water;
  centres.volume.clear();
  EXPECT_NEAR(gauge_elevation(centres, 0.45, kH, kStill), -0.5 * kH, 1e-12);
}

TEST(WaterSurface, StillWaterIn3DUsesTheCubeRoot) {
  PointCloud water;
  add_water(
      water, 0.0, 0.2, 0.0, kH, [](double) { return kStill; }, /*layers=*/4);
  ASSERT_EQ(water.dimension, 3);
  EXPECT_NEAR(gauge_elevation(water, 0.1, kH, kStill), 0.0, 1e-12);
  // Read as 2D, a volume h^3 would give a spacing of h^1.5: squares with gaps between them,
  // a visibly wrong surface (more than a spacing off).
  water.dimension = 2;
  EXPECT_GT(std::abs(gauge_elevation(water, 0.1, kH, kStill)), kH);
}

TEST(WaterSurface, SineWaveAtGaugesWithinTheWindowSlope) {
  // eta = A sin(2 pi x / L): within a window of half-width w the highest point differs from
  // eta(x_g) by at most max|eta'| w = A 2 pi / L w = 1.26e-3 m, well below the h/2 = 2.5e-3 m
  // that forgetting the half spacing would cost.
  constexpr double A = 0.02, L = 0.5;
  auto eta = [&](double x) { return A * std::sin(2 * std::numbers::pi * x / L); };
  PointCloud water;
  add_water(water, 0.0, 1.0, 0.0, kH, [&](double x) { return kStill + eta(x); });
  const double tolerance = A * 2 * std::numbers::pi / L * kH;
  for (double x : {0.05, 0.125, 0.2, 0.31, 0.375, 0.6, 0.83}) {
    const double measured = gauge_elevation(water, x, kH, kStill);
    EXPECT_NEAR(measured, eta(x), tolerance) << "gauge at x = " << x;
    // The highest point of the window is never below the surface at the gauge by more
    // than the tolerance, and at a crest it is the crest.
    EXPECT_GE(measured, eta(x) - tolerance);
  }
  EXPECT_NEAR(gauge_elevation(water, 0.125, kH, kStill), A, 1e-4);
  EXPECT_NEAR(gauge_elevation(water, 0.375, kH, kStill), -A, 1e-4);
}

// A gauge at the boundary between two columns with half-width h holds those two columns
// whole, half of its width each.
TEST(WaterSurface, APointAboveItsNeighboursLiftsTheSurfaceByItsShare) {
  PointCloud water;
  add_water(water, 0.0, 0.1, 0.0, kH, [](double) { return kStill; });
  const double gauge = 0.05;           // between the columns centred at 0.0475 and 0.0525
  size_t top = water.position.size();  // the top point of the column at 0.0525
  for (size_t i = 0; i < water.position.size(); ++i)
    if (std::abs(water.position[i].x() - (gauge + 0.5 * kH)) < 1e-9 &&
        (top == water.position.size() || water.position[i].y() > water.position[top].y()))
      top = i;
  ASSERT_NEAR(water.position[top].y(), kStill - 0.5 * kH, 1e-12);
  // Raised by 0.6 h: half the column is water up to 0.6 h higher, so the surface rises by
  // 0.3 h (the highest point's top, the former reading, by 0.6 h).
  water.position[top].y() += 0.6 * kH;
  EXPECT_NEAR(gauge_elevation(water, gauge, kH, kStill), 0.3 * kH, 1e-12);
  // A drop of spray far above the gauge adds its volume spread over the window, h^2 over a
  // width 2 h: a height h / 2 (the former reading: 10.5 h).
  PointCloud spray = water;
  spray.position[top].y() -= 0.6 * kH;
  spray.position.emplace_back(gauge, kStill + 10 * kH, 0.0);
  spray.volume.push_back(kH * kH);
  spray.material.push_back(0);
  spray.id.push_back(static_cast<int>(spray.id.size()));
  EXPECT_NEAR(gauge_elevation(spray, gauge, kH, kStill), 0.5 * kH, 1e-12);
}

TEST(WaterSurface, ADetachedSheetOfSprayAddsItsVolumeNotItsHeight) {
  // A row of points flying 2 h above still water across the whole window (a jet thrown ahead
  // of a crest, as Case B's impact throws at 0.01 m cells): it fills the window's width, so a
  // reading that takes the highest full level for the surface reads its top, 3 h. It is
  // water above a gap, to be spread over the window: its volume, a row h high, lifts the
  // surface by h.
  PointCloud water;
  add_water(water, 0.0, 0.1, 0.0, kH, [](double) { return kStill; });
  for (double x = 0.0375; x < 0.065; x += kH) {
    water.position.emplace_back(x, kStill + 2.5 * kH, 0.0);
    water.volume.push_back(kH * kH);
    water.material.push_back(0);
    water.id.push_back(static_cast<int>(water.id.size()));
  }
  EXPECT_NEAR(gauge_elevation(water, 0.05, kH, kStill), kH, 1e-12);
}

TEST(WaterSurface, SliversBetweenRowsAreNotGaps) {
  // Still water whose points hold 0.9 of their lattice cell (compressed, or a sheared
  // lattice): between two rows the column is empty over a sliver 0.05 h high. The body goes
  // on across it to the top row, whose top is 0.025 h below the lattice's surface.
  PointCloud water;
  add_water(water, 0.0, 0.1, 0.0, kH, [](double) { return kStill; });
  for (double& v : water.volume) v *= 0.9025;  // footprints 0.95 h a side
  EXPECT_NEAR(gauge_elevation(water, 0.05, kH, kStill), -0.025 * kH, 1e-12);
}

TEST(WaterSurface, PoreWaterAloneReadsTheTopOfItsDeposit) {
  // A saturated deposit standing 0.02 m above still water beside free water: its column
  // holds pore water only (fraction n), full at n, so it reads the deposit's top; the free
  // water column next to it reads its own surface.
  constexpr double n = 0.4;
  PointCloud water;
  add_water(water, 0.0, 0.05, 0.0, kH, [](double) { return kStill + 0.02; });
  water.porosity.assign(water.position.size(), n);
  for (double& v : water.volume) v *= n;
  add_water(water, 0.05, 0.1, 0.0, kH, [](double) { return kStill; });
  water.porosity.resize(water.position.size(), 1.0);
  EXPECT_NEAR(gauge_elevation(water, 0.0225, kH, kStill), 0.02, 1e-12);
  EXPECT_NEAR(gauge_elevation(water, 0.0775, kH, kStill), 0.0, 1e-12);
}

TEST(WaterSurface, NoLiquidInTheWindowIsNaN) {
  PointCloud water;
  add_water(water, 0.0, 0.5, 0.0, kH, [](double) { return kStill; });
  EXPECT_TRUE(std::isnan(gauge_elevation(water, 0.6, kH, kStill)));
  // The last column is centred at 0.4975: 0.0055 from x = 0.503 (outside), 0.0045 from
  // x = 0.502 (inside).
  EXPECT_TRUE(std::isnan(gauge_elevation(water, 0.503, kH, kStill)));
  EXPECT_NEAR(gauge_elevation(water, 0.502, kH, kStill), 0.0, 1e-12);
  EXPECT_TRUE(std::isnan(gauge_elevation(PointCloud{}, 0.1, kH, kStill)));
}

TEST(WaterSurface, MedianSpacingIgnoresAFewOddPoints) {
  PointCloud water;
  add_water(water, 0.0, 0.1, 0.0, kH, [](double) { return kStill; });
  // A few split or merged points do not move the median.
  water.volume[0] = 4 * kH * kH;
  water.volume[1] = 0.25 * kH * kH;
  water.volume[2] = 0.0;
  EXPECT_NEAR(median_point_spacing(water), kH, 1e-15);
  PointCloud cubes;
  add_water(
      cubes, 0.0, 0.05, 0.0, 0.01, [](double) { return 0.05; }, 2);
  EXPECT_NEAR(median_point_spacing(cubes), 0.01, 1e-15);
  EXPECT_TRUE(std::isnan(median_point_spacing(PointCloud{})));
}

using LiquidFile = synthetic::TempFolderTest;

TEST_F(LiquidFile, WithoutVolumesIsAnInputError) {
  PointCloud water;
  add_water(water, 0.0, 0.05, 0.0, kH, [](double) { return kStill; });
  synthetic::write_liquid_cloud(water, folder_ / "full.vtu");
  EXPECT_EQ(read_liquid_points(folder_ / "full.vtu").volume.size(), water.position.size());
  water.volume.clear();
  synthetic::write_cloud(water, folder_ / "no_volume.vtu");
  try {
    read_liquid_points(folder_ / "no_volume.vtu");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::filesystem::path(e.file()).filename(), "no_volume.vtu");
    EXPECT_NE(std::string(e.what()).find("'volume'"), std::string::npos) << e.what();
  }
}

TEST_F(LiquidFile, PoreWaterSpansItsMixtureVolume) {
  // Saturated soil under still water: its liquid points hold the water of a mixture volume
  // h^2, i.e. a volume n h^2 with porosity n. Their top is still h/2 above the centre, so
  // water standing at the top of a saturated layer reads its level exactly.
  constexpr double n = 0.4;
  PointCloud water;
  add_water(water, 0.0, 0.1, 0.0, kH, [](double) { return kStill; });
  water.porosity.assign(water.position.size(), n);
  for (double& v : water.volume) v *= n;
  synthetic::write_liquid_cloud(water, folder_ / "pore.vtu");
  const PointCloud read = read_liquid_points(folder_ / "pore.vtu");
  ASSERT_EQ(read.porosity.size(), water.position.size());
  EXPECT_NEAR(gauge_elevation(read, 0.05, kH, kStill), 0.0, 1e-12);
  EXPECT_NEAR(median_point_spacing(read), kH, 1e-15);
  // Read as solid points the porosity is not taken, and sqrt(n h^2) is the spacing.
  const PointCloud solid = read_points(folder_ / "pore.vtu");
  EXPECT_TRUE(solid.porosity.empty());
  EXPECT_NEAR(median_point_spacing(solid), std::sqrt(n) * kH, 1e-15);
}

TEST(SurfaceProfile, BinsAnchoredOnTheOriginWithGapsAsNaN) {
  PointCloud water;
  add_water(water, 0.0, 0.3, 0.0, kH, [](double) { return kStill; });
  add_water(water, 0.5, 0.8, 0.0, kH, [](double x) { return kStill + 0.01 * x; });
  const auto profile = surface_profile(water, 0.003, 0.01, kStill);
  // Bins [0.003 + k 0.01, ...) from k = -1 (holding x = 0.0025) to k = 79 (x = 0.7975).
  ASSERT_EQ(profile.size(), 81u);
  EXPECT_NEAR(profile.front().x, -0.002, 1e-12);
  EXPECT_NEAR(profile.back().x, 0.798, 1e-12);
  for (const SurfaceBin& bin : profile) {
    if (bin.x < 0.3) {
      EXPECT_NEAR(bin.eta, 0.0, 1e-12) << "x = " << bin.x;
    } else if (bin.x > 0.305 && bin.x < 0.495) {
      EXPECT_TRUE(std::isnan(bin.eta)) << "x = " << bin.x;
    } else if (bin.x > 0.51) {
      // The bin's columns lie within 0.005 m of its centre, and its surface is between
      // their tops.
      EXPECT_NEAR(bin.eta, 0.01 * bin.x, 0.01 * 0.005 + 1e-12) << "x = " << bin.x;
    }
  }
  EXPECT_TRUE(surface_profile(PointCloud{}, 0.0, 0.01, kStill).empty());
}

// A leading crest of 0.02 m at x = 1.205 ahead of a 0.05 m hump at x = 0.3 (the splash at the
// shore), with a 3 mm one-bin bump on the crest's downstream flank and two ripples further
// downstream: 1.5 mm (below the 2 mm floor) and 4 mm (above the floor, but below a tenth of
// the 0.05 m hump).
class LeadingWaveProfile : public ::testing::Test {
 protected:
  static double surface(double x) {
    double eta = gaussian(x, 0.3, 0.05, 0.05) + gaussian(x, 1.205, 0.02, 0.04) +
                 gaussian(x, 1.6, 0.0015, 0.03) + gaussian(x, 1.8, 0.004, 0.03);
    if (x >= 1.23 && x < 1.24) eta += 0.003;  // exactly the bin [1.23, 1.24)
    return kStill + eta;
  }
  // A bin of width 2 h starting at `left` holds two columns of points, half of it each: it
  // reads the mean of their tops.
  static double bin_reading(double left) {
    return 0.5 * (surface(left + 0.5 * kH) + surface(left + 1.5 * kH)) - kStill;
  }
  void SetUp() override { add_water(water_, 0.0, 2.0, 0.0, kH, surface); }
  PointCloud water_;
};

TEST_F(LeadingWaveProfile, CrestIsTheMostDownstreamMaximumOverTwoBins) {
  const auto profile = surface_profile(water_, 0.0, 2 * kH, kStill);
  // The bump makes bin [1.23, 1.24) higher than both its neighbours (0.0188 m against 0.0182
  // and 0.0129): a +-1 bin test would take it for the crest, the +-2 test must not.
  ASSERT_GT(profile[123].eta, profile[122].eta);
  ASSERT_GT(profile[123].eta, profile[124].eta);
  const LeadingWave wave = find_leading_wave(profile, 0.0, 0.002);
  EXPECT_NEAR(wave.crest_x, 1.205, 1e-9);  // the bin centre; analytically 1.205
  EXPECT_NEAR(wave.crest_eta, 0.02, 1e-4);
  EXPECT_NEAR(wave.crest_eta, bin_reading(1.2), 1e-12);
  // The hump's top bins [0.29, 0.30) and [0.30, 0.31) read 0.0497 m, the mean of columns
  // 0.0025 and 0.0075 m from its crest.
  EXPECT_NEAR(wave.max_eta, bin_reading(0.3), 1e-12);
  EXPECT_NEAR(wave.max_eta, 0.05, 4e-4);
}

TEST_F(LeadingWaveProfile, StartingBeyondTheCrestFindsTheRippleAboveTheFloor) {
  // Beyond x = 1.4 the highest surface is the 4 mm ripple, so the relative threshold drops to
  // the 2 mm floor: the 4 mm ripple is now the leading crest and the 1.5 mm one still is not.
  const auto profile = surface_profile(water_, 1.4, 2 * kH, kStill);
  const LeadingWave wave = find_leading_wave(profile, 1.4, 0.002);
  EXPECT_NEAR(wave.crest_x, 1.8, 2 * kH);
  // Bins [1.79, 1.80) and [1.80, 1.81) read the same, the mean of columns 0.0025 and
  // 0.0075 m from the ripple's crest.
  EXPECT_NEAR(wave.crest_eta, bin_reading(1.8), 1e-10);
  EXPECT_NEAR(wave.max_eta, bin_reading(1.8), 1e-10);
  // With a 5 mm floor nothing downstream of 1.4 m is a wave.
  const LeadingWave none = find_leading_wave(profile, 1.4, 0.005);
  EXPECT_TRUE(std::isnan(none.crest_x));
  EXPECT_TRUE(std::isnan(none.crest_eta));
  EXPECT_NEAR(none.max_eta, bin_reading(1.8), 1e-10);
}

TEST(LeadingWave, StillWaterAndNoWaterHaveNoCrest) {
  PointCloud water;
  add_water(water, 0.0, 1.0, 0.0, kH, [](double) { return kStill; });
  const LeadingWave flat = find_leading_wave(surface_profile(water, 0.0, 0.01, kStill), 0.0, 0.002);
  EXPECT_TRUE(std::isnan(flat.crest_x));
  EXPECT_NEAR(flat.max_eta, 0.0, 1e-12);
  const LeadingWave dry = find_leading_wave({}, 0.0, 0.002);
  EXPECT_TRUE(std::isnan(dry.crest_x) && std::isnan(dry.crest_eta) && std::isnan(dry.max_eta));
}

TEST(LeadingWave, WaterPiledAgainstTheEndWallIsACrest) {
  // The surface rises to the downstream end: the last bin has no downstream neighbour to be
  // compared with, and the crest is there (a wave running up the end wall).
  PointCloud water;
  add_water(water, 0.0, 1.0, 0.0, kH, [](double x) { return kStill + 0.03 * x; });
  const LeadingWave wave = find_leading_wave(surface_profile(water, 0.0, 0.01, kStill), 0.0, 0.002);
  EXPECT_NEAR(wave.crest_x, 0.995, 1e-9);
  // The mean of the bin's two columns (tops at 0.9925 and 0.9975), the surface at its centre.
  EXPECT_NEAR(wave.crest_eta, 0.03 * 0.995, 1e-12);
}

TEST(FirstWaveCrest, IsTheHighestSampleOfTheFirstWaveNotItsFirstWiggle) {
  // No water first (NaN), a ripple under the 1 mm onset, then the first wave: a wiggle on its
  // rising flank (0.020 -> 0.019), its crest 0.030 at 0.6 s, a dip of its plateau, its fall
  // below still water at 1.0 s; then a higher second wave.
  const std::vector<double> t{0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1};
  const std::vector<double> eta{NAN,   0.0005, 0.004, 0.020, 0.019,  0.025,
                                0.030, 0.028,  0.029, 0.010, -0.002, 0.050};
  const WaveCrest crest = first_wave_crest(t, eta, 0.001);
  EXPECT_TRUE(crest.complete);
  EXPECT_DOUBLE_EQ(crest.height, 0.030);
  // Parabola through (0.5, 0.025), (0.6, 0.030), (0.7, 0.028): its top is 0.3 / 1.4 of a
  // sample after 0.6 s.
  EXPECT_NEAR(crest.time, 0.6 + 0.1 * 0.5 * (0.025 - 0.028) / (0.025 - 0.060 + 0.028), 1e-12);
  EXPECT_NEAR(crest.time, 0.6214286, 1e-7);
}

TEST(FirstWaveCrest, AreaIsTheIntegralOfTheFirstWaveBetweenItsStillWaterCrossings) {
  // A piecewise linear wave: crossings of still water at 0.5 s (between -0.01 and 0.01) and
  // at 3.5 s; trapezoids 0.0025 + 0.02 + 0.02 + 0.0025 = 0.045 m s. The second wave after it
  // is not part of the first.
  const WaveCrest linear =
      first_wave_crest({0, 1, 2, 3, 4, 5, 6}, {-0.01, 0.01, 0.03, 0.01, -0.01, 0.02, -0.01}, 0.001);
  EXPECT_TRUE(linear.complete);
  EXPECT_NEAR(linear.area, 0.045, 1e-15);
  // A half sine of amplitude a and duration d sampled every d / 200: 2 a d / pi, to the
  // trapezoids' (pi / 200)^2 / 12 relative error.
  const double a = 0.04, d = 0.5;
  std::vector<double> t, eta;
  for (int i = -3; i <= 203; ++i) {
    t.push_back(0.2 + i * d / 200);
    eta.push_back(i < 0 || i > 200 ? -0.001 : a * std::sin(std::numbers::pi * i / 200.0));
  }
  const WaveCrest sine = first_wave_crest(t, eta, 0.001);
  EXPECT_NEAR(sine.area, 2 * a * d / std::numbers::pi, 2 * a * d / std::numbers::pi * 3e-5);
  EXPECT_NEAR(sine.height, a, 1e-12);
}

TEST(FirstWaveCrest, BelowTheOnsetIsNoWaveAndARiseCutOffIsIncomplete) {
  const WaveCrest none = first_wave_crest({0, 1, 2, 3}, {0.0002, 0.0009, 0.0004, 0.0}, 0.001);
  EXPECT_TRUE(std::isnan(none.time) && std::isnan(none.height));
  EXPECT_FALSE(none.complete);
  // Still rising at the end of the record: its last sample, not complete.
  const WaveCrest rising = first_wave_crest({0, 1, 2, 3}, {0.0, 0.01, 0.02, 0.03}, 0.001);
  EXPECT_DOUBLE_EQ(rising.height, 0.03);
  EXPECT_DOUBLE_EQ(rising.time, 3.0);
  EXPECT_FALSE(rising.complete);
  // Its area so far: from the first sample (at still water) to the last.
  EXPECT_NEAR(rising.area, 0.005 + 0.015 + 0.025, 1e-15);
  EXPECT_TRUE(std::isnan(none.area));
}

}  // namespace
}  // namespace lituya::post
