// Probes and stage histories (probe_recorder.hpp) on scenes built in code: a pressure probe in
// still water reads the hydrostatic pressure, a velocity probe on a free-falling block reads
// g t, the history's kinetic energy is the simulation's, and a run resumed from a stage time
// keeps the rows up to it and no others.
#include "lituya/solver/probe_recorder.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <fstream>
#include <map>

#include "lituya/common/csv_writer.hpp"
#include "lituya/solver/box_scene.hpp"

namespace {

using namespace lituya::solver;
namespace fs = std::filesystem;

constexpr double kGravity = 9.81;

class ScratchFolder {
 public:
  ScratchFolder()
      : path_(fs::temp_directory_path() /
              ("lituya_probe_test_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchFolder() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// A table as column name -> values per row (text).
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  const std::string& text(std::size_t row, const std::string& column) const {
    const auto at = std::find(header.begin(), header.end(), column);
    EXPECT_NE(at, header.end()) << column;
    return rows.at(row).at(static_cast<std::size_t>(at - header.begin()));
  }
  double number(std::size_t row, const std::string& column) const {
    return std::stod(text(row, column));
  }
};

Table read_table(const fs::path& file) {
  Table t;
  std::ifstream in(file);
  EXPECT_TRUE(in) << file;
  std::string line;
  std::getline(in, line);
  t.header = lituya::csv_split(line);
  while (std::getline(in, line)) t.rows.push_back(lituya::csv_split(line));
  return t;
}

Material sand() {
  Material m;
  m.name = "sand";
  m.model = MaterialModel::kLinearElastic;
  m.solid_density = 2650.0;
  m.porosity = 0.4;
  m.youngs_modulus = 1.0e7;
  m.poisson_ratio = 0.3;
  m.grain_diameter = 0.002;
  return m;
}

Stage dynamic_stage(const std::string& name, double duration, double output_interval,
                    std::vector<std::string> boundaries) {
  Stage s;
  s.name = name;
  s.type = StageType::kDynamic;
  s.duration = duration;
  s.output_interval = output_interval;
  s.boundaries = std::move(boundaries);
  return s;
}

Probe probe_at(const std::string& name, std::vector<double> position, double interval = 0) {
  Probe p;
  p.name = name;
  p.position = std::move(position);
  p.interval = interval;
  return p;
}

// Runs `stage` with the recorder hooked in as solve.cpp hooks it.
template <int dim>
StageReport run_recorded(Simulation<dim>& sim, ProbeRecorder<dim>& recorder, const Stage& stage,
                         double run_start = 0) {
  recorder.begin_stage(stage, run_start, std::nullopt);
  StageReport report = sim.run_stage(
      stage, [&](const Stage&, double t, int) { recorder.at_output(sim, t); },
      [&](const Stage&, const StageProgress& at) { recorder.after_step(sim, at.time); });
  recorder.write();
  return report;
}

// A 2D tank 1 m wide with still water, roller walls and bottom; no soil.
BoxScene<2> tank(double depth) {
  return still_water_tank(depth);
}

// Reference: p = rho_w g (H - y) at probes 0.05 to 0.15 m deep, inside cells and on a node.
// Tolerance: 0.5 % of rho_w g H at every sample of the 0.3 s run (measured: below 0.01 %;
// the pressure projection keeps a linear pressure field exactly, so the nodal average of the
// points' pressures is linear too; with liquid_pressure = "nodal_fit" the probes read the
// nodes' fitted pressures, exact for a linear field). Reading the pressure one cell (0.05 m)
// off would be 25 %.
void expect_probes_read_hydrostatic_pressure(LiquidPressure mode) {
  const double depth = 0.2;
  BoxScene<2> scene = tank(depth);
  scene.solver.liquid_pressure = mode;
  Simulation<2> sim = make_box_simulation<2>(scene);
  ScratchFolder folder;
  const std::vector<Probe> probes = {
      probe_at("mid", {0.5, 0.1}, 0.01), probe_at("shallow", {0.37, 0.15}, 0.01),
      probe_at("deep", {0.63, 0.05}, 0.01), probe_at("node", {0.25, 0.1}, 0.01)};
  ProbeRecorder<2> recorder(sim, probes, folder.path());
  run_recorded(sim, recorder, dynamic_stage("still", 0.3, 0.1, {"x-", "x+", "y-"}));
  const double scale = 1000.0 * kGravity * depth;
  for (const Probe& p : probes) {
    const Table t = read_table(folder.path() / "probes" / (p.name + ".csv"));
    // Every 0.01 s and the outputs (which fall on the same times): 31 rows from t = 0.
    EXPECT_EQ(t.rows.size(), 31u) << p.name;
    const double exact = 1000.0 * kGravity * (depth - p.position[1]);
    double worst = 0;
    for (std::size_t r = 0; r < t.rows.size(); ++r)
      worst = std::max(worst, std::abs(t.number(r, "pore_pressure") - exact));
    EXPECT_LT(worst / scale, 0.005) << p.name << ": worst error " << worst << " Pa of " << exact;
    std::cout << "probe " << p.name << ": hydrostatic " << exact << " Pa, worst error "
              << worst / scale * 100 << " % of rho g H\n";
    // Free water: porosity 1, and no soil, so no effective stress or soil velocity.
    EXPECT_EQ(t.number(t.rows.size() - 1, "porosity"), 1.0);
    EXPECT_EQ(t.text(t.rows.size() - 1, "effective_stress_xx"), "");
    EXPECT_EQ(t.text(t.rows.size() - 1, "velocity_y"), "");
  }
}

TEST(Probe, StillWaterReadsTheHydrostaticPressure) {
  expect_probes_read_hydrostatic_pressure(LiquidPressure::kPoints);
}

TEST(Probe, StillWaterReadsTheHydrostaticPressureWithTheNodalFit) {
  expect_probes_read_hydrostatic_pressure(LiquidPressure::kNodalFit);
}

TEST(Probe, FreeFallingBlockReadsGTimesTime) {
  // No boundaries: every point falls with v = -g t exactly (the nodal velocities are exact in
  // free fall), so the probe must read it to rounding: tolerance 1e-9 g t. A probe riding on a
  // point reads the same, and its position is the point's.
  BoxScene<2> s;
  s.domain_size = {1.0, 1.0};
  s.cells = {10, 10};
  s.block_min = {0.3, 0.5};
  s.block_max = {0.7, 0.9};
  s.material = sand();
  s.gravity = {0.0, -kGravity};
  Simulation<2> sim = make_box_simulation<2>(s);
  ScratchFolder folder;
  Probe on_point;
  on_point.name = "point";
  on_point.follows = Probe::Follows::kSolidPoint;
  on_point.point_id = 7;
  on_point.interval = 0.005;
  // The probe sits in the block at the start and 0.5 g t^2 = 0.05 m lower at the end: in it
  // all the time.
  const std::vector<Probe> probes = {probe_at("fixed", {0.51, 0.72}, 0.005), on_point};
  ProbeRecorder<2> recorder(sim, probes, folder.path());
  run_recorded(sim, recorder, dynamic_stage("fall", 0.1, 0.05, {}));
  for (const Probe& p : probes) {
    const Table t = read_table(folder.path() / "probes" / (p.name + ".csv"));
    ASSERT_EQ(t.rows.size(), 21u) << p.name;  // every 0.005 s from 0 to 0.1 s
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      // The first step on or after each multiple of the interval (steps are ~0.4 ms).
      const double time = t.number(r, "time");
      EXPECT_GE(time, 0.005 * static_cast<double>(r) - 1e-12);
      EXPECT_LT(time, 0.005 * static_cast<double>(r) + 0.001);
      EXPECT_NEAR(t.number(r, "velocity_y"), -kGravity * time, 1e-9 * kGravity * time + 1e-15)
          << p.name << " at " << time;
      EXPECT_NEAR(t.number(r, "velocity_x"), 0.0, 1e-12);
    }
  }
  const Table point = read_table(folder.path() / "probes" / "point.csv");
  std::size_t p = 0;
  while (sim.points().id[p] != 7) ++p;
  EXPECT_EQ(point.number(point.rows.size() - 1, "y"), sim.points().position[p](1));
  EXPECT_NEAR(point.number(point.rows.size() - 1, "porosity"), 0.4, 1e-12);
}

TEST(Probe, FreeFallingBlockReadsGTimesTimeIn3D) {
  // As in 2D, on tetrahedra: the velocity to 1e-9 g t, and the six stress components of a
  // stress-free block (zero to 1e-9 of rho g times the block's height).
  BoxScene<3> s;
  s.domain_size = {1.0, 1.0, 1.0};
  s.cells = {5, 5, 5};
  s.block_min = {0.2, 0.4, 0.2};
  s.block_max = {0.8, 1.0, 0.8};
  s.material = sand();
  s.gravity = {0.0, -kGravity, 0.0};
  Simulation<3> sim = make_box_simulation<3>(s);
  ScratchFolder folder;
  std::vector<Probe> probes = {probe_at("centre", {0.51, 0.71, 0.49}, 0.01)};
  probes[0].fields = {"effective_stress", "velocity", "porosity"};  // a dry scene's default
  ProbeRecorder<3> recorder(sim, probes, folder.path());
  run_recorded(sim, recorder, dynamic_stage("fall", 0.05, 0.05, {}));
  const Table t = read_table(folder.path() / "probes" / "centre.csv");
  ASSERT_EQ(t.header.size(), 3u + 3u + 6u + 3u + 1u);
  ASSERT_EQ(t.rows.size(), 6u);
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const double time = t.number(r, "time");
    EXPECT_NEAR(t.number(r, "velocity_y"), -kGravity * time, 1e-9 * kGravity * time + 1e-15);
    EXPECT_NEAR(t.number(r, "velocity_z"), 0.0, 1e-12);
    for (const char* c : {"xx", "yy", "zz", "xy", "yz", "xz"})
      EXPECT_NEAR(t.number(r, std::string("effective_stress_") + c), 0.0, 1e-9 * 1590.0 * 9.81)
          << c;
  }
}

TEST(History, KineticEnergyIsTheSimulations) {
  // A block of saturated soil falling into a tank: both phases move. The history's total is
  // kinetic_energy() itself, and its two phases add up to it (tolerance 1e-12 relative: they are
  // summed in another order). Rows: at most kHistoryRowsPerStage plus one per output.
  BoxScene<2> s = tank(0.2);
  s.block_min = {0.3, 0.3};
  s.block_max = {0.6, 0.5};
  s.water_max = {1.0, 0.5};
  s.water_min = {0.0, 0.0};
  Simulation<2> sim = make_box_simulation<2>(s);
  ScratchFolder folder;
  ProbeRecorder<2> recorder(sim, {}, folder.path());
  const Stage stage = dynamic_stage("splash", 0.05, 0.01, {"x-", "x+", "y-"});
  const StageReport report = run_recorded(sim, recorder, stage);
  const Table t = read_table(folder.path() / "splash_history.csv");
  ASSERT_FALSE(t.rows.empty());
  EXPECT_LE(t.rows.size(), static_cast<std::size_t>(ProbeRecorder<2>::kHistoryRowsPerStage + 6));
  // Fewer steps than kHistoryRowsPerStage: one row per step.
  ASSERT_LT(report.steps, ProbeRecorder<2>::kHistoryRowsPerStage);
  EXPECT_EQ(t.rows.size(), static_cast<std::size_t>(report.steps));
  const std::size_t last = t.rows.size() - 1;
  EXPECT_EQ(t.number(last, "stage_time"), report.simulated_time);
  EXPECT_EQ(t.number(last, "kinetic_energy"), sim.kinetic_energy());
  EXPECT_GT(t.number(last, "kinetic_energy_liquid"), 0.0);
  EXPECT_GT(t.number(last, "kinetic_energy_solid"), 0.0);
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const double total = t.number(r, "kinetic_energy");
    EXPECT_NEAR(t.number(r, "kinetic_energy_solid") + t.number(r, "kinetic_energy_liquid"), total,
                1e-12 * total);
    EXPECT_GT(t.number(r, "time_step"), 0.0);
  }
  double speed = 0;
  for (const auto& v : sim.points().velocity) speed = std::max(speed, v.norm());
  EXPECT_EQ(t.number(last, "max_speed_solid"), speed);
  EXPECT_EQ(t.number(last, "step"), static_cast<double>(sim.step_count()));
}

