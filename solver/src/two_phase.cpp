// The liquid phase of the two-layer two-phase MPM (section 2 of the paper), the half of the
// time loop that a dry case never calls.
//
// Discretisation (why it looks like this):
// - Porosity at the nodes comes from the solid points: the solid volume fraction of node i is
//   sum_s N_i(x_s) V_s (1 - n_s) divided by the node's lumped mesh volume integral(N_i), so
//   n_i = 1 in free water and n_i -> n_s inside the soil; a half-covered node at the edge of the
//   slide gets an intermediate value (the interface is one cell wide).
// - Momentum (eqs. 11-16). Substituting (13) and (14) into (11) and (12) gives
//       solid:  (1-n) rho_s a_s = div sigma' + (1-n) div sigma_w + (1-n) rho_s g + f_d
//       liquid:     n rho_w a_w =              n  div sigma_w +     n rho_w g - f_d
//   (the sigma_w grad n terms of (13) cancel against those of div((1-n) sigma_w) and
//   div(n sigma_w); eqs. (15) and (16) as printed keep them, which would push still water into
//   a soil bed at rest; see the scientific manual). The weak form of -grad p over the mixture,
//   F_i = integral p grad N_i, is integrated over the two volumes that partition the mixture:
//   the water volume of the liquid points (p_q) and the grain volume V_s (1 - n_s) of the solid
//   points (the pore pressure interpolated from the nodes). The liquid node gets s_i F_i and
//   the solid node (1 - s_i) F_i, s_i the water's share of the wet mixture at the node
//   (pore_pressure_water_share): n_i where the water fills all the space the grains leave,
//   the soil's own porosity where it fills only (part of) the pores. The sum is the full
//   pore-pressure force (momentum is conserved), and with n_i from the same grain volumes, still
//   water over and in a soil bed starts in discrete balance (hydrostatic pressure carries the
//   water, buoyancy lightens the skeleton; test TwoPhase.SaturatedBedUnderWaterStaysAtRest).
// - Two water fields. The water of a cell that holds solid points is pore water, the rest
//   free water, each with its own nodal mass, momentum and velocity. The drag acts on the pore
//   water only; where the two meet (the soil's surface) they share the velocity normal to it
//   and slide along it (couple_across_soil_surface). With one water velocity per node, the
//   drag locked the free water of the cells around a soil to the grains, a layer one cell
//   thick carried along (scientific manual 10.3).
// - Drag (eqs. 23, 24) is integrated implicitly per node: with a = dt sum_s N_i V_s C_s,
//       (m_s + a) v_s - a v_w = m_s v_s*,   -a v_s + (m_w + a) v_w = m_w v_w*
//   (v* the velocities after the explicit forces), a 2x2 solve shared by all directions. The
//   relative speed in the Forchheimer term is the previous step's, so the system is linear.
//   Any permeability is then stable at the fluid's Courant step.
// - Pressure (eq. 8): its bracket is the divergence of the mixture's volume flux,
//       (1-n) div v_s + n div v_w + (v_w - v_s).grad n = div((1-n) v_s + n v_w),
//   evaluated with the nodal flux q_i = (1-n_i) v_s,i + n_i v_w,i (exactly eq. 8, with the
//   porosity-gradient term included), and dp = -(K_w / n) div q dt (p compression positive).
//   Linear velocity with one pressure per cell is the P1/P0 pair, which is not inf-sup
//   stable: a cell-to-cell (checkerboard) pressure pattern exerts no nodal force, so nothing
//   here removes it. pressure_projection.cpp does, every few steps. Tried before that and
//   rejected: averaging the divergence at the nodes (pumps energy into a FLIP run unless the
//   force is built from the same nodal field, and then still drifts), starting each point from
//   its cell's mean pressure (worse at rest: the exact field varies within a cell), and a
//   bulk viscosity alpha rho c h div v (does not act on a mode that carries no velocity). The
//   bulk viscosity is used, but for another purpose: it damps sound waves (see
//   update_liquid_and_relocate).
#include <omp.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "lituya/common/input_error.hpp"
#include "lituya/solver/simulation.hpp"
#include "simulation_kernels.hpp"

