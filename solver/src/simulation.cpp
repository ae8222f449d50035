#include "lituya/solver/simulation.hpp"

#include <omp.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <sstream>

#include "lituya/common/input_error.hpp"
#include "lituya/common/process_memory.hpp"
#include "simulation_kernels.hpp"

namespace lituya::solver {

namespace {

using namespace detail;

// The default pressure projection period: this many steps of still water at this Courant
// number (resolve_pressure_projection()).
constexpr int kDefaultProjectionSteps = 10;
constexpr double kDefaultProjectionCourant = 0.5;

double wall_seconds() {
  using clock = std::chrono::steady_clock;
  static const auto start = clock::now();
  return std::chrono::duration<double>(clock::now() - start).count();
}

}  // namespace

template <int dim>
Simulation<dim>::Simulation(CaseDescription description, Mesh<dim> mesh, MaterialPoints<dim> points,
                            std::vector<NodalConstraint<dim>> constraints, LiquidPoints<dim> liquid)
    : description_(std::move(description)),
      mesh_(std::move(mesh)),
      constraints_(std::move(constraints)),
      has_liquid_(!liquid.empty()) {
  solid_.points = std::move(points);
  water_.points = std::move(liquid);
  for (int d = 0; d < dim; ++d) gravity_(d) = description_.gravity.at(d);
  damping_ = resolve_transfer_damping(
      description_.solver, characteristic_cell_size(mesh_.cell_volume, dim), gravity_.norm());
  musl_ = description_.solver.scheme == TransferScheme::kMUSL;
  max_velocity_ = description_.solver.max_velocity;
  volumetric_smoothing_ = description_.solver.volumetric_smoothing;
  for (const Material& m : description_.materials) {
    MaterialModelData data;
    data.model = m.model;
    if (m.is_liquid()) {
      data.liquid_density = m.liquid_density;
      data.bulk_modulus = m.bulk_modulus;
      data.viscosity = m.viscosity;
      data.wave_speed = std::sqrt(m.bulk_modulus / m.liquid_density);
      if (pore_liquid_ < 0) pore_liquid_ = static_cast<int>(materials_.size());
      materials_.push_back(std::move(data));
      continue;
    }
    data.solid_density = m.solid_density;
    data.dry_density = m.dry_density();
    data.max_porosity = m.max_porosity;
    data.grain_diameter = m.grain_diameter;
    data.elastic = ElasticConstants::from_young_poisson(m.youngs_modulus, m.poisson_ratio);
    if (m.model == MaterialModel::kMohrCoulomb)
      data.mohr_coulomb =
          std::make_unique<MohrCoulomb>(m.youngs_modulus, m.poisson_ratio, m.friction_angle,
                                        m.dilatancy_angle, m.cohesion, m.tensile_strength);
    data.wave_speed = std::sqrt(data.elastic.constrained_modulus() / m.dry_density());
    materials_.push_back(std::move(data));
  }
  solid_.damping = damping_.solid;
  water_.damping = damping_.liquid;
  // The grains take a wall's velocity for the components it holds (phase.hpp,
  // nodes_to_points). The water does not: there it damped the standing wave (scientific
  // manual 4.1).
  solid_.wall_velocity_to_points = true;
  set_threads(1);
  if (volumetric_smoothing_) point_volumetric_strain_.assign(solid_.points.size(), 0.0);
  locate_all<dim>(mesh_, solid_.points.position, solid_.points.cell, solid_.points.id, solid_.shape,
                  description_.points_file, "point");
  if (has_liquid_) setup_liquid();
  next_time_step_ = stable_time_step(1.0);
  resolve_pressure_projection();
}

template <int dim>
void Simulation<dim>::resolve_pressure_projection() {
  if (!has_liquid_) return;  // a dry scene projects nothing and logs nothing about it
  const SolverSettings& settings = description_.solver;
  std::ostringstream line;
  line.precision(3);
  line << "pressure projection: ";
  if (settings.pressure_projection_interval) {
    if (*settings.pressure_projection_interval > 0)
      line << "every " << *settings.pressure_projection_interval << " steps (given)";
    else
      line << "off (given)";
  } else if (settings.pressure_projection_time) {
    projection_time_ = *settings.pressure_projection_time;
    line << "every " << projection_time_ << " s (given)";
  } else {
    // Ten steps of still water at Courant 0.5, the step count that was the default until
    // December 2026: the same projections as then wherever the water sets the step, but now
    // fixed in time, so that the Courant number no longer changes how much they damp (user
    // manual 2.6). The step of still water is h_min / s, s the water's signal speed at rest
    // (sound and the viscous limits, as stable_time_step() takes it), in the smallest cell.
    double h_min = std::numeric_limits<double>::max();
    for (double h : mesh_.cell_min_height) h_min = std::min(h_min, h);
    double signal_speed = 0;
    for (const MaterialModelData& m : materials_)
      if (m.model == MaterialModel::kWater)
        signal_speed = std::max(signal_speed, detail::liquid_signal_speed(
                                                  settings.liquid_bulk_viscosity, m.liquid_density,
                                                  m.wave_speed, m.viscosity, 0.0, h_min));
    if (signal_speed > 0) {
      projection_time_ = kDefaultProjectionSteps * kDefaultProjectionCourant * h_min / signal_speed;
      line << "every " << projection_time_ << " s (" << kDefaultProjectionSteps
           << " steps of still water at Courant " << kDefaultProjectionCourant << ")";
    }
  }
  if (nodal_pressure_)
    line << "; liquid_pressure = \"nodal_fit\": no pressure is projected, the clock runs the pore "
            "water volume projection only";
  if (settings.pore_pressure_cell_measure == PorePressureMeasure::kWater)
    line << "; pore_pressure_cell_measure = \"water\": inside a soil the water points weigh "
            "their pressure by the cell's pores over their own volume";
  if (!settings.free_water_cell_volume)
    line << "; free_water_cell_volume = false: free water's interior cells weigh their points' "
            "pressure by the points' own volumes (water in motion settles)";
  if (settings.liquid_advection == LiquidAdvection::kFlux)
    line << "; liquid_advection = \"flux\": the liquid points move with the grains plus the "
            "water's relative volume flux over their cell's pores";
  if (!crossed_quadrangles_.empty())
    line << "; crossed mesh: the free pressure pattern of its " << crossed_quadrangles_.cells.size()
         << " quadrangles is removed each step (crossed_pressure_filter)";
  projection_description_ = line.str();
}

template <int dim>
double Simulation<dim>::porosity(std::size_t p) const {
  const MaterialPoints<dim>& points = solid_.points;
  const double rho_s = materials_[points.material[p]].solid_density;
  return 1.0 - points.mass[p] / (rho_s * points.volume[p]);
}

template <int dim>
void Simulation<dim>::set_threads(int threads) {
  // Per-thread nodal buffers (nodal_scatter.hpp): a dry case allocates none for water.
  threads_ = std::max(1, threads);
  const std::size_t n_nodes = mesh_.node_count();
  solid_.allocate_nodes(threads_, n_nodes);
  if (volumetric_smoothing_) smoothing_.allocate(threads_, n_nodes);
  if (has_liquid_) {
    water_.allocate_nodes(threads_, n_nodes);
    coupling_.allocate(threads_, n_nodes);
    projection_.sums.allocate(threads_, n_nodes);
    if (description_.solver.liquid_pressure == LiquidPressure::kNodalFit)
      pressure_fit_.allocate(threads_, n_nodes);
    if (description_.solver.liquid_xpic_order > 1) xpic_.allocate(threads_, n_nodes);
  }
}

template <int dim>
void Simulation<dim>::activate_boundaries(const std::vector<std::string>& names) {
  solid_.constraints.clear();
  water_.constraints.clear();
  active_tractions_.clear();
  for (const std::string& name : names)
    for (std::size_t i = 0; i < description_.boundaries.size(); ++i) {
      if (description_.boundaries[i].name != name) continue;
      const NodalConstraint<dim>* c = &constraints_[i];
      if (c->type == BoundaryType::kTraction)
        active_tractions_.push_back(c);
      else {
        if (c->phase != BoundaryPhase::kLiquid) solid_.constraints.push_back(c);
        if (c->phase != BoundaryPhase::kSolid) water_.constraints.push_back(c);
      }
    }
  solid_.hold_nodes();
  if (has_liquid_) water_.hold_nodes();
  // The nodes whose forces the boundary forces sum (wall_loads.cpp).
  collect_wall_nodes();
}

template <int dim>
void Simulation<dim>::apply_tractions() {
  // Surface loads: nodal forces on the loaded phase, where that phase has mass (a load on
  // empty space acts on nothing).
  for (const NodalConstraint<dim>* c : active_tractions_) {
    const bool liquid = c->phase == BoundaryPhase::kLiquid;
    if (liquid && !has_liquid_) continue;
    // A load ramp: the traction rises linearly from zero over ramp_time, so that a load does
    // not strike like a hammer (a sudden load rings as an undrained wave, see Terzaghi).
    const double factor = c->ramp_time > 0 ? std::min(1.0, stage_time_ / c->ramp_time) : 1.0;
    auto& sums =
        liquid ? static_cast<detail::PhaseSums<dim>&>(water_.nodal.sums()) : solid_.nodal.sums();
    std::vector<double>& mass = sums.mass;
    std::vector<Vec>& force = sums.force;
    for (std::size_t k = 0; k < c->nodes.size(); ++k)
      if (mass[c->nodes[k]] > kMassFloor) force[c->nodes[k]] += factor * c->force[k];
  }
}

template <int dim>
double Simulation<dim>::stable_time_step(double courant) const {
  // A minimum does not depend on the order of the comparisons: the reduction is exact.
  double dt = std::numeric_limits<double>::max();
  const MaterialPoints<dim>& points = solid_.points;
  const LiquidPoints<dim>& liquid = water_.points;
  const std::size_t n = points.size();
#pragma omp parallel for num_threads(threads_) reduction(min : dt) schedule(static)
  for (std::size_t p = 0; p < n; ++p) {
    const double speed = materials_[points.material[p]].wave_speed + points.velocity[p].norm();
    dt = std::min(dt, mesh_.cell_min_height[points.cell[p]] / speed);
  }
  const std::size_t n_liquid = liquid.size();
#pragma omp parallel for num_threads(threads_) reduction(min : dt) schedule(static)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const MaterialModelData& water = materials_[liquid.material[q]];
    const double h = mesh_.cell_min_height[liquid.cell[q]];
    dt = std::min(dt, h / detail::liquid_signal_speed(
                              description_.solver.liquid_bulk_viscosity, water.liquid_density,
                              water.wave_speed, water.viscosity, liquid.velocity[q].norm(), h));
  }
  return courant * dt;
}

