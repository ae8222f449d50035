#include "lituya/sweep/report.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lituya/common/input_error.hpp"
#include "lituya/common/json_file.hpp"
#include "lituya/post/plot.hpp"

namespace {

using namespace lituya::sweep;
namespace fs = std::filesystem;
using lituya::Json;

// A folder of its own per test and process (ctest may run the tests side by side).
fs::path test_folder(const std::string& name) {
  const fs::path folder =
      fs::temp_directory_path() / ("lituya_report_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

// A sweep.json as `lituya sweep` writes it (sweep.cpp, write_summary), with only the fields the
// report reads besides the format: a cell-size sweep with two repeats per size.
struct SweptRun {
  double cell_size;
  double courant;
  std::vector<std::pair<std::string, Json>> measures;
  std::string status = "ok";
};

fs::path write_sweep(const fs::path& folder, const std::vector<SweptRun>& runs,
                     const std::vector<std::string>& measures,
                     const std::vector<std::string>& keys = {"mesh.cell_size",
                                                             "stage.release.courant"}) {
  fs::create_directories(folder);
  Json list = Json::array();
  int number = 0;
  for (const SweptRun& r : runs) {
    Json values = {{keys[0], r.cell_size}, {keys[1], r.courant}};
    Json m = Json::object();
    for (const auto& [name, value] : r.measures) m[name] = value;
    ++number;
    list.push_back({{"number", number},
                    {"folder", "run_" + std::to_string(number)},
                    {"values", values},
                    {"status", r.status},
                    {"kept", false},
                    {"wall_time", 1.0},
                    {"measures", m},
                    {"message", r.status == "ok" ? "" : "it failed"}});
  }
  lituya::write_json_file(folder / "sweep.json", {{"format", "lituya-sweep-summary"},
                                                  {"version", 1},
                                                  {"parameters", keys},
                                                  {"measures", measures},
                                                  {"repeat_key", keys[1]},
                                                  {"runs", list}});
  return folder;
}

// f(h) = 1 + 2 h^2 with repeats that scatter by +-1e-6 around it: the means lie on the power
// law, so an estimate from any three of its sizes has order 2 and limit 1.
double exact(double h) {
  return 1.0 + 2.0 * h * h;
}

std::vector<SweptRun> repeated(const std::vector<double>& sizes, const std::string& measure,
                               double offset_at_finest = 0) {
  std::vector<SweptRun> runs;
  for (double h : sizes) {
    const double off = h == sizes.back() ? offset_at_finest : 0.0;
    runs.push_back({h, 0.5, {{measure, exact(h) + off + 1e-6}}});
    runs.push_back({h, 0.4999, {{measure, exact(h) + off - 1e-6}}});
  }
  return runs;
}

// What the sweep wrote comes back: the keys' values as text in their shortest exact form, the
// repeat key, the labels, and a measure the run did not give (null) as NaN.
TEST(SweepReport, ReadsTheSummaryASweepWrote) {
  const fs::path folder = test_folder("read");
  write_sweep(folder,
              {{0.015, 0.5, {{"gauge_first_crest:X1", 0.04692}, {"front_travel_final", nullptr}}},
               {0.01, 0.4999, {{"gauge_first_crest:X1", 0.05092}}, "error"}},
              {"gauge_first_crest:X1", "front_travel_final"});
  const SweepResult r = read_sweep_summary(folder);
  ASSERT_EQ(r.runs.size(), 2u);
  EXPECT_EQ(r.labels, (std::vector<std::string>{"cell_size", "courant"}));
  EXPECT_EQ(r.repeat_parameter, 1);
  EXPECT_EQ(r.runs[0].values, (std::vector<std::string>{"0.015", "0.5"}));
  EXPECT_EQ(r.runs[1].values, (std::vector<std::string>{"0.01", "0.4999"}));
  EXPECT_DOUBLE_EQ(r.runs[0].measures[0], 0.04692);
  EXPECT_TRUE(std::isnan(r.runs[0].measures[1]));
  EXPECT_TRUE(std::isnan(r.runs[1].measures[1]));  // the measure is missing from the run
  EXPECT_EQ(r.runs[1].status, RunStatus::kError);
  EXPECT_EQ(r.runs[1].message, "it failed");
  fs::remove_all(folder);
}

// Sizes from two sweeps, one of them with a measure the other lacks: the runs are numbered on,
// only the common measure is kept (its values from the right column of each sweep), and the
// estimate from the three finest sizes mixes both sweeps' runs. The finest size is 3e-5 above
// the power law: with ratio 2, e21 = 1.5e-4 - 3e-5 and e32 = 6e-4 give order log2(5) for the
// three finest, while the three chosen coarser sizes give order 2 and limit 1 to rounding.
TEST(SweepReport, MergesSweepsAndEstimatesFromTheChosenSizes) {
  const fs::path folder = test_folder("merge");
  const std::string m = "gauge_first_crest:X1";
  write_sweep(folder / "coarse", repeated({0.04, 0.02, 0.01}, m), {m});
  std::vector<SweptRun> fine = repeated({0.005}, m, 3e-5);
  for (SweptRun& r : fine) r.measures.insert(r.measures.begin(), {"speed_solid_max", 7.0});
  write_sweep(folder / "fine", fine, {"speed_solid_max", m});

  const MergedSweep merged = merge_sweeps({folder / "coarse", folder / "fine"});
  EXPECT_EQ(merged.result.measures, (std::vector<std::string>{m}));
  ASSERT_EQ(merged.result.runs.size(), 8u);
  EXPECT_EQ(merged.result.runs[6].number, 7);
  EXPECT_NEAR(merged.result.runs[6].measures[0], exact(0.005) + 3e-5 + 1e-6, 1e-15);
  ASSERT_EQ(merged.sources.size(), 2u);
  EXPECT_EQ(merged.sources[1].first, 7);
  EXPECT_EQ(merged.sources[1].last, 8);

  std::vector<MeshConvergenceRow> finest, chosen;
  const std::string text = format_report(merged, {}, &finest);
  ASSERT_EQ(finest.size(), 1u);
  EXPECT_DOUBLE_EQ(finest[0].estimate.cell_size[0], 0.005);
  EXPECT_EQ(finest[0].runs, (std::array<int, 3>{7, 5, 3}));
  EXPECT_EQ(finest[0].spread[0].count, 2);
  EXPECT_NEAR(finest[0].estimate.order, std::log2(5.0), 1e-6);
  EXPECT_NE(text.find("runs 7-8: "), std::string::npos);
  EXPECT_NE(text.find("three finest"), std::string::npos);

  const std::string chosen_text = format_report(merged, {0.02, 0.01, 0.04}, &chosen);
  ASSERT_EQ(chosen.size(), 1u);
  EXPECT_DOUBLE_EQ(chosen[0].estimate.cell_size[0], 0.01);
  EXPECT_DOUBLE_EQ(chosen[0].estimate.cell_size[2], 0.04);
  EXPECT_NEAR(chosen[0].estimate.order, 2.0, 1e-6);
  EXPECT_NEAR(chosen[0].estimate.extrapolated, 1.0, 1e-9);
  EXPECT_NE(chosen_text.find("the three chosen"), std::string::npos);
  fs::remove_all(folder);
}

// The report's folder: the merged runs in sweep.csv's columns, the means per size with the
// extrapolation at h = 0 (order 2, limit 1, from the power law of `repeated`), one plot a
// measure when gnuplot is there, and no second write into it without `overwrite`.
TEST(SweepReport, WritesTheMergedTablesAndTheConvergencePlots) {
  const fs::path folder = test_folder("write");
  const std::string m = "gauge_first_crest:X1";
  write_sweep(folder / "coarse", repeated({0.04, 0.02}, m), {m});
  write_sweep(folder / "fine", repeated({0.01}, m), {m});
  const MergedSweep merged = merge_sweeps({folder / "coarse", folder / "fine"});
  std::vector<MeshConvergenceRow> rows;
  format_report(merged, {}, &rows);
  const ReportFiles files = write_report(folder / "report", merged, rows, false);

  std::ifstream runs(files.runs);
  std::string header, line;
  std::getline(runs, header);
  EXPECT_EQ(header,
            "run,mesh.cell_size,stage.release.courant," + m + ",wall_time_s,status,message");
  int rows_read = 0;
  while (std::getline(runs, line)) ++rows_read;
  EXPECT_EQ(rows_read, 6);
  EXPECT_FALSE(files.repeats.empty());
  ASSERT_FALSE(files.convergence.empty());

  // cell_size_m, the mean, the extrapolation: first the row at h = 0, then the sizes.
  std::ifstream means(files.means);
  std::getline(means, header);
  EXPECT_EQ(header, "cell_size_m," + m + ",extrapolated:" + m);
  std::getline(means, line);
  EXPECT_EQ(line.substr(0, 3), "0,,");
  EXPECT_NEAR(std::stod(line.substr(3)), 1.0, 1e-9);
  std::getline(means, line);
  EXPECT_EQ(line.substr(0, 5), "0.01,");
  EXPECT_NEAR(std::stod(line.substr(5)), exact(0.01), 1e-12);  // the two repeats' mean
  EXPECT_EQ(files.plots.size(), lituya::post::gnuplot_available() ? 1u : 0u);
  if (!files.plots.empty()) {
    EXPECT_EQ(files.plots[0].filename(), "convergence_gauge_first_crest_X1.png");
  }

  EXPECT_THROW(write_report(folder / "report", merged, rows, false), lituya::InputError);
  EXPECT_NO_THROW(write_report(folder / "report", merged, rows, true));
  fs::remove_all(folder);
}

// A folder without sweep.json, sweeps of different keys, and sizes no run has: each an
// InputError that says what is wrong and names the file or folder.
TEST(SweepReport, RefusesWhatItCannotReport) {
  const fs::path folder = test_folder("refuse");
  const std::string m = "gauge_first_crest:X1";
  fs::create_directories(folder / "empty");
  try {
    read_sweep_summary(folder / "empty");
    FAIL() << "a folder without sweep.json was read";
  } catch (const lituya::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a sweep folder"), std::string::npos) << e.what();
    EXPECT_EQ(e.file(), (folder / "empty").string());
  }
  write_sweep(folder / "a", repeated({0.02, 0.01}, m), {m});
  write_sweep(folder / "b", repeated({0.005}, m), {m},
              {"mesh.cell_size", "material.sand.friction_angle"});
  try {
    merge_sweeps({folder / "a", folder / "b"});
    FAIL() << "sweeps of different keys were merged";
  } catch (const lituya::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("differ"), std::string::npos) << e.what();
    EXPECT_EQ(e.file(), (folder / "b" / "sweep.json").string());
  }
  write_sweep(folder / "c", repeated({0.005}, m), {m});
  const MergedSweep merged = merge_sweeps({folder / "a", folder / "c"});
  try {
    format_report(merged, {0.005, 0.01, 0.03}, nullptr);
    FAIL() << "an estimate was asked for a size no run has";
  } catch (const lituya::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("0.03"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0.02, 0.01, 0.005"), std::string::npos) << e.what();
  }
  fs::remove_all(folder);
}

}  // namespace
