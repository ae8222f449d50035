#include "lituya/sweep/convergence.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "lituya/sweep/sweep.hpp"
#include "run_record.hpp"

namespace {

using namespace lituya::sweep;

// f(h) = f_inf + C h^p: Richardson's assumption holds exactly, so the estimate must give back
// p and f_inf to rounding, whatever the (unequal) refinement ratios and the input order. The
// grid convergence index is then 1.25 times the true relative error of the finest value
// (Roache's safety factor on an exact error estimate): 1.25 * 0.002 / 0.056 here.
TEST(Richardson, RecoversTheOrderAndLimitOfAPowerLawWithUnequalRatios) {
  auto f = [](double h) { return 0.058 - 2.0 * std::pow(h, 1.5); };
  const RichardsonEstimate e =
      richardson_estimate({0.02, 0.01, 0.015}, {f(0.02), f(0.01), f(0.015)});
  EXPECT_EQ(e.behaviour, ConvergenceBehaviour::kMonotone);
  EXPECT_DOUBLE_EQ(e.cell_size[0], 0.01);
  EXPECT_DOUBLE_EQ(e.cell_size[2], 0.02);
  EXPECT_NEAR(e.order, 1.5, 1e-9);
  EXPECT_NEAR(e.extrapolated, 0.058, 1e-12);
  EXPECT_NEAR(e.gci_fine, 1.25 * 0.002 / 0.056, 1e-9);
  EXPECT_NEAR(e.change_fine, (f(0.01) - f(0.015)) / f(0.015), 1e-14);
  EXPECT_TRUE(e.note.empty());
}

// Equal ratios: the order is the closed form ln(e32 / e21) / ln r, here ln 4 / ln 2 = 2.
TEST(Richardson, SecondOrderWithARatioOfTwo) {
  const RichardsonEstimate e = richardson_estimate({0.01, 0.02, 0.04}, {1.0001, 1.0004, 1.0016});
  EXPECT_EQ(e.behaviour, ConvergenceBehaviour::kMonotone);
  EXPECT_NEAR(e.order, 2.0, 1e-9);
  EXPECT_NEAR(e.extrapolated, 1.0, 1e-12);
}

// Changes that alternate in sign (0.01 -> 0.015 -> 0.02: +0.1 then -0.15) or that do not
// shrink (+0.1 then +0.05 towards the fine end) give neither an order nor a limit.
TEST(Richardson, OscillatingAndGrowingChangesGiveNoEstimate) {
  const RichardsonEstimate oscillating = richardson_estimate({0.01, 0.015, 0.02}, {1.0, 1.1, 0.95});
  EXPECT_EQ(oscillating.behaviour, ConvergenceBehaviour::kOscillatory);
  EXPECT_TRUE(std::isnan(oscillating.order));
  EXPECT_TRUE(std::isnan(oscillating.extrapolated));
  EXPECT_FALSE(oscillating.note.empty());
  const RichardsonEstimate growing = richardson_estimate({0.01, 0.015, 0.02}, {1.0, 1.1, 1.15});
  EXPECT_EQ(growing.behaviour, ConvergenceBehaviour::kNotConverging);
  EXPECT_TRUE(std::isnan(growing.order));
  EXPECT_NEAR(growing.change_fine, -0.1 / 1.1, 1e-14);
}

// With unequal ratios the bound on R = e21 / e32 is ln r21 / ln r32, not 1 (convergence.hpp).
// f = 1 + h at 0.01 / 0.04 / 0.05 m (r21 = 4, r32 = 1.25): the finest step changes f three
// times as much as the one before, yet the order is 1 and the limit 1. Case B's first crest
// at X1 at 0.005 / 0.0075 / 0.015 m (46.08, 46.69, 46.92 mm; r21 = 1.5, r32 = 2) has
// R = 2.65 above the bound 0.585: no positive order fits, where the absolute value in Celik's
// fixed-point form read an order of 8.5 and a limit of 46.1 mm.
TEST(Richardson, TheBoundOnTheChangesFollowsTheRefinementRatios) {
  const RichardsonEstimate wide = richardson_estimate({0.01, 0.04, 0.05}, {1.01, 1.04, 1.05});
  EXPECT_EQ(wide.behaviour, ConvergenceBehaviour::kMonotone);
  EXPECT_NEAR(wide.order, 1.0, 1e-9);
  EXPECT_NEAR(wide.extrapolated, 1.0, 1e-12);
  const RichardsonEstimate crest =
      richardson_estimate({0.005, 0.0075, 0.015}, {46.08, 46.69, 46.92});
  EXPECT_EQ(crest.behaviour, ConvergenceBehaviour::kNotConverging);
  EXPECT_TRUE(std::isnan(crest.order));
  EXPECT_NE(crest.note.find("refinement ratios"), std::string::npos);
}

TEST(Richardson, EqualValuesAreUnchanged) {
  const RichardsonEstimate e = richardson_estimate({0.01, 0.015, 0.02}, {2.0, 2.0, 2.0});
  EXPECT_EQ(e.behaviour, ConvergenceBehaviour::kUnchanged);
  EXPECT_DOUBLE_EQ(e.extrapolated, 2.0);
  EXPECT_DOUBLE_EQ(e.change_fine, 0.0);
}

// Values that level off abruptly (Case B's first crest at X1 with the nodal fit, mm, at
// 0.01 / 0.015 / 0.02 m: 50.3, 49.9, 45.8) converge monotonically at an order far above what
// linear shape functions can give: the note says not to read the limit as one.
TEST(Richardson, AnImplausiblyHighOrderIsFlagged) {
  const RichardsonEstimate e = richardson_estimate({0.01, 0.015, 0.02}, {50.3, 49.9, 45.8});
  EXPECT_EQ(e.behaviour, ConvergenceBehaviour::kMonotone);
  EXPECT_GT(e.order, 3.0);
  EXPECT_NE(e.note.find("asymptotic"), std::string::npos);
}

TEST(Richardson, RefusesRepeatedOrInvalidCellSizes) {
  EXPECT_THROW(richardson_estimate({0.01, 0.01, 0.02}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(richardson_estimate({0.0, 0.01, 0.02}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(richardson_estimate({0.005, 0.01, 0.02}, {1, NAN, 3}), std::invalid_argument);
}

using lituya::sweep::testing::run;

// A grid of a solver key and the cell size. For x = a: four sizes, the finest run failed (it is
// left out) and m2 has no value at 0.01 m, so m1 takes 0.01 / 0.015 / 0.02 and m2 0.015 / 0.02 /
// 0.03. For x = b: two sizes, no estimate.
TEST(MeshConvergence, TakesTheThreeFinestFinishedRunsOfEachGroup) {
  SweepResult result;
  result.parameters = {"solver.x", "mesh.cell_size"};
  result.labels = {"x", "cell_size"};
  result.measures = {"front_position", "gauge_max:X1"};
  result.runs = {run(1, {"a", "0.03"}, {4.0, 0.8}),
                 run(2, {"a", "0.02"}, {3.0, 0.9}),
                 run(3, {"a", "0.015"}, {2.5, 0.95}),
                 run(4, {"a", "0.01"}, {2.25, NAN}),
                 run(5, {"a", "0.005"}, {NAN, NAN}, RunStatus::kError),
                 run(6, {"b", "0.02"}, {1.0, 1.0}),
                 run(7, {"b", "0.01"}, {1.0, 1.0})};
  const std::vector<MeshConvergenceRow> rows = mesh_convergence(result);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].group, "x=a");
  EXPECT_EQ(rows[0].measure, "front_position");
  EXPECT_EQ(rows[0].runs, (std::array<int, 3>{4, 3, 2}));
  EXPECT_EQ(rows[1].measure, "gauge_max:X1");
  EXPECT_EQ(rows[1].runs, (std::array<int, 3>{3, 2, 1}));
  EXPECT_DOUBLE_EQ(rows[1].estimate.cell_size[0], 0.015);

  // A sweep that does not vary the cell size has nothing to say.
  result.parameters = {"solver.x", "materials.sand.friction_angle"};
  EXPECT_TRUE(mesh_convergence(result).empty());
}

// The table a user reads: a header row and one row per estimate, and the note of an
// oscillating measure under it.
TEST(MeshConvergence, WritesAndPrintsItsTable) {
  SweepResult result;
  result.parameters = {"mesh.cell_size"};
  result.labels = {"cell_size"};
  result.measures = {"front_position"};
  result.runs = {run(1, {"0.01"}, {1.0}), run(2, {"0.015"}, {1.1}), run(3, {"0.02"}, {0.95})};
  const std::vector<MeshConvergenceRow> rows = mesh_convergence(result);
  ASSERT_EQ(rows.size(), 1u);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "lituya_convergence_test.csv";
  write_convergence_table(file, rows);
  std::ifstream in(file);
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  EXPECT_EQ(header.rfind("group,measure,runs,h_fine,h_medium,h_coarse", 0), 0u);
  EXPECT_NE(line.find("oscillatory"), std::string::npos);
  const std::string text = format_convergence(rows);
  EXPECT_NE(text.find("front_position"), std::string::npos);
  EXPECT_NE(text.find("alternate in sign"), std::string::npos);
  std::filesystem::remove(file);
}

}  // namespace
