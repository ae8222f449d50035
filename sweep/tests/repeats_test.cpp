#include "lituya/sweep/repeats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <toml++/toml.h>
#include <nlohmann/json.hpp>

#include "lituya/common/input_error.hpp"
#include "lituya/common/vtu_writer.hpp"
#include "lituya/sweep/convergence.hpp"
#include "lituya/sweep/definition.hpp"
#include "lituya/sweep/mesh_fingerprint.hpp"
#include "lituya/sweep/sweep.hpp"
#include "run_record.hpp"

namespace {

namespace fs = std::filesystem;
using namespace lituya::sweep;

using lituya::sweep::testing::run;

// Repeat k changes the Courant number by 2e-4 k of itself: 0.5 -> 0.4999, 0.4998 (the runs of
// verification/speed_accuracy_case_b's crossed-mesh scatter study).
TEST(Repeats, CourantNumbersStepBy2e4OfThemselves) {
  EXPECT_EQ(repeat_values(0.5, 3), (std::vector<std::string>{"0.5", "0.4999", "0.4998"}));
  EXPECT_EQ(repeat_values(0.9, 2), (std::vector<std::string>{"0.9", "0.89982"}));
  // A whole Courant number stays a float, so a scene's integer `courant = 1` takes them.
  EXPECT_EQ(repeat_values(1.0, 2), (std::vector<std::string>{"1.0", "0.9998"}));
}

// The key is the last stage's, by name (the stage the post reads in a scene of stages).
TEST(Repeats, KeyIsTheLastStagesCourantNumber) {
  const toml::table scene =
      toml::parse("[[stage]]\nname = \"gravity\"\ncourant = 0.5\n[[stage]]\nname = \"release\"\n");
  EXPECT_EQ(repeat_key(scene, "scene.toml"), "stage.release.courant");
  const toml::table unnamed = toml::parse("[[stage]]\ncourant = 0.5\n[[stage]]\nduration = 1\n");
  EXPECT_EQ(repeat_key(unnamed, "scene.toml"), "stage.1.courant");
  EXPECT_THROW(repeat_key(toml::parse("title = \"no stages\"\n"), "scene.toml"),
               lituya::InputError);
}

// Sample mean and standard deviation (n - 1): 1, 2, 3 -> 2 and 1; what is not finite (a run
// without the measure) is left out; one value has no standard deviation.
TEST(Repeats, SpreadOfFiniteValues) {
  const Spread s = spread_of({1.0, NAN, 3.0, 2.0});
  EXPECT_EQ(s.count, 3);
  EXPECT_DOUBLE_EQ(s.mean, 2.0);
  EXPECT_DOUBLE_EQ(s.sd, 1.0);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 3.0);
  const Spread one = spread_of({4.0});
  EXPECT_EQ(one.count, 1);
  EXPECT_DOUBLE_EQ(one.mean, 4.0);
  EXPECT_TRUE(std::isnan(one.sd));
  EXPECT_EQ(spread_of({NAN}).count, 0);
}

// The summary groups the runs by the other keys; a failed run does not count.
TEST(Repeats, SummaryGroupsTheRunsByTheOtherKeys) {
  SweepResult result;
  result.parameters = {"solver.x", "stage.release.courant"};
  result.labels = {"x", "courant"};
  result.measures = {"front"};
  result.repeat_parameter = 1;
  result.runs = {run(1, {"a", "0.5"}, {1.0}),
                 run(2, {"a", "0.4999"}, {1.2}),
                 run(3, {"a", "0.4998"}, {1.4}),
                 run(4, {"b", "0.5"}, {2.0}),
                 run(5, {"b", "0.4999"}, {9.0}, RunStatus::kError),
                 run(6, {"b", "0.4998"}, {2.5})};
  const std::vector<RepeatSummaryRow> rows = repeat_summary(result);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].group, "x=a");
  EXPECT_EQ(rows[0].spread.count, 3);
  EXPECT_NEAR(rows[0].spread.mean, 1.2, 1e-12);
  EXPECT_NEAR(rows[0].spread.sd, 0.2, 1e-12);
  EXPECT_EQ(rows[1].group, "x=b");
  EXPECT_EQ(rows[1].spread.count, 2);
  EXPECT_DOUBLE_EQ(rows[1].spread.mean, 2.25);
  EXPECT_NE(format_repeats(rows, "stage.release.courant").find("x=b"), std::string::npos);
  result.repeat_parameter = -1;
  EXPECT_TRUE(repeat_summary(result).empty());
}