namespace lituya::solver {

using namespace detail;

namespace {
// Porosity below which the nodal value is not taken (a node over-covered by solid points in
// a compacted or boundary cell): keeps the pore-pressure split and K_w / n finite.
constexpr double kMinimumPorosity = 0.05;

// Drag coefficient C of eq. (23), f_d = C (v_w - v_s), per unit mixture volume, with the
// Kozeny-Carman permeability of eq. (24):
//   kappa = n^3 D^2 / (150 (1-n)^2),  C = n^2 mu / kappa + 1.75 n^1.5 rho_w |v_r| / sqrt(150 kappa)
double drag_coefficient(double n, double grain_diameter, double viscosity, double liquid_density,
                        double relative_speed) {
  n = std::clamp(n, kMinimumPorosity, 1.0 - 1e-9);
  const double kappa = n * n * n * grain_diameter * grain_diameter / (150.0 * (1 - n) * (1 - n));
  return n * n * viscosity / kappa +
         1.75 * n * std::sqrt(n) * liquid_density * relative_speed / std::sqrt(150.0 * kappa);
}

// The interior of a set of cells, as the cell-volume weights below need it (a cell whose points
// fill it, not one at the set's edge): marks in `edge` the nodes of every cell outside the set;
// a cell of the set is interior when none of its nodes is marked (interior_cell).
template <class CellNodes, class InSet>
void mark_edge_nodes(const CellNodes& cell_nodes, std::size_t n_nodes, InSet in_set,
                     std::vector<char>& edge) {
  edge.assign(n_nodes, 0);
  for (std::size_t c = 0; c < cell_nodes.size(); ++c)
    if (!in_set(c))
      for (int node : cell_nodes[c]) edge[static_cast<std::size_t>(node)] = 1;
}

template <class Nodes>
bool interior_cell(const Nodes& nodes, const std::vector<char>& edge) {
  for (int node : nodes)
    if (edge[static_cast<std::size_t>(node)]) return false;
  return true;
}

// The first row (alpha, beta) of the inverse of the moment matrix [[m0, m1^T], [m1, m2]] of
// the water volume about a node (weights N_i V, offsets d = x - x_i): the node's value of the
// volume-weighted linear least-squares fit of point values f is alpha sum N V f + beta . sum N
// V d f, exact for linear f. Where the points do not span the node (their spread below a tenth
// of the smallest cell height in some direction) the plain average 1 / m0 is kept.
template <int dim>
void pressure_fit_row(double m0, const Eigen::Matrix<double, dim, 1>& m1,
                      const Eigen::Matrix<double, dim, dim>& m2, double smallest_cell_height,
                      double& alpha, Eigen::Matrix<double, dim, 1>& beta) {
  using Vec = Eigen::Matrix<double, dim, 1>;
  using Mat = Eigen::Matrix<double, dim, dim>;
  alpha = m0 > 0 ? 1.0 / m0 : 0.0;
  beta = Vec::Zero();
  if (!(m0 > 0)) return;
  const Vec mean = m1 / m0;
  const Mat spread = m2 / m0 - mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Mat> eig;
  eig.computeDirect(spread, Eigen::EigenvaluesOnly);  // closed form for 2x2 and 3x3
  const double h = smallest_cell_height;
  if (!(eig.eigenvalues().minCoeff() > 0.01 * h * h)) return;
  Eigen::Matrix<double, dim + 1, dim + 1> M;
  M(0, 0) = m0;
  M.template block<1, dim>(0, 1) = m1.transpose();
  M.template block<dim, 1>(1, 0) = m1;
  M.template block<dim, dim>(1, 1) = m2;
  // M is symmetric: its inverse's first row is its first column. Fixed-size inverses up to
  // 4x4 are closed-form in Eigen.
  const Eigen::Matrix<double, dim + 1, dim + 1> inverse = M.inverse();
  alpha = inverse(0, 0);
  beta = inverse.template block<dim, 1>(1, 0);
}
}  // namespace

template <int dim>
void Simulation<dim>::setup_liquid() {
  const std::size_t n_nodes = mesh_.node_count();
  if (pore_liquid_ < 0)
    throw InputError(description_.materials_file, 0,
                     "the case has liquid points but no water material");
  LiquidPoints<dim>& liquid = water_.points;
  for (std::size_t q = 0; q < liquid.size(); ++q)
    if (!description_.materials[liquid.material[q]].is_liquid())
      throw InputError(description_.liquid_points_file, 0,
                       "liquid point " + std::to_string(liquid.id[q]) + " has material '" +
                           description_.materials[liquid.material[q]].name +
                           "', which is not a water material");
  const MaterialModelData& water = materials_[pore_liquid_];
  for (std::size_t m = 0; m < materials_.size(); ++m) {
    MaterialModelData& soil = materials_[m];
    const Material& material = description_.materials[m];
    if (material.is_liquid()) continue;
    if (!(soil.grain_diameter > 0))
      throw InputError(description_.materials_file, 0,
                       "material '" + material.name +
                           "' has no grain_diameter: with water in the case, the drag of eq. (23) "
                           "needs D_p (eq. 24)");
    // Undrained wave speed of the saturated mixture, sqrt((M + K_w / n) / rho_sat): the stiffest
    // wave the coupled system carries (drag locks the phases together at low permeability).
    const double n = material.porosity;
    const double undrained =
        std::sqrt((soil.elastic.constrained_modulus() + water.bulk_modulus / n) /
                  (material.dry_density() + n * water.liquid_density));
    soil.wave_speed = std::max(soil.wave_speed, undrained);
  }
  // The nodal buffers of the water, the coupling and the projection are sized by set_threads,
  // which the constructor calls before this.
  node_porosity_.assign(n_nodes, 1.0);
  node_pressure_.assign(n_nodes, 0.0);
  node_wall_pore_pressure_push_.assign(n_nodes, Vec::Zero());
  cell_has_soil_.assign(mesh_.cell_count(), 0);
  pore_pressure_cell_scale_.assign(mesh_.cell_count(), 1.0);
  liquid_in_soil_.assign(liquid.size(), 0);
  pore_water_velocity_.assign(n_nodes, Vec::Zero());
  pore_water_acceleration_.assign(n_nodes, Vec::Zero());
  mean_water_velocity_.assign(n_nodes, Vec::Zero());
  node_mesh_volume_ = mesh_.lumped_node_volume();
  smallest_cell_height_ =
      *std::min_element(mesh_.cell_min_height.begin(), mesh_.cell_min_height.end());
  liquid_flux_divergence_.assign(liquid.size(), 0.0);
  smoothed_flux_divergence_.assign(liquid.size(), 0.0);
  nodal_pressure_ = description_.solver.liquid_pressure == LiquidPressure::kNodalFit;
  if constexpr (dim == 2)
    if (description_.solver.crossed_pressure_filter)
      crossed_quadrangles_ = find_crossed_quadrangles(mesh_);
  // Sponge zones: sigma at each node once, the strongest zone where two overlap. A node is
  // damped by its own position; the water in a cell sees the linear blend of its nodes.
  if (!description_.sponges.empty()) {
    node_sponge_rate_.assign(n_nodes, 0.0);
    for (std::size_t i = 0; i < n_nodes; ++i)
      for (const Sponge& sponge : description_.sponges)
        node_sponge_rate_[i] =
            std::max(node_sponge_rate_[i], sponge.rate_at(mesh_.node_position[i](0)));
  }
  locate_all<dim>(mesh_, liquid.position, liquid.cell, liquid.id, water_.shape,
                  description_.liquid_points_file, "liquid point");
}

template <int dim>
void Simulation<dim>::relocate_liquid_for_test() {
  LiquidPoints<dim>& liquid = water_.points;
  locate_all<dim>(mesh_, liquid.position, liquid.cell, liquid.id, water_.shape,
                  description_.liquid_points_file, "liquid point");
}

template <int dim>
void Simulation<dim>::liquid_to_nodes() {
  using detail::LiquidSums;
  const MaterialPoints<dim>& points = solid_.points;
  LiquidPoints<dim>& liquid = water_.points;
  const std::size_t n_nodes = mesh_.node_count();
  const MaterialModelData& water = materials_[pore_liquid_];

  // Pore water and free water. A node shared by a soil and free water beside it has one water
  // velocity per field, and the drag of eq. (23) acts on the pore water's only: with a single
  // water velocity per node, the drag locked the free water of the cells around a soil to the
  // grains (a layer one cell thick dragged along). The water of a cell that holds solid points
  // is pore water; each cell's water thus follows one field.
  std::fill(cell_has_soil_.begin(), cell_has_soil_.end(), char{0});
  for (std::size_t p = 0; p < points.size(); ++p) cell_has_soil_[points.cell[p]] = 1;
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t q = 0; q < liquid.size(); ++q)
    liquid_in_soil_[q] = cell_has_soil_[liquid.cell[q]];
  update_pore_pressure_cell_scale();
  const std::vector<double>& water_scale = water_cell_scale();

