// Checkpoints (checkpoint.hpp): a run continued from one must be bit for bit the run that was
// never interrupted, dry and with water, within a stage and across a stage boundary; and a
// checkpoint that cannot continue a run (another case, another build, a damaged or cut file)
// is refused with a message that says why.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "lituya/common/error_message.hpp"
#include "lituya/common/provenance.hpp"
#include "lituya/solver/box_scene.hpp"
#include "lituya/solver/checkpoint.hpp"

namespace {

namespace fs = std::filesystem;
using namespace lituya::solver;

// A Mohr-Coulomb column that collapses beside a water column that breaks: both phases move,
// mix at the middle (drag, pore pressure) and hit the walls, so every part of the state that
// carries from one step to the next matters. 12 x 6 cells, about 150 points per phase.
BoxScene<2> collapse_scene(bool with_water) {
  BoxScene<2> s;
  s.domain_size = {1.2, 0.6};
  s.cells = {12, 6};
  s.block_min = {0.0, 0.0};
  s.block_max = {0.4, 0.4};
  s.material.name = "sand";
  s.material.model = MaterialModel::kMohrCoulomb;
  s.material.solid_density = 2650.0;
  s.material.porosity = 0.4;
  s.material.youngs_modulus = 2.0e6;
  s.material.poisson_ratio = 0.3;
  s.material.friction_angle = 30.0;
  s.material.tensile_strength = 0.0;
  s.material.grain_diameter = 0.002;
  s.gravity = {0.0, -9.81};
  s.k0 = 0.5;
  s.solver.pressure_projection_interval = 3;  // the projection's warm start is state too
  if (with_water) {
    s.with_water = true;
    s.water = paper_water();
    s.water_min = {0.3, 0.0};
    s.water_max = {0.8, 0.3};
  }
  for (const char* side : {"x-", "x+", "y-"})
    s.boundaries.push_back({side, box_condition(BoundaryType::kRoller)});
  return s;
}

Stage collapse_stage(double duration) {
  Stage s;
  s.name = "collapse";
  s.type = StageType::kDynamic;
  s.duration = duration;
  s.courant = 0.5;
  s.output_interval = duration / 4;
  s.boundaries = {"x-", "x+", "y-"};
  return s;
}

template <int dim>
void expect_same_state(const Simulation<dim>& a, const Simulation<dim>& b) {
  EXPECT_EQ(a.step_count(), b.step_count());
  // Every array exactly (==, not a tolerance): a resumed run must be the same run.
  const MaterialPoints<dim>& p = a.points();
  const MaterialPoints<dim>& q = b.points();
  EXPECT_TRUE(p.position == q.position);
  EXPECT_TRUE(p.velocity == q.velocity);
  EXPECT_TRUE(p.mass == q.mass);
  EXPECT_TRUE(p.volume == q.volume);
  EXPECT_TRUE(p.material == q.material);
  EXPECT_TRUE(p.cell == q.cell);
  EXPECT_TRUE(p.id == q.id);
  EXPECT_TRUE(p.displacement == q.displacement);
  EXPECT_TRUE(p.stress == q.stress);
  EXPECT_TRUE(p.plastic_strain == q.plastic_strain);
  EXPECT_TRUE(a.node_velocity() == b.node_velocity());
  ASSERT_EQ(a.has_liquid(), b.has_liquid());
  if (!a.has_liquid()) return;
  const LiquidPoints<dim>& w = a.liquid();
  const LiquidPoints<dim>& v = b.liquid();
  EXPECT_TRUE(w.position == v.position);
  EXPECT_TRUE(w.velocity == v.velocity);
  EXPECT_TRUE(w.volume == v.volume);
  EXPECT_TRUE(w.cell == v.cell);
  EXPECT_TRUE(w.pressure == v.pressure);
  EXPECT_TRUE(w.viscous_stress == v.viscous_stress);
  EXPECT_TRUE(w.porosity == v.porosity);
  EXPECT_TRUE(a.node_liquid_velocity() == b.node_liquid_velocity());
}

class Checkpoint : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("lituya_checkpoint_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  static CheckpointHeader header(int stage, std::optional<StageProgress> within) {
    CheckpointHeader h;
    h.case_hash = "fnv1a64:00000000000000aa";
    h.inputs_hash = "fnv1a64:00000000000000bb";
    h.started = "2026-01-01T00:00:00Z";
    h.reason = "test";
    h.stage = stage;
    h.within_stage = within;
    return h;
  }

