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
//   points (the pore pressure interpolated from the nodes). The liquid node gets n_i F_i and
//   the solid node (1 - n_i) F_i: their sum is the full pore-pressure force (momentum is
//   conserved), and with n_i from the same grain volumes, still water over and in a soil bed
//   starts in discrete balance (hydrostatic pressure carries the water, buoyancy lightens
//   the skeleton; test TwoPhase.SaturatedBedUnderWaterStaysAtRest).
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
//   bulk viscosity alpha rho c h div v (does not act on a mode that carries no velocity).
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
         1.75 * std::pow(n, 1.5) * liquid_density * relative_speed / std::sqrt(150.0 * kappa);
}
}  // namespace

template <int dim>
void Simulation<dim>::LiquidBuffer::assign(std::size_t n_nodes) {
  mass.assign(n_nodes, 0.0);
  momentum.assign(n_nodes, Vec::Zero());
  force.assign(n_nodes, Vec::Zero());
  pressure_force.assign(n_nodes, Vec::Zero());
  water_volume.assign(n_nodes, 0.0);
  water_volume_pressure.assign(n_nodes, 0.0);
  solid_volume.assign(n_nodes, 0.0);
  drag.assign(n_nodes, 0.0);
}

template <int dim>
void Simulation<dim>::setup_liquid() {
  const std::size_t n_nodes = mesh_.node_count();
  if (pore_liquid_ < 0)
    throw InputError(description_.materials_file, 0,
                     "the case has liquid points but no water material");
  for (std::size_t q = 0; q < liquid_.size(); ++q)
    if (!description_.materials[liquid_.material[q]].is_liquid())
      throw InputError(description_.liquid_points_file, 0,
                       "liquid point " + std::to_string(liquid_.id[q]) + " has material '" +
                           description_.materials[liquid_.material[q]].name +
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
  liquid_grid_.assign(n_nodes);
  node_liquid_velocity_.assign(n_nodes, Vec::Zero());
  node_liquid_acceleration_.assign(n_nodes, Vec::Zero());
  node_porosity_.assign(n_nodes, 1.0);
  node_pressure_.assign(n_nodes, 0.0);
  node_mesh_volume_.assign(n_nodes, 0.0);
  for (std::size_t c = 0; c < mesh_.cell_count(); ++c)
    for (int node : mesh_.cell_nodes[c])
      node_mesh_volume_[node] += mesh_.cell_volume[c] / (dim + 1);
  liquid_flux_divergence_.assign(liquid_.size(), 0.0);
  locate_all<dim>(mesh_, liquid_.position, liquid_.cell, liquid_.id, liquid_shape_,
                  description_.liquid_points_file, "liquid point");
}

template <int dim>
void Simulation<dim>::liquid_to_nodes(Transfer what) {
  const bool with_force = what == Transfer::kMassMomentumForce;
  const std::size_t n_points = points_.size();
  const std::size_t n_liquid = liquid_.size();
  const std::size_t n_nodes = mesh_.node_count();
  const MaterialModelData& water = materials_[pore_liquid_];

  // Pass 1 (forces only): the solid volume fraction and the drag coefficient at the nodes.
  if (with_force) {
#pragma omp parallel num_threads(threads_)
    {
      const int t = omp_get_thread_num();
      LiquidBuffer& b = t == 0 ? liquid_grid_ : liquid_thread_buffers_[t - 1];
      std::fill(b.solid_volume.begin(), b.solid_volume.end(), 0.0);
      std::fill(b.drag.begin(), b.drag.end(), 0.0);
#pragma omp for schedule(static)
      for (std::size_t p = 0; p < n_points; ++p) {
        const auto& nodes = mesh_.cell_nodes[points_.cell[p]];
        const Shape& n = shape_[p];
        Vec relative = Vec::Zero();  // previous step's v_w - v_s at the point
        for (int i = 0; i <= dim; ++i)
          relative += n(i) * (node_liquid_velocity_[nodes[i]] - node_velocity_[nodes[i]]);
        const double porosity_p = porosity(p);
        const double v = points_.volume[p];
        const double c =
            drag_coefficient(porosity_p, materials_[points_.material[p]].grain_diameter,
                             water.viscosity, water.liquid_density, relative.norm());
        for (int i = 0; i <= dim; ++i) {
          b.solid_volume[nodes[i]] += n(i) * v * (1.0 - porosity_p);
          b.drag[nodes[i]] += n(i) * v * c;
        }
      }
      if (threads_ > 1) {
#pragma omp for schedule(static)
        for (std::size_t i = 0; i < n_nodes; ++i)
          for (const LiquidBuffer& other : liquid_thread_buffers_) {
            liquid_grid_.solid_volume[i] += other.solid_volume[i];
            liquid_grid_.drag[i] += other.drag[i];
          }
      }
    }
#pragma omp parallel for num_threads(threads_) schedule(static)
    for (std::size_t i = 0; i < n_nodes; ++i)
      node_porosity_[i] = std::clamp(1.0 - liquid_grid_.solid_volume[i] / node_mesh_volume_[i],
                                     kMinimumPorosity, 1.0);
  }

  // Pass 2: liquid mass, momentum, gravity, viscous and pressure forces.
#pragma omp parallel num_threads(threads_)
  {
    const int t = omp_get_thread_num();
    LiquidBuffer& b = t == 0 ? liquid_grid_ : liquid_thread_buffers_[t - 1];
    if (with_force) {
      std::fill(b.mass.begin(), b.mass.end(), 0.0);
      std::fill(b.force.begin(), b.force.end(), Vec::Zero());
      std::fill(b.pressure_force.begin(), b.pressure_force.end(), Vec::Zero());
      std::fill(b.water_volume.begin(), b.water_volume.end(), 0.0);
      std::fill(b.water_volume_pressure.begin(), b.water_volume_pressure.end(), 0.0);
    }
    std::fill(b.momentum.begin(), b.momentum.end(), Vec::Zero());
#pragma omp for schedule(static)
    for (std::size_t q = 0; q < n_liquid; ++q) {
      const int cell = liquid_.cell[q];
      const auto& nodes = mesh_.cell_nodes[cell];
      const Shape& n = liquid_shape_[q];
      const double m = liquid_.mass[q];
      const Vec momentum = m * liquid_.velocity[q];
      if (with_force) {
        const auto& grad = mesh_.cell_shape_gradient[cell];
        double porosity_q = 0;
        for (int i = 0; i <= dim; ++i) porosity_q += n(i) * node_porosity_[nodes[i]];
        liquid_.porosity[q] = porosity_q;
        const double volume = liquid_.volume[q];
        const double pressure_volume = liquid_.pressure[q] * volume;
        const Vec weight = m * gravity_;
        for (int i = 0; i <= dim; ++i) {
          const int node = nodes[i];
          b.mass[node] += n(i) * m;
          b.momentum[node] += n(i) * momentum;
          b.pressure_force[node] += pressure_volume * grad[i];
          b.water_volume[node] += n(i) * volume;
          b.water_volume_pressure[node] += n(i) * pressure_volume;
          b.force[node] +=
              n(i) * weight - liquid_.volume[q] * stress_dot(liquid_.viscous_stress[q], grad[i]);
        }
      } else {
        for (int i = 0; i <= dim; ++i) b.momentum[nodes[i]] += n(i) * momentum;
      }
    }
    if (threads_ > 1) {
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n_nodes; ++i)
        for (const LiquidBuffer& other : liquid_thread_buffers_) {
          if (with_force) {
            liquid_grid_.mass[i] += other.mass[i];
            liquid_grid_.force[i] += other.force[i];
            liquid_grid_.pressure_force[i] += other.pressure_force[i];
            liquid_grid_.water_volume[i] += other.water_volume[i];
            liquid_grid_.water_volume_pressure[i] += other.water_volume_pressure[i];
          }
          liquid_grid_.momentum[i] += other.momentum[i];
        }
    }
  }
  if (!with_force) return;

    // Pass 3: the pore pressure on the grain volume of the solid points, with the pressure
    // interpolated from its volume-weighted nodal average.
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i)
    node_pressure_[i] = liquid_grid_.water_volume[i] > 0
                            ? liquid_grid_.water_volume_pressure[i] / liquid_grid_.water_volume[i]
                            : 0.0;