template <int dim>
void Simulation<dim>::points_to_nodes(Transfer what) {
  // The solid's own stress is the effective stress sigma' (eq. 19).
  detail::scatter_to_nodes(solid_, mesh_, gravity_, solid_.points.stress, what, [](auto&&...) {});
}

template <int dim>
void Simulation<dim>::nodal_update(double dt, double damping) {
  if (has_liquid_) {
    two_phase_nodal_update(dt, damping);
    return;
  }
  const std::size_t n_nodes = mesh_.node_count();
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    if (solid_.nodal.sums().mass[i] <= kMassFloor) {
      solid_.node_velocity[i].setZero();
      solid_.node_acceleration[i].setZero();
      continue;
    }
    const NodeStep n = dry_node_step(i, damping);
    solid_.node_velocity[i] = n.vs_old + dt * n.fs / n.ms;
    solid_.node_acceleration[i] = n.vs_old;  // the old velocity, finished below
  }
  finish_nodal_update(solid_, dt, threads_);
}

template <int dim>
typename Simulation<dim>::NodeStep Simulation<dim>::dry_node_step(std::size_t i,
                                                                  double damping) const {
  const detail::PhaseSums<dim>& sums = solid_.nodal.sums();
  NodeStep n;
  n.ms = sums.mass[i];
  n.vs_old = sums.momentum[i] / n.ms;
  n.fs = sums.force[i];
  apply_local_damping(n.fs, n.vs_old, damping);
  return n;
}