  // Runs the collapse for `duration`, taking a checkpoint after step `at_step`; a fresh
  // simulation reads it and runs the rest; both must end in the same state and write the
  // same outputs after the checkpoint. Output maps the points to the grid as the writer does
  // (it overwrites the nodal velocities the next step's drag reads).
  // by_time: the pressure projection at its default period in time, whose clock (the time
  // since the last projection) is state too.
  void resume_within_stage(bool with_water, bool by_time = false) {
    const fs::path file = folder_ / "latest.checkpoint";
    const Stage stage = collapse_stage(0.04);
    BoxScene<2> scene = collapse_scene(with_water);
    if (by_time) scene.solver.pressure_projection_interval.reset();
    Simulation<2> whole = make_box_simulation<2>(scene);
    std::vector<std::pair<double, int>> outputs_whole, outputs_resumed;
    bool taken = false;
    whole.run_stage(
        stage,
        [&](const Stage&, double t, int index) {
          whole.map_to_grid();
          if (taken) outputs_whole.emplace_back(t, index);
        },
        [&](const Stage&, const StageProgress& at) {
          if (at.steps == 25) {
            write_checkpoint(file, whole, header(0, at), RunRecord{});
            taken = true;
          }
        });
    ASSERT_TRUE(taken) << "the stage ended before step 25";
    ASSERT_GT(whole.step_count(), 40) << "too few steps after the checkpoint to compare";

    Simulation<2> resumed = make_box_simulation<2>(scene);
    const CheckpointHeader h = read_checkpoint_header(file);
    ASSERT_TRUE(h.within_stage);
    EXPECT_EQ(h.step_count, 25);
    read_checkpoint(file, resumed);
    resumed.run_stage(
        stage,
        [&](const Stage&, double t, int index) {
          resumed.map_to_grid();
          outputs_resumed.emplace_back(t, index);
        },
        {}, &*h.within_stage);
    expect_same_state(whole, resumed);
    EXPECT_EQ(outputs_whole, outputs_resumed);
    EXPECT_FALSE(outputs_resumed.empty());
  }

  fs::path folder_;
};

TEST_F(Checkpoint, DryRunResumedWithinAStageIsBitForBitTheSame) {
  resume_within_stage(false);
}

TEST_F(Checkpoint, RunWithWaterResumedWithinAStageIsBitForBitTheSame) {
  resume_within_stage(true);
}

TEST_F(Checkpoint, RunWithWaterProjectedByTimeResumedWithinAStageIsBitForBitTheSame) {
  resume_within_stage(true, true);
}

TEST_F(Checkpoint, ThreeDimensionalRunResumedWithinAStageIsBitForBitTheSame) {
  // A sand cube collapsing in a box of 4 x 4 x 3 cells (tetrahedra).
  BoxScene<3> scene;
  scene.domain_size = {0.8, 0.8, 0.6};
  scene.cells = {4, 4, 3};
  scene.block_max = {0.4, 0.4, 0.4};
  scene.material = collapse_scene(false).material;
  scene.gravity = {0.0, -9.81, 0.0};
  for (const char* side : {"x-", "x+", "y-", "z-", "z+"})
    scene.boundaries.push_back({side, box_condition(BoundaryType::kRoller)});
  Stage stage = collapse_stage(0.1);
  stage.boundaries = {"x-", "x+", "y-", "z-", "z+"};
  const fs::path file = folder_ / "latest.checkpoint";
  Simulation<3> whole = make_box_simulation<3>(scene);
  std::optional<StageProgress> taken;
  whole.run_stage(stage, nullptr, [&](const Stage&, const StageProgress& at) {
    if (at.steps != 10) return;
    write_checkpoint(file, whole, header(0, at), RunRecord{});
    taken = at;
  });
  ASSERT_TRUE(taken);
  ASSERT_GT(whole.step_count(), 20);
  Simulation<3> resumed = make_box_simulation<3>(scene);
  read_checkpoint(file, resumed);
  EXPECT_EQ(read_checkpoint_header(file).dimension, 3);
  resumed.run_stage(stage, nullptr, {}, &*taken);
  expect_same_state(whole, resumed);
}