// With repeats, the mesh convergence extrapolates each size's mean. The means follow
// f = 1 + h exactly (order 1, limit 1) while each pair of repeats straddles its mean by
// +-0.0001: the estimate must give back order 1 and limit 1. A second measure whose repeats
// scatter by +-0.02 around the same means has a last change (0.005) within twice its standard
// error (0.02): the note says the change is not resolved.
TEST(Repeats, MeshConvergenceExtrapolatesTheMeansAndJudgesTheLastChange) {
  SweepResult result;
  result.parameters = {"mesh.cell_size", "stage.release.courant"};
  result.labels = {"cell_size", "courant"};
  result.measures = {"quiet", "noisy"};
  result.repeat_parameter = 1;
  int number = 0;
  for (double h : {0.02, 0.015, 0.01})
    for (double sign : {1.0, -1.0})
      result.runs.push_back(run(++number, {std::to_string(h), sign > 0 ? "0.5" : "0.4999"},
                                {1.0 + h + sign * 1e-4, 1.0 + h + sign * 0.02}));
  const std::vector<MeshConvergenceRow> rows = mesh_convergence(result);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].group, "");
  EXPECT_EQ(rows[0].spread[0].count, 2);
  EXPECT_NEAR(rows[0].estimate.value[0], 1.01, 1e-12);
  EXPECT_NEAR(rows[0].estimate.order, 1.0, 1e-6);
  EXPECT_NEAR(rows[0].estimate.extrapolated, 1.0, 1e-9);
  EXPECT_EQ(rows[0].estimate.note.find("standard error"), std::string::npos)
      << rows[0].estimate.note;
  EXPECT_NE(rows[1].estimate.note.find("standard error"), std::string::npos);
  EXPECT_NEAR(rows[1].spread[0].sd, 0.02 * std::sqrt(2.0), 1e-12);
}

// A sweep of the test column at one friction angle, repeated, front travel measured, into a
// fresh folder under the temporary directory.
SweepDefinition repeated_column_sweep(const std::string& folder_name, int repeats,
                                      RepeatBy by = RepeatBy::kCourant) {
  SweepDefinition d;
  d.scene = fs::path(LITUYA_SWEEP_TEST_DATA) / "collapse.toml";
  d.parameters = {{"material.sand.friction_angle", {"30"}}};
  d.measures = {"front_travel_final"};
  d.output = fs::temp_directory_path() / folder_name;
  fs::remove_all(d.output);
  d.repeats = repeats;
  d.repeat_by = by;
  return d;
}

