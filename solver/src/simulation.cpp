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
      points_(std::move(points)),
      constraints_(std::move(constraints)),
      has_liquid_(!liquid.empty()),
      liquid_(std::move(liquid)) {
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
  const std::size_t n_nodes = mesh_.node_count();
  grid_.mass.assign(n_nodes, 0.0);
  grid_.momentum.assign(n_nodes, Vec::Zero());
  grid_.force.assign(n_nodes, Vec::Zero());
  node_velocity_.assign(n_nodes, Vec::Zero());
  node_acceleration_.assign(n_nodes, Vec::Zero());
  if (volumetric_smoothing_) {
    node_volumetric_strain_.assign(n_nodes, 0.0);
    node_volume_.assign(n_nodes, 0.0);
    point_volumetric_strain_.assign(points_.size(), 0.0);
  }
  locate_all<dim>(mesh_, points_.position, points_.cell, points_.id, shape_,
                  description_.points_file, "point");
  if (has_liquid_) setup_liquid();
  next_time_step_ = stable_time_step(1.0);
}

template <int dim>
double Simulation<dim>::porosity(std::size_t p) const {
  const double rho_s = materials_[points_.material[p]].solid_density;
  return 1.0 - points_.mass[p] / (rho_s * points_.volume[p]);
}

template <int dim>
void Simulation<dim>::set_threads(int threads) {
  threads_ = std::max(1, threads);
  thread_buffers_.resize(threads_ - 1);
  for (NodalBuffer& b : thread_buffers_) {
    b.mass.assign(mesh_.node_count(), 0.0);
    b.momentum.assign(mesh_.node_count(), Vec::Zero());
    b.force.assign(mesh_.node_count(), Vec::Zero());
  }
  if (has_liquid_) {
    liquid_thread_buffers_.resize(threads_ - 1);
    for (LiquidBuffer& b : liquid_thread_buffers_) b.assign(mesh_.node_count());
  }
}

template <int dim>
void Simulation<dim>::activate_boundaries(const std::vector<std::string>& names) {
  active_constraints_.clear();
  active_liquid_constraints_.clear();
  active_tractions_.clear();
  for (const std::string& name : names)
    for (std::size_t i = 0; i < description_.boundaries.size(); ++i) {
      if (description_.boundaries[i].name != name) continue;
      const NodalConstraint<dim>* c = &constraints_[i];
      if (c->type == BoundaryType::kTraction)
        active_tractions_.push_back(c);
      else {
        if (c->phase != BoundaryPhase::kLiquid) active_constraints_.push_back(c);
        if (c->phase != BoundaryPhase::kSolid) active_liquid_constraints_.push_back(c);
      }
    }
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
    std::vector<double>& mass = liquid ? liquid_grid_.mass : grid_.mass;
    std::vector<Vec>& force = liquid ? liquid_grid_.force : grid_.force;
    for (std::size_t k = 0; k < c->nodes.size(); ++k)
      if (mass[c->nodes[k]] > kMassFloor) force[c->nodes[k]] += factor * c->force[k];
  }
}

template <int dim>
double Simulation<dim>::stable_time_step(double courant) const {
  double dt = std::numeric_limits<double>::max();
  const std::size_t n = points_.size();
#pragma omp parallel for num_threads(threads_) reduction(min : dt) schedule(static)
  for (std::size_t p = 0; p < n; ++p) {
    const double speed = materials_[points_.material[p]].wave_speed + points_.velocity[p].norm();
    dt = std::min(dt, mesh_.cell_min_height[points_.cell[p]] / speed);
  }
  const std::size_t n_liquid = liquid_.size();
#pragma omp parallel for num_threads(threads_) reduction(min : dt) schedule(static)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const MaterialModelData& water = materials_[liquid_.material[q]];
    const double h = mesh_.cell_min_height[liquid_.cell[q]];
    // Sound speed plus the viscous (diffusive) limit 2 mu / (rho h).
    const double speed = water.wave_speed + liquid_.velocity[q].norm() +
                         2.0 * water.viscosity / (water.liquid_density * h);
    dt = std::min(dt, h / speed);
  }
  return courant * dt;
}