template <int dim>
void Simulation<dim>::remap_momentum() {
  remap_velocity(solid_, mesh_, threads_);
  apply_constraints<dim>(solid_.constraints, solid_.node_velocity);
  if (has_liquid_) remap_liquid_momentum();
}

template <int dim>
double Simulation<dim>::reference_volume(std::size_t p) const {
  return solid_.points.mass[p] / materials_[solid_.points.material[p]].dry_density;
}

template <int dim>
void Simulation<dim>::smooth_volumetric_strain(double dt) {
  // The volumetric strain increment of a linear simplex is constant over the cell; with
  // more cells than nodes, isochoric flow over-constrains the mesh (locking). Averaging it
  // at the nodes and interpolating back (nodal_average.hpp) leaves one volumetric constraint
  // per node instead of per cell. The weights are the points' volumes at the dry density,
  // V_0 = m / rho_d, the measure of the Kirchhoff stress (4.6): a point dilated at a thin
  // front weighs what its grains weigh, not its inflated volume.
  const MaterialPoints<dim>& points = solid_.points;
  detail::nodal_average<dim>(
      smoothing_, mesh_, points.cell, solid_.shape, threads_,
      [&](std::size_t p) { return reference_volume(p); },
      [&](std::size_t p) {
        const int cell = points.cell[p];
        const auto& nodes = mesh_.cell_nodes[cell];
        const auto& grad = mesh_.cell_shape_gradient[cell];
        double divergence = 0;
        for (int i = 0; i <= dim; ++i) divergence += solid_.node_velocity[nodes[i]].dot(grad[i]);
        return divergence * dt;
      },
      [&](std::size_t p, double smoothed) { point_volumetric_strain_[p] = smoothed; });
}