  // Pass 1: the solid volume fraction and the drag coefficient at the nodes, from the solid
  // points.
  coupling_.run(
      points.size(),
      [](CouplingSums& c) {
        return std::tie(c.solid_volume, c.soil_volume, c.drag, c.solid_mass_gradient);
      },
      [&](CouplingSums& c, std::size_t p) {
        const auto& nodes = mesh_.cell_nodes[points.cell[p]];
        const auto& grad = mesh_.cell_shape_gradient[points.cell[p]];
        const Shape& n = solid_.shape[p];
        Vec relative = Vec::Zero();  // previous step's v_w - v_s at the point (pore water)
        for (int i = 0; i <= dim; ++i)
          relative += n(i) * (pore_water_velocity_[nodes[i]] - solid_.node_velocity[nodes[i]]);
        const double porosity_p = porosity(p);
        const double v = points.volume[p];
        const double drag =
            drag_coefficient(porosity_p, materials_[points.material[p]].grain_diameter,
                             water.viscosity, water.liquid_density, relative.norm());
        for (int i = 0; i <= dim; ++i) {
          c.solid_volume[nodes[i]] += n(i) * v * (1.0 - porosity_p);
          c.soil_volume[nodes[i]] += n(i) * v;
          c.drag[nodes[i]] += n(i) * v * drag;
          c.solid_mass_gradient[nodes[i]] += points.mass[p] * grad[i];
        }
      });
  const CouplingSums& coupling = coupling_.sums();
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i)
    node_porosity_[i] =
        std::clamp(1.0 - coupling.solid_volume[i] / node_mesh_volume_[i], kMinimumPorosity, 1.0);

  // Pass 2: liquid mass, momentum, gravity and viscous force (the phase's own transfer), the
  // pore water's share of them, and the liquid's pressure terms.
  scatter_to_nodes(
      water_, mesh_, gravity_, liquid.viscous_stress, Transfer::kMassMomentumForce,
      [&](LiquidSums<dim>& b, std::size_t q, const auto& nodes, const Shape& n, const auto& grad) {
        double porosity_q = 0;
        for (int i = 0; i <= dim; ++i) porosity_q += n(i) * node_porosity_[nodes[i]];
        liquid.porosity[q] = porosity_q;
        const double volume = liquid.volume[q];
        const double pressure_volume = liquid.pressure[q] * volume;
        const double scaled = water_scale[liquid.cell[q]] * pressure_volume;
        for (int i = 0; i <= dim; ++i) {
          b.pressure_force[nodes[i]] += scaled * grad[i];
          b.water_volume[nodes[i]] += n(i) * volume;
          b.water_volume_pressure[nodes[i]] += n(i) * pressure_volume;
        }
      },
      liquid_in_soil_.data());

  // Pass 3: the pore pressure on the grain volume of the solid points, with the pressure
  // interpolated from its nodal value: the water's volume-weighted pressure spread over the
  // node's pore volume n V_i. Where the pores are full the two agree. Where the water only
  // touches the node (one liquid point at the far corner of a cell, N ~ 0.01) the average
  // alone would still be that point's full pressure, and at a slide's first contact that is a
  // water-hammer spike (rho_w c_w v, 100 times hydrostatic) that every grain point of the
  // cells around the node would feel (verification/extremes/impact/README.md). Read as
  // Bishop's effective stress with chi = S_r, the degree of saturation W / (n V_i): a node
  // whose pores the water only partly fills passes that fraction of the pressure to the grains.
  const LiquidSums<dim>& sums = water_.nodal.sums();
  // With liquid_pressure = "nodal_fit" (experimental; scientific manual 10.4) the nodal
  // pressure is fitted at each node, every step, by the volume-weighted linear least-squares
  // fit a_i + b_i . (x - x_i) of the point pressures in the node's cells (weights N_i V). Its
  // value a_i = alpha_i sum N V p + beta_i . sum N V (x - x_i) p is exact for any linear
  // field whatever the points' spread, so a hydrostatic state is untouched at free surfaces
  // and walls too (a plain nodal average is one-sided there). The water's force and the
  // grains' pore pressure both take it. Eq. (8) then takes the adjoint smoothing of the flux
  // divergence (update_liquid_and_relocate), so the force's power equals the pressure's
  // energy change and the P1/P0 checkerboard exerts no force and is not driven: no periodic
  // projection. A node whose points do not span it (spread below a tenth of the smallest
  // cell height) keeps the plain average.
  if (nodal_pressure_) {
    // Moments of the water volume about each node: w = N_i V, d = x - x_i.
    pressure_fit_.run(
        liquid.size(),
        [](PressureFitSums& c) {
          return std::tie(c.volume_first_moment, c.pressure_first_moment, c.volume_second_moment);
        },
        [&](PressureFitSums& c, std::size_t q) {
          const auto& nodes = mesh_.cell_nodes[liquid.cell[q]];
          Vec x = Vec::Zero();
          for (int i = 0; i <= dim; ++i) x += water_.shape[q](i) * mesh_.node_position[nodes[i]];
          for (int i = 0; i <= dim; ++i) {
            const double w = water_.shape[q](i) * liquid.volume[q];
            const Vec d = x - mesh_.node_position[nodes[i]];
            c.volume_first_moment[nodes[i]] += w * d;
            c.pressure_first_moment[nodes[i]] += (w * liquid.pressure[q]) * d;
            c.volume_second_moment[nodes[i]] += w * d * d.transpose();
          }
        });
    const PressureFitSums& m = pressure_fit_.sums();
    node_fit_alpha_.resize(n_nodes);
    node_fit_beta_.resize(n_nodes);
    node_fitted_pressure_.resize(n_nodes);
#pragma omp parallel for num_threads(threads_) schedule(static)
    for (std::size_t i = 0; i < n_nodes; ++i)
      pressure_fit_row<dim>(sums.water_volume[i], m.volume_first_moment[i],
                            m.volume_second_moment[i], smallest_cell_height_, node_fit_alpha_[i],
                            node_fit_beta_[i]);
  }
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    const double pore_volume = node_porosity_[i] * node_mesh_volume_[i];
    node_pressure_[i] = sums.water_volume[i] > 0 ? sums.water_volume_pressure[i] /
                                                       std::max(sums.water_volume[i], pore_volume)
                                                 : 0.0;
    if (nodal_pressure_) {
      node_fitted_pressure_[i] =
          node_fit_alpha_[i] * sums.water_volume_pressure[i] +
          node_fit_beta_[i].dot(pressure_fit_.sums().pressure_first_moment[i]);
      if (sums.water_volume[i] > 0)
        node_pressure_[i] =
            node_fitted_pressure_[i] * std::min(1.0, sums.water_volume[i] / pore_volume);
    }
  }
  coupling_.run(
      points.size(), [](CouplingSums& c) { return std::tie(c.grain_pressure_force); },
      [&](CouplingSums& c, std::size_t p) {
        const int cell = points.cell[p];
        const auto& nodes = mesh_.cell_nodes[cell];
        const auto& grad = mesh_.cell_shape_gradient[cell];
        double pore_pressure = 0;
        for (int i = 0; i <= dim; ++i)
          pore_pressure += solid_.shape[p](i) * node_pressure_[nodes[i]];
        if (pore_pressure == 0) return;
        const double grain_volume =
            pore_pressure_cell_scale_[cell] * points.volume[p] * (1.0 - porosity(p));
        for (int i = 0; i <= dim; ++i)
          c.grain_pressure_force[nodes[i]] += pore_pressure * grain_volume * grad[i];
      });
  if (nodal_pressure_) {
    pressure_fit_.run(
        liquid.size(), [](PressureFitSums& c) { return std::tie(c.water_pressure_force); },
        [&](PressureFitSums& c, std::size_t q) {
          const int cell = liquid.cell[q];
          const auto& nodes = mesh_.cell_nodes[cell];
          const auto& grad = mesh_.cell_shape_gradient[cell];
          double smoothed = 0;
          for (int i = 0; i <= dim; ++i)
            smoothed += water_.shape[q](i) * node_fitted_pressure_[nodes[i]];
          const double w = water_scale[cell] * smoothed * liquid.volume[q];
          for (int i = 0; i <= dim; ++i) c.water_pressure_force[nodes[i]] += w * grad[i];
        });
  }
}

