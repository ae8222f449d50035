// `lituya post` on a synthetic water case: wave gauges, the leading wave and the surface
// profiles read off a liquid series, the validation of the water keys of post.toml, and a
// case with both a slide and water.
#include <algorithm>
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "lituya/common/input_error.hpp"
#include "lituya/post/plot.hpp"
#include "synthetic_output.hpp"

namespace lituya::post {
namespace {

namespace fs = std::filesystem;
using synthetic::add_water;
using synthetic::read_csv_rows;
using synthetic::read_text;
using synthetic::write_text;

// Line numbers matter: the error tests below refer to them. No track_materials: a
// water-only case, whose slide measures are skipped.
const char* kWaterPostToml =
    "format = \"lituya-post\"\n"        // 1
    "version = 1\n"                     // 2
    "stage = \"release\"\n"             // 3
    "gauges = [0.45, 0.75]\n"           // 4
    "gauge_names = [\"G1\", \"G2\"]\n"  // 5
    "still_water_level = 0.15\n"        // 6
    "leading_wave = true\n"             // 7
    "leading_wave_start = 0.3\n"        // 8
    "profile_times = [0.0, 0.45]\n";    // 9

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

double gaussian(double x, double centre, double height, double width) {
  const double d = (x - centre) / width;
  return height * std::exp(-0.5 * d * d);
}

// Still water 0.15 m deep over x in [0, 1.5] with 5 mm points; a 0.02 m crest passes the
// first gauge (x = 0.45) at t = 0.25 s and a 0.015 m crest the second (x = 0.75) at 0.5 s.
class WaterCase : public synthetic::CaseFolderTest {
 protected:
  static constexpr double kTimes[3] = {0.0, 0.25, 0.5};
  static constexpr double kCrestX[3] = {0.0, 0.45, 0.75};
  static constexpr double kCrestHeight[3] = {0.0, 0.02, 0.015};

  void SetUp() override {
    CaseFolderTest::SetUp();
    write_text(case_ / "post.toml", kWaterPostToml);
    write_text(case_ / "materials.toml",
               "format = \"lituya-materials\"\nversion = 1\n[[material]]\nname = \"water\"\n");
    write_text(case_ / "stages.toml", "format = \"lituya-stages\"\nversion = 1\ndimension = 2\n");
    fs::create_directories(case_ / "output");
    PvdWriter pvd(case_ / "output" / "release_liquid.pvd");
    for (int k = 0; k < 3; ++k) {
      PointCloud water;
      add_water(water, 0.0, 1.5, 0.0, 0.005,
                [&](double x) { return 0.15 + gaussian(x, kCrestX[k], kCrestHeight[k], 0.05); });
      char name[64];
      std::snprintf(name, sizeof name, "release_liquid_%04d.vtu", k);
      synthetic::write_liquid_cloud(water, case_ / "output" / name);
      pvd.add(kTimes[k], name);
    }
  }

