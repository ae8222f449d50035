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
  ASSERT_EQ(d.parameters.size(), 1u);
  EXPECT_EQ(d.parameters[0].key, "material.beads.friction_angle");
  EXPECT_EQ(d.parameters[0].line, 4);
  EXPECT_EQ(d.parameters[0].values, (std::vector<std::string>{"10", "14.5", "x", "true"}));
  EXPECT_EQ(d.measures, (std::vector<std::string>{"gauge_max"}));
  EXPECT_EQ(default_output(d), folder / "case_b_phi");

  SweepDefinition from_command_line;
  from_command_line.scene = folder / "scene.toml";
  from_command_line.parameters = {{"mesh.cell_size", {"0.01"}}};
  EXPECT_EQ(default_output(from_command_line), folder / "sweep_mesh.cell_size");

  // The record a sweep writes is a sweep file that gives the same sweep.
  const fs::path record = folder / "record.toml";
  std::ofstream(record) << sweep_file_text(d, {{"10.0", "14.5"}}, {"gauge_max:G1"});
  const SweepDefinition again = read_sweep_file(record);
  EXPECT_EQ(again.scene, fs::absolute(folder / "scene.toml"));
  ASSERT_EQ(again.parameters.size(), 1u);
  EXPECT_EQ(again.parameters[0].key, d.parameters[0].key);
  EXPECT_EQ(again.parameters[0].values, (std::vector<std::string>{"10", "14.5"}));
  EXPECT_EQ(again.measures, (std::vector<std::string>{"gauge_max:G1"}));

  std::ofstream(file) << "format = \"lituya-sweep\"\nversion = 1\nscene = \"scene.toml\"\n"
                         "parameter = \"mesh.cell_size\"\nvalues = [0.01]\nmesures = []\n";
  EXPECT_NE(input_error_message([&] { read_sweep_file(file); }).find("mesures"), std::string::npos);
}

// Several keys: [[parameter]] entries, combined as a grid (every combination, the first key
// slowest) or zipped (the i-th values together); a sweep file of several keys round-trips.
TEST(SweepDefinition, SeveralKeysAsAGridOrZipped) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_definition";
  fs::create_directories(folder);
  const fs::path file = folder / "grid.toml";
  std::ofstream(file) << "format = \"lituya-sweep\"\nversion = 1\nscene = \"scene.toml\"\n"
                         "\n[[parameter]]\nkey = \"material.sand.friction_angle\"\n"
                         "values = [20, 30, 40]\n"
                         "\n[[parameter]]\nkey = \"mesh.cell_size\"\nvalues = [0.02, 0.01]\n";
  const SweepDefinition grid = read_sweep_file(file);
  ASSERT_EQ(grid.parameters.size(), 2u);
  EXPECT_EQ(grid.combination, Combination::kGrid);
  EXPECT_EQ(grid.parameters[0].line, 5);
  EXPECT_EQ(grid.parameters[1].line, 9);
  EXPECT_EQ(grid.parameters[1].values, (std::vector<std::string>{"0.02", "0.01"}));
  using Runs = std::vector<std::vector<size_t>>;
  EXPECT_EQ(combinations(grid), (Runs{{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 0}, {2, 1}}));
  EXPECT_EQ(default_output(grid), folder / "grid");

  SweepDefinition zip = grid;
  zip.combination = Combination::kZip;
  zip.parameters[1].values.push_back("0.005");
  EXPECT_EQ(combinations(zip), (Runs{{0, 0}, {1, 1}, {2, 2}}));

  // The record of a sweep of several keys is a sweep file that gives the same sweep.
  const fs::path record = folder / "record_zip.toml";
  std::ofstream(record) << sweep_file_text(zip, {{"20", "30", "40"}, {"0.02", "0.01", "0.005"}},
                                           {"front_travel_final"});
  const SweepDefinition again = read_sweep_file(record);
  EXPECT_EQ(again.combination, Combination::kZip);
  ASSERT_EQ(again.parameters.size(), 2u);
  EXPECT_EQ(again.parameters[0].key, "material.sand.friction_angle");
  EXPECT_EQ(again.parameters[1].values, (std::vector<std::string>{"0.02", "0.01", "0.005"}));
  EXPECT_EQ(again.measures, (std::vector<std::string>{"front_travel_final"}));

  // From the command line: the same, and default folders named after every key.
  SweepDefinition command_line;
  command_line.scene = folder / "scene.toml";
  command_line.parameters = {{"a.x", {"1", "2"}}, {"b.y", {"3"}}};
  EXPECT_EQ(combinations(command_line), (Runs{{0, 0}, {1, 0}}));
  EXPECT_EQ(default_output(command_line), folder / "sweep_a.x+b.y");
}