// The pore pressure over the cell's own volume, not over its points' quadrature of it
// (issue 8 item 4; scientific manual 10.4, "What the projection does to a soil's pore
// pressure").
// Why: with linear cells the nodal pressure forces of eqs. (15), (16) see each cell through
// the sum of V p over its points. Once a soil's points have crossed cells, its cells hold more
// or less point volume than they have, and a pressure p that is even across them pushes with
// p times the gradient of that crowding; p is depth / h times rho_w g h (4 in a layer 0.1 m
// thick on 0.025 m cells, tens under a reservoir). In free water eq. (8) evens that out
// within a few acoustic steps. In a soil the water must seep through the grains first, which
// in fine sand takes longer than the pressure projection leaves it, so the water leant on the
// grains: a rigid translation of 0.1 mm sand at 0.5 m/s lost a third of its mean pore
// pressure (284.8 against 424.2 Pa at rest; 411.9 with this), and a `contact` bed turned the
// skeleton's extra load into friction.
// What: every point of a cell inside a soil weighs its pressure by |c| / (sum over the cell's
// soil points of V_p). The force of an even pressure is then that of the cell's volume,
// whatever the points' spread. The soil's quadrature is the measure, so water that crowds
// the pores more than the grains do still pushes out. Eq. (8) takes the same factor: the
// water's volume change in the cell is shared by the points that fill it. Only cells none of
// whose nodes touches a cell without soil points are scaled: at a soil's surface the points
// fill only part of a cell, and their volume is then the right measure of it.
// With [solver] pore_pressure_cell_measure = "water" (December 2026, stop 31) the water
// points weigh theirs by n |c| / (sum over the cell's water points of V_q), n the soil
// points' porosity in the cell: the water pushes with exactly the cell's pores wherever its
// points are, and eq. (8) shares the cell's water volume change by the points that hold it.
// Why: the soil's measure is right only while the water points sit where the soil points do.
// The pore water volume projection moves them off the grains; a fine-sand block sliding
// under water (verification/saturated_block_fine, 0.01 m cells) then read its travel as an
// expansion, its pore water fell 1.26 kPa below hydrostatic in 0.21 m, and its friction
// ratio was 0.317 (0.553 with the water's measure; 0.571 exact). Not the default: the quick
// seepage column drains at 0.83 of Ergun's flux with it, against 0.92 (its full variant:
// 1.03 against 1.07).
template <int dim>
void Simulation<dim>::update_pore_pressure_cell_scale() {
  const MaterialPoints<dim>& points = solid_.points;
  const std::size_t n_cells = mesh_.cell_count();
  const bool water_measure =
      description_.solver.pore_pressure_cell_measure == PorePressureMeasure::kWater;
  const bool free_water = description_.solver.free_water_cell_volume;
  const bool soil_porosity =
      water_measure || description_.solver.liquid_advection == LiquidAdvection::kFlux;
  // Serial: a few adds per point, and the same bits on any thread count.
  std::vector<double>& scale = pore_pressure_cell_scale_;
  std::vector<double>& porosity_c = cell_soil_porosity_;  // the soil's pore volume, then n_c
  std::fill(scale.begin(), scale.end(), 0.0);
  if (soil_porosity) porosity_c.assign(n_cells, 0.0);
  for (std::size_t p = 0; p < points.size(); ++p) {
    scale[points.cell[p]] += points.volume[p];
    if (soil_porosity) porosity_c[points.cell[p]] += points.volume[p] * porosity(p);
  }
  if (soil_porosity)
    for (std::size_t c = 0; c < n_cells; ++c)
      porosity_c[c] = scale[c] > 0 ? porosity_c[c] / scale[c] : 1.0;
  std::vector<double>& water = pore_water_cell_volume_;
  if (water_measure || free_water) {
    pore_water_cell_scale_.resize(n_cells);
    const LiquidPoints<dim>& liquid = water_.points;
    water.assign(n_cells, 0.0);
    for (std::size_t q = 0; q < liquid.size(); ++q) water[liquid.cell[q]] += liquid.volume[q];
  }
  std::vector<char>& surface = pore_pressure_surface_node_;
  mark_edge_nodes(
      mesh_.cell_nodes, mesh_.node_count(), [&](std::size_t c) { return cell_has_soil_[c] != 0; },
      surface);
  for (std::size_t c = 0; c < n_cells; ++c) {
    // The cell holds soil points (scale[c] > 0, cell_has_soil_) and touches no cell without.
    const bool inside = scale[c] > 0 && interior_cell(mesh_.cell_nodes[c], surface);
    // The water's own measure (PorePressureMeasure::kWater): the cell's pores, |c| times the
    // soil points' porosity there, over the water points' volume sum, in the same cells.
    if (water_measure)
      pore_water_cell_scale_[c] =
          inside && water[c] > 0 ? mesh_.cell_volume[c] * porosity_c[c] / water[c] : 1.0;
    scale[c] = inside ? mesh_.cell_volume[c] / scale[c] : 1.0;
  }
  if (!free_water) return;
  // Free water (free_water_cell_volume): its interior cells weigh their points' pressure by
  // |c| / (sum of the cell's water points' volumes), as the soil's cells do above, in the
  // pressure force of eqs. (15), (16) and, as its adjoint, in the divergence of eq. (8), so that
  // the nodal force of a pressure field is the weak form's over the cell, whatever the points'
  // spread. Why: the force of the points' pressures, sum_q V_q p_q grad N_i, sees each cell's
  // pressure only through its sum over the points, sum_q V_q p_q; where the points' volumes
  // over- or under-fill a cell (their quadrature scatters by 20-35 % once a lattice has moved
  // a fraction of a cell), equilibrium needs a pressure that differs from cell to cell by as
  // much. The periodic pressure projection (pressure_projection.cpp) smooths that pattern
  // away; the water then compresses by dp / K_w to build it again, and that compression is
  // never given back: in a standing wave the points settled by 3.5 mm in 3 s at 0.02 m cells
  // (verification/standing_wave), at a rate proportional to the number of projections and to
  // 1 / K_w. Weighed by the cell's own volume, an even pressure is in balance whatever the
  // spread, and the projection takes nothing the balance needs. Cells at the water's surface
  // keep 1: their points fill only part of them. Soil cells keep the soil's measure, and free
  // water cells that touch a soil cell keep 1 too: a pond's points crowd at a sand's surface,
  // and that crowding is what pushes the water on into the sand (stop 32); scaled, the quick
  // seepage column drained at 0.76 of Ergun's flux (0.92 unscaled).
  std::vector<char>& edge = water_surface_node_;
  mark_edge_nodes(
      mesh_.cell_nodes, mesh_.node_count(),
      [&](std::size_t c) { return water[c] > 0 && !cell_has_soil_[c]; }, edge);
  for (std::size_t c = 0; c < n_cells; ++c) {
    if (cell_has_soil_[c]) {
      if (!water_measure) pore_water_cell_scale_[c] = scale[c];
      continue;
    }
    const bool inside = water[c] > 0 && interior_cell(mesh_.cell_nodes[c], edge);
    pore_water_cell_scale_[c] = inside ? mesh_.cell_volume[c] / water[c] : 1.0;
  }
}

namespace {
// Implicit drag between grains (mass m_s, velocity v_s) and water (m_w, v_w) with
// a = dt sum_s N V_s C: the 2x2 system of the header comment, momentum conserving.
template <class V>
void implicit_drag(double a, double ms, V& vs, double mw, V& vw) {
  if (!(a > 0)) return;
  const double det = ms * mw + a * (ms + mw);
  const V ps = ms * vs, pw = mw * vw;
  vs = ((mw + a) * ps + a * pw) / det;
  vw = (a * ps + (ms + a) * pw) / det;
}

// The water's mean velocity at a node from its two fields, free (mass m_f) and pore (m_p):
// exactly the one field's velocity where the other is absent.
template <class Vec>
Vec mean_water_velocity(double free_mass, const Vec& free_velocity, double pore_mass,
                        const Vec& pore_velocity) {
  if (pore_mass <= kMassFloor) return free_velocity;
  if (free_mass <= kMassFloor) return pore_velocity;
  return (free_mass * free_velocity + pore_mass * pore_velocity) / (free_mass + pore_mass);
}
}  // namespace

// At a node where free water meets pore water (the soil's surface): the water crosses the
// surface as one, and slides along it freely. Normal to the surface (n, the direction of the
// solid mass gradient) both fields take their common, mass-weighted velocity, dragged as one
// water mass m_w = m_f + m_p: the water crossing the surface is resisted as before the
// fields were split. Along the surface only the pore water is dragged; the free water keeps
// its own tangential velocity (inviscid water slips past the grains' surface and is not
// carried along by them). Without a surface direction (solid on all sides) the two fields
// move as one, dragged as one.
// Tried and lost (December 2026): holding the free water to the mixture's flux instead,
// v_f . n = (1 - phi) v_s . n + phi v_p . n, by an impulse shared with the grains and the
// pore water as a pressure is: the seepage column drained at 0.83 of Ergun's flux (0.98 with
// the common velocity) and both saturated blocks went unstable within 6000 steps.
template <int dim>
void Simulation<dim>::couple_across_soil_surface(std::size_t node, double a, double ms, Vec& vs,
                                                 double mf, Vec& vf, double mp, Vec& vp) const {
  const double mw = mf + mp;
  const Vec gradient = coupling_.sums().solid_mass_gradient[node];
  const double length = gradient.norm();
  const bool has_solid = ms > kMassFloor;
  // A mass gradient below a thousandth of the node's solid mass over the smallest cell height
  // of the mesh: no surface.
  if (!has_solid || !(length > 1e-3 * ms / smallest_cell_height_)) {
    Vec vw = (mf * vf + mp * vp) / mw;
    if (has_solid) implicit_drag(a, ms, vs, mw, vw);
    vf = vw;
    vp = vw;
    return;
  }
  const Vec normal = gradient / length;
  Vec vs_t = vs - vs.dot(normal) * normal, vp_t = vp - vp.dot(normal) * normal;
  const Vec vf_t = vf - vf.dot(normal) * normal;
  Eigen::Matrix<double, 1, 1> vs_n{vs.dot(normal)};
  Eigen::Matrix<double, 1, 1> vw_n{(mf * vf.dot(normal) + mp * vp.dot(normal)) / mw};
  implicit_drag(a, ms, vs_n, mw, vw_n);
  implicit_drag(a, ms, vs_t, mp, vp_t);
  vs = vs_t + vs_n(0) * normal;
  vf = vf_t + vw_n(0) * normal;
  vp = vp_t + vw_n(0) * normal;
}

