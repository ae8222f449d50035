#pragma once
// Geostatic (K0) initial stress: the vertical effective stress is the weight of the material
// above a point less the pore pressure there, the horizontal ones K0 times it; the water
// pressure is the weight of the water above. It starts the gravity stage close to equilibrium,
// so the quasi-static stage only has to settle the small remaining imbalance.
#include <cstddef>
#include <span>
#include <vector>

#include "lituya/pre/material_points.hpp"
#include "lituya/pre/mesh.hpp"

namespace lituya::pre {

// Weight per unit horizontal area (Pa, positive) of the material above each point, gravity
// along -y with magnitude `gravity`: g times the integral of the dry density along the
// vertical line from the point upwards,
//     p(x, y) = g * integral_y^inf rho(x, y') dy',
// where rho is `cell_density` in each background cell (0 for cells outside every region).
// The material points stand for exactly these cells, so this is the weight of the points
// above, the point's own cell counted from its height up (the continuum form of "the mass
// above plus half the point's own"). Unlike summing point masses in columns of finite width,
// it carries no sampling noise, holds at free faces and skips gaps (air between materials).
// `position` holds 3 coordinates per point.
std::vector<double> overburden_pressure(const Mesh& mesh, const std::vector<double>& cell_density,
                                        std::span<const double> position, double gravity);
// The same at solid points.
std::vector<double> overburden_pressure(const Mesh& mesh, const std::vector<double>& cell_density,
                                        const MaterialPoints& points, double gravity);

// Sets sigma'_yy = -vertical_effective, sigma'_xx = sigma'_zz = k0 sigma'_yy, shear 0 (effective
// stress, tension positive) on points [begin, end). vertical_effective is the overburden less
// the pore pressure (Terzaghi's principle, the total stress of eq. (14) split into sigma' and
// the water pressure); for dry soil the overburden itself.
void set_k0_stress(MaterialPoints& points, const std::vector<double>& vertical_effective,
                   std::size_t begin, std::size_t end, double k0);

}  // namespace lituya::pre