TEST(History, WallForcesAreTheMeansOverTheRowsIntervals) {
  // Still water 0.2 m deep in a tank 1 m wide: the floor carries rho_w g H L = 1962 N/m, each
  // wall rho_w g H^2 / 2 = 196.2 N/m (wall_loads_test.cpp has the tolerances; here 0.5 % and
  // 2 %). Each row holds the mean since the row before: the row takes the simulation's sums,
  // which are empty after the stage's last row. Rollers carry no effective-normal column (that
  // is for contact walls).
  Simulation<2> sim = make_box_simulation<2>(tank(0.2));
  ScratchFolder folder;
  ProbeRecorder<2> recorder(sim, {}, folder.path());
  run_recorded(sim, recorder, dynamic_stage("still", 0.1, 0.05, {"x-", "x+", "y-"}));
  const Table t = read_table(folder.path() / "still_history.csv");
  ASSERT_FALSE(t.rows.empty());
  for (const char* column : {"wall_x-_force_x", "wall_x-_force_y", "wall_x-_normal",
                             "wall_x-_tangential", "wall_x+_normal", "wall_y-_normal"})
    EXPECT_NE(std::find(t.header.begin(), t.header.end(), column), t.header.end()) << column;
  EXPECT_EQ(std::find(t.header.begin(), t.header.end(), "wall_y-_effective_normal"),
            t.header.end());
  double impulse = 0, previous = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const double time = t.number(r, "stage_time");
    impulse += t.number(r, "wall_y-_normal") * (time - previous);
    previous = time;
  }
  const double floor = 1000.0 * kGravity * 0.2;
  EXPECT_NEAR(impulse / previous, floor, 0.005 * floor);
  EXPECT_EQ(sim.wall_impulse_time(), 0.0);
  EXPECT_EQ(sim.wall_impulses()[2].normal, 0.0);
  EXPECT_NEAR(t.number(t.rows.size() - 1, "wall_x+_normal"), 196.2, 0.02 * 196.2);
}