TEST_F(Checkpoint, NextStageFromAnEndOfStageCheckpointIsBitForBitTheSame) {
  // Settle, then collapse: the end-of-stage checkpoint holds the settled state (velocities
  // zeroed by the quasi-static stage's end) and starts the next stage from its beginning.
  const fs::path file = folder_ / "settle_end.checkpoint";
  const BoxScene<2> scene = collapse_scene(true);
  const Stage settle = settling_stage(0.01, 0.0, {"x-", "x+", "y-"});
  Simulation<2> whole = make_box_simulation<2>(scene);
  whole.run_stage(settle, nullptr);
  write_checkpoint(file, whole, header(1, std::nullopt), RunRecord{});
  whole.run_stage(collapse_stage(0.02), nullptr);

  Simulation<2> resumed = make_box_simulation<2>(scene);
  const CheckpointHeader h = read_checkpoint_header(file);
  EXPECT_FALSE(h.within_stage);
  EXPECT_EQ(h.stage, 1);
  read_checkpoint(file, resumed);
  resumed.run_stage(collapse_stage(0.02), nullptr);
  expect_same_state(whole, resumed);
}

TEST_F(Checkpoint, HeaderAndRunRecordRoundTrip) {
  const fs::path file = folder_ / "x.checkpoint";
  Simulation<2> sim = make_box_simulation<2>(collapse_scene(true));
  StageProgress at;
  at.time = 0.125;
  at.next_output_index = 7;
  at.next_output_time = 0.25;
  at.max_kinetic_energy = 3.5;
  at.steps = 42;
  at.wall_time = 1.5;
  RunRecord record;
  StageReport report;
  report.stage = "settle";
  report.steps = 99;
  report.simulated_time = 0.5;
  report.stop_reason = "duration reached";
  record.reports.push_back(report);
  record.series.push_back({"settle_points", "settle_points.pvd", {{0.0, "a.vtu"}, {0.5, "b.vtu"}}});
  write_checkpoint(file, sim, header(1, at), record);

  const CheckpointHeader h = read_checkpoint_header(file);
  EXPECT_EQ(h.format_version, kCheckpointFormatVersion);
  EXPECT_EQ(h.lituya_version, lituya::lituya_version());
  EXPECT_EQ(h.commit, lituya::lituya_commit());
  EXPECT_EQ(h.case_hash, "fnv1a64:00000000000000aa");
  EXPECT_EQ(h.inputs_hash, "fnv1a64:00000000000000bb");
  EXPECT_EQ(h.dimension, 2);
  EXPECT_EQ(h.solid_points, sim.points().size());
  EXPECT_EQ(h.liquid_points, sim.liquid().size());
  EXPECT_EQ(h.nodes, sim.mesh().node_count());
  EXPECT_EQ(h.stage, 1);
  ASSERT_TRUE(h.within_stage);
  EXPECT_EQ(h.within_stage->time, 0.125);
  EXPECT_EQ(h.within_stage->next_output_index, 7);
  EXPECT_EQ(h.within_stage->next_output_time, 0.25);
  EXPECT_EQ(h.within_stage->max_kinetic_energy, 3.5);
  EXPECT_EQ(h.within_stage->steps, 42);
  Simulation<2> other = make_box_simulation<2>(collapse_scene(true));
  const RunRecord r = read_checkpoint(file, other);
  ASSERT_EQ(r.reports.size(), 1u);
  EXPECT_EQ(r.reports[0].stage, "settle");
  EXPECT_EQ(r.reports[0].steps, 99);
  ASSERT_EQ(r.series.size(), 1u);
  EXPECT_EQ(r.series[0].file, "settle_points.pvd");
  EXPECT_EQ(r.series[0].entries, record.series[0].entries);
}

// The bytes of `file`, changed by `edit`, written back.
template <class Edit>
void edit_bytes(const fs::path& file, Edit edit) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  edit(bytes);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

