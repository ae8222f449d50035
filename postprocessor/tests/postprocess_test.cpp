// The whole `lituya post` pipeline on a synthetic case, the validation of post.toml and of the
// files it points at, and the gnuplot driver.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "lituya/common/csv_writer.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/post/plot.hpp"
#include "synthetic_output.hpp"

namespace lituya::post {
namespace {

namespace fs = std::filesystem;
using synthetic::add_block;
using synthetic::read_csv_rows;
using synthetic::read_text;
using synthetic::write_text;

// Line numbers matter: the error tests below refer to them.
const char* kPostToml =
    "format = \"lituya-post\"\n"         // 1
    "version = 1\n"                      // 2
    "slope_origin = [0.3, 0.5]\n"        // 3
    "slope_angle = 22.0\n"               // 4
    "track_materials = [\"column\"]\n"   // 5
    "wall_position = 0.0\n"              // 6
    "bin_width = 0.01\n"                 // 7
    "min_points = 2\n"                   // 8
    "profile_times = [0.0, 0.4, 1.0]\n"  // 9
    "stage = \"release\"\n";             // 10

const char* kMaterialsToml =
    "format = \"lituya-materials\"\nversion = 1\n"
    "[[material]]\nname = \"column\"\nmodel = \"mohr-coulomb\"\n"
    "[[material]]\nname = \"bed\"\nmodel = \"mohr-coulomb\"\n";

// Replaces line `line` (1-based) of `text`.
std::string with_line(const std::string& text, int line, const std::string& replacement) {
  std::string out;
  size_t start = 0;
  for (int l = 1; start < text.size(); ++l) {
    size_t end = text.find('\n', start);
    out += (l == line ? replacement : text.substr(start, end - start)) + "\n";
    start = end + 1;
  }
  return out;
}

// A 2D case whose column spreads down the 22 degree slope over three outputs: length 0.2,
// 0.3, 0.5 m and height 0.14, 0.10, 0.06 m, on an untracked bed layer along the whole slope.
class PostCase : public synthetic::CaseFolderTest {
 protected:
  static constexpr double kTimes[3] = {0.0, 0.5, 1.0};
  static constexpr double kLength[3] = {0.2, 0.3, 0.5};
  static constexpr double kHeight[3] = {0.14, 0.10, 0.06};

