#include "lituya/sweep/sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "lituya/common/error_message.hpp"
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

// A sweep of the cell size writes the convergence table (convergence.hpp) from the runs'
// measures: the three finest of four sizes, fine first, the same numbers as sweep.csv.
TEST(Sweep, CellSizeSweepWritesTheMeshConvergenceTable) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_convergence";
  fs::remove_all(folder);
  SweepDefinition d;
  d.scene = kScene;
  d.parameters = {{"mesh.cell_size", {"0.025", "0.0125", "0.03", "0.02"}}};
  d.measures = {"front_travel_final"};
  d.output = folder;
  std::ostringstream report;
  SweepOptions options;
  options.report = &report;
  const SweepResult result = run_sweep(d, options);
  ASSERT_TRUE(result.all_ok());
  ASSERT_EQ(result.convergence, folder / "convergence.csv");
  const std::vector<std::vector<std::string>> rows = read_rows(result.convergence);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1][1], "front_travel_final");
  EXPECT_EQ(rows[1][2], "2 4 1");  // 0.0125, 0.02, 0.025
  EXPECT_DOUBLE_EQ(std::stod(rows[1][3]), 0.0125);
  EXPECT_DOUBLE_EQ(std::stod(rows[1][5]), 0.025);
  EXPECT_DOUBLE_EQ(std::stod(rows[1][6]), result.runs[1].measures[0]);
  EXPECT_DOUBLE_EQ(std::stod(rows[1][8]), result.runs[0].measures[0]);
  EXPECT_NE(report.str().find("mesh convergence"), std::string::npos) << report.str();
  nlohmann::json summary;
  std::ifstream(folder / "sweep.json") >> summary;
  EXPECT_EQ(summary["mesh_convergence"].size(), 1u);
}

// A dry granular column collapse (about 1 s a run) swept over its friction angle: a lower
// angle runs out further. 95 degrees is not a valid angle: that run fails, the others go on.
TEST(Sweep, FrictionAngleOfAColumnCollapse) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_e2e";
  fs::remove_all(folder);
  SweepDefinition d;
  d.scene = kScene;
  d.parameters = {{"material.sand.friction_angle", {"15", "95", "40"}}};
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

std::string file_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A grid of two keys of the column collapse (2 x 2 runs, about 1 s each).
SweepDefinition grid_sweep(const fs::path& folder) {
  SweepDefinition d;
  d.scene = kScene;
  d.parameters = {{"material.sand.friction_angle", {"20", "40"}},
                  {"boundary.bed.friction", {"0.3", "0.6"}}};
  d.measures = {"front_travel_final", "front_travel_max"};
  d.output = folder;
  return d;
}