template <int dim>
void Simulation<dim>::points_to_nodes(Transfer what) {
  const bool with_force = what == Transfer::kMassMomentumForce;
  const std::size_t n_points = points_.size();
  const std::size_t n_nodes = mesh_.node_count();
#pragma omp parallel num_threads(threads_)
  {
    const int t = omp_get_thread_num();
    NodalBuffer& b = t == 0 ? grid_ : thread_buffers_[t - 1];
    if (with_force) {
      std::fill(b.mass.begin(), b.mass.end(), 0.0);
      std::fill(b.force.begin(), b.force.end(), Vec::Zero());
    }
    std::fill(b.momentum.begin(), b.momentum.end(), Vec::Zero());
#pragma omp for schedule(static)
    for (std::size_t p = 0; p < n_points; ++p) {
      const int cell = points_.cell[p];
      const auto& nodes = mesh_.cell_nodes[cell];
      const Shape& n = shape_[p];
      const double m = points_.mass[p];
      const Vec momentum = m * points_.velocity[p];
      if (with_force) {
        const auto& grad = mesh_.cell_shape_gradient[cell];
        const double v = points_.volume[p];
        const Voigt6& sigma = points_.stress[p];
        const Vec weight = m * gravity_;
        for (int i = 0; i <= dim; ++i) {
          const int node = nodes[i];
          b.mass[node] += n(i) * m;
          b.momentum[node] += n(i) * momentum;
          // Internal force -V sigma . grad N (weak form of div sigma, eq. 11) and gravity.
          b.force[node] += n(i) * weight - v * stress_dot(sigma, grad[i]);
        }
      } else {
        for (int i = 0; i <= dim; ++i) b.momentum[nodes[i]] += n(i) * momentum;
      }
    }
    // Sum the other threads' buffers into the grid, in a fixed order (deterministic for a
    // given thread count).
    if (threads_ > 1) {
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n_nodes; ++i)
        for (const NodalBuffer& other : thread_buffers_) {
          if (with_force) {
            grid_.mass[i] += other.mass[i];
            grid_.force[i] += other.force[i];
          }
          grid_.momentum[i] += other.momentum[i];
        }
    }
  }
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
    const double m = grid_.mass[i];
    if (m <= kMassFloor) {
      node_velocity_[i].setZero();
      node_acceleration_[i].setZero();
      continue;
    }
    const Vec velocity = grid_.momentum[i] / m;
    Vec force = grid_.force[i];
    if (damping > 0) {
      // Local (Cundall) damping: a force opposing the velocity, proportional to the
      // unbalanced force, that vanishes at equilibrium.
      for (int d = 0; d < dim; ++d) {
        const double sign = velocity(d) > 0 ? 1.0 : (velocity(d) < 0 ? -1.0 : 0.0);
        force(d) -= damping * std::abs(force(d)) * sign;
      }
    }
    node_velocity_[i] = velocity + dt * force / m;
    node_acceleration_[i] = velocity;  // old velocity, finished below
  }
  apply_constraints<dim>(active_constraints_, node_velocity_);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i)
    node_acceleration_[i] = (node_velocity_[i] - node_acceleration_[i]) / dt;
}

template <int dim>
void Simulation<dim>::nodes_to_points(double dt) {
  const std::size_t n_points = points_.size();
  const double flip = damping_.solid.flip_share(dt);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t p = 0; p < n_points; ++p) {
    const auto& nodes = mesh_.cell_nodes[points_.cell[p]];
    const Shape& n = shape_[p];
    Vec acceleration = Vec::Zero(), velocity = Vec::Zero();
    for (int i = 0; i <= dim; ++i) {
      acceleration += n(i) * node_acceleration_[nodes[i]];
      velocity += n(i) * node_velocity_[nodes[i]];
    }
    // FLIP keeps the point's own velocity (little numerical dissipation), PIC takes the
    // grid's (stable, dissipative); the blend trades one against the other.
    points_.velocity[p] = flip * (points_.velocity[p] + dt * acceleration) + (1 - flip) * velocity;
    points_.position[p] += dt * velocity;
    points_.displacement[p] += dt * velocity;
  }
}