template <int dim>
void Simulation<dim>::update_stress_and_relocate(double dt) {
  using Gradient = Eigen::Matrix<double, dim, dim>;
  MaterialPoints<dim>& points = solid_.points;
  const std::size_t n_points = points.size();
  FirstFault fault;
  double dt_next = std::numeric_limits<double>::max();
#pragma omp parallel for num_threads(threads_) schedule(static) reduction(min : dt_next)
  for (std::size_t p = 0; p < n_points; ++p) {
    const int cell = points.cell[p];
    const auto& nodes = mesh_.cell_nodes[cell];
    const auto& grad = mesh_.cell_shape_gradient[cell];
    Gradient l = Gradient::Zero();  // velocity gradient dv/dx
    for (int i = 0; i <= dim; ++i)
      l.noalias() += solid_.node_velocity[nodes[i]] * grad[i].transpose();
    Voigt6 strain = strain_increment(l, dt);
    if (volumetric_smoothing_) {
      // Replace the cell's volumetric part by the smoothed one (in-plane in 2D).
      const double correction = (point_volumetric_strain_[p] - l.trace() * dt) / dim;
      for (int d = 0; d < dim; ++d) strain(d) += correction;
    }
    Voigt6& sigma = points.stress[p];
    rotate_stress(sigma, l, dt);
    const MaterialModelData& material = materials_[points.material[p]];
    // The constitutive update acts on the Kirchhoff stress tau = J sigma, J = V / V_0 the
    // point's volume over its volume at the material's dry density (scientific manual, 4.6).
    // Its force -V sigma . grad N = -V_0 tau . grad N then does not grow with the point's
    // dilation, and its P-wave speed stays the c_p of the time step at any density; with the
    // rate of the Cauchy stress, a point dilated 40-fold at a thin front (grains parted at
    // the tension apex) was recompressed with the dense soil's stiffness times its inflated
    // volume, and threw the points sharing its nearly empty nodes (issue 8).
    const double volume_at_dry_density = reference_volume(p);
    sigma *= points.volume[p] / volume_at_dry_density;
    if (material.max_porosity < 1.0 && porosity(p) >= material.max_porosity)
      sigma.setZero();  // n > n_max: grains separated, no effective stress (section 2.3)
    else if (detail::is_free_body(solid_, mesh_, p))
      sigma.setZero();  // a fragment flying free carries no stress (phase.hpp)
    else if (material.model == MaterialModel::kMohrCoulomb)
      points.plastic_strain[p] += material.mohr_coulomb->update(sigma, strain);
    else
      elastic_update(material.elastic, sigma, strain);
    points.volume[p] *= 1.0 + strain(0) + strain(1) + strain(2);
    sigma *= volume_at_dry_density / points.volume[p];

    const double speed = points.velocity[p].norm();
    const PointFault kind = relocate(solid_, mesh_, p, speed, sigma.allFinite(), max_velocity_);
    if (kind != PointFault::kNone)
      fault.note(p, kind);
    else
      dt_next =
          std::min(dt_next, mesh_.cell_min_height[points.cell[p]] / (material.wave_speed + speed));
  }
  next_time_step_ = dt_next;
  if (fault.point >= 0) {
    const std::size_t p = static_cast<std::size_t>(fault.point);
    std::ostringstream m;
    m << "step " << step_count_ << ": point " << points.id[p] << " (material '"
      << description_.materials[points.material[p]].name << "') at "
      << format_vector(points.position[p].data(), dim) << ": ";
    if (fault.kind == PointFault::kNotFinite)
      m << "velocity or stress is not finite (velocity "
        << format_vector(points.velocity[p].data(), dim) << ", stress "
        << format_vector(points.stress[p].data(), 6)
        << "); the run went unstable: reduce the Courant number or check the material";
    else
      m << describe_fault(fault.kind, points.velocity[p], max_velocity_);
    throw RunError(m.str());
  }
}

