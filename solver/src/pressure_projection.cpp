// Pressure-projection stabilisation of the liquid pressure.
//
// Why: the pressure update of eq. (8) uses one flux divergence per linear cell, i.e. linear
// velocities with a pressure that is constant per cell (the P1/P0 pair). That pair is not
// inf-sup stable: a cell-to-cell (checkerboard) pressure pattern exerts no nodal force, so
// nothing in the equations removes it, and in violent flow it grows to a sizeable fraction of
// rho_w g H (see verification/dam_break).
//
// What: at fixed simulated times (`pressure_projection_time`, by default ten steps of still
// water at Courant 0.5; or every `pressure_projection_interval` steps when that is given;
// Simulation::pressure_projection_due), the point pressures are replaced by their
// L2 projection onto the continuous piecewise-linear functions of the mesh, weighted by the
// points' water volumes:
//     find c (nodal values) with  M c = b,   M_ij = sum_q V_q N_i(x_q) N_j(x_q),
//                                            b_i  = sum_q V_q N_i(x_q) p_q,
//     then p_q <- sum_j N_j(x_q) c_j   (clipped at 0: no tension).
// This is the idea of the polynomial pressure projection of Dohrmann and Bochev (2004),
// applied as a periodic filter. Properties that matter here:
// - it is an orthogonal projection in the V-weighted inner product, so it can only remove
//   pressure "energy" sum V p^2 / 2K. It is not free of side effects: it also removes the
//   sub-cell part of the pressure that balances the points' uneven quadrature of the weight,
//   so each projection kicks slowly moving water (verification/seepage, ninth session) and
//   damps a travelling wave a little (Case B's X2 crest 11 % lower at 0.01 m cells than with
//   no projection; user manual 2.6). Hence a period in time, not in steps: in steps, the
//   Courant number changed how much it damps;
// - it reproduces any linear field exactly, at the free surface and the walls too (unlike a
//   lumped nodal average, which is one-sided there), so a hydrostatic tank is untouched;
// - pressure variation below the mesh scale, which the P1 velocities cannot feel, is removed.
// M is assembled once per projection (one pass over the points, PointMassMatrix in
// conjugate_gradient.hpp; applied matrix-free instead, each iteration would gather and scatter
// over all the points) and solved by conjugate gradients, preconditioned by symmetric
// Gauss-Seidel and warm-started from the previous projection's nodal values.
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "lituya/solver/conjugate_gradient.hpp"
#include "lituya/solver/simulation.hpp"
#include "simulation_kernels.hpp"

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
  if (s.solution.size() != n_nodes) s.solution.assign(n_nodes, 0.0);
  if (!s.mass.has_mesh(n_nodes, mesh_.cell_count())) s.mass.set_mesh(mesh_.cell_nodes, n_nodes);
  LiquidPoints<dim>& liquid = water_.points;
  s.point_values.resize(liquid.size());
  // M, its lumped diagonal (sum_q V_q N_i) and the right-hand side, on the rows of the nodes
  // that carry water: the others have zero rows, columns and right-hand sides, and their
  // nodal value is 0.
  s.mass.assemble(mesh_.cell_nodes, liquid.cell, water_.shape, liquid.volume, liquid.pressure,
                  threads_, s.diagonal, s.rhs);
  const std::vector<std::size_t>& row_node = s.mass.nodes();
  const std::size_t n_rows = row_node.size();
  s.row_rhs.resize(n_rows);
  s.row_solution.resize(n_rows);
  // Warm start: previous nodal values where the node still carries water, else the lumped
  // average.
  for (std::size_t r = 0; r < n_rows; ++r) {
    const std::size_t i = row_node[r];
    s.row_rhs[r] = s.rhs[i];
    s.row_solution[r] = s.solution[i] != 0 ? s.solution[i] : s.rhs[i] / s.diagonal[i];
  }
  // A node carried by almost no water: keep its equation well posed (its value hardly
  // matters to any point).
  detail::SparseMatrix& matrix = s.mass.matrix();
  for (std::size_t r = 0; r < n_rows; ++r)
    matrix.value[matrix.diagonal[r]] += 1e-12 * s.diagonal[row_node[r]];
  // Preconditioned by symmetric Gauss-Seidel sweeps rather than the lumped diagonal: on the
  // full dam break (verification/dam_break) 8.8 iterations per projection on average (at most
  // 14) instead of 53 (at most 146) to the same residual, each iteration about twice the work.
  // The sweeps are serial (the multiply is shared by rows): the same bits on any thread count.
  const int iteration = detail::gauss_seidel_conjugate_gradient(matrix, s.row_rhs, s.row_solution,
                                                                s.cg, 1e-8, 200, threads_);
  std::fill(s.solution.begin(), s.solution.end(), 0.0);
  for (std::size_t r = 0; r < n_rows; ++r) s.solution[row_node[r]] = s.row_solution[r];
  gather_liquid(s.solution, s.point_values);
  const std::size_t n_liquid = liquid.size();
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const MaterialModelData& water = materials_[liquid.material[q]];
    liquid.pressure[q] = std::max(0.0, s.point_values[q]);
    liquid.volume[q] = detail::water_volume(liquid.mass[q], water.liquid_density,
                                            liquid.pressure[q], water.bulk_modulus);
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
