#include "lituya/pre/material_points.hpp"

namespace lituya::pre {

void MaterialPoints::add(const double xyz[3], double point_volume, double point_mass,
                         std::int32_t material_id, std::int32_t cell_index) {
  position.insert(position.end(), xyz, xyz + 3);
  volume.push_back(point_volume);
  mass.push_back(point_mass);
  material.push_back(material_id);
  cell.push_back(cell_index);
  stress.insert(stress.end(), 6, 0.0);
  velocity.insert(velocity.end(), 3, 0.0);
}

}  // namespace lituya::pre
