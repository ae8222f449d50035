#pragma once
// The initial solid points (the soil skeleton), in the structure-of-arrays layout of
// points.vtu. Water has its own point set, LiquidPoints (liquid_points.hpp).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lituya::pre {

struct MaterialPoints {
  std::vector<double> position;        // 3 per point (z = 0 in 2D)
  std::vector<double> volume;          // m3 (2D: m2 per metre of thickness)
  std::vector<double> mass;            // kg (2D: per metre)
  std::vector<std::int32_t> material;  // id in materials.toml
  std::vector<std::int32_t> cell;      // background cell that contains the point
  std::vector<double> stress;          // 6 per point: xx, yy, zz, xy, yz, xz (tension +)
  std::vector<double> velocity;        // 3 per point

  std::size_t size() const { return volume.size(); }
  // Appends a point at rest and free of stress.
  void add(const double xyz[3], double point_volume, double point_mass, std::int32_t material_id,
           std::int32_t cell_index);
};

}  // namespace lituya::pre
