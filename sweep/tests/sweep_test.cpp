#include "lituya/sweep/sweep.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lituya/common/input_error.hpp"

namespace {

namespace fs = std::filesystem;
using namespace lituya::sweep;

const fs::path kScene = fs::path(LITUYA_SWEEP_TEST_DATA) / "collapse.toml";

std::vector<std::vector<std::string>> read_rows(const fs::path& csv) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(csv);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> row;
    std::stringstream fields(line + ",");
    for (std::string field; std::getline(fields, field, ',');) row.push_back(field);
    rows.push_back(row);
  }
  return rows;
}

// A dry granular column collapse (about 1 s a run) swept over its friction angle: a lower
// angle runs out further. 95 degrees is not a valid angle: that run fails, the others go on.
TEST(Sweep, FrictionAngleOfAColumnCollapse) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_e2e";
  fs::remove_all(folder);
  SweepDefinition d;
  d.scene = kScene;
  d.parameter = "material.sand.friction_angle";
  d.values = {"15", "95", "40"};
  d.measures = {"front_travel_final"};
  d.output = folder;
  std::ostringstream progress, report;
  SweepOptions options;
  options.progress = &progress;
  options.report = &report;
  const SweepResult result = run_sweep(d, options);

  ASSERT_EQ(result.runs.size(), 3u);
  EXPECT_EQ(result.runs[0].status, RunStatus::kOk) << result.runs[0].message;
  EXPECT_EQ(result.runs[2].status, RunStatus::kOk) << result.runs[2].message;
  EXPECT_EQ(result.runs[1].status, RunStatus::kInputError);
  EXPECT_NE(result.runs[1].message.find("run_02_95/scene.toml:"), std::string::npos)
      << result.runs[1].message;
  EXPECT_FALSE(result.all_ok());

  // sweep.csv: one row per run, the measure of the valid runs, the failed one marked.
  const std::vector<std::vector<std::string>> table = read_rows(folder / "sweep.csv");
  ASSERT_EQ(table.size(), 4u);
  EXPECT_EQ(table[0],
            (std::vector<std::string>{"run", "material.sand.friction_angle", "front_travel_final",
                                      "wall_time_s", "status", "message"}));
  EXPECT_EQ(table[1][1], "15.0");
  EXPECT_EQ(table[3][1], "40.0");
  EXPECT_EQ(table[1][4], "ok");
  EXPECT_EQ(table[2][4], "input error");
  EXPECT_EQ(table[3][4], "ok");
  EXPECT_EQ(table[2][2], "");  // no measure for the failed run
  const double travel_15 = std::stod(table[1][2]), travel_40 = std::stod(table[3][2]);
  EXPECT_GT(travel_15, travel_40 + 0.03) << travel_15 << " " << travel_40;
  EXPECT_GT(travel_40, 0.0);
  EXPECT_DOUBLE_EQ(result.runs[0].measures[0], travel_15);

  // Each run keeps its scene copy (which `lituya run` can re-run) and its case.
  EXPECT_TRUE(fs::exists(folder / "run_01_15" / "scene.toml"));
  EXPECT_TRUE(fs::exists(folder / "run_03_40" / "case" / "post" / "runout.csv"));
  EXPECT_TRUE(fs::exists(folder / "sweep.toml"));
  EXPECT_NE(report.str().find("front_travel_final (m)"), std::string::npos) << report.str();
  EXPECT_NE(progress.str().find("sweep [####################] 3/3 runs"), std::string::npos)
      << progress.str();

  // Nothing is overwritten without --force.
  EXPECT_THROW(run_sweep(d, options), lituya::InputError);
}

// A misspelt key makes every copy invalid: the sweep stops before it writes anything, and the
// message names the scene and what the scene reader said.
TEST(Sweep, MisspeltKeyStopsBeforeAnyRun) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_misspelt";
  fs::remove_all(folder);
  SweepDefinition d;
  d.scene = kScene;
  d.parameter = "material.sand.frction_angle";
  d.values = {"20", "30"};
  d.output = folder;
  std::string message;
  try {
    run_sweep(d, SweepOptions{});
  } catch (const lituya::InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find(kScene.string()), std::string::npos) << message;
  EXPECT_NE(message.find("frction_angle"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(folder));
}

}  // namespace
