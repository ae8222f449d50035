#pragma once
// The initial liquid (water) points, in the structure-of-arrays layout of liquid_points.vtu.
// The two-layer formulation keeps water in its own point set, apart from the soil skeleton's
// solid points (MaterialPoints): free water is seeded with liquid points only, saturated soil
// with a solid and a liquid point at each seeding position.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lituya::pre {

struct LiquidPoints {
  std::vector<double> position;        // 3 per point (z = 0 in 2D)
  std::vector<double> volume;          // m3 of water, n V for a point of mixture volume V
  std::vector<double> mass;            // kg, rho_w times volume: n rho_w V, eq. (2)
  std::vector<std::int32_t> material;  // id of the water material in materials.toml
  std::vector<std::int32_t> cell;      // background cell that contains the point
  std::vector<double> pressure;        // Pa, compression positive (p_w of eqs. (7), (8))
  std::vector<double> velocity;        // 3 per point

  std::size_t size() const { return volume.size(); }
  // Appends a point at rest and at zero pressure.
  void add(const double xyz[3], double water_volume, double water_mass, std::int32_t material_id,
           std::int32_t cell_index);
};

}  // namespace lituya::pre
