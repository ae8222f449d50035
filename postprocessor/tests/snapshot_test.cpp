// Snapshots of the scene: the points drawn (sizes, speeds, order), the tables and scripts
// written, one frame and one colour scale for all times, and the snapshots `lituya post` draws
// at the profile times.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "lituya/common/vtu_writer.hpp"
#include "lituya/post/plot.hpp"
#include "lituya/post/snapshot.hpp"
#include "synthetic_output.hpp"

namespace lituya::post {
namespace {

namespace fs = std::filesystem;
using synthetic::read_csv_rows;
using synthetic::read_text;

// Two soil points of material 1 and 2 (volumes 4e-4 and 1e-4 m2) moving at 3-4-0 and 0.1 m/s,
// and two water points of material 0: free water (volume 1e-4) and pore water (volume 2.5e-5
// at porosity 0.25, i.e. a 1e-4 m2 mixture).
PointCloud soil() {
  PointCloud c;
  c.position = {{0.1, 0.2, 0}, {0.3, 0.1, 0}};
  c.material = {1, 2};
  c.volume = {4e-4, 1e-4};
  c.speed = {5.0, 0.1};
  return c;
}
PointCloud water() {
  PointCloud c;
  c.position = {{0.5, 0.05, 0}, {0.3, 0.1, 0}};
  c.material = {0, 0};
  c.volume = {1e-4, 2.5e-5};
  c.porosity = {1.0, 0.25};
  c.speed = {0.2, 0.0};
  return c;
}

TEST(Snapshot, WaterFirstWithDiscRadiiAndSpeeds) {
  const PointCloud s = soil(), w = water();
  const Snapshot snap = make_snapshot(0.4, 0.5, &s, &w);
  EXPECT_DOUBLE_EQ(snap.requested_time, 0.4);
  EXPECT_DOUBLE_EQ(snap.time, 0.5);
  ASSERT_EQ(snap.points.size(), 4u);
  EXPECT_EQ(snap.points[0].phase, 1);
  EXPECT_EQ(snap.points[1].phase, 1);
  EXPECT_EQ(snap.points[2].phase, 0);
  EXPECT_EQ(snap.points[3].material, 2);
  // Discs around the points' squares: r = sqrt(V / 2) (for pore water, its mixture's V,
  // 2.5e-5 / 0.25).
  EXPECT_NEAR(snap.points[0].radius, std::sqrt(1e-4 / 2), 1e-15);
  EXPECT_NEAR(snap.points[1].radius, std::sqrt(1e-4 / 2), 1e-15);
  EXPECT_NEAR(snap.points[2].radius, 0.014142136, 1e-9);  // sqrt(4e-4 / 2)
  EXPECT_DOUBLE_EQ(snap.points[2].speed, 5.0);
  EXPECT_DOUBLE_EQ(snap.points[0].x, 0.5);

  // Without velocities the speed is unknown, not zero; a dry case has no water.
  PointCloud still = soil();
  still.speed.clear();
  const Snapshot dry = make_snapshot(0, 0, &still, nullptr);
  ASSERT_EQ(dry.points.size(), 2u);
  EXPECT_TRUE(std::isnan(dry.points[0].speed));
}

TEST(Snapshot, ThreeDimensionalPointsAreDrawnFarthestFirst) {
  PointCloud c;
  c.dimension = 3;
  c.position = {{0, 0, 0.3}, {0, 0, 0.1}, {0, 0, 0.2}};
  c.material = {0, 1, 2};
  c.volume = {8e-6, 8e-6, 8e-6};
  const Snapshot snap = make_snapshot(0, 0, &c, nullptr);
  ASSERT_EQ(snap.points.size(), 3u);
  EXPECT_EQ(snap.points[0].material, 1);
  EXPECT_EQ(snap.points[2].material, 0);
  EXPECT_NEAR(snap.points[0].radius, 0.02 / std::sqrt(2.0), 1e-12);  // cbrt(8e-6) / sqrt(2)
}

TEST(Snapshot, NamesHaveThreeDecimals) {
  EXPECT_EQ(snapshot_name(0.23), "t0.230");
  EXPECT_EQ(snapshot_name(1.2), "t1.200");
  EXPECT_EQ(snapshot_name(0.1004, 6), "t0.100400");
}

class SnapshotFolder : public synthetic::TempFolderTest {};

TEST_F(SnapshotFolder, TablesScriptsAndPicturesShareFrameAndColourScale) {
  const PointCloud s = soil(), w = water();
  PointCloud moved = soil();
  moved.position[0] = {0.9, 0.2, 0};  // the frame must hold both times
  moved.speed = {0.37, 0.0};
  const std::vector<Snapshot> snaps{make_snapshot(0, 0, &s, &w),
                                    make_snapshot(0.5, 0.5, &moved, &w)};
  const fs::path folder = folder_ / "snapshots";
  const SnapshotFiles files = draw_snapshots(folder, snaps, {"lake", "beads", "gravel"}, "release");

  const auto rows = read_csv_rows(folder / "t0.000.csv");
  EXPECT_EQ(read_text(folder / "t0.000.csv").substr(0, 38),
            "phase,material,x,y,z,radius,speed\n1,0,");
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_DOUBLE_EQ(rows[2][0], 0);  // soil after water
  EXPECT_DOUBLE_EQ(rows[2][1], 1);
  EXPECT_DOUBLE_EQ(rows[2][2], 0.1);
  EXPECT_DOUBLE_EQ(rows[2][5], 0.01414);  // radius, 4 digits
  EXPECT_DOUBLE_EQ(rows[2][6], 5.0);      // speed
  EXPECT_DOUBLE_EQ(read_csv_rows(folder / "t0.500.csv")[2][2], 0.9);

  const std::string material = read_text(folder / "t0.000_material.gp");
  const std::string speed = read_text(folder / "t0.500_speed.gp");
  for (const std::string* gp : {&material, &speed}) {
    EXPECT_NE(gp->find("set size ratio -1\n"), std::string::npos) << *gp;
    // One frame for both times: x from 0.1 - r to 0.9 + r (r = 0.02 / sqrt(2)), plus 2 % of
    // that width each side.
    const double r = 0.02 / std::sqrt(2.0), margin = 0.02 * (0.8 + 2 * r);
    char range[80];
    std::snprintf(range, sizeof range, "set xrange [%.8g:%.8g]\n", 0.1 - r - margin,
                  0.9 + r + margin);
    EXPECT_NE(gp->find(range), std::string::npos) << range << *gp;
    EXPECT_NEAR(0.1 - r - margin, 0.069292, 1e-6);
  }
  // Water first, each material named, in its own colour.
  const size_t lake = material.find("title 'lake'");
  const size_t beads = material.find("title 'beads'");
  const size_t gravel = material.find("title 'gravel'");
  EXPECT_NE(lake, std::string::npos) << material;
  EXPECT_LT(lake, beads);
  EXPECT_LT(beads, gravel);
  EXPECT_NE(material.find("'t0.000.csv' skip 1 using (($1 == 0 && $2 == 1) ? $3 : NaN):4:6 "
                          "with circles lc rgb '#b8742a' title 'beads'"),
            std::string::npos)
      << material;
  // The speed scale: 0 to the fastest point of all times (5 m/s), at 0 s as at 0.5 s.
  EXPECT_NE(speed.find("set cbrange [0:5]\n"), std::string::npos) << speed;
  EXPECT_NE(speed.find("set cblabel 'speed |v| (m/s)'\n"), std::string::npos) << speed;
  EXPECT_NE(speed.find("'t0.500.csv' skip 1 using 3:4:6:7 with circles lc palette"),
            std::string::npos)
      << speed;
  EXPECT_NE(speed.find("t = 0.5 s (stage ''release'')"), std::string::npos) << speed;

  if (gnuplot_available()) {
    EXPECT_TRUE(files.plotted);
    ASSERT_EQ(files.pictures.size(), 4u);
    EXPECT_EQ(files.pictures[0], folder / "t0.000_material.png");
    EXPECT_EQ(files.pictures[3], folder / "t0.500_speed.png");
    for (const fs::path& png : files.pictures) EXPECT_GT(fs::file_size(png), 5000u) << png;
  }
  EXPECT_EQ(files.files.size(), 2u * 3u + files.pictures.size());
}

TEST_F(SnapshotFolder, ColourScaleEndsOnARoundNumberAndMissingSpeedsAreBlank) {
  PointCloud s = soil();
  s.speed = {0.37, 0.02};
  PointCloud w = water();
  w.speed.clear();
  draw_snapshots(folder_, {make_snapshot(0, 0, &s, &w)}, {}, "");
  EXPECT_NE(read_text(folder_ / "t0.000_speed.gp").find("set cbrange [0:0.5]\n"),
            std::string::npos);
  const auto rows = read_csv_rows(folder_ / "t0.000.csv");
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_TRUE(std::isnan(rows[0][6]));
  EXPECT_DOUBLE_EQ(rows[2][6], 0.37);
  // Without material names: the ids are named.
  EXPECT_NE(read_text(folder_ / "t0.000_material.gp").find("title 'material 2'"),
            std::string::npos);
}

TEST_F(SnapshotFolder, CloseTimesGetLongerNames) {
  const PointCloud s = soil();
  const SnapshotFiles files = draw_snapshots(
      folder_, {make_snapshot(0.1, 0.1, &s, nullptr), make_snapshot(0.1, 0.1004, &s, nullptr)}, {},
      "");
  EXPECT_TRUE(fs::exists(folder_ / "t0.100000.csv"));
  EXPECT_TRUE(fs::exists(folder_ / "t0.100400.csv"));
  EXPECT_TRUE(fs::exists(folder_ / "t0.100400_speed.gp"));
}

// The solid point reader takes |velocity| as the speed.
TEST_F(SnapshotFolder, SpeedIsReadFromTheVelocityField) {
  VtuWriter writer;
  const std::vector<double> xyz{0, 0, 0, 1, 0, 0};
  writer.set_points(xyz);
  writer.set_vertex_cells();
  writer.add_point_data("velocity", 3, std::vector<double>{3, 4, 0, 0, 0, -2});
  writer.write(folder_ / "p.vtu");
  const PointCloud cloud = read_points(folder_ / "p.vtu");
  ASSERT_EQ(cloud.speed.size(), 2u);
  EXPECT_DOUBLE_EQ(cloud.speed[0], 5.0);
  EXPECT_DOUBLE_EQ(cloud.speed[1], 2.0);
}

}  // namespace
}  // namespace lituya::post