// End to end on the test column (about a second a run): three repeats of one friction angle
// are three runs at release Courant numbers 0.5, 0.4999, 0.4998; repeats.csv holds their
// mean; they share the gravity stage (run once); sweep.toml records `repeats = 3` and reads
// back as the same sweep of one key.
TEST(Repeats, SweepRunsEachRunRepeatedAndSummarisesIt) {
  const SweepDefinition d = repeated_column_sweep("lituya_sweep_repeats", 3);
  const fs::path folder = d.output;
  const SweepResult result = run_sweep(d, SweepOptions{});
  ASSERT_TRUE(result.all_ok());
  ASSERT_EQ(result.runs.size(), 3u);
  EXPECT_EQ(result.repeat_parameter, 1);
  EXPECT_EQ(result.parameters[1], "stage.release.courant");
  EXPECT_EQ(result.runs[2].values[1], "0.4998");
  EXPECT_EQ(result.runs[1].reused_from, 1);
  const double mean =
      (result.runs[0].measures[0] + result.runs[1].measures[0] + result.runs[2].measures[0]) / 3.0;
  ASSERT_EQ(result.repeats, folder / "repeats.csv");
  std::ifstream table(result.repeats);
  std::string header, line;
  std::getline(table, header);
  std::getline(table, line);
  EXPECT_EQ(header, "group,measure,runs,mean,sd,relative_sd,min,max");
  std::stringstream fields(line);
  std::string group, measure, runs, mean_text;
  std::getline(fields, group, ',');
  std::getline(fields, measure, ',');
  std::getline(fields, runs, ',');
  std::getline(fields, mean_text, ',');
  EXPECT_EQ(group, "friction_angle=30");
  EXPECT_EQ(runs, "3");
  EXPECT_NEAR(std::stod(mean_text), mean, 1e-9 * std::abs(mean));
  // The plot draws the measure (column 4 of sweep.csv: run, friction_angle, courant, measure)
  // against the swept key (column 2), not against the repeat key.
  std::ifstream script(folder / "sweep.gp");
  const std::string plot((std::istreambuf_iterator<char>(script)), {});
  EXPECT_NE(plot.find("using 2:($4)"), std::string::npos) << plot;
  EXPECT_EQ(plot.find("using 2:($3)"), std::string::npos) << plot;
  const SweepDefinition again = read_sweep_file(folder / "sweep.toml");
  EXPECT_EQ(again.repeats, 3);
  ASSERT_EQ(again.parameters.size(), 1u);
  EXPECT_EQ(again.parameters[0].key, "material.sand.friction_angle");
  nlohmann::json summary;
  std::ifstream(folder / "sweep.json") >> summary;
  EXPECT_EQ(summary["repeat_key"], "stage.release.courant");
  EXPECT_EQ(summary["repeats"].size(), 1u);
  fs::remove_all(folder);
}

// Repeats on other meshes (--repeat-by mesh): two repeats are runs with [mesh] seed 1 and 2
// (the test scene gives none: gmsh's own 1 first), each with its own mesh, so the second run
// cannot take the gravity stage from the first (the stage inputs differ) and their front
// travels differ; sweep.toml records repeat_by and reads back as the same sweep.
TEST(Repeats, MeshRepeatsRunEachRepeatOnAnotherMesh) {
  const SweepDefinition d = repeated_column_sweep("lituya_sweep_repeats_mesh", 2, RepeatBy::kMesh);
  const fs::path folder = d.output;
  const SweepResult result = run_sweep(d, SweepOptions{});
  ASSERT_TRUE(result.all_ok());
  ASSERT_EQ(result.runs.size(), 2u);
  EXPECT_EQ(result.parameters[1], "mesh.seed");
  EXPECT_EQ(result.runs[0].values[1], "1");
  EXPECT_EQ(result.runs[1].values[1], "2");
  EXPECT_EQ(result.runs[1].reused_from, 0);
  std::ifstream geometry_a(folder / result.runs[0].folder.filename() / "case" / "geometry.vtu");
  std::ifstream geometry_b(folder / result.runs[1].folder.filename() / "case" / "geometry.vtu");
  const std::string mesh_a((std::istreambuf_iterator<char>(geometry_a)), {});
  const std::string mesh_b((std::istreambuf_iterator<char>(geometry_b)), {});
  ASSERT_FALSE(mesh_a.empty());
  EXPECT_NE(mesh_a, mesh_b);
  EXPECT_NE(result.runs[0].measures[0], result.runs[1].measures[0]);
  const SweepDefinition again = read_sweep_file(folder / "sweep.toml");
  EXPECT_EQ(again.repeats, 2);
  EXPECT_EQ(again.repeat_by, RepeatBy::kMesh);
  EXPECT_NE(format_repeats(repeat_summary(result), repeat_key_of(result)).find("another mesh"),
            std::string::npos);
  fs::remove_all(folder);
}

