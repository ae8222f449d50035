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
// How: L is assembled once per call (MeshMatrix in conjugate_gradient.hpp) and solved by
// conjugate gradients preconditioned by symmetric Gauss-Seidel, as the pressure projection's
// mass matrix is. Applied matrix-free, each of the up to 1000 iterations walked all the wet
// cells serially: a third of a two-phase run's time. The loops over cells and nodes around the
// solve run on the threads, each nodal sum made by one thread over the node's cells in cell
// order: the same bits on any thread count (nodal_scatter.hpp says why that matters).
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "lituya/solver/conjugate_gradient.hpp"
#include "lituya/solver/simulation.hpp"
#include "simulation_kernels.hpp"

namespace lituya::solver {

namespace {
// Over-filling of a node's pores below this fraction of its pore volume is not corrected.
constexpr double kNegligibleExcess = 1e-3;
}  // namespace

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
  // The soil's volume sum N V and grain volume S_i = sum N V (1 - n) at the same positions
  // (the coupling sums of this step were taken before the points moved).
  const MaterialPoints<dim>& points = solid_.points;
  coupling_.run(
      points.size(), [](CouplingSums& c) { return std::tie(c.solid_volume, c.soil_volume); },
      [&](CouplingSums& c, std::size_t p) {
        const auto& nodes = mesh_.cell_nodes[points.cell[p]];
        const double volume = points.volume[p], grains = volume * (1.0 - porosity(p));
        for (int a = 0; a <= dim; ++a) {
          c.soil_volume[nodes[a]] += solid_.shape[p](a) * volume;
          c.solid_volume[nodes[a]] += solid_.shape[p](a) * grains;
        }
      });
  const CouplingSums& soil = coupling_.sums();
  s.rhs.resize(n_nodes);
  bool any_excess = false;
#pragma omp parallel for num_threads(threads_) schedule(static) reduction(|| : any_excess)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    const double n = node_porosity_[i];
    // The space node i offers the water: all that the grains leave of the node's volume V_i,
    // counted with the soil points' own quadrature where that counts more than V_i,
    //     max(V_i, sum N V) - S_i.
    // Where the soil's points over-count the node's volume (their quadrature of the hat
    // function, which scatters by several per cent as a soil moves across the cells), pore
    // water that moves with them over-counts by as much. Against n_i V_i = V_i - S_i that
    // was an excess, and only excesses are removed: a saturated layer sliding on a slope lost
    // a sixth of its pore water to its surface in 0.2 s (TwoPhase.SlidingSaturatedLayerKeeps
    // ItsPoreWater). With the soil's own count, water that fills exactly the pores of its
    // points shows no excess; water that crowds them (seepage into a bed) still does.
    const double pore_volume =
        std::max(node_mesh_volume_[i], soil.soil_volume[i]) - soil.solid_volume[i];
    const double excess = water_volume[i] - pore_volume;
    // Free water (n = 1) is left to the pressure. An excess below a thousandth of the pore
    // volume is left too: the projection itself stops at that relative residual, and the
    // water's own compression at the pressures of a model (p / K_w, 1e-4 to 1e-3) changes
    // the volumes by as much. In `lituya_benchmark --water 1` the regular lattice of the
    // saturated column over-fills one to four nodes by 3e-6 to 5e-5 of their pores, and
    // removing that cost a solve over 36 000 unknowns (50-60 iterations) every tenth step,
    // a tenth of the run's time.
    s.rhs[i] = n < 1.0 && excess > kNegligibleExcess * pore_volume ? -excess : 0.0;
    any_excess = any_excess || s.rhs[i] < 0;
  }
  if (!any_excess) return 0;

  // The wet region and its free surface. (Serial: the points of a cell would race to mark it,
  // and a byte a point is little work.)
  s.wet_cell.assign(n_cells, 0);
  for (std::size_t q = 0; q < n_liquid; ++q) s.wet_cell[liquid.cell[q]] = 1;
  // The water's share of each wet cell's volume: n_c |c|, n_c the mean of its nodal
  // porosities (the integral of the linear porosity field over the cell).
  s.cell_weight.resize(n_cells);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t c = 0; c < n_cells; ++c) {
    double porosity = 0;
    if (s.wet_cell[c])
      for (int node : mesh_.cell_nodes[c]) porosity += node_porosity_[node];
    s.cell_weight[c] = mesh_.cell_volume[c] * porosity / (dim + 1);
  }
  // The unknowns: the nodes all of whose cells are wet (a node of a dry cell is on the free
  // surface, phi = 0) and whose row of L is not zero.
  if (!s.laplacian.has_mesh(n_nodes, n_cells)) s.laplacian.set_mesh(mesh_.cell_nodes, n_nodes);
  s.diagonal.resize(n_nodes);
  s.unknown.resize(n_nodes);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    double diagonal = 0;
    bool wet = false, dry = false;
    s.laplacian.for_each_cell_around(i, [&](std::size_t c, int a) {
      if (!s.wet_cell[c]) {
        dry = true;
        return;
      }
      wet = true;
      diagonal += s.cell_weight[c] * mesh_.cell_shape_gradient[c][a].squaredNorm();
    });
    s.diagonal[i] = diagonal;
    s.unknown[i] = wet && !dry && diagonal > 0;
    if (!s.unknown[i]) s.rhs[i] = 0;
  }

  // L phi = rhs on the unknowns' rows and columns (phi = 0 at the other nodes). A wet region
  // without a free-surface node (a closed, full box) makes L singular; the small diagonal
  // shift keeps CG bounded there.
  s.laplacian.assemble([&](std::size_t c) { return s.wet_cell[c] ? static_cast<int>(c) : -1; },
                       [&](std::size_t i) { return s.unknown[i] != 0; },
                       [&](int c, int a, int b) {
                         const auto& grad = mesh_.cell_shape_gradient[static_cast<std::size_t>(c)];
                         return s.cell_weight[static_cast<std::size_t>(c)] * grad[a].dot(grad[b]);
                       },
                       threads_);
  detail::SparseMatrix& matrix = s.laplacian.matrix();
  const std::vector<std::size_t>& row_node = s.laplacian.nodes();
  const std::size_t n_rows = row_node.size();
  s.row_rhs.resize(n_rows);
  s.row_potential.assign(n_rows, 0.0);
  for (std::size_t r = 0; r < n_rows; ++r) {
    s.row_rhs[r] = s.rhs[row_node[r]];
    matrix.value[matrix.diagonal[r]] += 1e-9 * s.diagonal[row_node[r]];
  }
  // Stops at a relative residual of 1e-3, |rhs - L phi| <= 1e-3 |rhs| (the other nodes'
  // right-hand sides are zero, so these are the norms over all nodes, as before L was
  // assembled): a position correction to a fraction of the excess, which the next call sees
  // again. Preconditioned by symmetric Gauss-Seidel rather than the diagonal: in
  // `lituya_benchmark --water 1` (36 000 unknowns) 91 iterations a call on average instead of
  // 258, each dearer by two sweeps. At the same residual it is also nearer the exact phi: the
  // diagonal left enough of phi's smooth part unsolved that the seepage column
  // (verification/seepage) drained at 0.764 of Ergun's flux, against 0.813 now and 0.814
  // with a 1e-8 residual. The sweeps are serial and the multiply is shared by rows: the same
  // bits on any thread count.
  const int iteration = detail::gauss_seidel_conjugate_gradient(matrix, s.row_rhs, s.row_potential,
                                                                s.cg, 1e-3, 1000, threads_);
  s.potential.assign(n_nodes, 0.0);
  for (std::size_t r = 0; r < n_rows; ++r) s.potential[row_node[r]] = s.row_potential[r];

  // Nodal displacement: the volume-weighted mean of grad(phi) over the wet cells around the
  // node, then the walls' conditions (water slides along walls and may leave a contact wall).
  s.cell_gradient.resize(n_cells);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t c = 0; c < n_cells; ++c) {
    if (!s.wet_cell[c]) continue;
    const auto& nodes = mesh_.cell_nodes[c];
    const auto& grad = mesh_.cell_shape_gradient[c];
    Vec g = Vec::Zero();
    for (int a = 0; a <= dim; ++a) g += s.potential[nodes[a]] * grad[a];
    s.cell_gradient[c] = g;
  }
  s.displacement.resize(n_nodes);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    Vec sum = Vec::Zero();
    double weight = 0;
    s.laplacian.for_each_cell_around(i, [&](std::size_t c, int) {
      if (!s.wet_cell[c]) return;
      sum += mesh_.cell_volume[c] * s.cell_gradient[c];
      weight += mesh_.cell_volume[c];
    });
    s.displacement[i] = weight > 0 ? Vec(sum / weight) : Vec::Zero();
  }
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
    liquid.volume[q] = detail::water_volume(liquid.mass[q], water.liquid_density,
                                            liquid.pressure[q], water.bulk_modulus);
  }
  return iteration;
}

template int Simulation<2>::project_pore_water_volume();
template int Simulation<3>::project_pore_water_volume();

}  // namespace lituya::solver
