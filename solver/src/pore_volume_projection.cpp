// Pore water volume projection: liquid points that over-fill the pores of a soil are moved
// out (issue 8, item 2; scientific manual 10.4).
//
// Why: the pressure of eq. (8) is integrated in rate form at each liquid point from the
// divergence of the grid's mixture flux. It never compares the water the points carry with the
// space they fill. Where water enters a soil its interstitial speed jumps to q / n, a jump the
// linear grid smears over a cell, so the points entering crowd: in the seepage column the sand
// held 48 % water where n = 0.4, the pond above fell 1.4 times faster than Ergun's law allows,
// and nothing in the rate form noticed (verification/seepage).
//
// What: node i holds the water volume W_i = sum_q N_i(x_q) V_q and offers the pore volume
// n_i V_i (V_i = integral of N_i). At a soil node (n_i < 1) the excess E_i = W_i - n_i V_i > 0
// is spread out by moving the points by u = grad(phi). The water's volume flux is n u (it
// moves through the pores), and moving the points changes W_i by -integral N_i div(n u), so
//     sum_j L_ij phi_j = -E_i,   L_ij = integral over the wet cells of n grad N_i . grad N_j,
// phi = 0 at the free surface (a node of a cell that holds no water), no normal gradient at
// walls (the natural condition; the walls' velocity conditions are applied to u too). The
// liquid points move by the nodal average of grad(phi); the excess leaves the soil through the
// free water to the surface, which rises by that volume. A point's pressure follows its move to
// first order (p += grad p . u). It is the implicit density projection of FLIP liquids
// (Kugelstadt et al. 2019) restricted to the pores, with no constant: each call removes the
// whole excess.
// Why only soil nodes and only excess: a pore may be partly empty (an unsaturated soil, a dry
// slide entering water: the grains see the pore pressure times the degree of saturation,
// two_phase.cpp), but never over-full. In free water, where no under-filled node is physical,
// removing only the positive part of the particles' quadrature noise would bias every free
// surface outward (a dam break failed Ritter's solution that way); removing both signs there
// and in the soil was tried and lost: a position correction moves water past the grains
// without the drag of eq. (23), and the under-filled sand at an outflow then sucked the pond
// through at four times Darcy's rate (scientific manual 10.4).
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "lituya/solver/conjugate_gradient.hpp"
#include "lituya/solver/simulation.hpp"
#include "simulation_kernels.hpp"