  void SetUp() override {
    CaseFolderTest::SetUp();
    write_text(case_ / "post.toml", kPostToml);
    write_text(case_ / "materials.toml", kMaterialsToml);
    write_text(case_ / "stages.toml", "format = \"lituya-stages\"\nversion = 1\ndimension = 2\n");
    SlopeFrame frame(Eigen::Vector3d(0.3, 0.5, 0.0), 22.0);
    fs::create_directories(case_ / "output");
    PvdWriter pvd(case_ / "output" / "release_points.pvd");
    for (int k = 0; k < 3; ++k) {
      PointCloud cloud;
      add_block(cloud, frame, 0.0, kLength[k], 0.0, kHeight[k], 0.005, 0);
      add_block(cloud, frame, -0.1, 1.0, -0.01, 0.0, 0.005, 1);
      char name[64];
      std::snprintf(name, sizeof name, "release_points_%04d.vtu", k);
      synthetic::write_cloud(cloud, case_ / "output" / name);
      pvd.add(kTimes[k], name);
    }
  }
};

// The same column with masses (an untracked bed of heavy points under it), and at the last
// output one grain of a hundredth of the column's mass flung 2 m ahead. The points sit at the
// centres of 5 mm columns of equal mass, so 99 % of a column N columns long is reached in its
// ceil(0.99 N)-th column: at 0.1975 and 0.2975 m for 0.2 and 0.3 m; with the grain, 99 % of
// 1.01 column masses is reached only in the last column, 0.4975 m, not at the grain.
TEST_F(PostCase, MassFrontIsWhere99PercentOfTheTrackedMassLies) {
  SlopeFrame frame(Eigen::Vector3d(0.3, 0.5, 0.0), 22.0);
  PvdWriter pvd(case_ / "output" / "release_points.pvd");
  for (int k = 0; k < 3; ++k) {
    PointCloud cloud;
    add_block(cloud, frame, 0.0, kLength[k], 0.0, kHeight[k], 0.005, 0);
    double column_mass = 0;
    for (double v : cloud.volume) {
      cloud.mass.push_back(1500.0 * v);
      column_mass += 1500.0 * v;
    }
    add_block(cloud, frame, -0.1, 1.0, -0.01, 0.0, 0.005, 1);  // the untracked bed
    cloud.mass.resize(cloud.volume.size(), 1e6);               // heavy, but not tracked
    if (k == 2) {
      cloud.position.push_back(frame.point(2.5, 0.01));
      cloud.material.push_back(0);
      cloud.volume.push_back(0.005 * 0.005);
      cloud.mass.push_back(0.01 * column_mass);
      cloud.id.push_back(static_cast<int>(cloud.id.size()));
    }
    char name[64];
    std::snprintf(name, sizeof name, "release_points_%04d.vtu", k);
    synthetic::write_cloud(cloud, case_ / "output" / name);
    pvd.add(kTimes[k], name);
  }
  PostResult result = postprocess(case_, case_ / "post", false);
  ASSERT_EQ(result.mass_front_position.size(), 3u);
  const double expected[3] = {0.1975, 0.2975, 0.4975};
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(result.mass_front_position[k], expected[k], 1e-9) << "t = " << kTimes[k];
  EXPECT_NEAR(result.mass_front_travel[0], 0.0, 1e-12);
  EXPECT_NEAR(result.mass_front_travel[2], 0.3, 1e-9);
  auto runout = read_csv_rows(case_ / "post" / "runout.csv");
  ASSERT_EQ(runout.size(), 3u);
  EXPECT_DOUBLE_EQ(runout[2][3], result.mass_front_position[2]);
  EXPECT_DOUBLE_EQ(runout[2][4], result.mass_front_travel[2]);
  EXPECT_NE(read_text(case_ / "post" / "runout.gp").find("front of 99 % of the mass"),
            std::string::npos);
}

TEST_F(PostCase, RunoutWallHeightAndProfilesOfASpreadingColumn) {
  PostResult result = postprocess(case_, case_ / "post", false);

  auto runout = read_csv_rows(case_ / "post" / "runout.csv");
  ASSERT_EQ(runout.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(runout[k][0], kTimes[k]);
    EXPECT_NEAR(runout[k][1], kLength[k], 1e-9) << "front at t = " << kTimes[k];
    EXPECT_NEAR(runout[k][2], kLength[k] - 0.2, 1e-9) << "travel at t = " << kTimes[k];
    EXPECT_NEAR(result.front_travel[k], kLength[k] - 0.2, 1e-9);
  }
  EXPECT_EQ(read_text(case_ / "post" / "runout.csv").substr(0, 73),
            "time,front_position,front_travel,mass_front_position,mass_front_travel\n0,");
  // These outputs carry no masses: the mass front is blank, not a number made up.
  for (int k = 0; k < 3; ++k) {
    ASSERT_EQ(runout[k].size(), 5u);
    EXPECT_TRUE(std::isnan(runout[k][3]) && std::isnan(runout[k][4]));
  }

  auto wall = read_csv_rows(case_ / "post" / "wall_height.csv");
  ASSERT_EQ(wall.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(wall[k][1], kHeight[k], 1e-9);

  // profile_times 0, 0.4, 1.0 -> outputs at 0, 0.5, 1.0, recorded with their own times.
  ASSERT_EQ(result.profiles.size(), 3u);
  EXPECT_DOUBLE_EQ(result.profiles[1].requested_time, 0.4);
  EXPECT_DOUBLE_EQ(result.profiles[1].time, 0.5);
  auto profiles = read_csv_rows(case_ / "post" / "profiles.csv");
  int rows_at_half = 0;
  for (const auto& row : profiles) {
    ASSERT_EQ(row.size(), 3u);
    if (row[0] != 0.5) continue;
    ++rows_at_half;
    const bool in_mass = row[1] > 0 && row[1] < 0.3;
    EXPECT_NEAR(row[2], in_mass ? 0.10 : 0.0, 1e-9) << "s = " << row[1];
  }
  EXPECT_EQ(rows_at_half, 32);  // 0.3 m of column in 0.01 m bins, an empty bin each side
  EXPECT_EQ(profiles.size(), 22u + 32u + 52u);

  EXPECT_TRUE(fs::exists(case_ / "post" / "runout.gp"));
  EXPECT_TRUE(fs::exists(case_ / "post" / "wall_height.gp"));
  EXPECT_TRUE(fs::exists(case_ / "post" / "profiles.gp"));
  if (gnuplot_available()) {
    EXPECT_TRUE(result.plots_written);
    for (const char* png : {"runout.png", "wall_height.png", "profiles.png"})
      EXPECT_GT(fs::file_size(case_ / "post" / png), 1000u) << png;
  }
}

// The forces on the held boundaries (solver/src/wall_loads.cpp) get one plot per boundary,
// with exactly its own normal, tangential and (on a contact wall with water) effective normal
// columns: a boundary named "bed_normal" is a boundary, not the normal force of "bed".
TEST_F(PostCase, ForcesOnEachHeldBoundaryArePlotted) {
  write_text(case_ / "output" / "slide_history.csv",
             "step,time,stage_time,kinetic_energy,wall_bed_force_x,wall_bed_force_y,"
             "wall_bed_normal,wall_bed_tangential,wall_bed_effective_normal,"
             "wall_bed_normal_force_x,wall_bed_normal_force_y,wall_bed_normal_normal,"
             "wall_bed_normal_tangential\n"
             "10,0.1,0.1,1,2,-9,9,2,5,0,-3,3,0\n"
             "20,0.2,0.2,2,3,-9,9,3,5,0,-3,3,0\n");
  const PostResult result = plot_run_histories(case_, case_ / "post", false);
  const std::string bed = read_text(case_ / "post" / "slide_history_wall_bed.gp");
  const std::string other = read_text(case_ / "post" / "slide_history_wall_bed_normal.gp");
  // Columns by position, 1-based: stage_time 3; bed's normal 7, tangential 8, effective 9;
  // bed_normal's normal 12, tangential 13.
  for (const char* expected :
       {"using 3:($7)", "using 3:($8)", "using 3:($9)", "'wall_bed_effective_normal'",
        "forces on the boundary bed'", "'force (N per m)'"})
    EXPECT_NE(bed.find(expected), std::string::npos) << expected << "\n" << bed;
  for (const char* unexpected : {"($12)", "($13)", "($5)"})
    EXPECT_EQ(bed.find(unexpected), std::string::npos) << unexpected << "\n" << bed;
  EXPECT_NE(other.find("using 3:($12)"), std::string::npos) << other;
  EXPECT_NE(other.find("using 3:($13)"), std::string::npos) << other;
  EXPECT_EQ(other.find("($7)"), std::string::npos) << other;
  if (gnuplot_available()) {
    EXPECT_TRUE(result.plots_written);
    EXPECT_GT(fs::file_size(case_ / "post" / "slide_history_wall_bed.png"), 1000u);
  }
}

TEST_F(PostCase, InitialFrontAndReferenceData) {
  write_text(case_ / "reference.csv",
             "time,front_travel,wall_height\n0,0,0.14\n0.32,0.3,0.125\n0.64,,0.08\n");
  write_text(case_ / "post.toml",
             std::string(kPostToml) + "initial_front = 0.1\nreference = \"reference.csv\"\n");
  PostResult result = postprocess(case_, case_ / "post", false);
  ASSERT_EQ(result.front_travel.size(), 3u);
  EXPECT_NEAR(result.front_travel[0], 0.1, 1e-9);
  EXPECT_NEAR(result.front_travel[2], 0.4, 1e-9);

  EXPECT_EQ(read_text(case_ / "post" / "reference.csv"), read_text(case_ / "reference.csv"));
  auto reference_runout = read_csv_rows(case_ / "post" / "reference_runout.csv");
  ASSERT_EQ(reference_runout.size(), 2u);  // the blank front at 0.64 s is no value
  EXPECT_DOUBLE_EQ(reference_runout[1][1], 0.3);
  auto reference_wall = read_csv_rows(case_ / "post" / "reference_wall_height.csv");
  ASSERT_EQ(reference_wall.size(), 3u);
  EXPECT_DOUBLE_EQ(reference_wall[2][0], 0.64);
  EXPECT_DOUBLE_EQ(reference_wall[2][1], 0.08);
  EXPECT_NE(read_text(case_ / "post" / "runout.gp").find("reference_runout.csv"),
            std::string::npos);
}

// The front travels 0, 0.1, 0.3 m and the wall height falls 0.14, 0.10, 0.06 m at 0, 0.5,
// 1 s; the reference says 0, 0.2, 0.3 m and 0.14, 0.12, (none) m.
TEST_F(PostCase, ErrorsAgainstTheReferenceInTitlesAndCsv) {
  write_text(case_ / "reference.csv",
             "time,front_travel,wall_height\n0,0,0.14\n0.5,0.2,0.12\n1.0,0.3,\n");
  write_text(case_ / "post.toml", std::string(kPostToml) + "reference = \"reference.csv\"\n");
  const PostResult result = postprocess(case_, case_ / "post", false);
  ASSERT_EQ(result.errors.size(), 2u);

  const std::string csv = read_text(case_ / "post" / "errors.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "plot,series,unit,span_start,span_end,samples,rms_error,simulated_peak,"
            "reference_peak,peak_error,peak_error_relative,arrival_threshold,simulated_arrival,"
            "reference_arrival,arrival_error");
  EXPECT_EQ(csv.substr(csv.find('\n') + 1, 34), "runout.png,front_travel,m,0,1,3,0.");
  // Columns from span_start on, as numbers (the three text columns left out).
  std::vector<std::vector<double>> rows;
  {
    std::istringstream lines(csv);
    std::string line;
    std::getline(lines, line);
    while (std::getline(lines, line)) {
      const std::vector<std::string> fields = csv_split(line);
      ASSERT_EQ(fields.size(), 15u) << line;
      rows.emplace_back();
      for (size_t k = 3; k < fields.size(); ++k)
        rows.back().push_back(fields[k].empty() ? NAN : std::stod(fields[k]));
    }
  }
  ASSERT_EQ(rows.size(), 2u);
  // Runout: errors 0, -0.1, 0; peaks 0.3 both; 10 % of 0.3 reached at 0.15 s (simulation,
  // 0 -> 0.1 m over 0.5 s) and 0.075 s (reference, 0 -> 0.2 m).
  const auto& runout = rows[0];
  EXPECT_EQ(runout[2], 3);
  EXPECT_NEAR(runout[3], std::sqrt(0.01 / 3), 1e-9);
  EXPECT_NEAR(runout[6], 0.0, 1e-9);
  EXPECT_NEAR(runout[8], 0.03, 1e-12);
  EXPECT_NEAR(runout[9], 0.15, 1e-8);
  EXPECT_NEAR(runout[10], 0.075, 1e-12);
  EXPECT_NEAR(runout[11], 0.075, 1e-8);
  // Wall height: the reference ends at 0.5 s; errors 0 and -0.02; it only falls, so no
  // arrival (blank cells).
  const auto& wall = rows[1];
  EXPECT_EQ(csv.substr(csv.find("\nwall_height.png,wall_height,m,"), 31),
            "\nwall_height.png,wall_height,m,");
  EXPECT_DOUBLE_EQ(wall[1], 0.5);
  EXPECT_EQ(wall[2], 2);
  EXPECT_NEAR(wall[3], std::sqrt(0.0004 / 2), 1e-9);
  EXPECT_NEAR(wall[6], 0.0, 1e-9);
  EXPECT_TRUE(std::isnan(wall[9]) && std::isnan(wall[11]));

  // The titles carry them, on a second line.
  EXPECT_NE(read_text(case_ / "post" / "runout.gp")
                .find("set title 'Front travel along the slope (stage ''release'')'.\"\\n\"."
                      "'RMS 0.0577 m, peak "),
            std::string::npos)
      << read_text(case_ / "post" / "runout.gp");
  EXPECT_NE(read_text(case_ / "post" / "wall_height.gp").find("RMS 0.0141 m, peak "),
            std::string::npos);
  EXPECT_NE(read_text(case_ / "post" / "wall_height.gp").find(", arrival -'"), std::string::npos);
}

TEST_F(PostCase, NoReferenceNoErrorsCsv) {
  const PostResult result = postprocess(case_, case_ / "post", false);
  EXPECT_TRUE(result.errors.empty());
  EXPECT_FALSE(fs::exists(case_ / "post" / "errors.csv"));
}

// profile_times 0, 0.4, 1 -> the outputs at 0, 0.5 and 1 s, drawn by material (column, bed)
// and by speed; an earlier post's snapshots at other times do not survive --force.
TEST_F(PostCase, SnapshotsAtTheProfileTimes) {
  PostResult result = postprocess(case_, case_ / "post", false);
  ASSERT_EQ(result.snapshot_times.size(), 3u);
  EXPECT_DOUBLE_EQ(result.snapshot_times[1], 0.5);
  const fs::path snapshots = case_ / "post" / "snapshots";
  // The column at 0.5 s (0.3 x 0.10 m in 5 mm points) and the bed (1.1 x 0.01 m).
  EXPECT_EQ(read_csv_rows(snapshots / "t0.500.csv").size(), 60u * 20u + 220u * 2u);
  const std::string material = read_text(snapshots / "t0.500_material.gp");
  EXPECT_NE(material.find("title 'column'"), std::string::npos) << material;
  EXPECT_NE(material.find("title 'bed'"), std::string::npos) << material;
  // The synthetic output has no velocity: the speed picture says so.
  EXPECT_NE(read_text(snapshots / "t0.500_speed.gp").find("the output has no velocity"),
            std::string::npos);
  EXPECT_NE(std::find(result.files.begin(), result.files.end(), snapshots / "t1.000.csv"),
            result.files.end());
  if (gnuplot_available()) {
    EXPECT_EQ(result.snapshots.size(), 6u);
    EXPECT_GT(fs::file_size(snapshots / "t1.000_material.png"), 5000u);
  }

  write_text(case_ / "post.toml", with_line(kPostToml, 9, "profile_times = [1.0]"));
  result = postprocess(case_, case_ / "post", true);
  EXPECT_EQ(result.snapshot_times.size(), 1u);
  EXPECT_FALSE(fs::exists(snapshots / "t0.500.csv"));
  EXPECT_TRUE(fs::exists(snapshots / "t1.000.csv"));
}

TEST_F(PostCase, AnEarlierPostIsOverwrittenOnlyWhenForced) {
  postprocess(case_, case_ / "post", false);
  EXPECT_THROW(postprocess(case_, case_ / "post", false), InputError);
  EXPECT_NO_THROW(postprocess(case_, case_ / "post", true));
}

TEST_F(PostCase, UnknownKeyIsAnErrorAtItsLine) {
  expect_input_error(std::string(kPostToml) + "frnt_bin = 3\n", 11, "frnt_bin");
}

TEST_F(PostCase, WrongTypeIsAnErrorAtItsLine) {
  expect_input_error(with_line(kPostToml, 4, "slope_angle = \"22\""), 4, "slope_angle");
}

TEST_F(PostCase, OutOfRangeValuesAreErrorsAtTheirLines) {
  expect_input_error(with_line(kPostToml, 8, "min_points = 0"), 8, "min_points");
  expect_input_error(with_line(kPostToml, 7, "bin_width = -0.01"), 7, "bin_width");
  expect_input_error(with_line(kPostToml, 3, "slope_origin = [0.3]"), 3, "slope_origin");
}

TEST_F(PostCase, UnknownMaterialIsAnErrorAtTrackMaterials) {
  expect_input_error(with_line(kPostToml, 5, "track_materials = [\"colum\"]"), 5, "\"colum\"");
}

TEST_F(PostCase, MissingOutputSeriesIsAnErrorAtTheStage) {
  expect_input_error(with_line(kPostToml, 10, "stage = \"runout\""), 10, "runout_points.pvd");
}

TEST_F(PostCase, MissingReferenceFileIsAnErrorAtItsLine) {
  expect_input_error(std::string(kPostToml) + "reference = \"nowhere.csv\"\n", 11, "nowhere.csv");
}

TEST_F(PostCase, PointFileListedButMissingIsAnError) {
  fs::remove(case_ / "output" / "release_points_0001.vtu");
  try {
    postprocess(case_, case_ / "post", false);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(fs::path(e.file()).filename(), "release_points_0001.vtu") << e.what();
  }
}

using SeriesFiles = synthetic::TempFolderTest;

TEST_F(SeriesFiles, PvdPathsAreRelativeToItsFolderAndSortedByTime) {
  write_text(folder_ / "out" / "s.pvd",
             "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
             "  <Collection>\n"
             "    <DataSet timestep=\"0.25\" part=\"0\" file=\"b &amp; c.vtu\"/>\n"
             "    <DataSet part=\"0\" timestep=\"0\" file=\"a.vtu\"/>\n"
             "  </Collection>\n</VTKFile>\n");
  auto entries = read_pvd(folder_ / "out" / "s.pvd");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_DOUBLE_EQ(entries[0].time, 0.0);
  EXPECT_EQ(entries[0].file, folder_ / "out" / "a.vtu");
  EXPECT_DOUBLE_EQ(entries[1].time, 0.25);
  EXPECT_EQ(entries[1].file, folder_ / "out" / "b & c.vtu");
}

TEST_F(SeriesFiles, MissingOrGarbledPvdIsAnInputError) {
  EXPECT_THROW(read_pvd(folder_ / "none.pvd"), InputError);
  write_text(folder_ / "cut.pvd",
             "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
             "  <Collection>\n    <DataSet timestep=\"0\" file=\"a.vtu\"/>\n");
  EXPECT_THROW(read_pvd(folder_ / "cut.pvd"), InputError);
  write_text(folder_ / "bad.pvd",
             "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
             "  <Collection>\n    <DataSet timestep=\"soon\" file=\"a.vtu\"/>\n"
             "  </Collection>\n</VTKFile>\n");
  try {
    read_pvd(folder_ / "bad.pvd");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 4) << e.what();
  }
}

TEST_F(SeriesFiles, PointsRoundTripThroughTheSolversWriter) {
  SlopeFrame frame(Eigen::Vector3d::Zero(), 22.0);
  PointCloud written;
  add_block(written, frame, 0.0, 0.02, 0.0, 0.01, 0.005, 3);
  synthetic::write_cloud(written, folder_ / "p.vtu");
  PointCloud read = read_points(folder_ / "p.vtu");
  ASSERT_EQ(read.position.size(), 8u);
  EXPECT_EQ(read.dimension, 2);
  EXPECT_TRUE(read.position[5].isApprox(written.position[5], 1e-15));
  EXPECT_EQ(read.material[5], 3);
  EXPECT_DOUBLE_EQ(read.volume[5], 0.005 * 0.005);
  EXPECT_EQ(read.id[5], 5);
}

TEST_F(SeriesFiles, GarbledPointFileIsAnInputError) {
  write_text(folder_ / "bad.vtu", "<?xml version=\"1.0\"?>\n<VTKFile type=\"Unstruct");
  EXPECT_THROW(read_points(folder_ / "bad.vtu"), InputError);
  EXPECT_THROW(read_points(folder_ / "missing.vtu"), InputError);
  // A file cut short while being copied: the header is fine, the data is not.
  PointCloud cloud;
  add_block(cloud, SlopeFrame(Eigen::Vector3d::Zero(), 22.0), 0.0, 0.1, 0.0, 0.1, 0.005, 0);
  synthetic::write_cloud(cloud, folder_ / "cut.vtu");
  fs::resize_file(folder_ / "cut.vtu", fs::file_size(folder_ / "cut.vtu") / 2);
  EXPECT_THROW(read_points(folder_ / "cut.vtu"), InputError);
}

TEST_F(SeriesFiles, ReferenceColumnsByHeaderNameWithBlanks) {
  write_text(folder_ / "ref.csv",
             "# Mangeney et al. 2010, read off fig. 5\n"
             "wall_height, time ,front_travel\n0.14,0,0\n,0.32,0.3\n");
  ReferenceData data = read_reference(folder_ / "ref.csv");
  ASSERT_EQ(data.time.size(), 2u);
  EXPECT_DOUBLE_EQ(data.time[1], 0.32);
  EXPECT_DOUBLE_EQ(*data.front_travel[1], 0.3);
  EXPECT_FALSE(data.wall_height[1].has_value());
  EXPECT_DOUBLE_EQ(*data.wall_height[0], 0.14);
  write_text(folder_ / "bad.csv", "time,front_travel\n0,0\n0.3,far\n");
  try {
    read_reference(folder_ / "bad.csv");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3) << e.what();
  }
}

using Plot = synthetic::TempFolderTest;

TEST_F(Plot, CsvColumnsByName) {
  write_text(folder_ / "a.csv", "time,front_position,front_travel\n0,1,2\n");
  EXPECT_EQ(csv_column(folder_ / "a.csv", "front_travel"), 3);
  EXPECT_THROW(csv_column(folder_ / "a.csv", "height"), InputError);
}

TEST_F(Plot, WritesScriptAndPng) {
  write_text(folder_ / "data.csv", "time,value\n0,0\n0.5,0.25\n1,1\n");
  write_text(folder_ / "ref.csv", "time,value\n0.5,0.3\n");
  const bool made = plot_xy(folder_ / "plot.png", "A title", "time (s)", "value (m)",
                            {{folder_ / "data.csv", 1, 2, "simulation"},
                             {folder_ / "ref.csv", 1, 2, "it's measured", true}});
  const std::string script = read_text(folder_ / "plot.gp");
  EXPECT_NE(script.find("set terminal pngcairo size 900,600"), std::string::npos);
  EXPECT_NE(script.find("'data.csv'"), std::string::npos);  // relative to the script
  EXPECT_NE(script.find("'it''s measured'"), std::string::npos);
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not on PATH";
  ASSERT_TRUE(made);
  const std::string png = read_text(folder_ / "plot.png");
  ASSERT_GT(png.size(), 1000u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST_F(Plot, WithoutGnuplotTheScriptIsStillWritten) {
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", (folder_ / "no-such-bin").c_str(), 1);
  write_text(folder_ / "data.csv", "time,value\n0,0\n1,1\n");
  const bool made =
      plot_xy(folder_ / "plot.png", "t", "x", "y", {{folder_ / "data.csv", 1, 2, "data"}});
  ::setenv("PATH", path.c_str(), 1);
  EXPECT_FALSE(made);
  EXPECT_TRUE(fs::exists(folder_ / "plot.gp"));
  EXPECT_FALSE(fs::exists(folder_ / "plot.png"));
}

}  // namespace
}  // namespace lituya::post
