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
// - the water needs none for stability since the corners of roller groups hold (a tank's
//   corner drove a flow that only heavy PIC held down) and sound is damped by the bulk
//   viscosity (scientific manual 10.5). Until then it was 0.09 grid times, pinned by
//   stability, and it flattened surge waves: Case B's first crest (0.03 m cells) is 20.7 /
//   27.3 / 30.4 / 30.9 / 33.1 / 33.5 / 33.6 / 33.6 / 33.6 mm at liquid damping times 0.09 /
//   0.29 / 0.9 / 3 / 9 / 30 / 90 / 300 / 900 grid times. 30 is inside the flat part: a third
//   or three times it moves that crest by 1.5 %, a tenth or ten times it by 8 %.
// - with XPIC(m >= 2) for the free water ([solver] liquid_xpic_order) the water's default is
//   1 grid time: XPIC takes far less of the resolved motion per damped step, so it can damp
//   faster. A standing wave on a crossed 0.02 m mesh (4 points per cell) ends with a noise of
//   44.5 / 28.5 / 16.3 / 10.2 / 6.2 mm/s at 30 / 10 / 3 / 1 / 0.3 gt and loses 1.31 / 0.96 /
//   0.95 / 1.71 / 4.29 % a period; at 1 gt with 9 points per cell the noise stays flat
//   (verification/standing_wave/README.md, stop 56). Case B's crests at 0.02 m move by -3.7 /
//   +1.8 % at a third / three times it (verification/speed_accuracy_case_b/README.md, stop 57).
inline constexpr double kSolidDampingGridTimes = 3.0;
inline constexpr double kLiquidDampingGridTimes = 30.0;
inline constexpr double kLiquidXpicDampingGridTimes = 1.0;

// The cell size h of a mesh: (d! times the median cell volume)^(1/d), the leg of the
// right-angled triangle or tetrahedron of that volume.
double characteristic_cell_size(const std::vector<double>& cell_volumes, int dimension);

// Explicit settings win; missing damping times default to the multiples above of sqrt(h / g)
// (the water's by its transfer: the plain blend or XPIC).
// Without gravity there is no grid time: phases without a given time keep 0.99 per step.
TransferDamping resolve_transfer_damping(const SolverSettings& settings, double cell_size,
                                         double gravity);

}  // namespace lituya::solver
