#pragma once
// Geostatic (K0) initial stress: the vertical effective stress is the weight of the material
// above a point, the horizontal ones K0 times it. It starts the gravity stage close to
// equilibrium, so the quasi-static stage only has to settle the small remaining imbalance.
#include <cstddef>
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
std::vector<double> overburden_pressure(const Mesh& mesh, const std::vector<double>& cell_density,
                                        const MaterialPoints& points, double gravity);

// Sets sigma_yy = -overburden, sigma_xx = sigma_zz = k0 sigma_yy, shear 0 (tension positive)
// on points [begin, end).
void set_k0_stress(MaterialPoints& points, const std::vector<double>& overburden, std::size_t begin,
                   std::size_t end, double k0);

}  // namespace lituya::pre
