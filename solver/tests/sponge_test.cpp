// The sponge (absorbing) zone of the water (case_description.hpp, two_phase.cpp): water moving
// inside it comes to rest at the rate sigma the zone sets, and water outside it is untouched.
// The wave a tank sends through it is verification/sponge.
#include <gtest/gtest.h>

#include <cmath>

#include "lituya/solver/box_scene.hpp"
#include "lituya/solver/simulation.hpp"

namespace {

using namespace lituya::solver;

// A 1 m x 0.6 m box, no gravity, no walls, with a block of water moving at `speed` along x:
// no pressure builds up (the flow is uniform, div v = 0), so the only force is the sponge's.
BoxScene<2> moving_water(double speed, std::vector<Sponge> sponges) {
  BoxScene<2> s;
  s.domain_size = {1.0, 0.6};
  s.cells = {20, 12};
  s.block_min = {2.0, 2.0};  // no soil
  s.block_max = {-1.0, -1.0};
  s.material.name = "sand";
  s.material.model = MaterialModel::kLinearElastic;
  s.material.solid_density = 2650.0;
  s.material.porosity = 0.4;
  s.material.youngs_modulus = 1e7;
  s.material.poisson_ratio = 0.3;
  s.material.grain_diameter = 0.002;
  s.gravity = {0.0, 0.0};
  s.with_water = true;
  s.water = paper_water();
  s.water_min = {0.1, 0.1};
  s.water_max = {0.9, 0.5};
  s.water_velocity = {speed, 0.0};
  s.sponges = std::move(sponges);
  return s;
}

TEST(Sponge, RateRisesQuadraticallyFromTheZoneStartEitherWay) {
  // sigma = sigma_max ((x - x_start) / (x_end - x_start))^2 inside, 0 before, sigma_max beyond.
  const Sponge right{2.0, 3.0, 10.0};
  EXPECT_EQ(right.rate_at(1.0), 0.0);
  EXPECT_EQ(right.rate_at(2.0), 0.0);
  EXPECT_DOUBLE_EQ(right.rate_at(2.5), 2.5);
  EXPECT_DOUBLE_EQ(right.rate_at(3.0), 10.0);
  EXPECT_DOUBLE_EQ(right.rate_at(4.0), 10.0);
  const Sponge left{-2.0, -3.0, 10.0};  // a sponge at the -x end
  EXPECT_EQ(left.rate_at(0.0), 0.0);
  EXPECT_DOUBLE_EQ(left.rate_at(-2.5), 2.5);
  EXPECT_DOUBLE_EQ(left.rate_at(-3.5), 10.0);
}

TEST(Sponge, UniformWaterInTheZoneDecaysAtTheRateSigma) {
  // The whole box lies beyond x_end (sigma = sigma_max = 20 /s everywhere). Reference: the
  // backward-Euler relaxation the nodal update takes, v_N = v0 / (1 + sigma dt)^N; FLIP and
  // PIC agree for a uniform flow, so every point follows it to rounding (tolerance 1e-12
  // relative). It also matches the continuous decay exp(-sigma t) to O(sigma dt) = 4e-4.
  const double v0 = 0.2, sigma = 20.0, dt = 2e-5;
  const int steps = 1000;  // t = 0.02 s: the speed falls by a third
  Simulation<2> sim = make_box_simulation<2>(moving_water(v0, {Sponge{-2.0, -1.0, sigma}}));
  for (int n = 0; n < steps; ++n) sim.step(dt, 0.0);
  const double expected = v0 / std::pow(1.0 + sigma * dt, steps);
  ASSERT_GT(sim.liquid().size(), 100u);
  for (std::size_t q = 0; q < sim.liquid().size(); ++q) {
    ASSERT_NEAR(sim.liquid().velocity[q](0) / expected, 1.0, 1e-12) << "liquid point " << q;
    ASSERT_NEAR(sim.liquid().velocity[q](1), 0.0, 1e-12 * v0);
  }
  EXPECT_NEAR(expected / (v0 * std::exp(-sigma * steps * dt)), 1.0, 0.5 * sigma * dt * 1.01);
  // Without a sponge the same water keeps its speed: the decay above is the sponge's.
  Simulation<2> free = make_box_simulation<2>(moving_water(v0, {}));
  for (int n = 0; n < steps; ++n) free.step(dt, 0.0);
  EXPECT_NEAR(mean_velocity(free.liquid(), 0), v0, 1e-12);
}

TEST(Sponge, WaterOutsideTheZoneIsUntouched) {
  // A zone from x = 0.6 to 1 (sigma_max 50 /s). One step reads the nodes of a point's own
  // cell, and sigma is exactly 0 at every node with x <= 0.6. The box mesh's alternating
  // diagonals make it a crossed mesh, and the crossed pressure filter mixes the pressures of a
  // quadrangle's four cells (one cell further each way), so points left of x = 0.5 (cells whose
  // quadrangles reach no node beyond x = 0.6, with 0.05 m cells) must match a run without a
  // sponge bit for bit, and points in the zone's deep part (x > 0.7) must be slower.
  const double v0 = 0.2, dt = 2e-5;
  Simulation<2> damped = make_box_simulation<2>(moving_water(v0, {Sponge{0.6, 1.0, 50.0}}));
  Simulation<2> free = make_box_simulation<2>(moving_water(v0, {}));
  damped.step(dt, 0.0);
  free.step(dt, 0.0);
  ASSERT_EQ(damped.liquid().size(), free.liquid().size());
  int outside = 0, inside = 0;
  for (std::size_t q = 0; q < free.liquid().size(); ++q) {
    const double x = free.liquid().position[q](0);
    if (x < 0.5) {
      ++outside;
      EXPECT_EQ(damped.liquid().velocity[q], free.liquid().velocity[q]) << "point " << q;
      EXPECT_EQ(damped.liquid().position[q], free.liquid().position[q]) << "point " << q;
      EXPECT_EQ(damped.liquid().pressure[q], free.liquid().pressure[q]) << "point " << q;
    } else if (x > 0.7) {
      ++inside;
      EXPECT_LT(damped.liquid().velocity[q](0), free.liquid().velocity[q](0)) << "point " << q;
    }
  }
  EXPECT_GT(outside, 100);
  EXPECT_GT(inside, 50);
}

}  // namespace
