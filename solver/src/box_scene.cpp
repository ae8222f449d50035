#include "lituya/solver/box_scene.hpp"

#include <cmath>

namespace lituya::solver {

BoundaryCondition box_condition(BoundaryType type, double friction) {
  BoundaryCondition b;
  b.type = type;
  b.friction = friction;
  return b;
}

Stage settling_stage(double duration, double kinetic_energy_ratio,
                     std::vector<std::string> boundaries) {
  Stage settle;
  settle.name = "settle";
  settle.type = StageType::kQuasiStatic;
  settle.duration = duration;
  settle.damping = 0.7;
  settle.kinetic_energy_ratio = kinetic_energy_ratio;
  settle.boundaries = std::move(boundaries);
  return settle;
}

Material paper_water() {
  Material m;
  m.name = "water";
  m.model = MaterialModel::kWater;
  m.liquid_density = 1000.0;
  m.bulk_modulus = 2.15e7;
  m.viscosity = 1.0e-3;
  return m;
}

BoxScene<2> sand_bed_under_water(double grain_diameter) {
  BoxScene<2> s;
  s.domain_size = {0.4, 0.4};
  s.cells = {10, 10};
  s.block_min = {0.0, 0.0};
  s.block_max = {0.4, 0.2};
  s.material.name = "sand";
  s.material.model = MaterialModel::kLinearElastic;
  s.material.solid_density = 2650.0;
  s.material.porosity = 0.4;
  s.material.youngs_modulus = 1.0e7;
  s.material.poisson_ratio = 0.3;
  s.material.grain_diameter = grain_diameter;
  s.gravity = {0.0, -9.81};
  s.k0 = 0.5;
  s.with_water = true;
  s.water = paper_water();
  s.water_min = {0.0, 0.0};
  s.water_max = {0.4, 0.3};
  for (const char* side : {"x-", "x+", "y-"})
    s.boundaries.push_back({side, box_condition(BoundaryType::kRoller)});
  return s;
}

BoxScene<2> still_water_tank(double depth) {
  // The sand bed's scene (its water, gravity and roller walls) without the sand.
  BoxScene<2> s = sand_bed_under_water(0.002);
  s.domain_size = {1.0, 0.6};
  s.cells = {20, 12};
  s.block_min = {2.0, 2.0};  // no soil
  s.block_max = {-1.0, -1.0};
  s.water_max = {1.0, depth};
  return s;
}

BoxScene<2> block_on_incline(double theta_deg, const BoundaryCondition& bed) {
  BoxScene<2> scene;
  scene.domain_size = {2.0, 0.5};
  scene.cells = {80, 20};
  scene.block_min = {0.2, 0.0};
  scene.block_max = {0.6, 0.1};
  scene.material.name = "block";
  scene.material.model = MaterialModel::kLinearElastic;
  scene.material.porosity = 0.5;
  scene.material.solid_density = 4000.0;
  scene.material.youngs_modulus = 5e7;
  scene.material.poisson_ratio = 0.3;
  const double theta = theta_deg * 3.14159265358979323846 / 180;
  scene.gravity = {9.81 * std::sin(theta), -9.81 * std::cos(theta)};
  BoundaryCondition glued = box_condition(BoundaryType::kFixed);
  glued.name = "glued";
  scene.boundaries = {{"y-", glued}, {"y-", bed}};
  return scene;
}

namespace {
// Points of the standard patterns in barycentric coordinates (equal volumes).
template <int dim>
std::vector<Eigen::Matrix<double, dim + 1, 1>> pattern(int points_per_cell) {
  std::vector<Eigen::Matrix<double, dim + 1, 1>> out;
  if (points_per_cell == 1) {
    out.push_back(Eigen::Matrix<double, dim + 1, 1>::Constant(1.0 / (dim + 1)));
  } else if constexpr (dim == 2) {
    // Centroids of the 4 sub-triangles of the midpoint subdivision.
    out.push_back({4.0 / 6, 1.0 / 6, 1.0 / 6});
    out.push_back({1.0 / 6, 4.0 / 6, 1.0 / 6});
    out.push_back({1.0 / 6, 1.0 / 6, 4.0 / 6});
    out.push_back({1.0 / 3, 1.0 / 3, 1.0 / 3});
  } else {
    const double a = 0.5854101966249685, b = 0.1381966011250105;
    for (int k = 0; k < 4; ++k) {
      Eigen::Vector4d l = Eigen::Vector4d::Constant(b);
      l(k) = a;
      out.push_back(l);
    }
  }
  return out;
}
}  // namespace

template <int dim>
Simulation<dim> make_box_simulation(const BoxScene<dim>& scene) {
  using Vec = Eigen::Matrix<double, dim, 1>;
  Mesh<dim> mesh = make_box_mesh<dim>(scene.domain_origin, scene.domain_size, scene.cells);
  CaseDescription description;
  description.dimension = dim;
  description.gravity = scene.gravity;
  description.materials = {scene.material};
  if (scene.with_water) description.materials.push_back(scene.water);
  description.solver = scene.solver;
  description.sponges = scene.sponges;
  std::vector<NodalConstraint<dim>> constraints;
  const double tolerance = 1e-9 * scene.domain_size.maxCoeff();
  for (const auto& [side, bc] : scene.boundaries) {
    const int axis = side[0] - 'x';
    const double at = side[1] == '-' ? scene.domain_origin(axis)
                                     : scene.domain_origin(axis) + scene.domain_size(axis);
    auto facets = boundary_facets<dim>(
        mesh, [&](const Vec& x) { return std::abs(x(axis) - at) < tolerance; });
    BoundaryCondition named = bc;
    named.group = side;
    if (named.name.empty()) named.name = side;
    description.boundaries.push_back(named);
    constraints.push_back(make_constraint<dim>(named, facets, mesh, "box scene"));
  }
  MaterialPoints<dim> points;
  LiquidPoints<dim> liquid;
  const double density = scene.material.dry_density();
  const double rho_w = scene.water.liquid_density;
  const double buoyant_density =
      scene.with_water ? density - (1.0 - scene.material.porosity) * rho_w : density;
  auto inside = [](const Vec& x, const Vec& lo, const Vec& hi) {
    return !(x.array() < lo.array()).any() && !(x.array() > hi.array()).any();
  };
  const double g = Eigen::Map<const Vec>(scene.gravity.data()).norm();
  const auto local = pattern<dim>(scene.points_per_cell);
  for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
    Vec centroid = Vec::Zero();
    for (int n : mesh.cell_nodes[c]) centroid += mesh.node_position[n];
    centroid /= dim + 1;
    const bool solid = inside(centroid, scene.block_min, scene.block_max);
    const bool wet = scene.with_water && inside(centroid, scene.water_min, scene.water_max);
    for (const auto& l : local) {
      Vec x = Vec::Zero();
      for (int i = 0; i <= dim; ++i) x += l(i) * mesh.node_position[mesh.cell_nodes[c][i]];
      const double volume = mesh.cell_volume[c] / static_cast<double>(local.size());
      if (solid) {
        const std::size_t p = points.size();
        points.resize(p + 1);
        points.position[p] = x;
        points.volume[p] = volume;
        points.mass[p] = density * volume;
        points.cell[p] = static_cast<int>(c);
        points.id[p] = static_cast<int>(p);
        if (scene.k0 >= 0) {
          const double sigma_v = -buoyant_density * g * (scene.block_max(1) - x(1));
          points.stress[p] << scene.k0 * sigma_v, sigma_v, scene.k0 * sigma_v, 0, 0, 0;
        }
      }
      if (wet) {
        const double n = solid ? scene.material.porosity : 1.0;
        const std::size_t q = liquid.size();
        liquid.resize(q + 1);
        liquid.position[q] = x;
        liquid.velocity[q] = scene.water_velocity;
        liquid.volume[q] = n * volume;
        liquid.mass[q] = rho_w * n * volume;
        liquid.pressure[q] = rho_w * g * (scene.water_max(1) - x(1));
        liquid.material[q] = 1;
        liquid.cell[q] = static_cast<int>(c);
        liquid.id[q] = static_cast<int>(q);
      }
    }
  }
  return Simulation<dim>(std::move(description), std::move(mesh), std::move(points),
                         std::move(constraints), std::move(liquid));
}

template Simulation<2> make_box_simulation<2>(const BoxScene<2>&);
template Simulation<3> make_box_simulation<3>(const BoxScene<3>&);

}  // namespace lituya::solver
