#pragma once
// Small kernels of the time loop that are not transfers (those are in phase.hpp): strain and
// stress-rotation increments, point location at the start and fault messages. Internal to the
// solver library.
#include <sstream>
#include <string>

#include <Eigen/Core>

#include "lituya/common/input_error.hpp"
#include "lituya/solver/mesh.hpp"
#include "lituya/solver/mohr_coulomb.hpp"
#include "lituya/solver/phase.hpp"

namespace lituya::solver::detail {

// Strain increment (engineering shear) from the velocity gradient L = dv/dx times dt.
inline Voigt6 strain_increment(const Eigen::Matrix2d& l, double dt) {
  Voigt6 e;
  e << l(0, 0) * dt, l(1, 1) * dt, 0.0, (l(0, 1) + l(1, 0)) * dt, 0.0, 0.0;
  return e;
}
inline Voigt6 strain_increment(const Eigen::Matrix3d& l, double dt) {
  Voigt6 e;
  e << l(0, 0) * dt, l(1, 1) * dt, l(2, 2) * dt, (l(0, 1) + l(1, 0)) * dt, (l(1, 2) + l(2, 1)) * dt,
      (l(0, 2) + l(2, 0)) * dt;
  return e;
}

// Jaumann rotation of the stress: sigma += Omega sigma - sigma Omega, Omega = dt skew(L), so
// that a rigid rotation carries the stress with it (objective stress rate).
inline void rotate_stress(Voigt6& s, const Eigen::Matrix2d& l, double dt) {
  const double w = 0.5 * (l(0, 1) - l(1, 0)) * dt;
  const double sxx = s(0), syy = s(1), sxy = s(3);
  s(0) = sxx + 2 * w * sxy;
  s(1) = syy - 2 * w * sxy;
  s(3) = sxy + w * (syy - sxx);
}
inline void rotate_stress(Voigt6& s, const Eigen::Matrix3d& l, double dt) {
  const Eigen::Matrix3d omega = 0.5 * (l - l.transpose()) * dt;
  Eigen::Matrix3d sigma;
  sigma << s(0), s(3), s(5), s(3), s(1), s(4), s(5), s(4), s(2);
  const Eigen::Matrix3d rate = omega * sigma - sigma * omega;
  s(0) += rate(0, 0);
  s(1) += rate(1, 1);
  s(2) += rate(2, 2);
  s(3) += rate(0, 1);
  s(4) += rate(1, 2);
  s(5) += rate(0, 2);
}

inline std::string format_vector(const double* v, int n) {
  std::ostringstream s;
  s << "(";
  for (int i = 0; i < n; ++i) s << (i ? ", " : "") << v[i];
  s << ")";
  return s.str();
}

// Locates every point of a point set and caches its shape values: from its stored cell, else
// from the previous point's, else by a search. A point outside the mesh is an InputError
// naming `file` ("point" or "liquid point" `what`).
template <int dim, class Vec, class Shape>
void locate_all(const Mesh<dim>& mesh, const std::vector<Vec>& position, std::vector<int>& cell,
                const std::vector<int>& id, std::vector<Shape>& shape, const std::string& file,
                const std::string& what) {
  shape.resize(position.size());
  for (std::size_t p = 0; p < position.size(); ++p) {
    const int start = cell[p];
    int found = -1;
    if (start >= 0 && start < static_cast<int>(mesh.cell_count()))
      found = mesh.locate(start, position[p], shape[p]);
    if (found < 0 && p > 0) found = mesh.locate(cell[p - 1], position[p], shape[p]);
    if (found < 0) found = mesh.locate_anywhere(position[p], shape[p]);
    if (found < 0)
      throw InputError(file, 0,
                       what + " " + std::to_string(id[p]) + " at " +
                           format_vector(position[p].data(), dim) +
                           " lies outside the background mesh");
    cell[p] = found;
  }
}

// The diagnostic of a too fast point (with `remedy`, what to try) or one that left the mesh
// (a non-finite one names its own fields).
template <class Vec>
std::string describe_fault(PointFault fault, const Vec& velocity, double max_velocity,
                           const char* remedy = "reduce the Courant number") {
  std::ostringstream m;
  if (fault == PointFault::kTooFast)
    m << "speed " << velocity.norm() << " m/s exceeds [solver] max_velocity = " << max_velocity
      << " m/s; the run is probably unstable (" << remedy << ")";
  else
    m << "left the background mesh (velocity "
      << format_vector(velocity.data(), static_cast<int>(velocity.size()))
      << " m/s); extend the mesh or close the boundary it crossed";
  return m.str();
}

// Artificial bulk viscosity of the water, zeta = beta rho_w c_w h (Pa s; scientific manual
// 10.5): the linear artificial viscosity of shock-capturing codes, scaled so that the damping
// rate of a sound wave one cell long is a fixed fraction beta of its frequency.
inline double liquid_bulk_viscosity(double beta, double density, double wave_speed, double h) {
  return beta * density * wave_speed * h;
}

// Signal speed that sets a liquid point's stable step h / speed: sound plus the flow, plus the
// diffusive limit 2 (mu + zeta) / (rho h) of the shear and bulk viscosities.
inline double liquid_signal_speed(double beta, double density, double wave_speed, double viscosity,
                                  double speed, double h) {
  return wave_speed + speed +
         2.0 * (viscosity + liquid_bulk_viscosity(beta, density, wave_speed, h)) / (density * h);
}

// Eq. (7), rho_w = rho_w0 (1 + p / K_w): the volume of a water point of `mass` at pressure p.
inline double water_volume(double mass, double density, double pressure, double bulk_modulus) {
  return mass / (density * (1.0 + pressure / bulk_modulus));
}

}  // namespace lituya::solver::detail