template <int dim>
void Simulation<dim>::remap_momentum() {
  points_to_nodes(Transfer::kMomentum);
  const std::size_t n_nodes = mesh_.node_count();
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    node_velocity_[i] = velocity_from_momentum(grid_.momentum[i], grid_.mass[i]);
  }
  apply_constraints<dim>(active_constraints_, node_velocity_);
  if (has_liquid_) remap_liquid_momentum();
}

template <int dim>
void Simulation<dim>::smooth_volumetric_strain(double dt) {
  // The volumetric strain increment of a linear simplex is constant over the cell; with
  // more cells than nodes, isochoric flow over-constrains the mesh (locking). Averaging it
  // at the nodes over the surrounding material (weighted by point volume) and interpolating
  // back leaves one volumetric constraint per node instead of per cell.
  const std::size_t n_points = points_.size();
  std::fill(node_volumetric_strain_.begin(), node_volumetric_strain_.end(), 0.0);
  std::fill(node_volume_.begin(), node_volume_.end(), 0.0);
  auto cell_volumetric_strain = [&](std::size_t p) {
    const int cell = points_.cell[p];
    const auto& nodes = mesh_.cell_nodes[cell];
    const auto& grad = mesh_.cell_shape_gradient[cell];
    double divergence = 0;
    for (int i = 0; i <= dim; ++i) divergence += node_velocity_[nodes[i]].dot(grad[i]);
    return divergence * dt;
  };
  if (threads_ == 1) {
    for (std::size_t p = 0; p < n_points; ++p) {
      const double weighted = points_.volume[p] * cell_volumetric_strain(p);
      for (int node : mesh_.cell_nodes[points_.cell[p]]) {
        node_volumetric_strain_[node] += weighted;
        node_volume_[node] += points_.volume[p];
      }
    }
  } else {
#pragma omp parallel for num_threads(threads_) schedule(static)
    for (std::size_t p = 0; p < n_points; ++p) {
      const double weighted = points_.volume[p] * cell_volumetric_strain(p);
      for (int node : mesh_.cell_nodes[points_.cell[p]]) {
#pragma omp atomic
        node_volumetric_strain_[node] += weighted;
#pragma omp atomic
        node_volume_[node] += points_.volume[p];
      }
    }
  }
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t p = 0; p < n_points; ++p) {
    const auto& nodes = mesh_.cell_nodes[points_.cell[p]];
    double smoothed = 0;
    for (int i = 0; i <= dim; ++i)
      smoothed += shape_[p](i) * node_volumetric_strain_[nodes[i]] / node_volume_[nodes[i]];
    point_volumetric_strain_[p] = smoothed;
  }
}