#pragma omp parallel num_threads(threads_)
  {
    const int t = omp_get_thread_num();
    LiquidBuffer& b = t == 0 ? liquid_grid_ : liquid_thread_buffers_[t - 1];
    if (t > 0) std::fill(b.pressure_force.begin(), b.pressure_force.end(), Vec::Zero());
#pragma omp for schedule(static)
    for (std::size_t p = 0; p < n_points; ++p) {
      const int cell = points_.cell[p];
      const auto& nodes = mesh_.cell_nodes[cell];
      const auto& grad = mesh_.cell_shape_gradient[cell];
      double pore_pressure = 0;
      for (int i = 0; i <= dim; ++i) pore_pressure += shape_[p](i) * node_pressure_[nodes[i]];
      if (pore_pressure == 0) continue;
      const double grain_volume = points_.volume[p] * (1.0 - porosity(p));
      for (int i = 0; i <= dim; ++i)
        b.pressure_force[nodes[i]] += pore_pressure * grain_volume * grad[i];
    }
    if (threads_ > 1) {
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n_nodes; ++i)
        for (const LiquidBuffer& other : liquid_thread_buffers_)
          liquid_grid_.pressure_force[i] += other.pressure_force[i];
    }
  }
}

template <int dim>
void Simulation<dim>::two_phase_nodal_update(double dt, double damping) {
  const std::size_t n_nodes = mesh_.node_count();
  auto damp = [damping](Vec& force, const Vec& velocity) {
    if (damping <= 0) return;
    for (int d = 0; d < dim; ++d) {
      const double sign = velocity(d) > 0 ? 1.0 : (velocity(d) < 0 ? -1.0 : 0.0);
      force(d) -= damping * std::abs(force(d)) * sign;
    }
  };
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    const double ms = grid_.mass[i], mw = liquid_grid_.mass[i];
    const double n = node_porosity_[i];
    const Vec vs_old = velocity_from_momentum(grid_.momentum[i], ms);
    const Vec vw_old = velocity_from_momentum(liquid_grid_.momentum[i], mw);
    // Eqs. (15), (16): the pore-pressure force shared by porosity.
    Vec fs = grid_.force[i] + (1.0 - n) * liquid_grid_.pressure_force[i];
    Vec fw = liquid_grid_.force[i] + n * liquid_grid_.pressure_force[i];
    damp(fs, vs_old);
    damp(fw, vw_old);
    const bool solid = ms > kMassFloor, liquid = mw > kMassFloor;
    Vec vs = solid ? Vec(vs_old + dt * fs / ms) : Vec::Zero();
    Vec vw = liquid ? Vec(vw_old + dt * fw / mw) : Vec::Zero();
    const double a = dt * liquid_grid_.drag[i];
    if (solid && liquid && a > 0) {
      // Implicit drag: the 2x2 system of the header comment, momentum conserving.
      const double det = ms * mw + a * (ms + mw);
      const Vec ps = ms * vs, pw = mw * vw;
      vs = ((mw + a) * ps + a * pw) / det;
      vw = (a * ps + (ms + a) * pw) / det;
    }
    // Where one phase is absent its velocity is taken as the other's, so the mixture flux
    // of eq. (8) and the relative velocity of eq. (23) see no phantom motion.
    if (!liquid) vw = vs;
    if (!solid) vs = vw;
    node_velocity_[i] = vs;
    node_liquid_velocity_[i] = vw;
    node_acceleration_[i] = vs_old;
    node_liquid_acceleration_[i] = vw_old;
  }
  apply_constraints<dim>(active_constraints_, node_velocity_);
  apply_constraints<dim>(active_liquid_constraints_, node_liquid_velocity_);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    node_acceleration_[i] = (node_velocity_[i] - node_acceleration_[i]) / dt;
    node_liquid_acceleration_[i] = (node_liquid_velocity_[i] - node_liquid_acceleration_[i]) / dt;
  }
}

