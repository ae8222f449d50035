#include "lituya/pre/initial_state.hpp"

#include "lituya/pre/initial_stress.hpp"
#include "lituya/pre/seeding.hpp"

namespace lituya::pre {

namespace {

const std::vector<std::size_t>& region_cells(const Mesh& mesh, const Region& region) {
  return mesh.group_cells[*mesh.find_group(region.group, mesh.dimension)];
}

// Vertical effective stress magnitude at every solid point: the total overburden less the pore
// pressure (Terzaghi; eq. (14) with sigma_w = -p I). The solid points of saturated soil
// coincide with its liquid points, so the same water integral at the same positions gives
// them the same p. Dry soil has no pore pressure: its skeleton carries everything above,
// water included, and for a dry scene this is the dry overburden exactly.
std::vector<double> vertical_effective_stress(const Scene& scene, const Mesh& mesh,
                                              const CellDensities& density,
                                              const MaterialPoints& solid,
                                              const std::vector<std::size_t>& solid_begin,
                                              double g) {
  std::vector<double> effective = overburden_pressure(mesh, density.total, solid, g);
  std::vector<double> pore_pressure;
  for (std::size_t r = 0; r < scene.regions.size(); ++r) {
    if (!scene.regions[r].pore_water) continue;
    if (pore_pressure.empty()) pore_pressure = overburden_pressure(mesh, density.water, solid, g);
    for (std::size_t p = solid_begin[r]; p < solid_begin[r + 1]; ++p)
      effective[p] -= pore_pressure[p];
  }
  return effective;
}

}  // namespace

CellDensities cell_densities(const Scene& scene, const Mesh& mesh) {
  CellDensities density{std::vector<double>(mesh.cell_count(), 0.0),
                        std::vector<double>(mesh.cell_count(), 0.0)};
  for (const Region& region : scene.regions) {
    const solver::Material& material = scene.materials[region.material];
    const solver::Material* water = scene.water_of(region);
    // Apparent densities of eqs. (1) and (2): the skeleton's (1 - n0) rho_s, the water's
    // n rho_w with n = n0 in the pores and n = 1 in free water.
    double total = 0, water_density = 0;
    if (scene.is_free_water(region)) {
      total = water_density = water->liquid_density;
    } else {
      total = material.dry_density();
      if (water) {
        water_density = water->liquid_density;
        total += material.porosity * water->liquid_density;
      }
    }
    for (std::size_t cell : region_cells(mesh, region)) {
      density.total[cell] = total;
      density.water[cell] = water_density;
    }
  }
  return density;
}

InitialState make_initial_state(const Scene& scene, const Mesh& mesh) {
  InitialState state;
  const std::size_t regions = scene.regions.size();
  std::vector<std::size_t> solid_begin(regions + 1), liquid_begin(regions + 1);
  for (std::size_t r = 0; r < regions; ++r) {
    const Region& region = scene.regions[r];
    const solver::Material& material = scene.materials[region.material];
    const auto& cells = region_cells(mesh, region);
    solid_begin[r] = state.solid.size();
    liquid_begin[r] = state.liquid.size();
    if (scene.is_free_water(region)) {
      seed_liquid_cells(mesh, cells, scene.points_per_cell, 1.0, material.liquid_density,
                        static_cast<std::int32_t>(region.material), state.liquid);
      continue;
    }
    seed_cells(mesh, cells, scene.points_per_cell, material.dry_density(),
               static_cast<std::int32_t>(region.material), state.solid);
    if (region.pore_water)
      seed_liquid_cells(mesh, cells, scene.points_per_cell, material.porosity,
                        scene.materials[*region.pore_water].liquid_density,
                        static_cast<std::int32_t>(*region.pore_water), state.liquid);
  }
  solid_begin[regions] = state.solid.size();
  liquid_begin[regions] = state.liquid.size();

  bool any_initial_state = false;
  for (const Region& region : scene.regions)
    any_initial_state = any_initial_state || region.initial_stress != InitialStress::kZero;
  if (!any_initial_state) return state;

  // The integrals along -y; read_scene allows k0 and hydrostatic only for gravity along -y.
  const double g = -scene.gravity[1];
  const CellDensities density = cell_densities(scene, mesh);
  const std::vector<double> liquid_pressure =
      overburden_pressure(mesh, density.water, state.liquid.position, g);
  std::vector<double> vertical_effective;  // at the solid points, computed when needed
  for (std::size_t r = 0; r < regions; ++r) {
    const Region& region = scene.regions[r];
    if (region.initial_stress == InitialStress::kZero) continue;
    // Liquid points: hydrostatic free water, and the pore water of saturated k0 soil.
    // The water at pressure p is compressed: the solver reads a point's volume from its mass as
    // m / (rho_w (1 + p / K_w)) (the state law behind eq. (8)), so a point seeded to fill its
    // volume V at pressure p holds m = rho_w (1 + p / K_w) V. With m = rho_w V the column
    // would shrink by p / K_w at the first step and ring (7e-5 of the depth at the bottom of
    // a 0.15 m tank with the paper's K_w, 0.7 % with K_w reduced to 2.15e5 Pa).
    for (std::size_t p = liquid_begin[r]; p < liquid_begin[r + 1]; ++p) {
      state.liquid.pressure[p] = liquid_pressure[p];
      const solver::Material& water = scene.materials[state.liquid.material[p]];
      state.liquid.mass[p] *= 1.0 + liquid_pressure[p] / water.bulk_modulus;
    }
    if (region.initial_stress != InitialStress::kK0) continue;
    if (vertical_effective.empty())
      vertical_effective =
          vertical_effective_stress(scene, mesh, density, state.solid, solid_begin, g);
    set_k0_stress(state.solid, vertical_effective, solid_begin[r], solid_begin[r + 1], region.k0);
  }
  return state;
}

}  // namespace lituya::pre
