#include "lituya/pre/liquid_points.hpp"

namespace lituya::pre {

void LiquidPoints::add(const double xyz[3], double water_volume, double water_mass,
                       std::int32_t material_id, std::int32_t cell_index) {
  position.insert(position.end(), xyz, xyz + 3);
  volume.push_back(water_volume);
  mass.push_back(water_mass);
  material.push_back(material_id);
  cell.push_back(cell_index);
  pressure.push_back(0.0);
  velocity.insert(velocity.end(), 3, 0.0);
}

}  // namespace lituya::pre