namespace lituya::solver {

template <int dim>
int Simulation<dim>::project_pore_water_volume() {
  const std::size_t n_nodes = mesh_.node_count();
  const std::size_t n_cells = mesh_.cell_count();
  LiquidPoints<dim>& liquid = water_.points;
  const std::size_t n_liquid = liquid.size();
  PoreVolumeScratch& s = pore_volume_;

  // Nothing to do without soil (a water-only scene pays one pass over the nodes).
  if (std::none_of(node_porosity_.begin(), node_porosity_.end(), [](double n) { return n < 1.0; }))
    return 0;
  // W_i with the points' current volumes and cells.
  projection_.point_values.assign(n_liquid, 1.0);
  const std::vector<double>& water_volume = scatter_liquid(projection_.point_values);
  s.rhs.assign(n_nodes, 0.0);
  bool any_excess = false;
  for (std::size_t i = 0; i < n_nodes; ++i) {
    const double n = node_porosity_[i];
    if (n >= 1.0) continue;  // free water: left to the pressure
    const double excess = water_volume[i] - n * node_mesh_volume_[i];
    if (excess > 0) {
      s.rhs[i] = -excess;
      any_excess = true;
    }
  }
  if (!any_excess) return 0;

  // The wet region and its free surface.
  s.wet_cell.assign(n_cells, 0);
  for (std::size_t q = 0; q < n_liquid; ++q) s.wet_cell[liquid.cell[q]] = 1;
  s.unknown.assign(n_nodes, 0);
  for (std::size_t c = 0; c < n_cells; ++c)
    if (s.wet_cell[c])
      for (int node : mesh_.cell_nodes[c]) s.unknown[node] = 1;
  for (std::size_t c = 0; c < n_cells; ++c)
    if (!s.wet_cell[c])
      for (int node : mesh_.cell_nodes[c]) s.unknown[node] = 0;
  // The water's share of each wet cell's volume: n_c |c|, n_c the mean of its nodal
  // porosities (the integral of the linear porosity field over the cell).
  s.cell_weight.assign(n_cells, 0.0);
  s.diagonal.assign(n_nodes, 0.0);
  for (std::size_t c = 0; c < n_cells; ++c) {
    if (!s.wet_cell[c]) continue;
    double porosity = 0;
    for (int node : mesh_.cell_nodes[c]) porosity += node_porosity_[node];
    s.cell_weight[c] = mesh_.cell_volume[c] * porosity / (dim + 1);
    const auto& grad = mesh_.cell_shape_gradient[c];
    for (int a = 0; a <= dim; ++a)
      s.diagonal[mesh_.cell_nodes[c][a]] += s.cell_weight[c] * grad[a].squaredNorm();
  }
  for (std::size_t i = 0; i < n_nodes; ++i)
    if (!s.unknown[i] || !(s.diagonal[i] > 0)) {
      s.unknown[i] = 0;
      s.rhs[i] = 0;
    }

  // L phi = rhs by conjugate gradients with the diagonal as preconditioner. Serial loops over
  // cells and nodes: the same bits for any thread count. A wet region without a free-surface
  // node (a closed, full box) makes L singular; the small diagonal shift keeps CG bounded there.
  auto apply = [&](const std::vector<double>& x, std::vector<double>& y) {
    std::fill(y.begin(), y.end(), 0.0);
    for (std::size_t c = 0; c < n_cells; ++c) {
      if (!s.wet_cell[c]) continue;
      const auto& nodes = mesh_.cell_nodes[c];
      const auto& grad = mesh_.cell_shape_gradient[c];
      Vec g = Vec::Zero();
      for (int a = 0; a <= dim; ++a) g += x[nodes[a]] * grad[a];
      for (int a = 0; a <= dim; ++a) y[nodes[a]] += s.cell_weight[c] * grad[a].dot(g);
    }
    for (std::size_t i = 0; i < n_nodes; ++i)
      y[i] = s.unknown[i] ? y[i] + 1e-9 * s.diagonal[i] * x[i] : 0.0;
  };
  s.potential.assign(n_nodes, 0.0);
  // Relative residual 1e-3: a position correction to a fraction of the excess, which the next
  // call sees again.
  const int iteration = detail::conjugate_gradient(
      apply, [&](std::size_t i, double r) { return s.unknown[i] ? r / s.diagonal[i] : 0.0; }, s.rhs,
      s.potential, s.cg, 1e-3, 1000);

  // Nodal displacement: the volume-weighted mean of grad(phi) over the wet cells around the
  // node, then the walls' conditions (water slides along walls and may leave a contact wall).
  s.displacement.assign(n_nodes, Vec::Zero());
  s.node_weight.assign(n_nodes, 0.0);
  for (std::size_t c = 0; c < n_cells; ++c) {
    if (!s.wet_cell[c]) continue;
    const auto& nodes = mesh_.cell_nodes[c];
    const auto& grad = mesh_.cell_shape_gradient[c];
    Vec g = Vec::Zero();
    for (int a = 0; a <= dim; ++a) g += s.potential[nodes[a]] * grad[a];
    for (int a = 0; a <= dim; ++a) {
      s.displacement[nodes[a]] += mesh_.cell_volume[c] * g;
      s.node_weight[nodes[a]] += mesh_.cell_volume[c];
    }
  }
  for (std::size_t i = 0; i < n_nodes; ++i)
    if (s.node_weight[i] > 0) s.displacement[i] /= s.node_weight[i];
  apply_constraints<dim>(water_.constraints, s.displacement, nullptr, false);

  // Move the points; one that the move would take out of the mesh stays where it is.
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const int cell = liquid.cell[q];
    const auto& nodes = mesh_.cell_nodes[cell];
    const auto& grad = mesh_.cell_shape_gradient[cell];
    Vec u = Vec::Zero(), pressure_gradient = Vec::Zero();
    for (int a = 0; a <= dim; ++a) {
      u += water_.shape[q](a) * s.displacement[nodes[a]];
      pressure_gradient += node_pressure_[nodes[a]] * grad[a];
    }
    const Vec moved = liquid.position[q] + u;
    typename Mesh<dim>::Shape shape;
    const int found = mesh_.locate(cell, moved, shape);
    if (found < 0) continue;
    liquid.position[q] = moved;
    liquid.cell[q] = found;
    water_.shape[q] = shape;
    liquid.pressure[q] = std::max(0.0, liquid.pressure[q] + pressure_gradient.dot(u));
    const MaterialModelData& water = materials_[liquid.material[q]];
    liquid.volume[q] =
        liquid.mass[q] / (water.liquid_density * (1.0 + liquid.pressure[q] / water.bulk_modulus));
  }
  return iteration;
}

template int Simulation<2>::project_pore_water_volume();
template int Simulation<3>::project_pore_water_volume();

}  // namespace lituya::solver