template <int dim>
void Simulation<dim>::step(double dt, double damping) {
  points_to_nodes(Transfer::kMassMomentumForce);
  if (has_liquid_) liquid_to_nodes();
  if (!active_tractions_.empty()) apply_tractions();
  nodal_update(dt, damping);
  accumulate_wall_impulses(dt, damping);
  nodes_to_points(solid_, mesh_, dt, threads_);
  if (has_liquid_) {
    // Each liquid point follows its own water: the pore water's field or the free water's.
    // XPIC(m) for the free water's field (xpic.hpp); the pore water keeps the plain blend,
    // its damping being the drag's and the soil's business (not measured with XPIC).
    const Vec* free_water_correction = nullptr;
    if (const int order = description_.solver.liquid_xpic_order; order > 1)
      free_water_correction =
          xpic_
              .update(order, mesh_, water_.points.cell, water_.shape, water_.points.mass,
                      water_.node_velocity.data(), water_.node_acceleration.data(), dt,
                      [&](std::size_t q) { return !liquid_in_soil_[q]; })
              .data();
    const detail::NodalField<Vec> free_water{
        water_.node_velocity.data(), water_.node_acceleration.data(), free_water_correction};
    const detail::NodalField<Vec> pore_water{pore_water_velocity_.data(),
                                             pore_water_acceleration_.data()};
    nodes_to_points(water_, mesh_, dt, threads_,
                    [&](std::size_t q) { return liquid_in_soil_[q] ? pore_water : free_water; });
    if (description_.solver.liquid_landing == LiquidLanding::kMerge) merge_landed_liquid();
    if (description_.solver.liquid_advection == LiquidAdvection::kFlux) advect_liquid_by_flux(dt);
  }
  if (musl_) remap_momentum();
  if (volumetric_smoothing_) smooth_volumetric_strain(dt);
  update_stress_and_relocate(dt);
  if (has_liquid_) {
    update_liquid_and_relocate(dt);
    if (pressure_projection_due(dt)) {
      // With the nodal fit the pressure needs no filter; the clock still runs the pore water
      // volume projection.
      if (!nodal_pressure_) {
        project_liquid_pressure();
        ++projection_count_;
      }
      if (description_.solver.pore_volume_projection) project_pore_water_volume();
    }
  }
  ++step_count_;
}

template <int dim>
bool Simulation<dim>::pressure_projection_due(double dt) {
  if (const auto& interval = description_.solver.pressure_projection_interval)
    return *interval > 0 && (step_count_ + 1) % *interval == 0;
  // By simulated time. The period is taken off the clock (not the clock reset), so that steps
  // that do not divide it keep the mean rate; the relative slack absorbs the rounding of sums
  // of equal steps (ten steps of exactly a tenth of the period).
  projection_clock_ += dt;
  if (projection_clock_ < projection_time_ * (1.0 - 1e-9)) return false;
  projection_clock_ -= projection_time_;
  if (projection_clock_ >= projection_time_) projection_clock_ = 0;  // a step longer than it
  return true;
}