template <int dim>
void Simulation<dim>::update_stress_and_relocate(double dt) {
  using Gradient = Eigen::Matrix<double, dim, dim>;
  const std::size_t n_points = points_.size();
  long bad_point = -1;
  int bad_kind = 0;  // 1 = non-finite, 2 = too fast, 3 = left the mesh
  double dt_next = std::numeric_limits<double>::max();
#pragma omp parallel for num_threads(threads_) schedule(static) reduction(min : dt_next)
  for (std::size_t p = 0; p < n_points; ++p) {
    const int cell = points_.cell[p];
    const auto& nodes = mesh_.cell_nodes[cell];
    const auto& grad = mesh_.cell_shape_gradient[cell];
    Gradient l = Gradient::Zero();  // velocity gradient dv/dx
    for (int i = 0; i <= dim; ++i) l.noalias() += node_velocity_[nodes[i]] * grad[i].transpose();
    Voigt6 strain = strain_increment(l, dt);
    if (volumetric_smoothing_) {
      // Replace the cell's volumetric part by the smoothed one (in-plane in 2D).
      const double correction = (point_volumetric_strain_[p] - l.trace() * dt) / dim;
      for (int d = 0; d < dim; ++d) strain(d) += correction;
    }
    Voigt6& sigma = points_.stress[p];
    rotate_stress(sigma, l, dt);
    const MaterialModelData& material = materials_[points_.material[p]];
    if (material.max_porosity < 1.0 && porosity(p) >= material.max_porosity)
      sigma.setZero();  // n > n_max: grains separated, no effective stress (section 2.3)
    else if (material.model == MaterialModel::kMohrCoulomb)
      points_.plastic_strain[p] += material.mohr_coulomb->update(sigma, strain);
    else
      elastic_update(material.elastic, sigma, strain);
    points_.volume[p] *= 1.0 + strain(0) + strain(1) + strain(2);

    const double speed = points_.velocity[p].norm();
    int kind = 0;
    if (!std::isfinite(speed) || !sigma.allFinite())
      kind = 1;
    else if (speed > max_velocity_)
      kind = 2;
    else {
      const int found = mesh_.locate(cell, points_.position[p], shape_[p]);
      if (found < 0)
        kind = 3;
      else {
        points_.cell[p] = found;
        dt_next = std::min(dt_next, mesh_.cell_min_height[found] / (material.wave_speed + speed));
      }
    }
    if (kind != 0) {
#pragma omp critical(lituya_bad_point)
      if (bad_point < 0 || static_cast<long>(p) < bad_point) {
        bad_point = static_cast<long>(p);
        bad_kind = kind;
      }
    }
  }
  next_time_step_ = dt_next;
  if (bad_point >= 0) {
    const std::size_t p = static_cast<std::size_t>(bad_point);
    std::ostringstream m;
    m << "step " << step_count_ << ": point " << points_.id[p] << " (material '"
      << description_.materials[points_.material[p]].name << "') at "
      << format_vector(points_.position[p].data(), dim) << ": ";
    if (bad_kind == 1)
      m << "velocity or stress is not finite (velocity "
        << format_vector(points_.velocity[p].data(), dim) << ", stress "
        << format_vector(points_.stress[p].data(), 6)
        << "); the run went unstable: reduce the Courant number or check the material";
    else
      m << describe_fault(bad_kind == 2 ? PointFault::kTooFast : PointFault::kLeftMesh,
                          points_.velocity[p], max_velocity_);
    throw RunError(m.str());
  }
}

template <int dim>
void Simulation<dim>::step(double dt, double damping) {
  points_to_nodes(Transfer::kMassMomentumForce);
  if (has_liquid_) liquid_to_nodes(Transfer::kMassMomentumForce);
  if (!active_tractions_.empty()) apply_tractions();
  nodal_update(dt, damping);
  nodes_to_points(dt);
  if (has_liquid_) liquid_nodes_to_points(dt);
  if (musl_) remap_momentum();
  if (volumetric_smoothing_) smooth_volumetric_strain(dt);
  update_stress_and_relocate(dt);
  if (has_liquid_) {
    update_liquid_and_relocate(dt);
    const int interval = description_.solver.pressure_projection_interval;
    if (interval > 0 && (step_count_ + 1) % interval == 0) project_liquid_pressure();
  }
  ++step_count_;
}

template <int dim>
void Simulation<dim>::map_to_grid() {
  points_to_nodes(Transfer::kMassMomentumForce);
  for (std::size_t i = 0; i < mesh_.node_count(); ++i)
    node_velocity_[i] = velocity_from_momentum(grid_.momentum[i], grid_.mass[i]);
  if (has_liquid_) {
    liquid_to_nodes(Transfer::kMassMomentumForce);
    for (std::size_t i = 0; i < mesh_.node_count(); ++i)
      node_liquid_velocity_[i] =
          velocity_from_momentum(liquid_grid_.momentum[i], liquid_grid_.mass[i]);
  }
}

template <int dim>
double Simulation<dim>::kinetic_energy() const {
  double e = 0;
  const std::size_t n = points_.size();
#pragma omp parallel for num_threads(threads_) reduction(+ : e) schedule(static)
  for (std::size_t p = 0; p < n; ++p)
    e += 0.5 * points_.mass[p] * points_.velocity[p].squaredNorm();
  const std::size_t n_liquid = liquid_.size();
#pragma omp parallel for num_threads(threads_) reduction(+ : e) schedule(static)
  for (std::size_t q = 0; q < n_liquid; ++q)
    e += 0.5 * liquid_.mass[q] * liquid_.velocity[q].squaredNorm();
  return e;
}