TEST(History, ResumedRunKeepsTheRowsUpToTheCheckpointOnly) {
  // Two stages; a restart from stage "second" at stage time 0.02 keeps all of "first", the
  // rows of "second" up to 0.02 and none after, and the run then continues them: the tables
  // equal those of a run never interrupted, row for row.
  BoxScene<2> s;
  s.domain_size = {1.0, 1.0};
  s.cells = {10, 10};
  s.block_min = {0.3, 0.5};
  s.block_max = {0.7, 0.9};
  s.material = sand();
  s.gravity = {0.0, -kGravity};
  const std::vector<Stage> stages = {dynamic_stage("first", 0.03, 0.01, {}),
                                     dynamic_stage("second", 0.04, 0.01, {})};
  const std::vector<Probe> probes = {probe_at("p", {0.51, 0.72}, 0.002)};
  ScratchFolder folder;
  Simulation<2> sim = make_box_simulation<2>(s);
  ProbeRecorder<2> recorder(sim, probes, folder.path());
  const StageReport first = run_recorded(sim, recorder, stages[0]);
  run_recorded(sim, recorder, stages[1], run_time_at_stage_start({first}));
  const Table probe_before = read_table(folder.path() / "probes" / "p.csv");
  const Table history_before = read_table(folder.path() / "second_history.csv");

  ProbeRecorder<2> resumed(sim, probes, folder.path());
  resumed.restart(stages, 1, 0.02);
  resumed.begin_stage(stages[1], run_time_at_stage_start({first}), 0.02);
  resumed.write();
  const Table probe_after = read_table(folder.path() / "probes" / "p.csv");
  const Table history_after = read_table(folder.path() / "second_history.csv");
  std::size_t expected = 0;
  for (std::size_t r = 0; r < probe_before.rows.size(); ++r)
    if (probe_before.rows[r][1] == "first" || probe_before.number(r, "stage_time") <= 0.02)
      ++expected;
  EXPECT_EQ(probe_after.rows.size(), expected);
  EXPECT_EQ(probe_after.rows.size(), 16u + 11u);  // 0..0.03 by 0.002, then 0..0.02
  for (std::size_t r = 0; r < probe_after.rows.size(); ++r)
    EXPECT_EQ(probe_after.rows[r], probe_before.rows[r]);
  ASSERT_FALSE(history_after.rows.empty());
  EXPECT_LT(history_after.rows.size(), history_before.rows.size());
  EXPECT_LE(history_after.number(history_after.rows.size() - 1, "stage_time"), 0.02);
  for (std::size_t r = 0; r < history_after.rows.size(); ++r)
    EXPECT_EQ(history_after.rows[r], history_before.rows[r]);
  // A restart at the start of "second" (an end-of-stage checkpoint) drops its history file.
  ProbeRecorder<2> at_stage_start(sim, probes, folder.path());
  at_stage_start.restart(stages, 1, std::nullopt);
  at_stage_start.write();
  EXPECT_FALSE(fs::exists(folder.path() / "second_history.csv"));
  EXPECT_EQ(read_table(folder.path() / "probes" / "p.csv").rows.size(), 16u);
}

}  // namespace