template <int dim>
void Simulation<dim>::map_to_grid() {
  // Into arrays of their own: the nodal velocities of the last step carry into the next one
  // (the drag of eq. 23 uses the previous relative velocity), so writing grid output must not
  // overwrite them, or a run with grid output would differ from one without.
  const std::size_t n_nodes = mesh_.node_count();
  points_to_nodes(Transfer::kMassMomentumForce);
  const detail::PhaseSums<dim>& solid = solid_.nodal.sums();
  grid_velocity_.resize(n_nodes);
  for (std::size_t i = 0; i < n_nodes; ++i)
    grid_velocity_[i] = velocity_from_momentum(solid.momentum[i], solid.mass[i]);
  if (has_liquid_) {
    liquid_to_nodes();
    const detail::LiquidSums<dim>& liquid = water_.nodal.sums();
    grid_liquid_velocity_.resize(n_nodes);
    for (std::size_t i = 0; i < n_nodes; ++i)
      grid_liquid_velocity_[i] = velocity_from_momentum(liquid.momentum[i], liquid.mass[i]);
  }
}

template <int dim>
double Simulation<dim>::kinetic_energy() const {
  // Summed in a fixed order: the quasi-static stage stops on it, so its rounding must not
  // depend on the threads' timing.
  const MaterialPoints<dim>& points = solid_.points;
  const LiquidPoints<dim>& liquid = water_.points;
  return ordered_sum(threads_, points.size(),
                     [&](std::size_t p) {
                       return 0.5 * points.mass[p] * points.velocity[p].squaredNorm();
                     }) +
         ordered_sum(threads_, liquid.size(), [&](std::size_t q) {
           return 0.5 * liquid.mass[q] * liquid.velocity[q].squaredNorm();
         });
}

template <int dim>
std::size_t Simulation<dim>::storage_bytes() const {
  const std::size_t cells = mesh_.cell_count() * (2 * sizeof(typename Mesh<dim>::CellNodes) +
                                                  sizeof(Eigen::Matrix<double, dim, dim>) +
                                                  (dim + 1) * sizeof(Vec) + 2 * sizeof(double));
  const std::size_t nodes = mesh_.node_count();
  std::size_t bytes = solid_.bytes() + cells;
  if (volumetric_smoothing_)
    bytes += point_volumetric_strain_.size() * sizeof(double) +
             static_cast<std::size_t>(smoothing_.threads()) * nodes * 2 * sizeof(double);
  if (has_liquid_)
    bytes += water_.bytes() + liquid_flux_divergence_.size() * sizeof(double) +
             static_cast<std::size_t>(coupling_.threads()) * nodes *
                 (3 * sizeof(double) + 2 * sizeof(Vec)) +
             nodes * (2 * sizeof(double) + 4 * sizeof(Vec)) +  // + pore water and mean fields
             mesh_.cell_count() + water_.points.size() +       // the pore water flags
             mesh_.cell_count() * sizeof(double) + nodes +     // the pore pressure's cell scale
             // the landing of spray: a flag per cell; per node the bodies' roots, their
             // resting flags, the water met and the impulse handed back
             mesh_.cell_count() +
             nodes * (sizeof(int) + 2 * sizeof(char) + 2 * sizeof(Vec) + sizeof(double));
  if (nodal_pressure_)  // the fit's moments and force per thread, its nodal coefficients
    bytes += static_cast<std::size_t>(pressure_fit_.threads()) * nodes *
                 (3 * sizeof(Vec) + sizeof(Eigen::Matrix<double, dim, dim>)) +
             nodes * (2 * sizeof(double) + sizeof(Vec)) +
             smoothed_flux_divergence_.size() * sizeof(double);
  return bytes;
}

template <int dim>
void Simulation<dim>::report_progress(const Stage& stage, double t, double wall, bool final_line) {
  if (!progress_) return;
  const double now = wall_seconds();
  if (!final_line && now - last_progress_wall_ < 2.0) return;
  last_progress_wall_ = now;
  static const bool terminal = isatty(fileno(stderr));
  const double rate = wall > 0 ? static_cast<double>(point_count()) * stage_steps_ / wall : 0;
  const double eta = t > 0 ? wall * (stage.duration - t) / t : 0;
  char line[256];
  std::snprintf(line, sizeof line,
                "  %-12s t = %8.4f / %.4f s  step %8ld  dt %.3e s  %6.2f M point-steps/s  "
                "eta %5.0f s",
                stage.name.c_str(), t, stage.duration, stage_steps_, last_dt_, rate / 1e6,
                final_line ? 0.0 : eta);
  *progress_ << (terminal ? "\r" : "") << line << (terminal && !final_line ? "" : "\n")
             << std::flush;
}