  bool written(const PostResult& result, const char* name) const {
    return std::find(result.files.begin(), result.files.end(), case_ / "post" / name) !=
           result.files.end();
  }
};

TEST_F(WaterCase, GaugesLeadingWaveAndSurfaceProfiles) {
  const PostResult result = postprocess(case_, case_ / "post", false);

  // Half-width inferred from the point volumes: sqrt(0.005^2).
  EXPECT_NEAR(result.gauge_half_width, 0.005, 1e-15);

  // gauges.csv: at the crest the window holds the two columns 0.0025 m either side of it,
  // whose mean top is within 1e-4 m of the crest; away from the crest the water is still
  // (the Gaussian is below 1e-6 m 0.3 m away).
  EXPECT_EQ(read_text(case_ / "post" / "gauges.csv").substr(0, 13), "time,G1,G2\n0,");
  const auto gauges = read_csv_rows(case_ / "post" / "gauges.csv");
  ASSERT_EQ(gauges.size(), 3u);
  const double expected[3][2] = {{0.0, 0.0}, {0.02, 0.0}, {0.0, 0.015}};
  for (int k = 0; k < 3; ++k) {
    ASSERT_EQ(gauges[k].size(), 3u);
    EXPECT_DOUBLE_EQ(gauges[k][0], kTimes[k]);
    for (int g = 0; g < 2; ++g) {
      EXPECT_NEAR(gauges[k][1 + g], expected[k][g], 1e-4) << "t = " << kTimes[k] << " G" << g + 1;
      EXPECT_NEAR(result.gauge_eta[g][k], expected[k][g], 1e-4);
    }
  }
  EXPECT_NEAR(gauges[0][1], 0.0, 1e-12);  // still water reads exactly 0

  // leading_wave.csv: no crest in still water; then the crest within one bin (0.01 m) of
  // its true position, and its height: the bins start at 0.3 and are 0.01 m wide, so the
  // crest is at a bin's edge and that bin reads the mean of the columns 0.0025 and 0.0075 m
  // from it, 0.62 % of the height low (1 - (e^(-0.5 (0.05)^2) + e^(-0.5 (0.15)^2)) / 2).
  const auto leading = read_csv_rows(case_ / "post" / "leading_wave.csv");
  ASSERT_EQ(leading.size(), 3u);
  EXPECT_TRUE(std::isnan(leading[0][1]) && std::isnan(leading[0][2]));
  EXPECT_NEAR(leading[0][3], 0.0, 1e-12);
  for (int k = 1; k < 3; ++k) {
    EXPECT_NEAR(leading[k][1], kCrestX[k], 0.01) << "t = " << kTimes[k];
    const double bin_mean =
        0.5 * kCrestHeight[k] * (std::exp(-0.5 * 0.05 * 0.05) + std::exp(-0.5 * 0.15 * 0.15));
    EXPECT_NEAR(leading[k][2], bin_mean, 1e-9) << "t = " << kTimes[k];
    EXPECT_NEAR(leading[k][3], bin_mean, 1e-9) << "t = " << kTimes[k];
    EXPECT_NEAR(result.crest_x[k], kCrestX[k], 0.01);
  }

  // surface_profiles.csv: profile_times 0 and 0.45 -> outputs at 0 and 0.5; bins of
  // 2 x 0.005 m anchored on x = 0.3, from the bin holding x = 0.0025 to the one holding
  // 1.4975: k = -30 ... 119, 150 bins per time.
  ASSERT_EQ(result.surface_profiles.size(), 2u);
  EXPECT_DOUBLE_EQ(result.surface_profiles[1].time, 0.5);
  const auto profiles = read_csv_rows(case_ / "post" / "surface_profiles.csv");
  ASSERT_EQ(profiles.size(), 300u);
  EXPECT_NEAR(profiles[0][1], 0.005, 1e-12);
  for (int r = 0; r < 150; ++r) EXPECT_NEAR(profiles[r][2], 0.0, 1e-12) << "x = " << profiles[r][1];
  double highest = 0, at = 0;
  for (int r = 150; r < 300; ++r)
    if (profiles[r][2] > highest) highest = profiles[r][2], at = profiles[r][1];
  EXPECT_NEAR(at, 0.75, 0.01);
  EXPECT_NEAR(highest, 0.015, 1e-4);

  // Water only: the slide measures are skipped, not failed.
  EXPECT_TRUE(result.time.empty());
  EXPECT_FALSE(fs::exists(case_ / "post" / "runout.csv"));
  EXPECT_FALSE(fs::exists(case_ / "post" / "wall_height.csv"));
  for (const char* name : {"gauges.csv", "leading_wave.csv", "surface_profiles.csv", "gauges.gp",
                           "leading_wave.gp", "surface_profiles.gp"}) {
    EXPECT_TRUE(fs::exists(case_ / "post" / name)) << name;
    EXPECT_TRUE(written(result, name)) << name;
  }
  if (gnuplot_available()) {
    EXPECT_TRUE(result.plots_written);
    for (const char* png : {"gauges.png", "leading_wave.png", "surface_profiles.png"}) {
      EXPECT_GT(fs::file_size(case_ / "post" / png), 1000u) << png;
      EXPECT_TRUE(written(result, png)) << png;
    }
  }
}

TEST_F(WaterCase, GaugeReferenceIsOverlaidInTheGaugesColours) {
  write_text(case_ / "gauges_reference.csv",
             "# Viroulet et al. 2014, read off fig. 9\n"
             "time, G2 ,G1\n0.25,,0.019\n0.5,0.014,\n0.6,,\n");
  write_text(case_ / "post.toml",
             std::string(kWaterPostToml) + "gauge_reference = \"gauges_reference.csv\"\n");
  const PostResult result = postprocess(case_, case_ / "post", false);
  EXPECT_EQ(read_text(case_ / "post" / "gauge_reference.csv"),
            read_text(case_ / "gauges_reference.csv"));
  const auto g1 = read_csv_rows(case_ / "post" / "reference_gauge_1.csv");
  ASSERT_EQ(g1.size(), 1u);
  EXPECT_DOUBLE_EQ(g1[0][0], 0.25);
  EXPECT_DOUBLE_EQ(g1[0][1], 0.019);
  const auto g2 = read_csv_rows(case_ / "post" / "reference_gauge_2.csv");
  ASSERT_EQ(g2.size(), 1u);
  EXPECT_DOUBLE_EQ(g2[0][0], 0.5);
  EXPECT_DOUBLE_EQ(g2[0][1], 0.014);
  const std::string script = read_text(case_ / "post" / "gauges.gp");
  EXPECT_NE(script.find("'reference_gauge_2.csv' skip 1 using 1:($2) with points pt 7 ps 1.2 lt 2"),
            std::string::npos)
      << script;
  EXPECT_NE(script.find("'gauges.csv' skip 1 using 1:($3) with lines lw 2 lt 2 title 'G2'"),
            std::string::npos)
      << script;
  EXPECT_TRUE(written(result, "reference_gauge_2.csv"));
}

// G1 reads 0, e1 (about 0.02 m), 0 at 0, 0.25, 0.5 s; its reference rises later (0 until
// 0.1 s, 0.019 m at 0.25 s). G2 has no reference, so no errors.
TEST_F(WaterCase, GaugeErrorsAgainstTheReference) {
  write_text(case_ / "gauges_reference.csv", "time,G1\n0,0\n0.1,0\n0.25,0.019\n0.5,0\n");
  write_text(case_ / "post.toml",
             std::string(kWaterPostToml) + "gauge_reference = \"gauges_reference.csv\"\n");
  const PostResult result = postprocess(case_, case_ / "post", false);
  ASSERT_EQ(result.errors.size(), 1u);
  const ReferenceError& e = result.errors[0];
  EXPECT_EQ(e.plot, "gauges.png");
  EXPECT_EQ(e.series, "G1");
  const double e1 = result.gauge_eta[0][1], e2 = result.gauge_eta[0][2];
  EXPECT_NEAR(e1, 0.02, 1e-4);
  // At 0.1 s the simulation is interpolated to 0.4 e1.
  EXPECT_EQ(e.samples, 4);
  EXPECT_NEAR(e.rms, std::sqrt((0.16 * e1 * e1 + (e1 - 0.019) * (e1 - 0.019) + e2 * e2) / 4),
              1e-12);
  EXPECT_NEAR(e.peak_error, e1 - 0.019, 1e-12);
  EXPECT_NEAR(e.peak_error_relative, (e1 - 0.019) / 0.019, 1e-10);
  // 10 % of 0.019 m: reached at 0.25 * 0.0019 / e1 (about 0.024 s) and 0.115 s.
  EXPECT_NEAR(e.simulated_arrival, 0.25 * 0.0019 / e1, 1e-12);
  EXPECT_NEAR(e.reference_arrival, 0.115, 1e-12);
  EXPECT_NEAR(e.arrival_error, -0.091, 1e-3);

  const std::string errors = read_text(case_ / "post" / "errors.csv");
  EXPECT_EQ(std::count(errors.begin(), errors.end(), '\n'), 2);
  EXPECT_EQ(errors.substr(errors.find('\n') + 1, 17), "gauges.png,G1,m,0");
  EXPECT_NE(read_text(case_ / "post" / "gauges.gp").find(".'G1: RMS 0.00"), std::string::npos)
      << read_text(case_ / "post" / "gauges.gp");
  EXPECT_TRUE(written(result, "errors.csv"));
}

TEST_F(WaterCase, GaugeReferenceColumnThatNamesNoGaugeIsAnError) {
  write_text(case_ / "gauges_reference.csv", "time,G1,G3\n0.25,0.019,0.01\n");
  write_text(case_ / "post.toml",
             std::string(kWaterPostToml) + "gauge_reference = \"gauges_reference.csv\"\n");
  try {
    postprocess(case_, case_ / "post", false);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(fs::path(e.file()).filename(), "gauges_reference.csv") << e.what();
    EXPECT_EQ(e.line(), 1) << e.what();
    EXPECT_NE(std::string(e.what()).find("\"G3\""), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(case_ / "post"));
}

TEST_F(WaterCase, DefaultGaugeNamesAndAGivenHalfWidth) {
  // Without names the columns are "x=<position>". A half-width of 0.05 m spans 20 whole
  // columns of points, [0.66, 0.76], up the flank of the t = 0.5 s wave to its crest at 0.75.
  write_text(case_ / "post.toml", with_line(with_line(kWaterPostToml, 5, "gauge_half_width = 0.05"),
                                            4, "gauges = [0.45, 0.71]"));
  const PostResult result = postprocess(case_, case_ / "post", false);
  EXPECT_DOUBLE_EQ(result.gauge_half_width, 0.05);
  EXPECT_EQ(read_text(case_ / "post" / "gauges.csv").substr(0, 21), "time,x=0.45,x=0.71\n0,");
  const auto gauges = read_csv_rows(case_ / "post" / "gauges.csv");
  ASSERT_EQ(gauges.size(), 3u);
  // A window that wide reads the level below which three quarters of it are full (the 15th
  // highest of the 20 column tops), raised by the water above that level spread over the
  // window: here 0.0108 m (the mean of the tops is 0.0102 m, the highest 0.0150 m).
  std::vector<double> tops;
  for (int i = 0; i < 20; ++i) tops.push_back(gaussian(0.6625 + 0.005 * i, 0.75, 0.015, 0.05));
  std::sort(tops.begin(), tops.end(), std::greater<>());
  double expected = tops[14];
  for (int i = 0; i < 14; ++i) expected += (tops[i] - tops[14]) / 20;
  EXPECT_NEAR(gauges[2][2], expected, 1e-9);
}

TEST_F(WaterCase, GaugeWithoutWaterIsABlankCell) {
  write_text(case_ / "post.toml", with_line(kWaterPostToml, 4, "gauges = [0.45, 2.0]"));
  const PostResult result = postprocess(case_, case_ / "post", false);
  const auto gauges = read_csv_rows(case_ / "post" / "gauges.csv");
  ASSERT_EQ(gauges.size(), 3u);
  for (const auto& row : gauges) {
    EXPECT_FALSE(std::isnan(row[1]));
    EXPECT_TRUE(std::isnan(row[2]));  // the tank ends at x = 1.5
  }
  EXPECT_TRUE(std::isnan(result.gauge_eta[1][1]));
}

TEST_F(WaterCase, NoLiquidSeriesIsAnErrorAtTheGaugesLine) {
  fs::remove(case_ / "output" / "release_liquid.pvd");
  expect_input_error(kWaterPostToml, 4, "release_liquid.pvd");
}

TEST_F(WaterCase, NoLiquidSeriesForTheLeadingWaveIsAnErrorAtItsLine) {
  fs::remove(case_ / "output" / "release_liquid.pvd");
  expect_input_error(with_line(with_line(kWaterPostToml, 4, "#"), 5, "#"), 7, "leading wave");
}

TEST_F(WaterCase, LiquidStageNamesTheSeries) {
  expect_input_error(std::string(kWaterPostToml) + "liquid_stage = \"flood\"\n", 10,
                     "flood_liquid.pvd");
  fs::rename(case_ / "output" / "release_liquid.pvd", case_ / "output" / "flood_liquid.pvd");
  write_text(case_ / "post.toml", std::string(kWaterPostToml) + "liquid_stage = \"flood\"\n");
  const PostResult result = postprocess(case_, case_ / "post", false);
  EXPECT_EQ(result.liquid_time.size(), 3u);
}

TEST_F(WaterCase, UnknownKeyIsAnErrorAtItsLine) {
  expect_input_error(std::string(kWaterPostToml) + "gauge_halfwidth = 0.01\n", 10,
                     "gauge_halfwidth");
}

TEST_F(WaterCase, WrongTypesAreErrorsAtTheirLines) {
  expect_input_error(with_line(kWaterPostToml, 4, "gauges = \"0.45\""), 4, "gauges");
  expect_input_error(with_line(kWaterPostToml, 5, "gauge_names = [1, 2]"), 5, "gauge_names");
  expect_input_error(with_line(kWaterPostToml, 7, "leading_wave = 1"), 7, "leading_wave");
  expect_input_error(with_line(kWaterPostToml, 6, "still_water_level = \"0.15\""), 6,
                     "still_water_level");
}

TEST_F(WaterCase, OutOfRangeValuesAreErrorsAtTheirLines) {
  expect_input_error(std::string(kWaterPostToml) + "gauge_half_width = 0.0\n", 10,
                     "gauge_half_width");
  expect_input_error(std::string(kWaterPostToml) + "leading_wave_min_height = -0.001\n", 10,
                     "leading_wave_min_height");
  expect_input_error(with_line(kWaterPostToml, 4, "gauges = [0.45, nan]"), 4, "gauges");
  expect_input_error(with_line(kWaterPostToml, 8, "leading_wave_start = inf"), 8,
                     "leading_wave_start");
}

TEST_F(WaterCase, GaugeNamesMustMatchTheGauges) {
  expect_input_error(with_line(kWaterPostToml, 5, "gauge_names = [\"G1\"]"), 5, "1 names for 2");
  expect_input_error(with_line(kWaterPostToml, 5, "gauge_names = [\"G1\", \"G1\"]"), 5,
                     "two gauges are called \"G1\"");
  expect_input_error(with_line(kWaterPostToml, 5, "gauge_names = [\"G1\", \"a,b\"]"), 5, "a,b");
  // Default names repeat when the positions do.
  expect_input_error(with_line(with_line(kWaterPostToml, 5, "#"), 4, "gauges = [0.45, 0.45]"), 4,
                     "x=0.45");
}

TEST_F(WaterCase, StillWaterLevelIsRequiredForGaugesAndTheLeadingWave) {
  expect_input_error(with_line(kWaterPostToml, 6, "#"), 4, "still_water_level");
  expect_input_error(with_line(with_line(with_line(kWaterPostToml, 4, "#"), 5, "#"), 6, "#"), 7,
                     "still_water_level");
}

TEST_F(WaterCase, GaugeReferenceNeedsGaugesAndAFile) {
  write_text(case_ / "gauges_reference.csv", "time,G1\n0.25,0.019\n");
  expect_input_error(
      with_line(with_line(kWaterPostToml, 4, "#"), 5, "gauge_reference = \"gauges_reference.csv\""),
      5, "no 'gauges'");
  expect_input_error(std::string(kWaterPostToml) + "gauge_reference = \"nowhere.csv\"\n", 10,
                     "nowhere.csv");
}

TEST_F(WaterCase, RunoutReferenceWithoutTrackedMaterialsIsAnError) {
  write_text(case_ / "reference.csv", "time,front_travel\n0,0\n");
  expect_input_error(std::string(kWaterPostToml) + "reference = \"reference.csv\"\n", 10,
                     "gauge_reference");
}

TEST_F(WaterCase, WithoutWaterOrTrackedMaterialsNothingIsMeasured) {
  // A misspelt `gauges` leaves a post.toml that asks for nothing: said so, at the top.
  const std::string typo = with_line(with_line(kWaterPostToml, 4, "gauge = [0.45, 0.75]"), 5, "#");
  expect_input_error(with_line(typo, 7, "leading_wave = false"), 1, "measures nothing");
}

TEST_F(WaterCase, EmptyTrackMaterialsSkipsTheSlide) {
  write_text(case_ / "post.toml", std::string(kWaterPostToml) + "track_materials = []\n");
  const PostResult result = postprocess(case_, case_ / "post", false);
  EXPECT_TRUE(result.time.empty());
  EXPECT_FALSE(fs::exists(case_ / "post" / "runout.csv"));
  EXPECT_EQ(result.crest_x.size(), 3u);
}

// Case B's layout: a slide (tracked, points series) and water (liquid series) in one case.
TEST_F(WaterCase, SlideAndWaterAreBothMeasured) {
  write_text(case_ / "materials.toml",
             "format = \"lituya-materials\"\nversion = 1\n[[material]]\nname = \"beads\"\n"
             "[[material]]\nname = \"water\"\n");
  SlopeFrame frame(Eigen::Vector3d(-0.3, 0.3, 0.0), 45.0);
  PvdWriter pvd(case_ / "output" / "release_points.pvd");
  for (int k = 0; k < 2; ++k) {
    PointCloud slide;
    synthetic::add_block(slide, frame, 0.0, 0.1 + 0.1 * k, 0.0, 0.05, 0.005, 0);
    const std::string name = "release_points_000" + std::to_string(k) + ".vtu";
    synthetic::write_cloud(slide, case_ / "output" / name);
    pvd.add(0.5 * k, name);
  }
  write_text(case_ / "post.toml", std::string(kWaterPostToml) +
                                      "track_materials = [\"beads\"]\n"
                                      "slope_origin = [-0.3, 0.3]\nslope_angle = 45.0\n");
  const PostResult result = postprocess(case_, case_ / "post", false);
  ASSERT_EQ(result.front_travel.size(), 2u);
  EXPECT_NEAR(result.front_position[1], 0.2, 1e-9);
  EXPECT_NEAR(result.front_travel[1], 0.1, 1e-9);
  EXPECT_EQ(result.liquid_time.size(), 3u);
  EXPECT_NEAR(result.gauge_eta[0][1], 0.02, 1e-4);
  for (const char* name : {"runout.csv", "wall_height.csv", "profiles.csv", "gauges.csv",
                           "leading_wave.csv", "surface_profiles.csv"})
    EXPECT_TRUE(written(result, name)) << name;
}

TEST_F(WaterCase, SlideKeysAreStillCheckedWhenOnlyWaterIsMeasured) {
  // Without track_materials the slope frame is optional, but a wrong one is still an error.
  expect_input_error(std::string(kWaterPostToml) + "slope_angle = 95.0\n", 10, "slope_angle");
  // And with track_materials it is required, as in a dry case.
  expect_input_error(std::string(kWaterPostToml) + "track_materials = [\"water\"]\n", 1,
                     "slope_origin");
}

}  // namespace
}  // namespace lituya::post

namespace lituya::post {
namespace {

namespace fs = std::filesystem;

// Still water 0.15 m deep over [0, 1.5] with a 0.02 m crest at x = 0.45, and downstream of it
// a saturated mound (pore water, porosity 0.4) standing 0.1 m above the water at
// x in [0.8, 0.9], as a saturated slide that reaches past the shoreline.
class PoreWaterCase : public synthetic::CaseFolderTest {
 protected:
  void write_case(const std::string& extra_key) {
    synthetic::write_text(case_ / "post.toml",
                          "format = \"lituya-post\"\nversion = 1\nstage = \"release\"\n"
                          "gauges = [0.45, 0.85]\nstill_water_level = 0.15\n"
                          "leading_wave = true\nleading_wave_start = 0.0\n" +
                              extra_key);
    synthetic::write_text(
        case_ / "materials.toml",
        "format = \"lituya-materials\"\nversion = 1\n[[material]]\nname = \"water\"\n");
    synthetic::write_text(case_ / "stages.toml",
                          "format = \"lituya-stages\"\nversion = 1\ndimension = 2\n");
    fs::create_directories(case_ / "output");
    PointCloud cloud;
    const double h = 0.005;
    synthetic::add_water(cloud, 0.0, 0.8, 0.0, h, [](double x) {
      const double d = (x - 0.45) / 0.05;
      return 0.15 + 0.02 * std::exp(-0.5 * d * d);
    });
    synthetic::add_water(cloud, 0.9, 1.5, 0.0, h, [](double) { return 0.15; });
    cloud.porosity.assign(cloud.position.size(), 1.0);
    // The mound: pore water points, each holding 0.4 of its mixture volume.
    PointCloud mound;
    synthetic::add_water(mound, 0.8, 0.9, 0.0, h, [](double) { return 0.25; });
    for (size_t i = 0; i < mound.position.size(); ++i) {
      cloud.position.push_back(mound.position[i]);
      cloud.material.push_back(0);
      cloud.volume.push_back(0.4 * mound.volume[i]);
      cloud.id.push_back(static_cast<int>(cloud.id.size()));
      cloud.porosity.push_back(0.4);
    }
    PvdWriter pvd(case_ / "output" / "release_liquid.pvd");
    synthetic::write_liquid_cloud(cloud, case_ / "output" / "release_liquid_0000.vtu");
    pvd.add(0.0, "release_liquid_0000.vtu");
  }
};

TEST_F(PoreWaterCase, PoreWaterIsNotFreeSurface) {
  // Default (surface_min_porosity 0.9): the mound is not water surface. The leading crest
  // is the 0.02 m wave at x = 0.45 (within one 0.01 m bin), and the gauge over the mound
  // sees no free water (blank).
  write_case("");
  const PostResult r = postprocess(case_, case_ / "post", false);
  ASSERT_EQ(r.crest_x.size(), 1u);
  EXPECT_NEAR(r.crest_x[0], 0.45, 0.01);
  EXPECT_NEAR(r.crest_eta[0], 0.02, 0.003);
  EXPECT_TRUE(std::isnan(r.gauge_eta[1][0]));
}

TEST_F(PoreWaterCase, AllWaterCountsWhenAsked) {
  // surface_min_porosity = 0: the mound's top (0.25 m, 0.1 m above still water) becomes the
  // most downstream crest and the gauge over it reads 0.1 m (to half a point spacing).
  write_case("surface_min_porosity = 0.0\n");
  const PostResult r = postprocess(case_, case_ / "post", false);
  ASSERT_EQ(r.crest_x.size(), 1u);
  EXPECT_NEAR(r.crest_x[0], 0.85, 0.05);
  EXPECT_NEAR(r.gauge_eta[1][0], 0.1, 0.003);
}

}  // namespace
}  // namespace lituya::post
