// Front, thickness and wall height of blocks whose answers are known by construction: the
// blocks are laid out in the slope frame of a 22 degree slope and rotated into global
// coordinates, as Case A's column sits on its flume.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "synthetic_output.hpp"

namespace lituya::post {
namespace {

using synthetic::add_block;

constexpr double kSlope = 22.0;
constexpr double kSpacing = 0.005;  // 0.01 m cells, 4 points per cell
constexpr double kBin = 0.01;

// An origin away from (0, 0) so a sign or offset error in the frame shows up.
const Eigen::Vector3d kOrigin(0.3, 0.5, 0.0);

TEST(SlopeFrame, DownslopeIsTowardsPlusXAtTheSlopeAngle) {
  SlopeFrame frame(kOrigin, kSlope);
  const double a = kSlope * std::numbers::pi / 180.0;
  // One metre down the slope: x grows by cos, y drops by sin.
  Eigen::Vector3d down = kOrigin + Eigen::Vector3d(std::cos(a), -std::sin(a), 0.0);
  EXPECT_NEAR(frame.s(down), 1.0, 1e-12);
  EXPECT_NEAR(frame.t(down), 0.0, 1e-12);
  // One metre straight up: upslope by sin(a), above the slope by cos(a).
  Eigen::Vector3d up = kOrigin + Eigen::Vector3d(0.0, 1.0, 0.0);
  EXPECT_NEAR(frame.s(up), -std::sin(a), 1e-12);
  EXPECT_NEAR(frame.t(up), std::cos(a), 1e-12);
  // The flume width does not change s or t, and point() inverts s() and t().
  Eigen::Vector3d p = frame.point(0.37, 0.11, 0.05);
  EXPECT_NEAR(frame.s(p), 0.37, 1e-12);
  EXPECT_NEAR(frame.t(p), 0.11, 1e-12);
  EXPECT_DOUBLE_EQ(p.z(), 0.05);
}

TEST(FrontPosition, BlockEndOnABinEdgeIsFoundExactly) {
  SlopeFrame frame(kOrigin, kSlope);
  PointCloud cloud;
  add_block(cloud, frame, 0.0, 0.2, 0.0, 0.14, kSpacing, 0);
  EXPECT_NEAR(front_position(cloud, {true}, frame, kBin, 2), 0.2, 1e-9);
}

TEST(FrontPosition, BlockEndInsideABinIsFoundWithinOneBin) {
  SlopeFrame frame(kOrigin, kSlope);
  PointCloud cloud;
  add_block(cloud, frame, 0.05, 0.215, 0.0, 0.05, kSpacing, 0);
  const double front = front_position(cloud, {true}, frame, kBin, 2);
  // The bin holding the last points ends at 0.22: never short of the block, at most a bin long.
  EXPECT_NEAR(front, 0.22, 1e-9);
  EXPECT_GE(front, 0.215);
  EXPECT_LE(front - 0.215, kBin);
}

// Four tracked points of 1, 1, 1 and 97 kg (a heavy last one) and an untracked one far
// ahead: 99 % of the 100 kg is reached only at the heavy point; at a share of 0.03 at the
// third point; the untracked point never counts, however heavy; no masses, no front.
TEST(MassFrontPosition, WeighsTrackedPointsByTheirMass) {
  SlopeFrame frame(kOrigin, kSlope);
  PointCloud cloud;
  const double s[5] = {0.1, 0.2, 0.3, 0.4, 3.0}, mass[5] = {1, 1, 1, 97, 1e6};
  for (int i = 0; i < 5; ++i) {
    cloud.position.push_back(frame.point(s[i], 0.01));
    cloud.material.push_back(i < 4 ? 0 : 1);
    cloud.volume.push_back(kSpacing * kSpacing);
  }
  EXPECT_TRUE(std::isnan(mass_front_position(cloud, {true, false}, frame, 0.99)));
  cloud.mass.assign(mass, mass + 5);
  EXPECT_NEAR(mass_front_position(cloud, {true, false}, frame, 0.99), 0.4, 1e-12);
  EXPECT_NEAR(mass_front_position(cloud, {true, false}, frame, 0.03), 0.3, 1e-12);
  EXPECT_NEAR(mass_front_position(cloud, {true, true}, frame, 0.5), 3.0, 1e-12);
  EXPECT_TRUE(std::isnan(mass_front_position(cloud, {false, false}, frame, 0.99)));
}

TEST(FrontPosition, OnlyTrackedMaterialsCount) {
  SlopeFrame frame(kOrigin, kSlope);
  PointCloud cloud;
  add_block(cloud, frame, 0.0, 0.2, 0.0046, 0.14, kSpacing, 0);  // the column
  add_block(cloud, frame, -0.2, 2.0, 0.0, 0.005, kSpacing, 1);   // an erodible bed layer
  EXPECT_NEAR(front_position(cloud, {true, false}, frame, kBin, 2), 0.2, 1e-9);
  EXPECT_NEAR(front_position(cloud, {false, true}, frame, kBin, 2), 2.0, 1e-9);
}

TEST(FrontPosition, MinPointsIgnoresStrayPoints) {
  SlopeFrame frame(kOrigin, kSlope);
  PointCloud cloud;
  add_block(cloud, frame, 0.0, 0.2, 0.0, 0.14, kSpacing, 0);
  // One grain thrown just ahead of the front, one far ahead, one left behind upslope.
  for (double s : {0.205, 0.6, -0.3}) {
    cloud.position.push_back(frame.point(s, 0.01));
    cloud.material.push_back(0);
    cloud.volume.push_back(kSpacing * kSpacing);
  }
  EXPECT_NEAR(front_position(cloud, {true}, frame, kBin, 2), 0.2, 1e-9);
  // With min_points = 1 every grain is mass: the one left behind upslope starts the walk,
  // and there the mass ends at once. The grain ahead still needs a contiguous mass to join.
  EXPECT_NEAR(front_position(cloud, {true}, frame, kBin, 1), -0.29, 1e-9);
  cloud.position.pop_back();
  EXPECT_NEAR(front_position(cloud, {true}, frame, kBin, 1), 0.21, 1e-9);
  cloud.position.push_back(frame.point(-0.3, 0.01));
  // The stray bins are listed in the profile with thickness 0.
  auto profile = thickness_profile(cloud, {true}, frame, kBin, 2);
  for (const ProfileBin& bin : profile)
    if (bin.s > 0.2 || bin.s < 0.0) {
      EXPECT_EQ(bin.thickness, 0.0) << "bin at s = " << bin.s;
    }
}

TEST(FrontPosition, NoQualifyingBinIsNaN) {
  SlopeFrame frame(kOrigin, kSlope);
  PointCloud cloud;
  cloud.position.push_back(frame.point(0.1, 0.0));
  cloud.material.push_back(0);
  EXPECT_TRUE(std::isnan(front_position(cloud, {true}, frame, kBin, 2)));
}

TEST(ThicknessProfile, BlockHeightIncludesHalfThePointSpacing) {
  SlopeFrame frame(kOrigin, kSlope);
  PointCloud cloud;
  add_block(cloud, frame, 0.0, 0.2, 0.0, 0.14, kSpacing, 0);
  auto profile = thickness_profile(cloud, {true}, frame, kBin, 2);
  // 20 bins of mass and an empty one on each side.
  ASSERT_EQ(profile.size(), 22u);
  EXPECT_NEAR(profile.front().s, -0.5 * kBin, 1e-12);
  EXPECT_EQ(profile.front().thickness, 0.0);
  EXPECT_NEAR(profile.back().s, 0.205, 1e-12);
  EXPECT_EQ(profile.back().thickness, 0.0);
  for (size_t k = 1; k + 1 < profile.size(); ++k) {
    EXPECT_NEAR(profile[k].s, (k - 0.5) * kBin, 1e-12);
    // Top row centres at 0.1375, plus sqrt(0.005^2) / 2.
    EXPECT_NEAR(profile[k].thickness, 0.14, 1e-9);
  }
}

TEST(ThicknessProfile, WithoutVolumesTheTopPointCentreIsTheHeight) {
  SlopeFrame frame(kOrigin, kSlope);
  PointCloud cloud;
  add_block(cloud, frame, 0.0, 0.2, 0.0, 0.14, kSpacing, 0);
  cloud.volume.clear();
  auto profile = thickness_profile(cloud, {true}, frame, kBin, 2);
  ASSERT_EQ(profile.size(), 22u);
  EXPECT_NEAR(profile[1].thickness, 0.1375, 1e-9);
}

TEST(ThicknessProfile, In3DTheSpacingIsTheCubeRootOfTheVolume) {
  SlopeFrame frame(kOrigin, kSlope);
  PointCloud cloud;
  add_block(cloud, frame, 0.0, 0.1, 0.0, 0.08, kSpacing, 0, /*layers=*/4);
  cloud.dimension = 3;
  auto profile = thickness_profile(cloud, {true}, frame, kBin, 2);
  ASSERT_EQ(profile.size(), 12u);
  for (size_t k = 1; k + 1 < profile.size(); ++k) EXPECT_NEAR(profile[k].thickness, 0.08, 1e-9);
  EXPECT_NEAR(front_position(cloud, {true}, frame, kBin, 2), 0.1, 1e-9);
}

TEST(ThicknessProfile, StepInHeightAndGapAreResolvedPerBin) {
  SlopeFrame frame(kOrigin, kSlope);
  PointCloud cloud;
  add_block(cloud, frame, 0.0, 0.1, 0.0, 0.14, kSpacing, 0);
  add_block(cloud, frame, 0.1, 0.2, 0.0, 0.07, kSpacing, 0);
  add_block(cloud, frame, 0.25, 0.3, 0.0, 0.02, kSpacing, 0);  // a detached lobe
  auto profile = thickness_profile(cloud, {true}, frame, kBin, 2);
  ASSERT_EQ(profile.size(), 32u);  // bins -1 to 30
  EXPECT_NEAR(profile[1 + 9].thickness, 0.14, 1e-9);
  EXPECT_NEAR(profile[1 + 10].thickness, 0.07, 1e-9);
  EXPECT_EQ(profile[1 + 22].thickness, 0.0);  // the gap between the mass and the lobe
  EXPECT_NEAR(profile[1 + 27].thickness, 0.02, 1e-9);
  // The front stops at the gap: the lobe is not connected to the mass.
  EXPECT_NEAR(front_position(cloud, {true}, frame, kBin, 2), 0.2, 1e-9);
}

TEST(WallHeight, MeasuredInTheBinDownslopeOfTheWall) {
  SlopeFrame frame(kOrigin, kSlope);
  PointCloud cloud;
  add_block(cloud, frame, 0.0, 0.1, 0.0, 0.14, kSpacing, 0);
  add_block(cloud, frame, 0.1, 0.2, 0.0, 0.07, kSpacing, 0);
  add_block(cloud, frame, 0.0, 0.05, 0.0, 0.3, kSpacing, 1);  // untracked, taller
  const std::vector<bool> tracked{true, false};
  EXPECT_NEAR(wall_height(cloud, tracked, frame, 0.0, kBin, 2), 0.14, 1e-9);
  EXPECT_NEAR(wall_height(cloud, tracked, frame, 0.1, kBin, 2), 0.07, 1e-9);
  // A wall not on the bin grid: [0.095, 0.105) holds both heights, the taller one counts.
  EXPECT_NEAR(wall_height(cloud, tracked, frame, 0.095, kBin, 2), 0.14, 1e-9);
  // Nothing downslope of a wall at 0.2: no mass there.
  EXPECT_EQ(wall_height(cloud, tracked, frame, 0.2, kBin, 2), 0.0);
}

}  // namespace
}  // namespace lituya::post