template <int dim>
StageReport Simulation<dim>::run_stage(const Stage& stage, const OutputCallback& on_output,
                                       const StepCallback& after_step,
                                       const StageProgress* resume) {
  activate_boundaries(stage.boundaries);
  // The boundary forces of a stage are summed from its start (wall_loads.cpp); a stage going
  // on from a checkpoint keeps the sums the checkpoint holds.
  if (!resume) {
    wall_impulse_.assign(constraints_.size(), WallImpulse{});
    wall_impulse_time_ = 0;
  }
  StageReport report;
  report.stage = stage.name;
  const double start_wall = wall_seconds();
  const bool quasi_static = stage.type == StageType::kQuasiStatic;
  // Everything the loop carries from one step to the next, so that a checkpoint taken after any
  // step continues the stage as if it had never stopped.
  StageProgress at;
  const double output_interval = stage.output_interval > 0 ? stage.output_interval : stage.duration;
  if (resume) {
    at = *resume;
  } else {
    if (on_output) on_output(stage, at.time, at.next_output_index++);
    // An output interval longer than the stage still ends the stage with its final state.
    at.next_output_time = std::min(output_interval, stage.duration);
  }
  double& t = at.time;
  stage_steps_ = at.steps;
  report.stop_reason = "duration reached";
  const double time_tolerance = 1e-9 * stage.duration;
  while (t < stage.duration - time_tolerance) {
    // The Courant-limited step, shortened to land exactly on output times.
    double dt = stage.courant * next_time_step_;
    dt = std::min(dt, at.next_output_time - t);
    last_dt_ = dt;
    stage_time_ = t + dt;  // the load at the end of the step: a ramp reaches 1 at ramp_time
    step(dt, stage.damping);
    t += dt;
    at.steps = ++stage_steps_;
    const bool output_now = t >= at.next_output_time - time_tolerance;
    if (quasi_static && stage.kinetic_energy_ratio > 0) {
      const double e = kinetic_energy();
      at.max_kinetic_energy = std::max(at.max_kinetic_energy, e);
      if (stage_steps_ > 100 && e <= stage.kinetic_energy_ratio * at.max_kinetic_energy) {
        std::ostringstream reason;
        reason << "kinetic energy ratio " << e / at.max_kinetic_energy << " below "
               << stage.kinetic_energy_ratio;
        report.stop_reason = reason.str();
        if (on_output) on_output(stage, t, at.next_output_index++);
        break;
      }
    }
    if (output_now) {
      if (on_output) on_output(stage, t, at.next_output_index++);
      at.next_output_time = std::min(at.next_output_time + output_interval, stage.duration);
    }
    report_progress(stage, t, at.wall_time + wall_seconds() - start_wall, false);
    // A stop asked for by SIGINT/SIGTERM is acted on here too (solve.cpp): the state is whole
    // after the step.
    if (after_step) {
      StageProgress now = at;
      now.wall_time += wall_seconds() - start_wall;
      after_step(stage, now);
    }
  }
  report.steps = stage_steps_;
  report.simulated_time = t;
  report.wall_time = at.wall_time + wall_seconds() - start_wall;
  report.point_steps_per_second =
      report.wall_time > 0 ? static_cast<double>(point_count()) * stage_steps_ / report.wall_time
                           : 0;
  report.peak_memory = peak_memory_bytes();
  report_progress(stage, t, report.wall_time, true);
  if (quasi_static) {
    // The quasi-static stage ends in equilibrium: the next stage starts at rest.
    for (auto& v : solid_.points.velocity) v.setZero();
    for (auto& v : water_.points.velocity) v.setZero();
    if (stage.reset_displacement)
      for (auto& u : solid_.points.displacement) u.setZero();
  }
  return report;
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace lituya::solver