// Each mistake in a sweep file of several keys is an input error at its line.
TEST(SweepDefinition, SeveralKeysErrorsNameTheFileAndLine) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_definition";
  fs::create_directories(folder);
  const fs::path file = folder / "bad.toml";
  const std::string header =
      "format = \"lituya-sweep\"\nversion = 1\nscene = \"scene.toml\"\n";  // lines 1-3
  auto message = [&](const std::string& body) {
    std::ofstream(file) << header << body;
    return input_error_message([&] { read_sweep_file(file); });
  };
  const std::string two =
      "[[parameter]]\nkey = \"a.x\"\nvalues = [1, 2]\n"      // lines 5-7
      "[[parameter]]\nkey = \"b.y\"\nvalues = [1, 2, 3]\n";  // lines 8-10
  std::string m = message("combine = \"zip\"\n" + two);
  EXPECT_NE(m.find("bad.toml:8:"), std::string::npos) << m;
  EXPECT_NE(m.find("'b.y' has 3 values and 'a.x' has 2"), std::string::npos) << m;
  m = message("combine = \"diagonal\"\n" + two);
  EXPECT_NE(m.find("bad.toml:4:"), std::string::npos) << m;
  EXPECT_NE(m.find("combine"), std::string::npos) << m;
  m = message(
      "\n[[parameter]]\nkey = \"a.x\"\nvalues = [1]\n[[parameter]]\nkey = \"a.x\"\n"
      "values = [2]\n");
  EXPECT_NE(m.find("bad.toml:8: 'a.x' is given twice (first at line 5)"), std::string::npos) << m;
  m = message("values = [1]\n" + two);
  EXPECT_NE(m.find("bad.toml:4:"), std::string::npos) << m;
  EXPECT_NE(m.find("belongs in each [[parameter]]"), std::string::npos) << m;
  m = message("\n[[parameter]]\nkey = \"a.x\"\nvalue = [1]\n");
  EXPECT_NE(m.find("bad.toml:5:"), std::string::npos) << m;
  EXPECT_NE(m.find("'values'"), std::string::npos) << m;
  m = message("\n[[parameter]]\nkey = \"a.x\"\nvalues = [1]\nunit = \"deg\"\n");
  EXPECT_NE(m.find("bad.toml:8: unknown key 'unit'"), std::string::npos) << m;
  std::string big;
  for (const char* key : {"a.x", "b.y", "c.z", "d.w"})
    big += "[[parameter]]\nkey = \"" + std::string(key) +
           "\"\nvalues = [1, 2, 3, 4, 5, 6]\n";  // 6^4 = 1296 runs
  m = message(big);
  EXPECT_NE(m.find("6 x 6 x 6 x 6 = 1296 runs, more than 1000"), std::string::npos) << m;
}

// repeat_by: "courant" or "mesh"; anything else names the line and the choices. Left out, the
// repeats change the mesh when the sweep refines it (mesh.cell_size among its keys) and the
// Courant number otherwise.
TEST(SweepDefinition, RepeatByIsCourantOrMesh) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_definition";
  fs::create_directories(folder);
  const fs::path file = folder / "repeat_by.toml";
  const std::string header =
      "format = \"lituya-sweep\"\nversion = 1\nscene = \"scene.toml\"\n"
      "parameter = \"a.x\"\nvalues = [1]\nrepeats = 3\n";  // lines 1-6
  std::ofstream(file) << header;
  SweepDefinition d = read_sweep_file(file);
  EXPECT_FALSE(d.repeat_by.has_value());
  EXPECT_EQ(repeat_by_for(d), RepeatBy::kCourant);
  d.parameters.push_back({"mesh.cell_size", {"0.02", "0.01"}});
  EXPECT_EQ(repeat_by_for(d), RepeatBy::kMesh);
  d.repeat_by = RepeatBy::kCourant;
  EXPECT_EQ(repeat_by_for(d), RepeatBy::kCourant);
  std::ofstream(file) << header << "repeat_by = \"courant\"\n";
  EXPECT_EQ(read_sweep_file(file).repeat_by, RepeatBy::kCourant);
  std::ofstream(file) << header << "repeat_by = \"mesh\"\n";
  EXPECT_EQ(read_sweep_file(file).repeat_by, RepeatBy::kMesh);
  std::ofstream(file) << header << "repeat_by = \"seed\"\n";
  const std::string m = input_error_message([&] { read_sweep_file(file); });
  EXPECT_NE(m.find("repeat_by.toml:7:"), std::string::npos) << m;
  EXPECT_NE(m.find("mesh"), std::string::npos) << m;
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
  progress.end_run("friction_angle=10", "run 1/4 friction_angle=10: ok", 60.0, true);
  progress.start_run("friction_angle=14");
  // One run of 60 s done, three to go, this one just started: about 3 minutes.
  EXPECT_NE(progress.line().find("1/4 runs  friction_angle=14"), std::string::npos);
  EXPECT_NE(progress.line().find("eta 3m00s"), std::string::npos) << progress.line();
  EXPECT_NE(out.str().find("run 1/4 friction_angle=10: ok\n"), std::string::npos);

  // Runs side by side: the line names each, and the estimate shares the rest among the jobs.
  SweepProgress side_by_side(nullptr, false, 5, /*jobs=*/2);
  side_by_side.start_run("a=1");
  side_by_side.start_run("a=2");
  EXPECT_NE(side_by_side.line().find("0/5 runs  a=1 | a=2  elapsed"), std::string::npos)
      << side_by_side.line();
  side_by_side.end_run("a=1", "run 1/5 a=1: ok", 60.0, true);
  side_by_side.start_run("a=3");
  // Four runs of about 60 s to go on two jobs, two of them just started: about 2 minutes.
  EXPECT_NE(side_by_side.line().find("1/5 runs  a=2 | a=3"), std::string::npos)
      << side_by_side.line();
  EXPECT_NE(side_by_side.line().find("eta 2m00s"), std::string::npos) << side_by_side.line();

  EXPECT_EQ(run_folder_name(3, 5, "18"), "run_03_18");
  EXPECT_EQ(run_folder_name(7, 120, "a/b c"), "run_007_a_b_c");
}

}  // namespace
