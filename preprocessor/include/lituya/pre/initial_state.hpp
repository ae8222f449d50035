#pragma once
// The points a case starts from: every region seeded with solid and/or liquid points, with
// the initial effective stress of the solid points and the initial pressure of the water.
#include <cstddef>
#include <vector>

#include "lituya/pre/liquid_points.hpp"
#include "lituya/pre/material_points.hpp"
#include "lituya/pre/mesh.hpp"
#include "lituya/pre/scene.hpp"

namespace lituya::pre {

struct InitialState {
  MaterialPoints solid;  // soil skeleton: dry and saturated soil regions
  LiquidPoints liquid;   // water: free-water regions and the pores of saturated soil
};

// Densities per background cell (kg/m3, 0 where no region puts material) that the overburden
// integrals of initial_stress.hpp weigh:
//   total: the mixture, (1 - n0) rho_s for dry soil, (1 - n0) rho_s + n0 rho_w for saturated
//          soil (eqs. (1), (2)), rho_w for free water;
//   water: rho_w in every cell that holds water (free water and saturated soil), so that its
//          overburden is the hydrostatic pressure under a connected water column.
struct CellDensities {
  std::vector<double> total, water;
};
CellDensities cell_densities(const Scene& scene, const Mesh& mesh);

// Seeds the regions (region by region, so each region's points form one contiguous range of
// each set) and sets the initial state, with gravity along -y of magnitude |g_y|:
//   free water, "hydrostatic": p = weight of the water above (CellDensities::water);
//   soil, "k0": vertical effective stress = total overburden - p, horizontal k0 times it; in
//          saturated soil the pore water gets that p, in dry soil p = 0 (the skeleton carries
//          everything above it, water included);
//   "zero": stress-free skeleton and p = 0 (the quasi-static stage settles them).
// The overburdens count every region, also those that start at zero.
InitialState make_initial_state(const Scene& scene, const Mesh& mesh);

}  // namespace lituya::pre
