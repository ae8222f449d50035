// The FLIP/PIC blend settings: cell size of a mesh, defaults from the grid's gravity time,
// explicit settings, and the share applied per step.
#include "lituya/solver/transfer_damping.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lituya::solver {
namespace {

TEST(TransferDamping, CellSizeIsTheLegOfTheMedianCell) {
  // Squares of side 0.02 m split into two right triangles: area 2e-4 m2 each -> h = 0.02 m.
  // The median ignores a few large cells (a graded mesh's far field).
  std::vector<double> areas(100, 2e-4);
  areas[0] = 1.0;
  areas[1] = 5.0;
  EXPECT_NEAR(characteristic_cell_size(areas, 2), 0.02, 1e-12);
  // Cubes of side 0.01 m split into six tetrahedra: 1e-6 / 6 m3 each -> h = 0.01 m.
  EXPECT_NEAR(characteristic_cell_size(std::vector<double>(10, 1e-6 / 6), 3), 0.01, 1e-12);
}

TEST(TransferDamping, DefaultsAreMultiplesOfTheGridGravityTime) {
  const SolverSettings none;
  const TransferDamping d = resolve_transfer_damping(none, 0.02, 9.81);
  const double grid_time = std::sqrt(0.02 / 9.81);  // 0.0452 s
  EXPECT_NEAR(d.solid.time, 3.0 * grid_time, 1e-12);
  EXPECT_NEAR(d.liquid.time, 30.0 * grid_time, 1e-12);
  // The FLIP share of a step is exp(-dt / tau): two half steps damp as much as one step.
  const double dt = 2.5e-5;
  EXPECT_NEAR(d.liquid.flip_share(dt / 2) * d.liquid.flip_share(dt / 2), d.liquid.flip_share(dt),
              1e-15);
  EXPECT_NE(d.description.find("sqrt(h/g)"), std::string::npos) << d.description;
}

TEST(TransferDamping, GivenSettingsWin) {
  SolverSettings times;
  times.pic_damping_time = 0.5;
  const TransferDamping d = resolve_transfer_damping(times, 0.02, 9.81);
  EXPECT_DOUBLE_EQ(d.solid.time, 0.5);
  EXPECT_NEAR(d.liquid.time, 30.0 * std::sqrt(0.02 / 9.81), 1e-12);  // still the default

  SolverSettings per_step;
  per_step.flip_fraction = 0.9;
  const TransferDamping f = resolve_transfer_damping(per_step, 0.02, 9.81);
  EXPECT_DOUBLE_EQ(f.solid.flip_share(1e-3), 0.9);
  EXPECT_DOUBLE_EQ(f.liquid.flip_share(1e-6), 0.9);
}

TEST(TransferDamping, XpicWaterDefaultsToOneGridTime) {
  // XPIC(m >= 2) damps the grid-scale noise at the rate of a plain blend a grid time long
  // while keeping the resolved motion: the default is 1 grid time instead of 30.
  SolverSettings xpic;
  xpic.liquid_xpic_order = 2;
  const TransferDamping d = resolve_transfer_damping(xpic, 0.015, 9.81);
  const double grid_time = std::sqrt(0.015 / 9.81);  // 0.0391 s
  EXPECT_NEAR(d.liquid.time, grid_time, 1e-12);
  EXPECT_NEAR(d.solid.time, 3.0 * grid_time, 1e-12);  // the soil's default is unchanged
  EXPECT_NE(d.description.find("(1 sqrt(h/g)) by XPIC(2)"), std::string::npos) << d.description;
  // A given time still wins.
  xpic.liquid_pic_damping_time = 0.2;
  EXPECT_DOUBLE_EQ(resolve_transfer_damping(xpic, 0.015, 9.81).liquid.time, 0.2);
}

TEST(TransferDamping, WithoutGravityTheOldPerStepBlendRemains) {
  const TransferDamping d = resolve_transfer_damping(SolverSettings{}, 0.02, 0.0);
  EXPECT_DOUBLE_EQ(d.solid.flip_share(1e-3), 0.99);
  EXPECT_DOUBLE_EQ(d.liquid.flip_share(1e-3), 0.99);
  EXPECT_NE(d.description.find("no gravity"), std::string::npos) << d.description;
}

}  // namespace
}  // namespace lituya::solver