// Step 1 of the nodal update at node i: each phase's velocity before the step and its
// explicit force; the water's two fields (free water, pore water) each from its own mass,
// momentum and force.
template <int dim>
typename Simulation<dim>::NodeStep Simulation<dim>::two_phase_node_step(std::size_t i,
                                                                        double damping) const {
  const detail::PhaseSums<dim>& solid = solid_.nodal.sums();
  const detail::LiquidSums<dim>& liquid = water_.nodal.sums();
  const CouplingSums& coupling = coupling_.sums();
  NodeStep n;
  n.ms = solid.mass[i];
  n.mp = liquid.pore_mass[i];
  n.mf = liquid.mass[i] - n.mp;
  n.vs_old = velocity_from_momentum(solid.momentum[i], n.ms);
  n.vf_old = velocity_from_momentum(Vec(liquid.momentum[i] - liquid.pore_momentum[i]), n.mf);
  n.vp_old = velocity_from_momentum(liquid.pore_momentum[i], n.mp);
  // Eqs. (15), (16): the pore-pressure force shared by the volumes the phases fill.
  const Vec pressure_force =
      (nodal_pressure_ ? pressure_fit_.sums().water_pressure_force[i] : liquid.pressure_force[i]) +
      coupling.grain_pressure_force[i];
  const double water_share = pore_pressure_water_share(i);
  const Vec water_force = water_share * pressure_force;
  // The water's share goes to its two fields by mass (one pressure per node, one
  // acceleration); the normal coupling of step 3 keeps them together across the soil's
  // surface.
  const Vec pore_water_force =
      n.mp > kMassFloor ? Vec(water_force * (n.mp / liquid.mass[i])) : Vec(Vec::Zero());
  n.fs = solid.force[i] + (1.0 - water_share) * pressure_force;
  n.ff = liquid.force[i] - liquid.pore_force[i] + (water_force - pore_water_force);
  n.fp = liquid.pore_force[i] + pore_water_force;
  apply_local_damping(n.fs, n.vs_old, damping);
  apply_local_damping(n.ff, n.vf_old, damping);
  apply_local_damping(n.fp, n.vp_old, damping);
  return n;
}

template <int dim>
void Simulation<dim>::two_phase_nodal_update(double dt, double damping) {
  const std::size_t n_nodes = mesh_.node_count();
  const detail::PhaseSums<dim>& solid = solid_.nodal.sums();
  const detail::LiquidSums<dim>& liquid = water_.nodal.sums();
  const CouplingSums& coupling = coupling_.sums();
  // 1. Each phase's velocity after its explicit forces; the water's two fields (free water,
  // pore water) each from its own mass, momentum and force.
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    const NodeStep n = two_phase_node_step(i, damping);
    solid_.node_velocity[i] = n.ms > kMassFloor ? Vec(n.vs_old + dt * n.fs / n.ms) : Vec::Zero();
    water_.node_velocity[i] = n.mf > kMassFloor ? Vec(n.vf_old + dt * n.ff / n.mf) : Vec::Zero();
    pore_water_velocity_[i] = n.mp > kMassFloor ? Vec(n.vp_old + dt * n.fp / n.mp) : Vec::Zero();
    solid_.node_acceleration[i] = n.vs_old;
    water_.node_acceleration[i] = n.vf_old;
    pore_water_acceleration_[i] = n.vp_old;
  }
  // 2. The walls act on each phase before the drag couples them. At a contact wall the
  // grains' share of the pore pressure on the wall is given back without friction, and
  // Coulomb's law acts on what the skeleton itself pushes: the effective stress only (eq. 14).
  // Were the walls to come after the drag, then where the drag locks the phases the grains'
  // approach would carry m_s / (m_s + m_w) of the water's push on the wall too, and the
  // friction would act on 0.8 sigma'_n + 0.2 p (n = 0.4 quartz): a saturated block of fine
  // sand under 0.4 m of water slid at 0.31 of its frictionless acceleration instead of
  // 1 - mu / tan(theta) = 0.57 (verification/saturated_block/history.md). Only the contact
  // nodes need the push (a few hundred at most), each written by one iteration.
  for (const NodalConstraint<dim>* c : solid_.constraints)
    if (c->type == BoundaryType::kContact)
      for (int node : c->nodes)
        node_wall_pore_pressure_push_[node] = wall_pore_pressure_push(node, dt);
  apply_constraints<dim>(solid_.constraints, solid_.node_velocity, &node_wall_pore_pressure_push_);
  apply_constraints<dim>(water_.constraints, water_.node_velocity, nullptr, false);
  apply_constraints<dim>(water_.constraints, pore_water_velocity_, nullptr, false);
  // 3. Drag, sponges, absent phases.
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    const double ms = solid.mass[i], mp = liquid.pore_mass[i];
    const double mf = liquid.mass[i] - mp;
    const bool has_solid = ms > kMassFloor, has_pore = mp > kMassFloor, has_free = mf > kMassFloor;
    Vec vs = solid_.node_velocity[i];
    Vec vf = water_.node_velocity[i];
    Vec vp = pore_water_velocity_[i];
    const double a = dt * coupling.drag[i];
    if (has_pore && has_free)
      couple_across_soil_surface(i, a, ms, vs, mf, vf, mp, vp);
    else if (has_solid && has_pore)
      implicit_drag(a, ms, vs, mp, vp);
    // Sponge zone: dv/dt = -sigma v for the water, integrated implicitly (backward Euler), so
    // any sigma dt is stable and the water comes to rest, never reverses. sigma = 0 divides
    // by exactly 1: water outside the zones is untouched to the last bit.
    if (!node_sponge_rate_.empty()) {
      if (has_free) vf /= 1.0 + dt * node_sponge_rate_[i];
      if (has_pore) vp /= 1.0 + dt * node_sponge_rate_[i];
    }
    // Where a phase or a field is absent its velocity is taken as the one beside it, so the
    // mixture flux of eq. (8) and the relative velocity of eq. (23) see no phantom motion.
    if (!has_pore) vp = has_solid ? vs : vf;
    if (!has_free) vf = vp;
    if (!has_solid) vs = mean_water_velocity(mf, vf, mp, vp);
    solid_.node_velocity[i] = vs;
    water_.node_velocity[i] = vf;
    pore_water_velocity_[i] = vp;
  }
  // 4. The walls again (the drag mixes the phases' normal velocities where only one was
  // held), with the plain laws, and the accelerations.
  finish_nodal_update(solid_, dt, threads_);
  finish_nodal_update<dim>(water_, dt, threads_, false);
  apply_constraints<dim>(water_.constraints, pore_water_velocity_, nullptr, false);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    pore_water_acceleration_[i] = (pore_water_velocity_[i] - pore_water_acceleration_[i]) / dt;
    mean_water_velocity_[i] =
        mean_water_velocity(liquid.mass[i] - liquid.pore_mass[i], water_.node_velocity[i],
                            liquid.pore_mass[i], pore_water_velocity_[i]);
  }
}

