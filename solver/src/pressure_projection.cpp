// Pressure-projection stabilisation of the liquid pressure.
//
// Why: the pressure update of eq. (8) uses one flux divergence per linear cell, i.e. linear
// velocities with a pressure that is constant per cell (the P1/P0 pair). That pair is not
// inf-sup stable: a cell-to-cell (checkerboard) pressure pattern exerts no nodal force, so
// nothing in the equations removes it, and in violent flow it grows to a sizeable fraction of
// rho_w g H (see verification/dam_break).
//
// What: every `pressure_projection_interval` steps, the point pressures are replaced by their
// L2 projection onto the continuous piecewise-linear functions of the mesh, weighted by the
// points' water volumes:
//     find c (nodal values) with  M c = b,   M_ij = sum_q V_q N_i(x_q) N_j(x_q),
//                                            b_i  = sum_q V_q N_i(x_q) p_q,
//     then p_q <- sum_j N_j(x_q) c_j   (clipped at 0: no tension).
// This is the idea of the polynomial pressure projection of Dohrmann and Bochev (2004),
// applied as a periodic filter. Properties that matter here:
// - it is an orthogonal projection in the V-weighted inner product, so it can only remove
//   pressure "energy" sum V p^2 / 2K (dissipative, never pumps);
// - it reproduces any linear field exactly, at the free surface and the walls too (unlike a
//   lumped nodal average, which is one-sided there), so a hydrostatic tank is untouched;
// - pressure variation below the mesh scale, which the P1 velocities cannot feel, is removed.
// M is solved matrix-free by conjugate gradients with the lumped diagonal as preconditioner,
// warm-started from the previous projection's nodal values (few iterations once the flow is
// under way).
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "lituya/solver/conjugate_gradient.hpp"
#include "lituya/solver/simulation.hpp"

namespace lituya::solver {

template <int dim>
const std::vector<double>& Simulation<dim>::scatter_liquid(
    const std::vector<double>& point_values) {
  // nodal_i = sum_q V_q N_i(x_q) point_values_q, with per-thread sums added in a fixed order
  // (nodal_scatter.hpp): the projection runs inside the time loop, so its rounding must not
  // depend on the threads' timing.
  const LiquidPoints<dim>& liquid = water_.points;
  projection_.sums.run(
      liquid.size(), [](detail::ScalarSums& s) { return std::tie(s.value); },
      [&](detail::ScalarSums& s, std::size_t q) {
        const auto& nodes = mesh_.cell_nodes[liquid.cell[q]];
        const double w = liquid.volume[q] * point_values[q];
        for (int i = 0; i <= dim; ++i) s.value[nodes[i]] += water_.shape[q](i) * w;
      });
  return projection_.sums.sums().value;
}

template <int dim>
void Simulation<dim>::gather_liquid(const std::vector<double>& nodal,
                                    std::vector<double>& point_values) const {
  const LiquidPoints<dim>& liquid = water_.points;
  const std::size_t n_liquid = liquid.size();
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const auto& nodes = mesh_.cell_nodes[liquid.cell[q]];
    double value = 0;
    for (int i = 0; i <= dim; ++i) value += water_.shape[q](i) * nodal[nodes[i]];
    point_values[q] = value;
  }
}

template <int dim>
int Simulation<dim>::project_liquid_pressure() {
  const std::size_t n_nodes = mesh_.node_count();
  ProjectionScratch& s = projection_;
  if (s.solution.size() != n_nodes) {
    s.solution.assign(n_nodes, 0.0);
    s.rhs.assign(n_nodes, 0.0);
    s.diagonal.assign(n_nodes, 0.0);
  }
  LiquidPoints<dim>& liquid = water_.points;
  s.point_values.resize(liquid.size());
  // Lumped diagonal (sum_q V_q N_i) and right-hand side.
  std::fill(s.point_values.begin(), s.point_values.end(), 1.0);
  s.diagonal = scatter_liquid(s.point_values);
  s.rhs = scatter_liquid(liquid.pressure);
  auto apply = [&](const std::vector<double>& x, std::vector<double>& y) {
    gather_liquid(x, s.point_values);
    const std::vector<double>& mapped = scatter_liquid(s.point_values);
    // A node carried by almost no water: keep its equation well posed (its value hardly
    // matters to any point).
    for (std::size_t i = 0; i < n_nodes; ++i) y[i] = mapped[i] + 1e-12 * s.diagonal[i] * x[i];
  };
  // Warm start: previous nodal values where the node still carries water, else the lumped
  // average.
  for (std::size_t i = 0; i < n_nodes; ++i)
    if (s.diagonal[i] <= 0)
      s.solution[i] = 0;
    else if (s.solution[i] == 0)
      s.solution[i] = s.rhs[i] / s.diagonal[i];
  const int iteration = detail::conjugate_gradient(
      apply, [&](std::size_t i, double r) { return s.diagonal[i] > 0 ? r / s.diagonal[i] : 0.0; },
      s.rhs, s.solution, s.cg, 1e-8, 200);
  gather_liquid(s.solution, s.point_values);
  const std::size_t n_liquid = liquid.size();
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const MaterialModelData& water = materials_[liquid.material[q]];
    liquid.pressure[q] = std::max(0.0, s.point_values[q]);
    liquid.volume[q] =
        liquid.mass[q] / (water.liquid_density * (1.0 + liquid.pressure[q] / water.bulk_modulus));
  }
  return iteration;
}

template const std::vector<double>& Simulation<2>::scatter_liquid(const std::vector<double>&);
template const std::vector<double>& Simulation<3>::scatter_liquid(const std::vector<double>&);
template void Simulation<2>::gather_liquid(const std::vector<double>&, std::vector<double>&) const;
template void Simulation<3>::gather_liquid(const std::vector<double>&, std::vector<double>&) const;
template int Simulation<2>::project_liquid_pressure();
template int Simulation<3>::project_liquid_pressure();

}  // namespace lituya::solver