// A unit square as two triangles, written as a case's geometry.vtu: `numbering` 0 as given,
// 1 with the nodes and cells numbered in reverse (the same mesh), 2 with the diagonal flipped
// (another mesh of the same nodes).
void write_square_mesh(const fs::path& file, int numbering) {
  std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  std::vector<std::int64_t> connectivity = {0, 1, 2, 0, 2, 3};
  if (numbering == 1) {
    xyz = {0, 1, 0, 1, 1, 0, 1, 0, 0, 0, 0, 0};  // node k is node 3 - k of numbering 0
    connectivity = {3, 1, 0, 3, 2, 1};           // the cells swapped, each renumbered
  } else if (numbering == 2) {
    connectivity = {0, 1, 3, 1, 2, 3};
  }
  lituya::VtuWriter writer;
  writer.set_points(xyz);
  writer.set_cells(connectivity, {3, 6}, {5, 5});
  writer.add_cell_data("group", std::vector<std::int32_t>{1, 1});
  fs::create_directories(file.parent_path());
  writer.write(file);
}

// The fingerprint sees the mesh, not its numbering: renumbered nodes and cells, or nodes moved
// by rounding, give the same value, a flipped diagonal or a node moved by 1e-3 of the mesh
// another; a missing file gives none.
TEST(MeshFingerprint, IgnoresTheNumberingAndSeesTheCells) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_mesh_fingerprint";
  fs::remove_all(folder);
  for (int numbering : {0, 1, 2}) write_square_mesh(folder / std::to_string(numbering), numbering);
  const auto a = mesh_fingerprint(folder / "0");
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(mesh_fingerprint(folder / "1"), a);
  EXPECT_NE(mesh_fingerprint(folder / "2"), a);
  lituya::VtuWriter moved;
  moved.set_points(std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1.001, 0, 0, 1, 0});
  moved.set_cells({0, 1, 2, 0, 2, 3}, {3, 6}, {5, 5});
  moved.add_cell_data("group", std::vector<std::int32_t>{1, 1});
  moved.write(folder / "moved");
  EXPECT_NE(mesh_fingerprint(folder / "moved"), a);
  // A rounding-level jitter (Case B's seeds 1 and 2 at 0.02 m moved a third of the nodes by
  // about 1e-14 m) is the same mesh.
  lituya::VtuWriter jittered;
  jittered.set_points(std::vector<double>{0, 0, 0, 1 + 1e-14, 0, 0, 1, 1 - 2e-14, 0, 0, 1, 0});
  jittered.set_cells({0, 1, 2, 0, 2, 3}, {3, 6}, {5, 5});
  jittered.add_cell_data("group", std::vector<std::int32_t>{1, 1});
  jittered.write(folder / "jittered");
  EXPECT_EQ(mesh_fingerprint(folder / "jittered"), a);
  EXPECT_FALSE(mesh_fingerprint(folder / "missing").has_value());
  fs::remove_all(folder);
}