// The water's share s_i of the pore-pressure force at node i. Eqs. (15), (16) give the water n
// and the grains 1 - n of -grad p per unit volume: per unit volume of the wet mixture, water
// and the grains it surrounds, since dry grains feel no pore pressure. The nodal porosity
// n_i = 1 - S_i / V_i (S_i the grains' volume, V_i the node's) counts all the node's volume
// that the grains leave free as pore space, the empty space beside a soil too. Where the
// water fills that space, n_i is the right share. Where it does not, the water fills the
// pores first: with P_i the pore volume of the soil at the node (its points' volume less
// S_i) and W_i the water volume, a fraction min(1, W_i / P_i) of the grains is wet, and
//     s_i = W_i / (W_i + S_i min(1, W_i / P_i)) = max(n_soil, W_i / (W_i + S_i)),
// n_soil = P_i / (P_i + S_i) the soil's own porosity: water only in pores takes n_soil
// however full they are, free water beside the soil adds its own volume. W_i is capped at
// n_i V_i, the most the node can hold: where the pores are full, the water points' own sum
// carries their quadrature noise, and W_i / (W_i + S_i) uncapped took the saturated block's
// friction ratio from 0.571 to 0.558 and the seepage flux from 0.92 to 0.88 of Ergun's.
// Measured (December 2026), a saturated column between roller walls that starts in the
// exact equilibrium (TwoPhase.WaterTableAtTheSoilSurfaceStaysHydrostatic):
// - the water table at the soil's surface: with n_i, the surface row of nodes, half covered
//   (n_i = 0.7, water 0.4 of the filled volume), gave its water 0.7 / 0.4 of the force that
//   holds it up; the pore pressure fell to 0.896 of hydrostatic and the effective stress
//   rose to 1.108 times its value. With s_i: 1.008 and 1.000.
// - the water table half-way down a dry soil (TwoPhase.WaterTableInsideASoilStaysPut): n_i
//   and s_i give the same, 1.069 and 0.993; the rule W_i / (W_i + S_i) without n_soil,
//   which counts the dry grains above the water table as wet, 1.45 and 0.92.
template <int dim>
double Simulation<dim>::pore_pressure_water_share(std::size_t node) const {
  const double n = node_porosity_[node];
  const double grains = coupling_.sums().solid_volume[node];
  const double soil = coupling_.sums().soil_volume[node];
  if (!(soil > 0)) return n;  // free water (or nothing)
  const double soil_porosity = 1.0 - grains / soil;
  const double water =
      std::min(water_.nodal.sums().water_volume[node], n * node_mesh_volume_[node]);
  const double filled = (1.0 - n) * node_mesh_volume_[node] + water;
  return std::max(soil_porosity, filled > 0 ? water / filled : n);
}

// The wall's reaction to the grains' share of the pore pressure at a wall node, as the velocity
// dt (1 - n) W / m_s it gives the grains. The nodal pore-pressure force is
//     F_i = integral p grad N_i dV = -integral N_i grad p dV + integral over the wall N_i p nu dS,
// the weak form's boundary term being the wall's reaction that the momentum equation leaves
// out. W_i = F_i + integral N_i grad p dV is that wall term, p A nu (nu the outward normal).
// The volume integral is taken hydrostatic, rho_w g over the node's wet volume (its pore water
// W_i / n_i, at most the node's volume; zero in a dry soil). Not from the gradient of the
// nodal pressures: at the wall row those are one-sided averages, low by about rho_w g h / 3
// (TwoPhase.SaturatedBedUnderWaterStaysAtRest), which took 3.5 % off the saturated block's
// acceleration (1.371 against 1.421 m/s2). Using the nodal mean pressure p_i A for W instead (until
// December 2026) counted the pressure half a cell inside the soil: +3.8 % of the effective
// stress of verification/saturated_block at 0.02 m cells.
template <int dim>
typename Simulation<dim>::Vec Simulation<dim>::wall_pore_pressure_load(int node) const {
  const double n = node_porosity_[node];
  const double wet_volume =
      std::min(node_mesh_volume_[node], water_.nodal.sums().water_volume[node] / n);
  const Vec gradient_load = materials_[pore_liquid_].liquid_density * wet_volume * gravity_;
  return (nodal_pressure_ ? pressure_fit_.sums().water_pressure_force[node]
                          : water_.nodal.sums().pressure_force[node]) +
         coupling_.sums().grain_pressure_force[node] + gradient_load;
}

template <int dim>
typename Simulation<dim>::Vec Simulation<dim>::wall_pore_pressure_push(int node, double dt) const {
  const double ms = solid_.nodal.sums().mass[node];
  if (ms <= kMassFloor) return Vec::Zero();
  // The grains' share of the pore-pressure force, as in two_phase_nodal_update: the push must
  // give back exactly what the nodal update gave the grains, or the difference acts as a
  // skeleton load and takes friction.
  return dt * (1.0 - pore_pressure_water_share(static_cast<std::size_t>(node))) *
         wall_pore_pressure_load(node) / ms;
}

template <int dim>
void Simulation<dim>::remap_liquid_momentum() {
  // The MUSL remap of both water fields: the momentum of the updated point velocities, the
  // pore water's apart (the masses are the step's).
  const LiquidPoints<dim>& liquid = water_.points;
  water_.nodal.run(
      liquid.size(),
      [](detail::LiquidSums<dim>& s) { return std::tie(s.momentum, s.pore_momentum); },
      [&](detail::LiquidSums<dim>& b, std::size_t q) {
        const auto& nodes = mesh_.cell_nodes[liquid.cell[q]];
        const Vec momentum = liquid.mass[q] * liquid.velocity[q];
        for (int i = 0; i <= dim; ++i) b.momentum[nodes[i]] += water_.shape[q](i) * momentum;
        if (liquid_in_soil_[q])
          for (int i = 0; i <= dim; ++i) b.pore_momentum[nodes[i]] += water_.shape[q](i) * momentum;
      });
  const detail::LiquidSums<dim>& sums = water_.nodal.sums();
  const std::vector<double>& solid_mass = solid_.nodal.sums().mass;
  const std::size_t n_nodes = mesh_.node_count();
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    const double mp = sums.pore_mass[i], mf = sums.mass[i] - mp;
    Vec vf = velocity_from_momentum(Vec(sums.momentum[i] - sums.pore_momentum[i]), mf);
    Vec vp = velocity_from_momentum(sums.pore_momentum[i], mp);
    // As in the nodal update: an absent phase or field moves with the one beside it.
    const bool has_solid = solid_mass[i] > kMassFloor;
    if (mp > kMassFloor && mf > kMassFloor) {
      Vec vs = solid_.node_velocity[i];  // no drag here (a = 0): the common normal velocity
      couple_across_soil_surface(i, 0.0, solid_mass[i], vs, mf, vf, mp, vp);
    }
    if (!(mp > kMassFloor)) vp = has_solid ? solid_.node_velocity[i] : vf;
    if (!(mf > kMassFloor)) vf = vp;
    water_.node_velocity[i] = vf;
    pore_water_velocity_[i] = vp;
    if (!has_solid && sums.mass[i] > kMassFloor)
      solid_.node_velocity[i] = mean_water_velocity(mf, vf, mp, vp);
  }
  apply_constraints<dim>(water_.constraints, water_.node_velocity, nullptr, false);
  apply_constraints<dim>(water_.constraints, pore_water_velocity_, nullptr, false);
  apply_constraints<dim>(solid_.constraints, solid_.node_velocity);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i)
    mean_water_velocity_[i] =
        mean_water_velocity(sums.mass[i] - sums.pore_mass[i], water_.node_velocity[i],
                            sums.pore_mass[i], pore_water_velocity_[i]);
}

