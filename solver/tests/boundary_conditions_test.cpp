// Nodal velocity conditions built from a group's facets: a roller group that turns a corner
// (a tank's bottom and side walls in one group) must hold the corner node in every wall's
// normal direction, not only along the averaged normal.
#include "lituya/solver/boundary_conditions.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "lituya/solver/box_scene.hpp"
#include "lituya/solver/phase.hpp"
#include "lituya/solver/simulation.hpp"

namespace {

using namespace lituya::solver;

// The boundary facets of a unit box mesh that lie on one of the planes x_d = 0, d in `planes`.
template <int dim>
std::vector<std::array<int, dim>> facets_on_planes(const Mesh<dim>& mesh,
                                                   const std::vector<int>& planes) {
  std::vector<std::array<int, dim>> facets;
  for (std::size_t c = 0; c < mesh.cell_count(); ++c)
    for (int skip = 0; skip <= dim; ++skip) {
      std::array<int, dim> f;
      for (int k = 0, j = 0; k <= dim; ++k)
        if (k != skip) f[j++] = mesh.cell_nodes[c][k];
      for (int d : planes) {
        bool on = true;
        for (int n : f) on = on && std::abs(mesh.node_position[n](d)) < 1e-12;
        if (on) facets.push_back(f);
      }
    }
  return facets;
}

template <int dim>
Simulation<dim> unit_box() {
  BoxScene<dim> scene;
  scene.domain_size = Eigen::Matrix<double, dim, 1>::Constant(1.0);
  scene.cells.fill(4);
  scene.block_min = Eigen::Matrix<double, dim, 1>::Constant(0.25);
  scene.block_max = Eigen::Matrix<double, dim, 1>::Constant(0.75);
  scene.material.name = "elastic";
  scene.material.model = MaterialModel::kLinearElastic;
  scene.material.porosity = 0.4;
  scene.material.solid_density = 2500;
  scene.material.youngs_modulus = 1e6;
  scene.material.poisson_ratio = 0.3;
  scene.gravity.assign(dim, 0.0);
  return make_box_simulation<dim>(scene);
}

// Apply a roller on the planes x_d = 0 (d in `planes`, one group) to random nodal velocities
// and check every node of the group: the velocity component normal to each plane the node lies
// on is zero, and the components along the planes are untouched.
template <int dim>
void check_roller_corner(const std::vector<int>& planes) {
  auto sim = unit_box<dim>();
  const auto& mesh = sim.mesh();
  BoundaryCondition roller;
  roller.name = "walls";
  roller.group = "walls";
  roller.type = BoundaryType::kRoller;
  const NodalConstraint<dim> constraint =
      make_constraint<dim>(roller, facets_on_planes<dim>(mesh, planes), mesh, "test");
  std::vector<Eigen::Matrix<double, dim, 1>> velocity(mesh.node_count());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (auto& v : velocity)
    for (int d = 0; d < dim; ++d) v(d) = uniform(random);
  const auto before = velocity;
  apply_constraints<dim>({&constraint}, velocity, nullptr, false);
  int corner_nodes = 0;
  for (int n : constraint.nodes)
    for (int d = 0; d < dim; ++d) {
      const bool on_plane = std::find(planes.begin(), planes.end(), d) != planes.end() &&
                            std::abs(mesh.node_position[n](d)) < 1e-12;
      if (on_plane)
        EXPECT_EQ(velocity[n](d), 0.0) << "node " << n << " component " << d;
      else
        EXPECT_NEAR(velocity[n](d), before[n](d), 1e-15) << "node " << n << " component " << d;
      corner_nodes += d == 0 && std::abs(mesh.node_position[n](planes[0])) < 1e-12 &&
                      std::abs(mesh.node_position[n](planes[1])) < 1e-12;
    }
  EXPECT_GT(corner_nodes, 0);  // the group does turn a corner
}

TEST(BoundaryConditions, RollerGroupHoldsATankCornerIn2D) {
  check_roller_corner<2>({0, 1});
}

// 3D: the edge where two walls meet keeps only the motion along the edge; where three meet,
// none.
TEST(BoundaryConditions, RollerGroupHoldsABoxEdgeIn3D) {
  check_roller_corner<3>({0, 1});
}
TEST(BoundaryConditions, RollerGroupHoldsABoxVertexIn3D) {
  check_roller_corner<3>({0, 1, 2});
}

// A Coulomb contact on a saturated soil (two-phase cases): the wall gives back the grains'
// share of the pore pressure without friction; the rest of the grains' approach is the
// skeleton's own. Bed y = 0 (outward normal -y), mu = 0.5, velocities in m/s after the step's
// forces, the pore-pressure push 0.1 m/s into the wall. Every expected value is exact.
TEST(BoundaryConditions, SaturatedContactTakesFrictionFromTheSkeletonAndLetsItLiftOff) {
  using Vec = Eigen::Vector2d;
  NodalConstraint<2> bed;
  bed.type = BoundaryType::kContact;
  bed.friction = 0.5;
  bed.nodes = {0, 1, 2, 3};
  bed.normal.assign(4, Vec(0.0, -1.0));
  std::vector<Vec> velocity = {Vec(1.0, -0.3), Vec(1.0, -0.05), Vec(0.05, -0.3), Vec(1.0, 0.2)};
  const std::vector<Vec> push(4, Vec(0.0, -0.1));
  apply_constraints<2>({&bed}, velocity, &push);
  // Pressed: the skeleton approaches at 0.3 - 0.1 = 0.2, the slip loses mu 0.2 = 0.1.
  EXPECT_DOUBLE_EQ(velocity[0](0), 0.9);
  EXPECT_EQ(velocity[0](1), 0.0);
  // The grains approach at 0.05, less than the pore pressure's 0.1: the skeleton pulls away
  // (no tension at the wall), so no friction, and the node leaves the wall at 0.05.
  EXPECT_EQ(velocity[1](0), 1.0);
  EXPECT_DOUBLE_EQ(velocity[1](1), 0.05);
  // Sticks: mu 0.2 = 0.1 is more than the slip of 0.05.
  EXPECT_EQ(velocity[2], Vec::Zero());
  // Already leaving the wall: the pore pressure's reaction still pushes it off.
  EXPECT_EQ(velocity[3](0), 1.0);
  EXPECT_DOUBLE_EQ(velocity[3](1), 0.3);
  // A dry soil (no push): the friction acts on the whole approach, and a leaving node is free.
  std::vector<Vec> dry = {Vec(1.0, -0.3), Vec(1.0, 0.2)};
  bed.nodes = {0, 1};
  bed.normal.resize(2);
  apply_constraints<2>({&bed}, dry);
  EXPECT_DOUBLE_EQ(dry[0](0), 0.85);
  EXPECT_EQ(dry[0](1), 0.0);
  EXPECT_EQ(dry[1], Vec(1.0, 0.2));
}

// The toe of Case B's slope: a contact slope at 45 degrees (outward normal (-1, -1)/sqrt 2)
// meets a roller bed (outward normal (0, -1)) at node 0, an obtuse corner of the water. The
// node's velocity after the walls must be the admissible velocity nearest to its own (the
// walls' reaction): zero bed-normal velocity and no motion into the slope. Laws applied one
// after the other turned a velocity into the corner, (-1, -2), into (0.5, 0): along the bed,
// away from the slope, an impulse no wall gives (issue 8; it threw Case B's toe node along
// the bed at thousands of m/s). Each expected value follows from the geometry by hand.
TEST(BoundaryConditions, ANodeAtAnObtuseCornerTakesTheNearestAdmissibleVelocity) {
  using Vec = Eigen::Vector2d;
  const double r = std::sqrt(0.5);
  NodalConstraint<2> slope, bed;
  slope.type = BoundaryType::kContact;
  slope.nodes = {0};
  slope.normal = {Vec(-r, -r)};
  bed.type = BoundaryType::kRoller;
  bed.nodes = {0};
  bed.normal = {Vec(0.0, -1.0)};
  const auto after = [&](const Vec& v, bool slope_first, double friction = 0.0) {
    slope.friction = friction;
    std::vector<Vec> velocity = {v};
    if (slope_first)
      apply_constraints<2>({&slope, &bed}, velocity, nullptr, friction > 0);
    else
      apply_constraints<2>({&bed, &slope}, velocity, nullptr, friction > 0);
    return velocity[0];
  };
  for (bool slope_first : {true, false}) {
    // Into both walls: held.
    EXPECT_LT(after(Vec(-1.0, -2.0), slope_first).norm(), 1e-15);
    // Along the bed into the slope: held.
    EXPECT_LT(after(Vec(-1.0, 0.0), slope_first).norm(), 1e-15);
    // Along the bed away from the slope, into the bed: the bed takes the normal part only.
    EXPECT_NEAR((after(Vec(2.0, -1.0), slope_first) - Vec(2.0, 0.0)).norm(), 0.0, 1e-15);
    // Up and away from both: free of the slope, the bed still holds its normal.
    EXPECT_NEAR((after(Vec(1.0, 3.0), slope_first) - Vec(1.0, 0.0)).norm(), 0.0, 1e-15);
    // Up the slope and into it, (-2, 1): the bed removes the 1, then (-2, 0) goes into the
    // slope, so held; the nearest admissible point of the line v_y = 0 with v_x >= 0 is 0.
    EXPECT_LT(after(Vec(-2.0, 1.0), slope_first).norm(), 1e-15);
    // Friction cannot make a held node move, nor a free one slower along the bed.
    EXPECT_LT(after(Vec(-1.0, -2.0), slope_first, 0.5).norm(), 1e-15);
    EXPECT_NEAR((after(Vec(2.0, -1.0), slope_first, 0.5) - Vec(2.0, 0.0)).norm(), 0.0, 1e-15);
  }
  // Two contact walls at 135 degrees in 2D with friction: a velocity into the slope only
  // slides along it, slowed by mu times its normal part (the one-wall law).
  NodalConstraint<2> contact_bed = bed;
  contact_bed.type = BoundaryType::kContact;
  contact_bed.friction = 0.5;
  slope.friction = 0.5;
  std::vector<Vec> velocity = {Vec(-1.0, 0.5)};  // normal part into the slope 0.25 sqrt 2
  apply_constraints<2>({&slope, &contact_bed}, velocity);
  const Vec along = Vec(-r, r);  // up the slope
  const double slip = Vec(-1.0, 0.5).dot(along), normal = Vec(-1.0, 0.5).dot(Vec(-r, -r));
  EXPECT_NEAR((velocity[0] - (slip - 0.5 * normal) * along).norm(), 0.0, 1e-15);
}

// What a node's conditions hold, for the grains' velocity at walls (phase.hpp,
// nodes_to_points): a roller or a contact wall holds its normal, a node on both (a corner)
// the span of both normals (here every component), a node of no condition nothing. A phase
// whose points keep FLIP's increment at walls (the water) marks its held nodes but builds no
// projectors.
TEST(HeldComponents, WallsHoldTheirNormalsAndCornersTheirSpan) {
  using Vec = Eigen::Vector2d;
  detail::Phase<2, MaterialPoints<2>, detail::PhaseSums<2>> phase;
  phase.wall_velocity_to_points = true;
  phase.allocate_nodes(1, 3);
  NodalConstraint<2> bed, wall;
  bed.type = BoundaryType::kContact;
  bed.nodes = {1, 2};
  bed.normal = {Vec(0, -1), Vec(0, -1)};
  wall.type = BoundaryType::kRoller;
  wall.nodes = {2};
  wall.normal = {Vec(1, 0)};
  phase.constraints = {&bed, &wall};
  phase.hold_nodes();
  EXPECT_FALSE(phase.is_held(0));
  ASSERT_TRUE(phase.is_held(1) && phase.is_held(2));
  const Eigen::Matrix2d normal_only = Vec(0, 1) * Vec(0, 1).transpose();
  EXPECT_LT((phase.held_components(1) - normal_only).norm(), 1e-12);
  EXPECT_LT((phase.held_components(2) - Eigen::Matrix2d::Identity()).norm(), 1e-12);

  phase.wall_velocity_to_points = false;
  phase.hold_nodes();
  EXPECT_TRUE(phase.is_held(1) && phase.is_held(2));
  EXPECT_TRUE(phase.held.empty());
}

}  // namespace