template <int dim>
std::size_t Simulation<dim>::storage_bytes() const {
  const std::size_t nodes = mesh_.node_count() * (sizeof(double) + 4 * sizeof(Vec));
  const std::size_t cells = mesh_.cell_count() * (2 * sizeof(typename Mesh<dim>::CellNodes) +
                                                  sizeof(Eigen::Matrix<double, dim, dim>) +
                                                  (dim + 1) * sizeof(Vec) + 2 * sizeof(double));
  std::size_t liquid = 0;
  if (has_liquid_)
    liquid = liquid_.bytes() + liquid_shape_.size() * sizeof(Shape) +
             liquid_flux_divergence_.size() * sizeof(double) +
             (1 + liquid_thread_buffers_.size()) * mesh_.node_count() *
                 (5 * sizeof(double) + 3 * sizeof(Vec)) +
             mesh_.node_count() * (5 * sizeof(double) + 2 * sizeof(Vec));
  return points_.bytes() + shape_.size() * sizeof(Shape) + nodes + cells + liquid +
         thread_buffers_.size() * mesh_.node_count() * (sizeof(double) + 2 * sizeof(Vec));
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
StageReport Simulation<dim>::run_stage(const Stage& stage, const OutputCallback& on_output) {
  activate_boundaries(stage.boundaries);
  StageReport report;
  report.stage = stage.name;
  const double start_wall = wall_seconds();
  const bool quasi_static = stage.type == StageType::kQuasiStatic;
  double t = 0;
  int output_index = 0;
  if (on_output) on_output(stage, t, output_index++);
  double next_output = stage.output_interval > 0 ? stage.output_interval : stage.duration;
  double max_kinetic_energy = 0;
  stage_steps_ = 0;
  report.stop_reason = "duration reached";
  const double time_tolerance = 1e-9 * stage.duration;
  while (t < stage.duration - time_tolerance) {
    // The Courant-limited step, shortened to land exactly on output times.
    double dt = stage.courant * next_time_step_;
    dt = std::min(dt, next_output - t);
    last_dt_ = dt;
    stage_time_ = t + dt;  // the load at the end of the step: a ramp reaches 1 at ramp_time
    step(dt, stage.damping);
    t += dt;
    ++stage_steps_;
    bool output_now = t >= next_output - time_tolerance;
    if (quasi_static && stage.kinetic_energy_ratio > 0) {
      const double e = kinetic_energy();
      max_kinetic_energy = std::max(max_kinetic_energy, e);
      if (stage_steps_ > 100 && e <= stage.kinetic_energy_ratio * max_kinetic_energy) {
        std::ostringstream reason;
        reason << "kinetic energy ratio " << e / max_kinetic_energy << " below "
               << stage.kinetic_energy_ratio;
        report.stop_reason = reason.str();
        output_now = true;
        if (on_output) on_output(stage, t, output_index++);
        break;
      }
    }
    if (output_now) {
      if (on_output) on_output(stage, t, output_index++);
      next_output = std::min(
          next_output + (stage.output_interval > 0 ? stage.output_interval : stage.duration),
          stage.duration);
    }
    report_progress(stage, t, wall_seconds() - start_wall, false);
  }
  report.steps = stage_steps_;
  report.simulated_time = t;
  report.wall_time = wall_seconds() - start_wall;
  report.point_steps_per_second =
      report.wall_time > 0 ? static_cast<double>(point_count()) * stage_steps_ / report.wall_time
                           : 0;
  report.peak_memory = peak_memory_bytes();
  report_progress(stage, t, report.wall_time, true);
  if (quasi_static) {
    // The quasi-static stage ends in equilibrium: the next stage starts at rest.
    for (auto& v : points_.velocity) v.setZero();
    for (auto& v : liquid_.velocity) v.setZero();
    if (stage.reset_displacement)
      for (auto& u : points_.displacement) u.setZero();
  }
  return report;
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace lituya::solver