template <int dim>
void Simulation<dim>::update_liquid_and_relocate(double dt) {
  using Gradient = Eigen::Matrix<double, dim, dim>;
  LiquidPoints<dim>& liquid = water_.points;
  const std::size_t n_liquid = liquid.size();
  const std::vector<double>& water_scale = water_cell_scale();
  // Divergence of the mixture's volume flux (the bracket of eq. 8) and the viscous stress
  // (eqs. 17, 18) from the nodal velocities after the remap.
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const int cell = liquid.cell[q];
    const auto& nodes = mesh_.cell_nodes[cell];
    const auto& grad = mesh_.cell_shape_gradient[cell];
    // The viscous stress from the point's own water field; the flux from the mean.
    const Vec* own_water =
        liquid_in_soil_[q] ? pore_water_velocity_.data() : water_.node_velocity.data();
    Gradient l = Gradient::Zero();
    double divergence = 0;
    for (int i = 0; i <= dim; ++i) {
      const int node = nodes[i];
      const double n = node_porosity_[node];
      const Vec flux = (1.0 - n) * solid_.node_velocity[node] + n * mean_water_velocity_[node];
      divergence += flux.dot(grad[i]);
      l.noalias() += own_water[node] * grad[i].transpose();
    }
    // The volume change of the cell's water, shared by its points' volumes (the adjoint of the
    // scaled pressure force; update_pore_pressure_cell_scale).
    divergence *= water_scale[cell];
    liquid_flux_divergence_[q] = divergence;
    // Newtonian viscous stress mu (grad v + grad v^T) = 2 mu D (eq. 17 with eq. 18 read as
    // twice the strain rate D), stored in the engineering-shear Voigt layout as a stress.
    const MaterialModelData& water = materials_[liquid.material[q]];
    const Voigt6 rate = strain_increment(l, 1.0);  // D_xx, D_yy, D_zz, 2 D_xy, ...
    Voigt6& tau = liquid.viscous_stress[q];
    for (int k = 0; k < 3; ++k) tau(k) = 2.0 * water.viscosity * rate(k);
    for (int k = 3; k < 6; ++k) tau(k) = water.viscosity * rate(k);
    // Artificial bulk viscosity (scientific manual 10.5): zeta div(q) / n on the normal
    // stresses, from the same flux divergence that compresses the water in eq. (8), so it
    // resists exactly the motion that changes the pressure and vanishes in incompressible
    // flow. Without it the weakly compressible water keeps every sound wave it is given (a
    // still tank's corner started one that grew into sloshing once the PIC damping was
    // weakened).
    const double zeta =
        liquid_bulk_viscosity(description_.solver.liquid_bulk_viscosity, water.liquid_density,
                              water.wave_speed, mesh_.cell_min_height[cell]);
    const double n = std::max(liquid.porosity[q], kMinimumPorosity);
    for (int k = 0; k < dim; ++k) tau(k) += zeta * divergence / n;
  }

  // With the nodal fit (liquid_to_nodes), each point's pressure takes the V-adjoint of the
  // fit of the divergence: sum_i N_i (alpha_i + beta_i . (x - x_i)) sum N V div(q), positions
  // at the start of the step (from the shape values, exact for linear cells).
  const double* divergence = liquid_flux_divergence_.data();
  if (nodal_pressure_) {
    const std::vector<double>& nodal = scatter_liquid(liquid_flux_divergence_);
    const std::vector<double>& volume = water_.nodal.sums().water_volume;
#pragma omp parallel for num_threads(threads_) schedule(static)
    for (std::size_t q = 0; q < n_liquid; ++q) {
      const auto& nodes = mesh_.cell_nodes[liquid.cell[q]];
      Vec x = Vec::Zero();
      for (int i = 0; i <= dim; ++i) x += water_.shape[q](i) * mesh_.node_position[nodes[i]];
      double value = 0, unit = 0;
      for (int i = 0; i <= dim; ++i) {
        const std::size_t node = static_cast<std::size_t>(nodes[i]);
        const double weight =
            water_.shape[q](i) *
            (node_fit_alpha_[node] + node_fit_beta_[node].dot(x - mesh_.node_position[node]));
        value += weight * nodal[node];
        unit += weight * volume[node];
      }
      // The adjoint of the fit does not keep a uniform divergence uniform near walls and
      // surfaces (its weights tilt there); dividing by its value for a uniform field keeps it,
      // and keeps the energy balance too, with each point's pressure energy weighted by that
      // value (at least a quarter). Without it, verification/terzaghi's points split into bands
      // of different pressure at one depth (RMS 0.27 q at T = 0.1).
      value /= std::max(unit, 0.25);
      smoothed_flux_divergence_[q] = value;
    }
    divergence = smoothed_flux_divergence_.data();
  }
  FirstFault fault;
  double dt_next = next_time_step_;
#pragma omp parallel for num_threads(threads_) schedule(static) reduction(min : dt_next)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const MaterialModelData& water = materials_[liquid.material[q]];
    const double n = std::max(liquid.porosity[q], kMinimumPorosity);
    // Eq. (8), compression positive; no tension (free surface, cavitation). A drop flying
    // free (no other water and no grains at its nodes, none held by a wall) is at the
    // atmosphere's pressure: the grid sees no divergence in it, and the pressure it left the
    // water with would stay frozen until it lands (is_free_body, phase.hpp).
    double& p = liquid.pressure[q];
    if (detail::is_free_body(water_, mesh_, q, &solid_.nodal.sums().mass))
      p = 0;
    else
      p = std::max(0.0, p - water.bulk_modulus / n * divergence[q] * dt);
    // Water volume from eq. (7): rho_w = rho_w0 (1 + p / K_w).
    liquid.volume[q] = water_volume(liquid.mass[q], water.liquid_density, p, water.bulk_modulus);
    const double speed = liquid.velocity[q].norm();
    const PointFault kind = relocate(water_, mesh_, q, speed, std::isfinite(p), max_velocity_);
    if (kind != PointFault::kNone) {
      fault.note(q, kind);
    } else {
      const double h = mesh_.cell_min_height[liquid.cell[q]];
      dt_next = std::min(dt_next, h / liquid_signal_speed(description_.solver.liquid_bulk_viscosity,
                                                          water.liquid_density, water.wave_speed,
                                                          water.viscosity, speed, h));
    }
  }
  next_time_step_ = dt_next;
  if (fault.point >= 0) {
    const std::size_t q = static_cast<std::size_t>(fault.point);
    std::ostringstream m;
    m << "step " << step_count_ << ": liquid point " << liquid.id[q] << " (material '"
      << description_.materials[liquid.material[q]].name << "') at "
      << format_vector(liquid.position[q].data(), dim) << ": ";
    if (fault.kind == PointFault::kNotFinite)
      m << "velocity or pressure is not finite (velocity "
        << format_vector(liquid.velocity[q].data(), dim) << ", pressure " << liquid.pressure[q]
        << " Pa); the run went unstable: reduce the Courant number";
    else
      // Water jets out of the impact zone are FLIP noise grown unchecked (user manual, 2.6):
      // a shorter liquid damping time is the first thing to try, the Courant number rarely.
      m << describe_fault(fault.kind, liquid.velocity[q], max_velocity_,
                          "try a shorter [solver] liquid_pic_damping_time, e.g. a tenth of the one "
                          "in output/log.txt, or a smaller Courant number");
    throw RunError(m.str());
  }
  // A crossed mesh: the pressure pattern no force acts on, removed (crossed_quadrangles.cpp),
  // and the changed points' volumes follow eq. (7) again (the scratch's per-cell change says
  // which: a point of a quadrangle that is not full of water keeps its pressure and volume).
  // After the fault check: every point is then in a cell.
  if (!crossed_quadrangles_.empty() &&
      remove_free_pressure_pattern(crossed_quadrangles_, liquid.cell, water_scale, liquid.volume,
                                   liquid.pressure, free_pattern_scratch_) > 0) {
    const std::vector<double>& change = free_pattern_scratch_.change;
#pragma omp parallel for num_threads(threads_) schedule(static)
    for (std::size_t q = 0; q < n_liquid; ++q) {
      if (change[liquid.cell[q]] == 0) continue;
      const MaterialModelData& water = materials_[liquid.material[q]];
      liquid.volume[q] = water_volume(liquid.mass[q], water.liquid_density, liquid.pressure[q],
                                      water.bulk_modulus);
    }
  }
}