// Runs side by side (each in a process of its own, one thread each) give what the same runs
// give one after another: the same measures to the last bit, and the same post tables (which
// hold every digit of the measured front) and point files, byte for byte.
TEST(Sweep, JobsGiveTheSameResultsAsRunsOneAfterAnother) {
  const fs::path serial_folder = fs::temp_directory_path() / "lituya_sweep_serial";
  const fs::path jobs_folder = fs::temp_directory_path() / "lituya_sweep_jobs";
  fs::remove_all(serial_folder);
  fs::remove_all(jobs_folder);
  SweepOptions options;
  const SweepResult serial = run_sweep(grid_sweep(serial_folder), options);
  std::ostringstream progress;
  options.jobs = 2;
  options.progress = &progress;
  const SweepResult jobs = run_sweep(grid_sweep(jobs_folder), options);

  ASSERT_EQ(serial.runs.size(), 4u);
  ASSERT_EQ(jobs.runs.size(), 4u);
  EXPECT_TRUE(serial.all_ok());
  EXPECT_TRUE(jobs.all_ok()) << progress.str();
  // The grid: the first key varies slowest; the folders name both values.
  EXPECT_EQ(jobs.runs[1].values, (std::vector<std::string>{"20", "0.6"}));
  EXPECT_EQ(jobs.runs[2].folder.filename(), "run_03_40_0.3");
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(jobs.runs[i].values, serial.runs[i].values);
    for (size_t m = 0; m < 2; ++m) {
      EXPECT_TRUE(std::isfinite(jobs.runs[i].measures[m]));
      EXPECT_EQ(jobs.runs[i].measures[m], serial.runs[i].measures[m]) << "run " << i + 1;
    }
    const fs::path name = serial.runs[i].folder.filename();
    for (const char* table : {"runout.csv", "profiles.csv", "wall_height.csv"}) {
      const std::string a = file_text(serial_folder / name / "case" / "post" / table);
      EXPECT_FALSE(a.empty());
      EXPECT_EQ(a, file_text(jobs_folder / name / "case" / "post" / table)) << name << table;
    }
    // Every point file of the solve, too.
    int vtu_files = 0;
    for (const auto& entry : fs::directory_iterator(serial_folder / name / "case" / "output"))
      if (entry.path().extension() == ".vtu") {
        ++vtu_files;
        EXPECT_EQ(file_text(entry.path()),
                  file_text(jobs_folder / name / "case" / "output" / entry.path().filename()))
            << entry.path();
      }
    EXPECT_GT(vtu_files, 5) << name;
  }
  // Both keys change what the gravity stage reads: there is nothing to reuse.
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(jobs.runs[i].reused_from, 0) << "run " << i + 1;
  // A lower friction angle runs out further, whatever the bed friction.
  EXPECT_GT(serial.runs[0].measures[0], serial.runs[2].measures[0]);
  EXPECT_GT(serial.runs[1].measures[0], serial.runs[3].measures[0]);
  // sweep.csv is the same but for the wall times.
  const auto serial_rows = read_rows(serial_folder / "sweep.csv");
  const auto jobs_rows = read_rows(jobs_folder / "sweep.csv");
  ASSERT_EQ(jobs_rows.size(), 5u);
  EXPECT_EQ(jobs_rows[0],
            (std::vector<std::string>{"run", "material.sand.friction_angle",
                                      "boundary.bed.friction", "front_travel_final",
                                      "front_travel_max", "wall_time_s", "status", "message"}));
  for (size_t r = 1; r < 5; ++r)
    for (size_t c : {0, 1, 2, 3, 4, 6}) EXPECT_EQ(jobs_rows[r][c], serial_rows[r][c]);
  // sweep.json holds the measures exactly, and the values as numbers.
  std::ifstream json_file(jobs_folder / "sweep.json");
  const nlohmann::json json = nlohmann::json::parse(json_file);
  EXPECT_EQ(json["combine"], "grid");
  EXPECT_EQ(json["runs"][3]["values"]["boundary.bed.friction"].get<double>(), 0.6);
  EXPECT_EQ(json["runs"][3]["measures"]["front_travel_final"].get<double>(),
            serial.runs[3].measures[0]);
  EXPECT_NE(progress.str().find(" | "), std::string::npos) << progress.str();
}