template <int dim>
void Simulation<dim>::liquid_nodes_to_points(double dt) {
  const std::size_t n_liquid = liquid_.size();
  const double flip = damping_.liquid.flip_share(dt);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const auto& nodes = mesh_.cell_nodes[liquid_.cell[q]];
    const Shape& n = liquid_shape_[q];
    Vec acceleration = Vec::Zero(), velocity = Vec::Zero();
    for (int i = 0; i <= dim; ++i) {
      acceleration += n(i) * node_liquid_acceleration_[nodes[i]];
      velocity += n(i) * node_liquid_velocity_[nodes[i]];
    }
    liquid_.velocity[q] = flip * (liquid_.velocity[q] + dt * acceleration) + (1 - flip) * velocity;
    liquid_.position[q] += dt * velocity;
  }
}

template <int dim>
void Simulation<dim>::remap_liquid_momentum() {
  liquid_to_nodes(Transfer::kMomentum);
  const std::size_t n_nodes = mesh_.node_count();
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i) {
    const bool liquid = liquid_grid_.mass[i] > kMassFloor;
    node_liquid_velocity_[i] =
        liquid ? velocity_from_momentum(liquid_grid_.momentum[i], liquid_grid_.mass[i])
               : node_velocity_[i];
    if (grid_.mass[i] <= kMassFloor && liquid) node_velocity_[i] = node_liquid_velocity_[i];
  }
  apply_constraints<dim>(active_liquid_constraints_, node_liquid_velocity_);
  apply_constraints<dim>(active_constraints_, node_velocity_);
}

