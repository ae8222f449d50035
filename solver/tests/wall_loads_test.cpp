// The boundary forces (wall_loads.cpp) against closed forms: a block's weight on its bed, the
// Coulomb friction of a sliding block, still water on the floor and walls of a tank, and the
// effective normal force of a saturated bed under water.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "lituya/solver/box_scene.hpp"
#include "lituya/solver/simulation.hpp"

namespace {

using namespace lituya::solver;
constexpr double kPi = 3.14159265358979323846;
constexpr double kGravity = 9.81;

Stage dynamic_stage(double duration, std::vector<std::string> boundaries) {
  Stage s;
  s.name = "test";
  s.type = StageType::kDynamic;
  s.duration = duration;
  s.boundaries = std::move(boundaries);
  return s;
}

// The mean force on the boundary named `name` over the stage just run (N/m in 2D).
template <int dim>
typename Simulation<dim>::WallImpulse mean_load(const Simulation<dim>& sim,
                                                const std::string& name) {
  typename Simulation<dim>::WallImpulse mean;
  const double time = sim.wall_impulse_time();
  const auto& boundaries = sim.description().boundaries;
  for (std::size_t b = 0; b < boundaries.size(); ++b) {
    if (boundaries[b].name != name) continue;
    const auto& sum = sim.wall_impulses()[b];
    mean.force += sum.force / time;
    mean.normal += sum.normal / time;
    mean.tangential += sum.tangential / time;
    mean.pore_pressure += sum.pore_pressure / time;
  }
  return mean;
}

// A block 0.4 m x 0.1 m of dry density 2000 kg/m3 on a bed, gravity tilted by theta (an
// incline); it first settles on a glued bed, then the bed named `bed` holds it for `time`.
Simulation<2> block_on_bed(double theta_deg, const BoundaryCondition& bed, double time) {
  const BoxScene<2> scene = block_on_incline(theta_deg, bed);
  Simulation<2> sim = make_box_simulation<2>(scene);
  sim.run_stage(settling_stage(0.5, 1e-6, {"glued"}), nullptr);
  sim.run_stage(dynamic_stage(time, {bed.name}), nullptr);
  return sim;
}

TEST(WallLoads, BlockAtRestPressesItsWeightOnTheBed) {
  // Reference: the weight m g = 2000 x 0.04 x 9.81 = 784.8 N/m, straight down. Tolerance
  // 0.5 %: averaged over 0.1 s the bed carries the weight less the rate of change of the
  // block's momentum, and the settled block barely moves; no grip across the bed.
  BoundaryCondition bed = box_condition(BoundaryType::kFixed);
  bed.name = "bed";
  const Simulation<2> sim = block_on_bed(0, bed, 0.1);
  const double weight = 2000.0 * 0.4 * 0.1 * kGravity;
  const auto load = mean_load(sim, "bed");
  EXPECT_NEAR(load.normal, weight, 0.005 * weight);
  EXPECT_NEAR(load.force(1), -weight, 0.005 * weight);
  EXPECT_LT(load.tangential.norm(), 0.005 * weight);
  EXPECT_EQ(load.pore_pressure, 0.0);
  std::cout << "bed: normal " << load.normal << " N/m against the weight " << weight << "\n";
}

TEST(WallLoads, SlidingBlockFrictionIsMuTimesTheNormalForce) {
  // Reference: while it slides, the bed pushes m g cos(theta) = 679.7 N/m normal to it and
  // holds it back with mu times that, 135.9 N/m, pointing down the slope on the bed (+x).
  // Tolerances: 1 % for the normal force (the elastic block rings a little at the release, as
  // in Simulation.SlidingBlockMatchesCoulombAcceleration); 0.1 % for the friction against mu
  // times the measured normal force. The nodal Coulomb law takes exactly mu times a sliding
  // node's normal impulse, but a node at the block's front or back edge, with a few grams of
  // the block's 80 kg/m (the points just reaching its cells), can be pressed harder in a step
  // than its slip can pay for, and sticks: measured 2.2e-4 below mu N over the slide, all of
  // it from such nodes (a debug build listing the nodes where T differs from mu N).
  const double theta = 30, mu = 0.2;
  BoundaryCondition bed = box_condition(BoundaryType::kContact, mu);
  bed.name = "bed";
  const Simulation<2> sim = block_on_bed(theta, bed, 0.2);
  const double normal = 2000.0 * 0.4 * 0.1 * kGravity * std::cos(theta * kPi / 180);
  const auto load = mean_load(sim, "bed");
  EXPECT_NEAR(load.normal, normal, 0.01 * normal);
  EXPECT_NEAR(load.tangential.norm(), mu * load.normal, 1e-3 * mu * load.normal);
  EXPECT_GT(load.force(0), 0.0);
  std::cout << "bed: normal " << load.normal << " N/m (" << normal << "), friction "
            << load.tangential.norm() << " N/m (mu N " << mu * load.normal << ")\n";
}

TEST(WallLoads, StillWaterLoadsTheFloorAndTheWallsHydrostatically) {
  // A tank 1 m wide with still water 0.2 m deep, roller walls and floor. References: the floor
  // carries the water's weight, rho_w g H L = 1962 N/m; each wall the hydrostatic thrust
  // rho_w g H^2 / 2 = 196.2 N/m. Tolerances: 0.5 % for the floor (vertical momentum balance:
  // the rollers take no vertical force, and still water keeps its momentum), 2 % for the walls
  // (their thrust is the discrete pressure's integral over the wall's nodes, which the
  // points' pressures and the one-sided nodes of the floor's corner shape). The corner nodes
  // belong to a wall and the floor: their force is split along the two normals.
  const BoxScene<2> s = still_water_tank(0.2);
  Simulation<2> sim = make_box_simulation<2>(s);
  sim.run_stage(dynamic_stage(0.2, {"x-", "x+", "y-"}), nullptr);
  const double floor = 1000.0 * kGravity * 0.2 * 1.0, wall = 1000.0 * kGravity * 0.2 * 0.2 / 2;
  const auto bottom = mean_load(sim, "y-");
  EXPECT_NEAR(bottom.normal, floor, 0.005 * floor);
  EXPECT_NEAR(bottom.force(1), -floor, 0.005 * floor);
  for (const char* side : {"x-", "x+"}) {
    const auto load = mean_load(sim, side);
    EXPECT_NEAR(load.normal, wall, 0.02 * wall) << side;
    std::cout << side << ": " << load.normal << " N/m against " << wall << "\n";
  }
  std::cout << "floor: " << bottom.normal << " N/m against " << floor << "\n";
  EXPECT_LT(mean_load(sim, "x-").force(0), 0.0);  // pushed outward
  EXPECT_GT(mean_load(sim, "x+").force(0), 0.0);
}

TEST(WallLoads, SaturatedBedRestsItsBuoyantWeightOnAContactBed) {
  // A saturated sand bed 0.2 m thick under 0.1 m of water, 0.4 m wide (box_scene.hpp), on a
  // contact floor. References: the floor carries everything, rho_w g 0.1 m + rho_sat g 0.2 m
  // over 0.4 m = 1954.2 N/m (rho_sat = 1990 kg/m3); the effective normal force, what Coulomb's
  // law acts on, is the sand's buoyant weight (rho_sat - rho_w) g 0.2 m x 0.4 m = 776.9 N/m
  // (eq. 14). Tolerances: 0.5 % for the whole load (momentum balance, as for the tank);
  // 3 % for the effective force, the difference of the whole load and the wall's share of the
  // pore pressure (1177 N/m), whose nodal sum carries the bottom row's pressure error
  // (TwoPhase.SaturatedBedUnderWaterStaysAtRest: 0.5 % mean, 10 N/m here).
  BoxScene<2> scene = sand_bed_under_water(0.002);
  scene.boundaries.back().second = box_condition(BoundaryType::kContact, 0.3);
  Simulation<2> sim = make_box_simulation<2>(scene);
  sim.run_stage(dynamic_stage(0.2, {"x-", "x+", "y-"}), nullptr);
  const double rho_sat = 0.6 * 2650.0 + 0.4 * 1000.0;
  const double total = (1000.0 * 0.1 + rho_sat * 0.2) * kGravity * 0.4;
  const double buoyant = (rho_sat - 1000.0) * kGravity * 0.2 * 0.4;
  const auto floor = mean_load(sim, "y-");
  EXPECT_NEAR(floor.normal, total, 0.005 * total);
  EXPECT_NEAR(floor.normal - floor.pore_pressure, buoyant, 0.03 * buoyant);
  std::cout << "floor: " << floor.normal << " N/m (" << total << "), effective "
            << floor.normal - floor.pore_pressure << " N/m (" << buoyant << ")\n";
}

}  // namespace
