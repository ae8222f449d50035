#pragma once
// A scene built in code instead of from gmsh files: a structured box mesh, a block of
// material points and boundary conditions on the box sides. Used by unit tests and the
// benchmark, where the physics must be checked (or timed) without the preprocessor.
#include <string>
#include <vector>

#include "lituya/solver/simulation.hpp"

namespace lituya::solver {

template <int dim>
struct BoxScene {
  using Vec = Eigen::Matrix<double, dim, 1>;
  Vec domain_origin = Vec::Zero();
  Vec domain_size = Vec::Ones();
  std::array<int, dim> cells{};
  Vec block_min = Vec::Zero();  // cells whose centroid lies in [block_min, block_max] get points
  Vec block_max = Vec::Ones();
  int points_per_cell = 4;  // 1 or 4 (2D: sub-triangle centroids; 3D: Gauss points)
  Material material;
  std::vector<double> gravity;  // dim components
  // Boundary conditions on box sides: side is "x-", "x+", "y-", "y+", "z-" or "z+"; the
  // condition's `group` is set to the side name.
  std::vector<std::pair<std::string, BoundaryCondition>> boundaries;
  SolverSettings solver;
  // Vertical (y) geostatic stress sigma_yy = -rho g (y_top - y), sigma_xx = sigma_zz = k0
  // sigma_yy when k0 >= 0 (g = |gravity|, y_top = block_max.y); zero stress when k0 < 0.
  double k0 = -1;
  // Water (optional, model kWater): liquid points in the cells whose centroid lies in
  // [water_min, water_max] (free water outside the solid block, pore water inside it, mass
  // n rho_w V there), with hydrostatic pressure rho_w g (water_max.y - y). With water, the
  // k0 stress above is the buoyant (effective) one, (rho_dry - (1 - n) rho_w) g depth.
  bool with_water = false;
  Material water;
  Vec water_min = Vec::Zero();
  Vec water_max = Vec::Zero();
  Vec water_velocity = Vec::Zero();  // initial velocity of every liquid point
  std::vector<Sponge> sponges;       // absorbing zones for the water (damping_rate given)
};

template <int dim>
Simulation<dim> make_box_simulation(const BoxScene<dim>& scene);

// A boundary condition of `type` for a box side (Coulomb `friction` for kContact).
BoundaryCondition box_condition(BoundaryType type, double friction = 0);

// Water as in the paper's cases: rho_w = 1000 kg/m3, K_w = 2.15e7 Pa, mu = 1e-3 Pa s.
Material paper_water();

// A saturated sand bed 0.2 m thick under 0.1 m of still water in a 2D box 0.4 m wide and high
// (10 x 10 cells), with hydrostatic pore pressure and buoyant K0 = 0.5 stress; roller walls
// and bottom (sides "x-", "x+", "y-"). Sand: linear elastic, rho_s = 2650 kg/m3, n = 0.4,
// E = 10 MPa, nu = 0.3, D_p = `grain_diameter`; water: paper_water().
BoxScene<2> sand_bed_under_water(double grain_diameter);

// Still water `depth` deep in a 2D tank 1 m wide and 0.6 m high (20 x 12 cells), roller walls
// and floor (sides "x-", "x+", "y-"), hydrostatic pressure; no soil (the material is the sand
// of sand_bed_under_water, with no points).
BoxScene<2> still_water_tank(double depth);

// An elastic block 0.4 m x 0.1 m (dry density 2000 kg/m3, n = 0.5, E = 50 MPa, nu = 0.3)
// on the floor of a 2 m x 0.5 m box (80 x 20 cells), gravity tilted by theta (an incline
// descending towards +x). Two conditions on the floor ("y-"): "glued" (fixed), for a settling
// stage, and `bed`, which must be named.
BoxScene<2> block_on_incline(double theta_deg, const BoundaryCondition& bed);

// A quasi-static stage named "settle" with heavy local damping (0.7) that ends when the
// kinetic energy falls to `kinetic_energy_ratio` of its peak, with `boundaries` active: brings
// a scene to equilibrium stresses before a release.
Stage settling_stage(double duration, double kinetic_energy_ratio,
                     std::vector<std::string> boundaries);

// Mass-weighted mean of velocity component `d` of a point set (its momentum over its mass).
template <class Points>
double mean_velocity(const Points& points, int d) {
  double momentum = 0, mass = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    momentum += points.mass[i] * points.velocity[i](d);
    mass += points.mass[i];
  }
  return momentum / mass;
}

// Boundary facets (faces with no neighbour) whose nodes all satisfy `on_side`.
template <int dim, class Predicate>
std::vector<std::array<int, dim>> boundary_facets(const Mesh<dim>& mesh, Predicate on_side) {
  std::vector<std::array<int, dim>> facets;
  for (std::size_t c = 0; c < mesh.cell_count(); ++c)
    for (int i = 0; i <= dim; ++i) {
      if (mesh.cell_neighbour[c][i] >= 0) continue;
      std::array<int, dim> f;
      bool all = true;
      for (int k = 0, j = 0; k <= dim; ++k)
        if (k != i) {
          f[j++] = mesh.cell_nodes[c][k];
          all = all && on_side(mesh.node_position[mesh.cell_nodes[c][k]]);
        }
      if (all) facets.push_back(f);
    }
  return facets;
}

extern template Simulation<2> make_box_simulation<2>(const BoxScene<2>&);
extern template Simulation<3> make_box_simulation<3>(const BoxScene<3>&);

}  // namespace lituya::solver