template <int dim>
void Simulation<dim>::update_liquid_and_relocate(double dt) {
  using Gradient = Eigen::Matrix<double, dim, dim>;
  const std::size_t n_liquid = liquid_.size();
  // Divergence of the mixture's volume flux (the bracket of eq. 8) and the viscous stress
  // (eqs. 17, 18) from the nodal velocities after the remap.
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const int cell = liquid_.cell[q];
    const auto& nodes = mesh_.cell_nodes[cell];
    const auto& grad = mesh_.cell_shape_gradient[cell];
    Gradient l = Gradient::Zero();
    double divergence = 0;
    for (int i = 0; i <= dim; ++i) {
      const int node = nodes[i];
      const double n = node_porosity_[node];
      const Vec flux = (1.0 - n) * node_velocity_[node] + n * node_liquid_velocity_[node];
      divergence += flux.dot(grad[i]);
      l.noalias() += node_liquid_velocity_[node] * grad[i].transpose();
    }
    liquid_flux_divergence_[q] = divergence;
    // Newtonian viscous stress mu (grad v + grad v^T) = 2 mu D (eq. 17 with eq. 18 read as
    // twice the strain rate D), stored in the engineering-shear Voigt layout as a stress.
    const double mu = materials_[liquid_.material[q]].viscosity;
    const Voigt6 rate = strain_increment(l, 1.0);  // D_xx, D_yy, D_zz, 2 D_xy, ...
    Voigt6& tau = liquid_.viscous_stress[q];
    for (int k = 0; k < 3; ++k) tau(k) = 2.0 * mu * rate(k);
    for (int k = 3; k < 6; ++k) tau(k) = mu * rate(k);
  }

  long bad_point = -1;
  int bad_kind = 0;
  double dt_next = next_time_step_;
#pragma omp parallel for num_threads(threads_) schedule(static) reduction(min : dt_next)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const MaterialModelData& water = materials_[liquid_.material[q]];
    const double n = std::max(liquid_.porosity[q], kMinimumPorosity);
    // Eq. (8), compression positive; no tension (free surface, cavitation).
    double& p = liquid_.pressure[q];
    p = std::max(0.0, p - water.bulk_modulus / n * liquid_flux_divergence_[q] * dt);
    // Water volume from eq. (7): rho_w = rho_w0 (1 + p / K_w).
    liquid_.volume[q] = liquid_.mass[q] / (water.liquid_density * (1.0 + p / water.bulk_modulus));
    const double speed = liquid_.velocity[q].norm();
    int kind = 0;
    if (!std::isfinite(speed) || !std::isfinite(p))
      kind = 1;
    else if (speed > max_velocity_)
      kind = 2;
    else {
      const int found = mesh_.locate(liquid_.cell[q], liquid_.position[q], liquid_shape_[q]);
      if (found < 0)
        kind = 3;
      else {
        liquid_.cell[q] = found;
        const double h = mesh_.cell_min_height[found];
        dt_next = std::min(dt_next, h / (water.wave_speed + speed +
                                         2.0 * water.viscosity / (water.liquid_density * h)));
      }
    }
    if (kind != 0) {
#pragma omp critical(lituya_bad_liquid_point)
      if (bad_point < 0 || static_cast<long>(q) < bad_point) {
        bad_point = static_cast<long>(q);
        bad_kind = kind;
      }
    }
  }
  next_time_step_ = dt_next;
  if (bad_point >= 0) {
    const std::size_t q = static_cast<std::size_t>(bad_point);
    std::ostringstream m;
    m << "step " << step_count_ << ": liquid point " << liquid_.id[q] << " (material '"
      << description_.materials[liquid_.material[q]].name << "') at "
      << format_vector(liquid_.position[q].data(), dim) << ": ";
    if (bad_kind == 1)
      m << "velocity or pressure is not finite (velocity "
        << format_vector(liquid_.velocity[q].data(), dim) << ", pressure " << liquid_.pressure[q]
        << " Pa); the run went unstable: reduce the Courant number";
    else
      // Water jets out of the impact zone are FLIP noise grown unchecked (user manual, 2.6):
      // a shorter liquid damping time is the first thing to try, the Courant number rarely.
      m << describe_fault(bad_kind == 2 ? PointFault::kTooFast : PointFault::kLeftMesh,
                          liquid_.velocity[q], max_velocity_,
                          "try a shorter [solver] liquid_pic_damping_time, e.g. half the one "
                          "in output/log.txt, or a smaller Courant number");
    throw RunError(m.str());
  }
}

#define LITUYA_TWO_PHASE_INSTANCES(D)                                  \
  template void Simulation<D>::LiquidBuffer::assign(std::size_t);      \
  template void Simulation<D>::setup_liquid();                         \
  template void Simulation<D>::liquid_to_nodes(Transfer);              \
  template void Simulation<D>::two_phase_nodal_update(double, double); \
  template void Simulation<D>::liquid_nodes_to_points(double);         \
  template void Simulation<D>::remap_liquid_momentum();                \
  template void Simulation<D>::update_liquid_and_relocate(double);
LITUYA_TWO_PHASE_INSTANCES(2)
LITUYA_TWO_PHASE_INSTANCES(3)
#undef LITUYA_TWO_PHASE_INSTANCES

}  // namespace lituya::solver