// A sweep that was stopped is continued with `resume`: the runs that finished are kept, not run
// again (the progress says so), and the others are run. A run whose case files changed since
// its solve (the hash in its summary.toml no longer matches) is run again too.
TEST(Sweep, ResumeKeepsTheRunsThatFinished) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_resume";
  fs::remove_all(folder);
  SweepDefinition d = grid_sweep(folder);
  d.parameters[1].values = {"0.3"};  // 2 runs
  d.parameters.push_back({"stage.release.courant", {"0.5", "0.4"}});
  SweepOptions options;
  const SweepResult first = run_sweep(d, options);
  ASSERT_EQ(first.runs.size(), 4u);
  ASSERT_TRUE(first.all_ok());
  // The Courant number of the release is the last key: each odd run's gravity stage serves
  // the run after it.
  EXPECT_EQ(first.runs[1].reused_from, 1);
  EXPECT_EQ(first.runs[2].reused_from, 0);
  EXPECT_EQ(first.runs[3].reused_from, 3);

  // Run 2 was killed during its solve; run 3's case was edited after its solve; runs 1 and 4
  // finished.
  const fs::path run2 = first.runs[1].folder, run3 = first.runs[2].folder;
  const fs::path summary2 = run2 / "case" / "output" / "summary.toml";
  std::string text = file_text(summary2);
  text.replace(text.find("completed = true"), 16, "completed = false");
  std::ofstream(summary2, std::ios::binary) << text;
  fs::remove(run2 / "run.json");
  std::ofstream(run3 / "case" / "stages.toml", std::ios::app) << "# edited\n";
  const auto kept_time =
      fs::last_write_time(first.runs[0].folder / "case" / "output" / "summary.toml");

  // Without --resume (or --force) the earlier sweep is not touched.
  const std::string refused = lituya::input_error_message([&] { run_sweep(d, options); });
  EXPECT_NE(refused.find("--resume"), std::string::npos) << refused;

  std::ostringstream progress;
  options.resume = true;
  options.progress = &progress;
  const SweepResult resumed = run_sweep(d, options);
  ASSERT_EQ(resumed.runs.size(), 4u);
  EXPECT_TRUE(resumed.all_ok()) << progress.str();
  EXPECT_TRUE(resumed.runs[0].kept);
  EXPECT_FALSE(resumed.runs[1].kept);
  EXPECT_FALSE(resumed.runs[2].kept);
  EXPECT_TRUE(resumed.runs[3].kept);
  // Run 2 runs again from the gravity stage of run 1, which was kept.
  EXPECT_EQ(resumed.runs[1].reused_from, 1);
  EXPECT_NE(progress.str().find("run 1/4 friction_angle=20 friction=0.3 courant=0.5: ok (kept"),
            std::string::npos)
      << progress.str();
  EXPECT_EQ(fs::last_write_time(first.runs[0].folder / "case" / "output" / "summary.toml"),
            kept_time);
  for (size_t i = 0; i < 4; ++i)
    for (size_t m = 0; m < 2; ++m)
      EXPECT_EQ(resumed.runs[i].measures[m], first.runs[i].measures[m]) << "run " << i + 1;
  // The kept runs keep the wall time of their solve; sweep.csv says they were kept.
  EXPECT_EQ(resumed.runs[0].wall_time, first.runs[0].wall_time);
  const auto rows = read_rows(folder / "sweep.csv");
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[1].back(), "kept: finished in an earlier run of this sweep");
  EXPECT_EQ(rows[2].back(), "");
}

// The VTU, PVD and CSV files of a run's solve (the probe tables in output/probes too), by name.
std::map<std::string, std::string> output_files(const fs::path& run_folder) {
  std::map<std::string, std::string> files;
  const fs::path output = run_folder / "case" / "output";
  for (const auto& entry : fs::recursive_directory_iterator(output))
    if (entry.path().extension() == ".vtu" || entry.path().extension() == ".pvd" ||
        entry.path().extension() == ".csv")
      files[entry.path().lexically_relative(output).generic_string()] = file_text(entry.path());
  return files;
}

