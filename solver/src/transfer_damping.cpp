#include "lituya/solver/transfer_damping.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lituya::solver {

double PhaseDamping::flip_share(double dt) const {
  return time > 0 ? std::exp(-dt / time) : per_step_flip;
}

double characteristic_cell_size(const std::vector<double>& cell_volumes, int dimension) {
  if (cell_volumes.empty()) return 0;
  std::vector<double> v = cell_volumes;
  auto middle = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), middle, v.end());
  const double factorial = dimension == 3 ? 6.0 : 2.0;
  return std::pow(factorial * *middle, 1.0 / dimension);
}

TransferDamping resolve_transfer_damping(const SolverSettings& settings, double cell_size,
                                         double gravity) {
  TransferDamping d;
  std::ostringstream line;
  line.precision(3);
  if (settings.flip_fraction) {
    d.solid.per_step_flip = d.liquid.per_step_flip = *settings.flip_fraction;
    line << "FLIP/PIC blend: FLIP share " << *settings.flip_fraction
         << " per step (flip_fraction), both phases";
    if (settings.liquid_xpic_order > 1)
      line << "; the water's damped share by XPIC(" << settings.liquid_xpic_order << ")";
    d.description = line.str();
    return d;
  }
  const double grid_time = gravity > 0 && cell_size > 0 ? std::sqrt(cell_size / gravity) : 0.0;
  auto resolve = [&](const std::optional<double>& given, double grid_times, PhaseDamping& phase,
                     const char* name) {
    line << name << ' ';
    if (given) {
      phase.time = *given;
      line << phase.time << " s (given)";
    } else if (grid_time > 0) {
      phase.time = grid_times * grid_time;
      line << phase.time << " s (" << grid_times << " sqrt(h/g))";
    } else {
      line << "FLIP share 0.99 per step (no gravity: no grid time)";
    }
  };
  line << "FLIP/PIC blend, PIC damping time: ";
  resolve(settings.pic_damping_time, kSolidDampingGridTimes, d.solid, "solid");
  line << ", ";
  resolve(settings.liquid_pic_damping_time,
          settings.liquid_xpic_order > 1 ? kLiquidXpicDampingGridTimes : kLiquidDampingGridTimes,
          d.liquid, "liquid");
  if (settings.liquid_xpic_order > 1) line << " by XPIC(" << settings.liquid_xpic_order << ")";
  line << "; h = " << cell_size << " m";
  d.description = line.str();
  return d;
}

}  // namespace lituya::solver