// The liquid points moved by the water's volume flux through the pores, not by their field's
// velocity ([solver] liquid_advection = "flux"; scientific manual 10.4). Called after
// nodes_to_points, which moved each point by dt sum_i N_i v_i of its own field; this replaces
// that move by dt (v_s + sum_i N_i n_i (v_w,i - v_s,i) / n_c), v_s the grains' velocity at
// the point, v_w the water's mean velocity (eq. 8's), n_i the nodal porosity and n_c the
// porosity of the cell's soil points (their pore volume over their volume; 1 in a cell
// without soil).
// Why: eq. (8) conserves the water's volume through the mixture's flux (1 - n) v_s + n v_w,
// with n linear across each cell. The points moved with v_w instead. Where n is even the two
// agree, but at a soil's surface the grid's porosity ramps over a cell (0.7 at the surface
// node, 0.4 below) while the soil's pores are 0.4 right up to the surface. Water entering a
// sand at Darcy flux q must move at q / 0.4 in its pores; its points, interpolating the
// surface node's velocity (the two water fields' common, mass-weighted one, about 1.4 q), moved
// at about 2 q in the top cell and crowded it: the seepage column's top centimetre held 1.24 of
// its pores with pore_pressure_cell_measure = "water", the centimetre below 0.58, and the pore
// water volume projection sent the crowd back into the pond (0.83 of Ergun's flux). Moving the
// points with the flux over the soil's own pores keeps the top of the sand at 0.95-1.03 of its
// pores at 1 s, and the column drains at 0.94 ("water") and 0.98 ("soil") of Ergun's flux
// (verification/saturated_block_fine/known-failure.md, stop 32). A rigid motion (v_w = v_s)
// moves every point with the grains, as before. Not the default: the pond then ends
// 0.03-0.2 mm outside its band in three of the four seepage runs (quick and full, both
// measures), and the option has not been through the full verification.
template <int dim>
void Simulation<dim>::advect_liquid_by_flux(double dt) {
  LiquidPoints<dim>& liquid = water_.points;
  // n_c from this step's liquid_to_nodes (update_pore_pressure_cell_scale): the cells are the
  // step's start ones, for the grains and for these points alike.
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t q = 0; q < liquid.size(); ++q) {
    const int cell = liquid.cell[q];
    const auto& nodes = mesh_.cell_nodes[cell];
    const Shape& n = water_.shape[q];
    const Vec* own = liquid_in_soil_[q] ? pore_water_velocity_.data() : water_.node_velocity.data();
    Vec field = Vec::Zero(), grains = Vec::Zero(), relative_flux = Vec::Zero();
    for (int i = 0; i <= dim; ++i) {
      const int node = nodes[i];
      field += n(i) * own[node];
      grains += n(i) * solid_.node_velocity[node];
      relative_flux +=
          n(i) * node_porosity_[node] * (mean_water_velocity_[node] - solid_.node_velocity[node]);
    }
    const double pores = cell_soil_porosity_[cell];
    // The walls hold the nodal velocities of each phase, not this blend of them: where the
    // grains lift off a wall at a soil's surface node (porosity above the soil's), the blend
    // can point into the wall. A move that would take the point out of the mesh is not made;
    // the point keeps its field's move.
    const Vec moved = liquid.position[q] + dt * (grains + relative_flux / pores - field);
    Shape shape;
    if (mesh_.locate(cell, moved, shape) >= 0) liquid.position[q] = moved;
  }
}

// The water pressure the forces act with, at the points' current positions: each point's own
// with liquid_pressure = "points"; with "nodal_fit" the nodal fit interpolated to the point
// (liquid_to_nodes), which is what the output reports, since the points' own values then carry
// a part that no force feels. Refitted here from the points' state rather than taken from the
// last step's nodal fit (as the probes do): the output is then a function of the state alone, so
// a stage started from a checkpoint writes the same first frame as the whole run. Called once
// per output, so its serial pass and nodal scratch cost nothing per step.
template <int dim>
const std::vector<double>& Simulation<dim>::acting_liquid_pressure() const {
  const LiquidPoints<dim>& liquid = water_.points;
  if (!nodal_pressure_) return liquid.pressure;
  using Mat = Eigen::Matrix<double, dim, dim>;
  const std::size_t n_nodes = mesh_.node_count();
  std::vector<double> m0(n_nodes, 0.0), p0(n_nodes, 0.0);
  std::vector<Vec> m1(n_nodes, Vec::Zero()), p1(n_nodes, Vec::Zero());
  std::vector<Mat> m2(n_nodes, Mat::Zero());
  for (std::size_t q = 0; q < liquid.size(); ++q) {
    const auto& nodes = mesh_.cell_nodes[liquid.cell[q]];
    for (int i = 0; i <= dim; ++i) {
      const std::size_t node = static_cast<std::size_t>(nodes[i]);
      const double w = water_.shape[q](i) * liquid.volume[q];
      const Vec d = liquid.position[q] - mesh_.node_position[node];
      m0[node] += w;
      m1[node] += w * d;
      m2[node] += w * d * d.transpose();
      p0[node] += w * liquid.pressure[q];
      p1[node] += (w * liquid.pressure[q]) * d;
    }
  }
  std::vector<double> fitted(n_nodes, 0.0);
  for (std::size_t i = 0; i < n_nodes; ++i) {
    double alpha = 0;
    Vec beta = Vec::Zero();
    pressure_fit_row<dim>(m0[i], m1[i], m2[i], smallest_cell_height_, alpha, beta);
    fitted[i] = alpha * p0[i] + beta.dot(p1[i]);
  }
  acting_pressure_.resize(liquid.size());
  for (std::size_t q = 0; q < liquid.size(); ++q) {
    const auto& nodes = mesh_.cell_nodes[liquid.cell[q]];
    double value = 0;
    for (int i = 0; i <= dim; ++i) value += water_.shape[q](i) * fitted[nodes[i]];
    acting_pressure_[q] = value;
  }
  return acting_pressure_;
}

#define LITUYA_TWO_PHASE_INSTANCES(D)                                                             \
  template void Simulation<D>::setup_liquid();                                                    \
  template void Simulation<D>::relocate_liquid_for_test();                                        \
  template void Simulation<D>::update_pore_pressure_cell_scale();                                 \
  template void Simulation<D>::liquid_to_nodes();                                                 \
  template const std::vector<double>& Simulation<D>::acting_liquid_pressure() const;              \
  template void Simulation<D>::two_phase_nodal_update(double, double);                            \
  template Simulation<D>::NodeStep Simulation<D>::two_phase_node_step(std::size_t, double) const; \
  template Simulation<D>::Vec Simulation<D>::wall_pore_pressure_push(int, double) const;          \
  template Simulation<D>::Vec Simulation<D>::wall_pore_pressure_load(int) const;                  \
  template double Simulation<D>::pore_pressure_water_share(std::size_t) const;                    \
  template void Simulation<D>::couple_across_soil_surface(std::size_t, double, double, Vec&,      \
                                                          double, Vec&, double, Vec&) const;      \
  template void Simulation<D>::remap_liquid_momentum();                                           \
  template void Simulation<D>::update_liquid_and_relocate(double);                                \
  template void Simulation<D>::advect_liquid_by_flux(double);
LITUYA_TWO_PHASE_INSTANCES(2)
LITUYA_TWO_PHASE_INSTANCES(3)
#undef LITUYA_TWO_PHASE_INSTANCES

}  // namespace lituya::solver