TEST_F(Checkpoint, RefusesACheckpointItCannotContinue) {
  const fs::path file = folder_ / "x.checkpoint";
  const BoxScene<2> scene = collapse_scene(true);
  Simulation<2> sim = make_box_simulation<2>(scene);
  write_checkpoint(file, sim, header(0, std::nullopt), RunRecord{});
  const CheckpointHeader h = read_checkpoint_header(file);
  Simulation<2> fresh = make_box_simulation<2>(scene);
  auto read = [&] { read_checkpoint(file, fresh); };
  auto error = [&](auto f) { return lituya::input_error_message(f); };

  // The file as written: accepted, with its own hashes.
  EXPECT_EQ(error(read), "");
  EXPECT_EQ(error([&] { check_checkpoint(file, h, "fnv1a64:00000000000000aa", true); }), "");
  EXPECT_EQ(error([&] { check_checkpoint(file, h, "fnv1a64:00000000000000bb", false); }), "");

  // Other case files.
  std::string m = error([&] { check_checkpoint(file, h, "fnv1a64:0000000000000001", true); });
  EXPECT_NE(m.find("the case files changed since the checkpoint was written"), std::string::npos)
      << m;
  EXPECT_NE(m.find(file.string()), std::string::npos) << m;
  m = error([&] { check_checkpoint(file, h, "fnv1a64:0000000000000001", false); });
  EXPECT_NE(m.find("inputs of the stages it ran"), std::string::npos) << m;

  // Another build.
  CheckpointHeader older = h;
  older.lituya_version = "0.0.1";
  m = error([&] { check_checkpoint(file, older, h.case_hash, true); });
  EXPECT_NE(m.find("written by lituya 0.0.1"), std::string::npos) << m;
  older = h;
  older.commit = "0123abc";
  m = error([&] { check_checkpoint(file, older, h.case_hash, true); });
  EXPECT_NE(m.find("(commit 0123abc)"), std::string::npos) << m;

  // A case with other points.
  BoxScene<2> smaller = scene;
  smaller.water_max = {0.8, 0.2};
  Simulation<2> other = make_box_simulation<2>(smaller);
  m = error([&] { read_checkpoint(file, other); });
  EXPECT_NE(m.find("belongs to another case"), std::string::npos) << m;

  // A damaged byte in the middle of the arrays: the checksum.
  edit_bytes(file, [](std::string& b) { b[b.size() / 2] ^= 0x01; });
  m = error(read);
  EXPECT_NE(m.find("damaged checkpoint"), std::string::npos) << m;
  EXPECT_NE(m.find("checksum"), std::string::npos) << m;

  // Cut short (a copy interrupted, a full disk outside Lituya).
  write_checkpoint(file, sim, header(0, std::nullopt), RunRecord{});
  edit_bytes(file, [](std::string& b) { b.resize(b.size() * 2 / 3); });
  m = error(read);
  EXPECT_NE(m.find("cut short"), std::string::npos) << m;
  edit_bytes(file, [](std::string& b) { b.resize(20); });
  m = error([&] { read_checkpoint_header(file); });
  EXPECT_NE(m.find("cut short"), std::string::npos) << m;

  // Not a checkpoint at all, and a later format version.
  write_checkpoint(file, sim, header(0, std::nullopt), RunRecord{});
  edit_bytes(file, [](std::string& b) { b[0] = 'X'; });
  m = error([&] { read_checkpoint_header(file); });
  EXPECT_NE(m.find("not a Lituya checkpoint"), std::string::npos) << m;
  write_checkpoint(file, sim, header(0, std::nullopt), RunRecord{});
  edit_bytes(file, [](std::string& b) {  // after the magic and the byte order
    b[12] = static_cast<char>(kCheckpointFormatVersion + 1);
  });
  m = error([&] { read_checkpoint_header(file); });
  EXPECT_NE(m.find("checkpoint format version " + std::to_string(kCheckpointFormatVersion + 1) +
                   "; this Lituya"),
            std::string::npos)
      << m;
}

TEST_F(Checkpoint, NewestIsTheOneFurthestIntoTheRun) {
  const fs::path output = folder_ / "output";
  Simulation<2> sim = make_box_simulation<2>(collapse_scene(false));
  EXPECT_FALSE(newest_checkpoint(output));
  sim.run_stage(collapse_stage(0.004), nullptr);
  write_checkpoint(end_of_stage_checkpoint(output, "first"), sim, header(1, std::nullopt),
                   RunRecord{});
  EXPECT_EQ(newest_checkpoint(output), end_of_stage_checkpoint(output, "first"));
  sim.run_stage(collapse_stage(0.004), nullptr);
  StageProgress at;
  at.steps = 3;
  write_checkpoint(within_stage_checkpoint(output), sim, header(1, at), RunRecord{});
  EXPECT_EQ(newest_checkpoint(output), within_stage_checkpoint(output));
  // The end of a stage at the same step as a checkpoint within it comes after it.
  write_checkpoint(end_of_stage_checkpoint(output, "second"), sim, header(2, std::nullopt),
                   RunRecord{});
  EXPECT_EQ(newest_checkpoint(output), end_of_stage_checkpoint(output, "second"));
}

}  // namespace