// Seeds that give the same mesh are one sample, not several: the report counts the different
// meshes of each group and names the group whose runs shared a mesh. Here the
// group h=0.02 has three runs on two meshes (seeds 1 and 3 the same mesh numbered otherwise),
// the group h=0.01 two runs on two meshes, and a run that never meshed is not counted.
TEST(Repeats, MeshRepeatsOnTheSameMeshAreNamed) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_repeats_same_mesh";
  fs::remove_all(folder);
  SweepResult result;
  result.parameters = {"mesh.cell_size", "mesh.seed"};
  result.labels = {"cell_size", "seed"};
  result.measures = {"front"};
  result.repeat_parameter = 1;
  // {values, numbering of the square mesh (-1: no mesh)}
  const std::vector<std::pair<std::vector<std::string>, int>> runs = {
      {{"0.02", "1"}, 0},  {{"0.02", "2"}, 2}, {{"0.02", "3"}, 1},
      {{"0.02", "4"}, -1}, {{"0.01", "1"}, 0}, {{"0.01", "2"}, 2}};
  for (const auto& [values, numbering] : runs) {
    result.runs.push_back(run(static_cast<int>(result.runs.size()) + 1, values,
                              {1.0 + 0.1 * static_cast<double>(result.runs.size())}));
    result.runs.back().folder = folder / ("run_" + std::to_string(result.runs.size()));
    if (numbering >= 0)
      write_square_mesh(result.runs.back().folder / "case" / "geometry.vtu", numbering);
  }
  ASSERT_EQ(repeat_summary(result).size(), 2u);
  const std::string text = format_shared_meshes(result);
  // Group h=0.02: 3 runs that meshed, 2 different meshes; group h=0.01: 2 and 2, not named.
  EXPECT_NE(text.find("the repeats with cell_size=0.02: 3 runs on 2 different meshes"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("cell_size=0.01: "), std::string::npos) << text;
  // Courant repeats never count meshes.
  result.parameters[1] = "stage.release.courant";
  EXPECT_EQ(format_shared_meshes(result), "");
  fs::remove_all(folder);
}

// A refinement sweep repeats on other meshes unless told otherwise (repeat_by_for): a dry run
// of the test column over two cell sizes, two repeats each, plans seeds 1 and 2; the same
// sweep with repeat_by = courant plans the Courant repeats.
TEST(Repeats, ACellSizeSweepRepeatsOnOtherMeshesByDefault) {
  SweepDefinition d = repeated_column_sweep("lituya_sweep_repeats_default", 2);
  d.repeat_by.reset();
  d.parameters = {{"mesh.cell_size", {"0.025", "0.0125"}}};
  SweepOptions dry;
  dry.dry_run = true;
  SweepResult result = run_sweep(d, dry);
  ASSERT_EQ(result.parameters.size(), 2u);
  EXPECT_EQ(result.parameters[1], "mesh.seed");
  ASSERT_EQ(result.runs.size(), 4u);
  EXPECT_EQ(result.runs[1].values[1], "2");
  d.repeat_by = RepeatBy::kCourant;
  result = run_sweep(d, dry);
  EXPECT_EQ(result.parameters[1], "stage.release.courant");
  fs::remove_all(d.output);
}

TEST(Repeats, MeshSeedValuesCountUpFromTheScenesSeed) {
  EXPECT_EQ(mesh_seed_values(1, 3), (std::vector<std::string>{"1", "2", "3"}));
  EXPECT_EQ(mesh_seed_values(40, 2), (std::vector<std::string>{"40", "41"}));
}

// Sweeping the key the repeats change is refused before anything is written.
TEST(Repeats, SweepingTheRepeatKeyIsRefused) {
  const fs::path folder = fs::temp_directory_path() / "lituya_sweep_repeats_refused";
  fs::remove_all(folder);
  SweepDefinition d;
  d.scene = fs::path(LITUYA_SWEEP_TEST_DATA) / "collapse.toml";
  d.parameters = {{"stage.release.courant", {"0.4", "0.5"}}};
  d.output = folder;
  d.repeats = 2;
  EXPECT_THROW(run_sweep(d, SweepOptions{}), lituya::InputError);
  EXPECT_FALSE(fs::exists(folder));
  d.parameters = {{"mesh.seed", {"3", "4"}}};
  d.repeat_by = RepeatBy::kMesh;
  EXPECT_THROW(run_sweep(d, SweepOptions{}), lituya::InputError);
  EXPECT_FALSE(fs::exists(folder));
}

}  // namespace