// A key that only the release stage reads (its Courant number): the runs after the first take
// the gravity stage's end state from run 1's checkpoint instead of running it again, one after
// another and side by side, and give what whole runs (--no-reuse) give: the same measures to
// the last bit and the same post tables, VTU and PVD files, stage histories and probe table,
// byte for byte (those of the gravity stage and the whole-run series included). About 10 s.
TEST(Sweep, LaterStageKeyReusesTheEarlierStagesBitForBit) {
  const fs::path base = fs::temp_directory_path() / "lituya_sweep_reuse";
  fs::remove_all(base);
  // The column collapse with a probe in the column: its table spans both stages.
  fs::create_directories(base / "scene");
  fs::copy_file(kScene.parent_path() / "collapse.geo", base / "scene" / "collapse.geo");
  std::ofstream(base / "scene" / "collapse.toml", std::ios::binary)
      << file_text(kScene) << "\n[[probe]]\nname = \"column\"\nposition = [0.05, 0.02]\n";
  auto courant_sweep = [&](const std::string& name) {
    SweepDefinition d;
    d.scene = base / "scene" / "collapse.toml";
    d.parameters = {{"stage.release.courant", {"0.5", "0.3", "0.4"}}};
    d.measures = {"front_travel_final", "front_travel_max"};
    d.output = base / name;
    return d;
  };
  SweepOptions options;
  options.reuse = false;
  const SweepResult whole = run_sweep(courant_sweep("whole"), options);
  std::ostringstream progress, report;
  options.reuse = true;
  options.progress = &progress;
  options.report = &report;
  const SweepResult reused = run_sweep(courant_sweep("reused"), options);
  std::ostringstream jobs_progress;
  options.jobs = 2;
  options.progress = &jobs_progress;
  options.report = nullptr;
  const SweepResult jobs = run_sweep(courant_sweep("jobs"), options);

  for (const SweepResult* r : {&whole, &reused, &jobs}) {
    ASSERT_EQ(r->runs.size(), 3u);
    ASSERT_TRUE(r->all_ok()) << progress.str() << jobs_progress.str();
  }
  // What was reused, and that it is said.
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(whole.runs[i].reused_from, 0) << i;
  for (const SweepResult* r : {&reused, &jobs}) {
    EXPECT_EQ(r->runs[0].reused_from, 0);
    EXPECT_EQ(r->runs[1].reused_from, 1);
    EXPECT_EQ(r->runs[2].reused_from, 1);
    EXPECT_EQ(r->runs[2].reused_stages, std::vector<std::string>{"gravity"});
  }
  EXPECT_NE(progress.str().find("run 2/3 courant=0.3: ok in "), std::string::npos)
      << progress.str();
  EXPECT_NE(progress.str().find("(stages 'gravity' reused from run 1)"), std::string::npos)
      << progress.str();
  EXPECT_NE(report.str().find("2 of 3 runs started from the end of stages"), std::string::npos)
      << report.str();
  const std::string log = file_text(reused.runs[1].folder / "case" / "output" / "log.txt");
  EXPECT_NE(log.find("lituya sweep: run 2 reused stages 'gravity' from run 1"), std::string::npos)
      << log;
  EXPECT_NE(log.find("stage 'release': "), std::string::npos) << log;
  std::ifstream json_file(base / "reused" / "sweep.json");
  const nlohmann::json json = nlohmann::json::parse(json_file);
  EXPECT_EQ(json["runs"][2]["reused_from"], 1);
  EXPECT_EQ(json["runs"][0]["reused_from"], 0);

  for (const SweepResult* r : {&reused, &jobs})
    for (size_t i = 0; i < 3; ++i) {
      for (size_t m = 0; m < 2; ++m) {
        EXPECT_TRUE(std::isfinite(whole.runs[i].measures[m]));
        EXPECT_EQ(r->runs[i].measures[m], whole.runs[i].measures[m]) << "run " << i + 1;
      }
      const fs::path name = whole.runs[i].folder.filename();
      for (const char* table : {"runout.csv", "profiles.csv", "wall_height.csv"})
        EXPECT_EQ(file_text(r->folder / name / "case" / "post" / table),
                  file_text(whole.folder / name / "case" / "post" / table))
            << name << " " << table;
      const auto expected = output_files(whole.folder / name);
      const auto got = output_files(r->folder / name);
      ASSERT_EQ(got.size(), expected.size()) << name;
      EXPECT_GT(expected.size(), 10u) << name;
      for (const char* file : {"release_points_0010.vtu", "gravity_history.csv",
                               "release_history.csv", "probes/column.csv", "points.pvd"})
        EXPECT_EQ(expected.count(file), 1u) << name << " " << file;
      for (const auto& [file, bytes] : expected) {
        const auto other = got.find(file);
        ASSERT_NE(other, got.end()) << name << " " << file;
        EXPECT_TRUE(other->second == bytes) << name << " " << file << " differs";
      }
    }
  // The Courant number changes the release: the runs are not copies of each other.
  EXPECT_NE(output_files(whole.runs[0].folder).at("release_points_0010.vtu"),
            output_files(whole.runs[1].folder).at("release_points_0010.vtu"));

  // The reused run can itself go on with --from-stage: it has the gravity stage's checkpoint.
  EXPECT_TRUE(fs::exists(reused.runs[1].folder / "case" / "output" / "checkpoints" /
                         "gravity_end.checkpoint"));
}

// A misspelt key makes every copy invalid: the sweep stops before it writes anything, and the
// message names the scene and what the scene reader said.
TEST(Sweep, MisspeltKeyStopsBeforeAnyRun) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_misspelt";
  fs::remove_all(folder);
  SweepDefinition d;
  d.scene = kScene;
  d.parameters = {{"material.sand.frction_angle", {"20", "30"}}};
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
