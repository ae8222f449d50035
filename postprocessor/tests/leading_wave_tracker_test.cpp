// The leading-wave tracker on synthetic surface profiles over several frames, built bin by
// bin so that the crest it must report is known exactly: a wave with a precursor ripple that
// comes and goes, a crest that would have to outrun the long-wave speed, a crest lost for a
// frame, no water at all.
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "synthetic_output.hpp"

namespace lituya::post {
namespace {

constexpr double kBin = 0.01;    // m, profile bin width
constexpr double kDt = 0.02;     // s, between outputs
constexpr double kDepth = 0.15;  // m, still water depth
constexpr double kG = 9.81;      // m/s2
constexpr double kMinHeight = 0.002;

double centre(int bin) {
  return (bin + 0.5) * kBin;
}

// Still water over bins [0, bins), on which crests are raised bin by bin.
struct Profile {
  explicit Profile(int bins) {
    for (int k = 0; k < bins; ++k) bins_.push_back({centre(k), 0.0});
  }
  // A crest of `height` at bin k with flanks of half its height on the bins either side.
  Profile& crest(int k, double height) {
    bins_[k].eta = height;
    bins_[k - 1].eta = bins_[k + 1].eta = 0.5 * height;
    return *this;
  }
  std::vector<SurfaceBin> bins_;
};

std::vector<double> frame_times(size_t frames) {
  std::vector<double> time;
  for (size_t k = 0; k < frames; ++k) time.push_back(static_cast<double>(k) * kDt);
  return time;
}

TEST(LeadingWaveTracker, FollowsTheWaveWhileARippleAheadComesAndGoes) {
  // The wave runs one bin per output (0.5 m/s) and grows by 1 mm per output; a 7 mm ripple
  // stands 4 bins ahead of it in every other output. The ripple is above the single-frame
  // threshold max(2 mm, 10 % of 40-49 mm), so find_leading_wave, taking the most downstream
  // crest, jumps to it. It is within reach of the last crest, 5 bins behind it (c_max dt +
  // one bin = 5.1 to 5.2 bins), but lower than the wave, so the tracker stays on the wave.
  constexpr int kFrames = 10;
  std::vector<std::vector<SurfaceBin>> profiles;
  for (int k = 0; k < kFrames; ++k) {
    Profile p(200);
    p.crest(30 + k, 0.040 + 0.001 * k);
    if (k % 2 == 1) p.crest(34 + k, 0.007);
    profiles.push_back(p.bins_);
  }
  const std::vector<LeadingWave> track =
      track_leading_wave(frame_times(kFrames), profiles, 0.0, kMinHeight, kDepth, kG);
  ASSERT_EQ(track.size(), static_cast<size_t>(kFrames));
  for (int k = 0; k < kFrames; ++k) {
    const double wave_x = centre(30 + k), wave_eta = 0.040 + 0.001 * k;
    EXPECT_DOUBLE_EQ(track[k].crest_x, wave_x) << "frame " << k;
    EXPECT_DOUBLE_EQ(track[k].crest_eta, wave_eta) << "frame " << k;
    EXPECT_DOUBLE_EQ(track[k].max_eta, wave_eta) << "frame " << k;
    const LeadingWave single = find_leading_wave(profiles[k], 0.0, kMinHeight);
    EXPECT_DOUBLE_EQ(single.crest_x, k % 2 == 1 ? centre(34 + k) : wave_x) << "frame " << k;
    EXPECT_DOUBLE_EQ(single.crest_eta, k % 2 == 1 ? 0.007 : wave_eta) << "frame " << k;
  }
}

TEST(LeadingWaveTracker, ACrestBeyondTheLongWaveSpeedIsNotTaken) {
  // Wave A at bin 50, then 51; a higher crest B appears 0.3 m ahead (15 m/s, against
  // c_max = 1.5 sqrt(9.81 (0.15 + 0.05)) = 2.1 m/s). In output 2, A has vanished (broken):
  // nothing within reach, NaN. In output 3, A is back 6 bins on: beyond one output's reach
  // (2.1 m/s 0.02 s + 0.01 m = 0.052 m) but within the reach since A was last seen (0.094 m).
  std::vector<std::vector<SurfaceBin>> profiles(4, Profile(200).bins_);
  profiles[0] = Profile(200).crest(50, 0.03).bins_;
  profiles[1] = Profile(200).crest(51, 0.03).crest(80, 0.05).bins_;
  profiles[2] = Profile(200).crest(81, 0.05).bins_;
  profiles[3] = Profile(200).crest(57, 0.03).crest(82, 0.05).bins_;
  const std::vector<LeadingWave> track =
      track_leading_wave(frame_times(4), profiles, 0.0, kMinHeight, kDepth, kG);
  ASSERT_EQ(track.size(), 4u);
  EXPECT_DOUBLE_EQ(track[0].crest_x, centre(50));
  EXPECT_DOUBLE_EQ(track[1].crest_x, centre(51));
  EXPECT_DOUBLE_EQ(track[1].crest_eta, 0.03);
  EXPECT_DOUBLE_EQ(track[1].max_eta, 0.05);  // the highest surface is still reported
  EXPECT_TRUE(std::isnan(track[2].crest_x));
  EXPECT_TRUE(std::isnan(track[2].crest_eta));
  EXPECT_DOUBLE_EQ(track[2].max_eta, 0.05);
  EXPECT_DOUBLE_EQ(track[3].crest_x, centre(57));
  EXPECT_DOUBLE_EQ(track[3].crest_eta, 0.03);
  // Frame by frame, B is the leading crest from output 1 on.
  EXPECT_DOUBLE_EQ(find_leading_wave(profiles[1], 0.0, kMinHeight).crest_x, centre(80));
  EXPECT_DOUBLE_EQ(find_leading_wave(profiles[3], 0.0, kMinHeight).crest_x, centre(82));
  // The same jump of 6 bins in a single output is out of reach.
  const std::vector<LeadingWave> jump =
      track_leading_wave(frame_times(2), {profiles[0], Profile(200).crest(56, 0.03).bins_}, 0.0,
                         kMinHeight, kDepth, kG);
  EXPECT_TRUE(std::isnan(jump[1].crest_x));
}

TEST(LeadingWaveTracker, ClimbsTowardsACrestBeyondReachAtTheWaveSpeed) {
  // Output 0: a crest at bin 50. Outputs 1-5: the surface rises by 2 mm a bin from bin 45 to
  // a 50 mm crest at bin 70, 0.2 m ahead. No bin of the window (reach c_max dt + one bin =
  // 2.1 m/s 0.02 s + 0.01 m = 0.052 m) is a crest: its highest bin, on its downstream edge, is
  // taken, and the track climbs the flank 5 bins per output until it reaches the crest.
  std::vector<std::vector<SurfaceBin>> profiles{Profile(100).crest(50, 0.03).bins_};
  Profile flank(100);
  for (int k = 45; k <= 70; ++k) flank.bins_[k].eta = 0.002 * (k - 45);
  for (int k = 1; k <= 5; ++k) profiles.push_back(flank.bins_);
  const std::vector<LeadingWave> track =
      track_leading_wave(frame_times(6), profiles, 0.0, kMinHeight, kDepth, kG);
  ASSERT_EQ(track.size(), 6u);
  const int expected_bin[] = {50, 55, 60, 65, 70, 70};
  for (int k = 1; k <= 5; ++k) {
    EXPECT_DOUBLE_EQ(track[k].crest_x, centre(expected_bin[k])) << "output " << k;
    EXPECT_DOUBLE_EQ(track[k].crest_eta, 0.002 * (expected_bin[k] - 45)) << "output " << k;
    EXPECT_DOUBLE_EQ(track[k].max_eta, 0.002 * 25) << "output " << k;
  }
}

TEST(LeadingWaveTracker, NoWaterIsNaNAndWaterComingBackIsTrackedAgain) {
  // No liquid in any output: nothing to track, and nothing measured.
  const std::vector<LeadingWave> dry = track_leading_wave(
      frame_times(3), std::vector<std::vector<SurfaceBin>>(3), 0.0, kMinHeight, kDepth, kG);
  ASSERT_EQ(dry.size(), 3u);
  for (const LeadingWave& wave : dry)
    EXPECT_TRUE(std::isnan(wave.crest_x) && std::isnan(wave.crest_eta) && std::isnan(wave.max_eta));
  // Still water has no crest and starts no track; an output without liquid after the track
  // started is NaN too, and the crest is found again when the water is back.
  const std::vector<LeadingWave> gap = track_leading_wave(frame_times(4),
                                                          {Profile(100).bins_,
                                                           Profile(100).crest(40, 0.02).bins_,
                                                           {},
                                                           Profile(100).crest(42, 0.02).bins_},
                                                          0.0, kMinHeight, kDepth, kG);
  EXPECT_TRUE(std::isnan(gap[0].crest_x));
  EXPECT_DOUBLE_EQ(gap[0].max_eta, 0.0);
  EXPECT_DOUBLE_EQ(gap[1].crest_x, centre(40));
  EXPECT_TRUE(std::isnan(gap[2].crest_x) && std::isnan(gap[2].max_eta));
  EXPECT_DOUBLE_EQ(gap[3].crest_x, centre(42));
  EXPECT_DOUBLE_EQ(gap[3].crest_eta, 0.02);
}

TEST(LeadingWaveTracker, OnlyBinsFromTheStartCountAndSizesMustMatch) {
  // The crest at bin 20 lies before from_x = 0.3 m: the track starts at bin 35.
  const std::vector<LeadingWave> track =
      track_leading_wave(frame_times(1), {Profile(100).crest(20, 0.05).crest(35, 0.01).bins_}, 0.3,
                         kMinHeight, kDepth, kG);
  EXPECT_DOUBLE_EQ(track[0].crest_x, centre(35));
  EXPECT_DOUBLE_EQ(track[0].max_eta, 0.01);
  EXPECT_THROW(track_leading_wave({0.0, kDt}, {{}}, 0.0, kMinHeight, kDepth, kG),
               std::invalid_argument);
  EXPECT_THROW(track_leading_wave({0.0}, {{}}, 0.0, kMinHeight, kDepth, 0.0),
               std::invalid_argument);
}

TEST(StillWaterDepth, IsTheLevelAboveTheLowestPointBottom) {
  PointCloud lake;
  synthetic::add_water(lake, 0.0, 1.0, 0.02, 0.005, [](double) { return 0.15; });
  EXPECT_NEAR(still_water_depth(lake, 0.15), 0.13, 1e-12);
  EXPECT_TRUE(std::isnan(still_water_depth(PointCloud{}, 0.15)));
}

}  // namespace
}  // namespace lituya::post
