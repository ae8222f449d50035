#include "lituya/sweep/definition.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lituya/common/error_message.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/sweep/progress.hpp"
#include "lituya/sweep/sweep.hpp"

namespace {

namespace fs = std::filesystem;
using namespace lituya::sweep;

using lituya::input_error_message;

TEST(SweepDefinition, ValueListsAndRanges) {
  EXPECT_EQ(parse_value_list("10, 14,18"), (std::vector<std::string>{"10", "14", "18"}));
  EXPECT_EQ(parse_value_list("10:22:4,30"),
            (std::vector<std::string>{"10", "14", "18", "22", "30"}));
  // No roundoff in the values, and STOP is kept when the steps land on it.
  EXPECT_EQ(parse_value_list("0.1:0.3:0.1"), (std::vector<std::string>{"0.1", "0.2", "0.3"}));
  EXPECT_EQ(parse_value_list("musl,usl"), (std::vector<std::string>{"musl", "usl"}));
  EXPECT_NE(input_error_message([] { parse_value_list("10,,14"); }).find("--values: empty value"),
            std::string::npos);
  EXPECT_NE(input_error_message([] { parse_value_list("22:10:4"); }).find("STEP"),
            std::string::npos);
  EXPECT_NE(input_error_message([] { parse_value_list("0:1:0.0001"); }).find("1000"),
            std::string::npos);
  EXPECT_EQ(split_list("gauge_max:G1, leading_wave_max,"),
            (std::vector<std::string>{"gauge_max:G1", "leading_wave_max"}));
}

TEST(SweepDefinition, SweepFileRoundTrip) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_definition";
  fs::create_directories(folder);
  const fs::path file = folder / "case_b_phi.toml";
  std::ofstream(file) << "format = \"lituya-sweep\"\nversion = 1\nscene = \"scene.toml\"\n"
                         "parameter = \"material.beads.friction_angle\"\n"
                         "values = [10, 14.5, \"x\", true]\nmeasures = [\"gauge_max\"]\n";
  EXPECT_TRUE(is_sweep_file(file));
  const SweepDefinition d = read_sweep_file(file);
  EXPECT_EQ(d.scene, folder / "scene.toml");
  EXPECT_EQ(d.values, (std::vector<std::string>{"10", "14.5", "x", "true"}));
  EXPECT_EQ(d.measures, (std::vector<std::string>{"gauge_max"}));
  EXPECT_EQ(default_output(d), folder / "case_b_phi");

  SweepDefinition from_command_line;
  from_command_line.scene = folder / "scene.toml";
  from_command_line.parameter = "mesh.cell_size";
  EXPECT_EQ(default_output(from_command_line), folder / "sweep_mesh.cell_size");

  // The record a sweep writes is a sweep file that gives the same sweep.
  const fs::path record = folder / "record.toml";
  std::ofstream(record) << sweep_file_text(d, {"10.0", "14.5"}, {"gauge_max:G1"});
  const SweepDefinition again = read_sweep_file(record);
  EXPECT_EQ(again.scene, fs::absolute(folder / "scene.toml"));
  EXPECT_EQ(again.parameter, d.parameter);
  EXPECT_EQ(again.values, (std::vector<std::string>{"10", "14.5"}));
  EXPECT_EQ(again.measures, (std::vector<std::string>{"gauge_max:G1"}));

  std::ofstream(file) << "format = \"lituya-sweep\"\nversion = 1\nscene = \"scene.toml\"\n"
                         "parameter = \"mesh.cell_size\"\nvalues = [0.01]\nmesures = []\n";
  EXPECT_NE(input_error_message([&] { read_sweep_file(file); }).find("mesures"), std::string::npos);
}

TEST(SweepProgressLine, BarCountsRunsAndEstimatesTheRest) {
  EXPECT_EQ(format_duration(7.44), "7.4s");
  EXPECT_EQ(format_duration(42.4), "42s");
  EXPECT_EQ(format_duration(80), "1m20s");
  EXPECT_EQ(format_duration(7500), "2h05m");
  EXPECT_EQ(progress_bar(2, 5, 10), "[####......]");

  std::ostringstream out;
  SweepProgress progress(&out, /*terminal=*/false, 4);
  progress.start_run("friction_angle=10");
  EXPECT_EQ(progress.line().rfind("sweep [....................] 0/4 runs  friction_angle=10", 0),
            0u)
      << progress.line();
  progress.end_run("run 1/4 friction_angle=10: ok", 60.0, true);
  progress.start_run("friction_angle=14");
  // One run of 60 s done, three to go, this one just started: about 3 minutes.
  EXPECT_NE(progress.line().find("1/4 runs  friction_angle=14"), std::string::npos);
  EXPECT_NE(progress.line().find("eta 3m00s"), std::string::npos) << progress.line();
  EXPECT_NE(out.str().find("run 1/4 friction_angle=10: ok\n"), std::string::npos);

  EXPECT_EQ(run_folder_name(3, 5, "18"), "run_03_18");
  EXPECT_EQ(run_folder_name(7, 120, "a/b c"), "run_007_a_b_c");
}

}  // namespace
