#pragma once
// The seepage column's reference (verification/seepage/README.md): a pond of depth d over a sand
// column L high, whose water drains through a plate into an empty chamber, resisted by the drag
// of eqs. (23), (24) (Ergun's law). Two readings of it:
// - steady: the flux through the sand at rest for the head of the moment, the pond falling as
//   dd/dt = -q(d) (the reference until December 2026);
// - transient: the same drag with the column's storage. The water's compression (n / K_w, the
//   scene's reduced K_w) and the skeleton's (1 / M) store water while the pore pressure is
//   high. At the start the column's pore water is hydrostatic; once the plate lets it out, the
//   pressure falls towards the steady profile, and the water that expands on the way leaves
//   through both ends. What leaves through the top is water the pond does not lose.
#include <vector>

namespace lituya::verify {

struct SeepageColumn {
  double length = 0.3;           // m, the sand's height
  double porosity = 0.4;         // n
  double grain_diameter = 1e-3;  // m, D_p
  double viscosity = 1e-3;       // Pa s, mu_w
  double density = 1000;         // kg/m3, rho_w
  double gravity = 9.81;         // m/s2
  double bulk_modulus = 2.15e5;  // Pa, the water's K_w
  // Pa, the skeleton's constrained modulus M (constrained_modulus_of); 0: rigid.
  double constrained_modulus = 0;
  bool forchheimer = true;  // false: Darcy's term of eq. (23) alone

  // Darcy flux q = n v (m/s, positive downwards) for a driving gradient G = dp/dz + rho_w g
  // (Pa/m, z upwards; zero in hydrostatic water): n G = a v + b v |v|, with eq. (24)'s
  // kappa = n^3 D_p^2 / (150 (1 - n)^2), a = n^2 mu / kappa and
  // b = 1.75 n^1.5 rho_w / sqrt(150 kappa).
  double flux(double drive) const;
  double darcy_coefficient() const;        // a, Pa s/m2
  double forchheimer_coefficient() const;  // b, kg/m4 (0 without Forchheimer's term)
  // The steady flux under a pond of depth d: G = rho_w g (L + d) / L.
  double steady_flux(double depth) const;
  // The pond's depth at each of `times` (ascending, s) from d0 with the steady flux: one RK4
  // integration, equal steps of at most 1e-4 s between two times.
  std::vector<double> steady_depth(double d0, const std::vector<double>& times) const;

  // One-dimensional (oedometric) stiffness of a linear-elastic skeleton,
  // M = E (1 - nu) / ((1 + nu)(1 - 2 nu)).
  static double constrained_modulus_of(double youngs_modulus, double poisson_ratio);

  // Water stored per unit volume of the column and per pascal of pore pressure,
  // n / K_w + 1 / M (0 for a rigid skeleton and incompressible water).
  double storage() const;

  struct Transient {
    std::vector<double> pond_depth;  // m, at each of the requested times
    std::vector<double> outflow;     // m3/m2 that left through the plate by then
    std::vector<double> stored;      // m3/m2 the column holds beyond its start (negative: released)
  };
  // The transient column on `cells` equal cells: nodal pore pressures, hydrostatic under d0 at
  // the start, p = 0 at the plate and rho_w g d at the top from then on; at the interior nodes
  // S dp/dt - (1 / M) d sigma / dt = dq/dz, sigma = rho_w g d the pond's weight on the column;
  // dd/dt = -q at the top. Explicit steps at 0.4 of the diffusive limit of Darcy's conductivity
  // (Forchheimer's term only lowers it). `times` ascending, in s. Needs storage() > 0.
  Transient transient(double d0, const std::vector<double>& times, int cells = 100) const;
};

}  // namespace lituya::verify
