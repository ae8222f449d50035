// How much PIC each step mixes into the FLIP velocity update, for the solid and the liquid
// points. FLIP (the point keeps its own velocity plus the grid's acceleration) hardly
// dissipates; PIC (the point takes the grid's velocity) removes what the grid cannot
// represent. A fixed share per step makes the damping depend on the number of steps, so on
// the Courant number and the stiffness; a share fixed per unit time does not.
#pragma once

#include <string>
#include <vector>

#include "lituya/solver/case_description.hpp"

namespace lituya::solver {

struct PhaseDamping {
  double time = 0;              // s: FLIP share exp(-dt / time) per step when > 0
  double per_step_flip = 0.99;  // otherwise: this FLIP share at every step
  double flip_share(double dt) const;
};

struct TransferDamping {
  PhaseDamping solid, liquid;
  std::string description;  // one line for the solver log: values and where they come from
};

// Defaults, in units of the grid's gravity time sqrt(h / g), measured (user manual, 2.6):
// - the solid needs little PIC, its own friction dissipates: Case A's front at 0.64 s is
//   0.80 / 0.88 / 0.92 m at 1 / 3 / 30 grid times;
// - water has no such dissipation, and the window is narrow: below 0.08 grid time the dam
//   break misses Ritter's solution (RMS depth error 0.0104 m against 0.010 at 0.07), at 0.1
//   the full Case C (dry slide, rigid slope) blew up after 1.4 s (pore pressure grew in the
//   submerged deposit and threw grains and water out), at 0.15 the still tank's pressures
//   drift out of their 2 % tolerance. 0.09 runs every case; it still damps surge waves.
inline constexpr double kSolidDampingGridTimes = 3.0;
inline constexpr double kLiquidDampingGridTimes = 0.09;

// The cell size h of a mesh: (d! times the median cell volume)^(1/d), the leg of the
// right-angled triangle or tetrahedron of that volume.
double characteristic_cell_size(const std::vector<double>& cell_volumes, int dimension);

// Explicit settings win; missing damping times default to the multiples above of sqrt(h / g).
// Without gravity there is no grid time: phases without a given time keep 0.99 per step.
TransferDamping resolve_transfer_damping(const SolverSettings& settings, double cell_size,
                                         double gravity);

}  // namespace lituya::solver
