#pragma once
// One phase of the two-layer MPM (section 2 of the paper): a point set, solid or liquid, and
// its share of the background nodes. Each phase has its own points, shape-value cache, nodal
// sums (per-thread buffers), nodal velocities, FLIP/PIC damping and active velocity
// conditions. The transfers between its points and the nodes are the same for both phases and
// are written here once:
//   scatter_to_nodes     step 1: mass, momentum, gravity and the phase's own stress divergence
//   finish_nodal_update  step 2: velocity conditions and the nodal acceleration
//   nodes_to_points      step 3: FLIP/PIC velocity update and the point's move (the
//                        grains take a wall's velocity for the components it prescribes)
//   remap_velocity       step 4 (MUSL): nodal velocity from the updated point momenta
//   relocate             step 5: the point's new cell, or the fault that stops the run
//   is_free_body         a point alone at its nodes, which carries no stress (no pressure)
// What couples the phases (porosity, drag, the pore-pressure split, eq. 8) is in
// two_phase.cpp. Internal to the solver library; the public interface is simulation.hpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "lituya/solver/boundary_conditions.hpp"
#include "lituya/solver/mesh.hpp"
#include "lituya/solver/mohr_coulomb.hpp"
#include "lituya/solver/nodal_scatter.hpp"
#include "lituya/solver/transfer_damping.hpp"

namespace lituya::solver::detail {

// Nodes that hold almost no mass (a point at the far corner of a cell) would get
// meaningless velocities; their velocity is taken as zero.
inline constexpr double kMassFloor = 1e-14;

template <class Vec>
inline Vec velocity_from_momentum(const Vec& momentum, double mass) {
  return mass > kMassFloor ? Vec(momentum / mass) : Vec::Zero();
}

// sigma . g for the in-plane (2D) or full (3D) stress tensor in Voigt storage.
inline Eigen::Vector2d stress_dot(const Voigt6& s, const Eigen::Vector2d& g) {
  return {s(0) * g(0) + s(3) * g(1), s(3) * g(0) + s(1) * g(1)};
}
inline Eigen::Vector3d stress_dot(const Voigt6& s, const Eigen::Vector3d& g) {
  return {s(0) * g(0) + s(3) * g(1) + s(5) * g(2), s(3) * g(0) + s(1) * g(1) + s(4) * g(2),
          s(5) * g(0) + s(4) * g(1) + s(2) * g(2)};
}

// What the points of one phase put on the nodes.
template <int dim>
struct PhaseSums {
  using Vec = Eigen::Matrix<double, dim, 1>;
  std::vector<double> mass;   // sum N m
  std::vector<Vec> momentum;  // sum N m v
  std::vector<Vec> force;     // sum N m g - V sigma . grad N (the phase's own stress)
  void assign(std::size_t n) {
    mass.assign(n, 0.0);
    momentum.assign(n, Vec::Zero());
    force.assign(n, Vec::Zero());
  }
  auto all() { return std::tie(mass, momentum, force); }
  static constexpr std::size_t kBytesPerNode = sizeof(double) + 2 * sizeof(Vec);
};

// The liquid's sums add its pressure terms and the pore water's own share of mass, momentum
// and force (two_phase.cpp: the pore water and the free water at a node are two velocity
// fields; the free water's sums are the whole less the pore water's).
template <int dim>
struct LiquidSums : PhaseSums<dim> {
  using Vec = typename PhaseSums<dim>::Vec;
  std::vector<Vec> pressure_force;                          // sum V_w p grad N (eqs. 15, 16)
  std::vector<double> water_volume, water_volume_pressure;  // sum N V_w, sum N V_w p
  std::vector<double> pore_mass;                            // the sums above of mass,
  std::vector<Vec> pore_momentum, pore_force;               // momentum and force, pore water only
  void assign(std::size_t n) {
    PhaseSums<dim>::assign(n);
    pressure_force.assign(n, Vec::Zero());
    water_volume.assign(n, 0.0);
    water_volume_pressure.assign(n, 0.0);
    pore_mass.assign(n, 0.0);
    pore_momentum.assign(n, Vec::Zero());
    pore_force.assign(n, Vec::Zero());
  }
  auto all() {
    return std::tie(this->mass, this->momentum, this->force, pressure_force, water_volume,
                    water_volume_pressure, pore_mass, pore_momentum, pore_force);
  }
  static constexpr std::size_t kBytesPerNode =
      PhaseSums<dim>::kBytesPerNode + 3 * sizeof(Vec) + 3 * sizeof(double);
};

template <int dim, class Points, class Sums>
struct Phase {
  using Vec = Eigen::Matrix<double, dim, 1>;
  using Shape = typename Mesh<dim>::Shape;

  Points points;
  std::vector<Shape> shape;            // shape values of each point in its cell
  NodalScatter<Sums> nodal;            // nodal.sums(): the phase's nodal mass, momentum, forces
  std::vector<Vec> node_velocity;      // after the nodal update, then after the MUSL remap
  std::vector<Vec> node_acceleration;  // holds the old velocity until finish_nodal_update
  PhaseDamping damping;                // the FLIP/PIC blend of this phase
  std::vector<const NodalConstraint<dim>*> constraints;  // active velocity conditions
  std::vector<char> held_node;  // per node: 1 where one of `constraints` holds the phase
  std::vector<int> held_nodes;  // those nodes in increasing order; `held` is parallel to it
  // What the conditions at each held node hold: the projector on the velocity components
  // they prescribe (all for `fixed`, the listed axes for a fixity, the normal for a roller or
  // a contact wall), parallel to `held_nodes`.
  std::vector<Eigen::Matrix<double, dim, dim>> held;
  // Whether the points take the wall's velocity for those components (nodes_to_points).
  bool wall_velocity_to_points = false;

  void allocate_nodes(int threads, std::size_t n_nodes) {
    nodal.allocate(threads, n_nodes);
    node_velocity.assign(n_nodes, Vec::Zero());
    node_acceleration.assign(n_nodes, Vec::Zero());
    held_node.assign(n_nodes, 0);
  }
  bool is_held(std::size_t node) const { return held_node[node] != 0; }
  // What held node `node` holds (a binary search: held nodes are few, and a byte per node
  // keeps the solver's storage per point where it was).
  std::size_t held_index(std::size_t node) const {
    const auto at = std::lower_bound(held_nodes.begin(), held_nodes.end(), static_cast<int>(node));
    return static_cast<std::size_t>(at - held_nodes.begin());
  }
  // The projector on the components the conditions at held node `node` prescribe (built only
  // with `wall_velocity_to_points`). A contact
  // wall counts as holding its normal also where the grains lift off: a version that held it
  // only while they pressed (no normal velocity left after the conditions) threw a point of a
  // collapsing column at 14 m/s (stop 48; `Simulation.CohesionlessSandCollapsesFromZeroStress`).
  const Eigen::Matrix<double, dim, dim>& held_components(std::size_t node) const {
    return held[held_index(node)];
  }
  // Marks the nodes the active constraints hold and what they hold (after `constraints`
  // changes). A node on several walls holds the span of their components: the projector onto
  // the range of the sum of theirs (two rollers meeting at a corner hold both components).
  void hold_nodes() {
    using Matrix = Eigen::Matrix<double, dim, dim>;
    std::fill(held_node.begin(), held_node.end(), 0);
    for (const NodalConstraint<dim>* c : constraints)
      for (int node : c->nodes) held_node[static_cast<std::size_t>(node)] = 1;
    held_nodes.clear();
    for (std::size_t node = 0; node < held_node.size(); ++node)
      if (held_node[node]) held_nodes.push_back(static_cast<int>(node));
    // Only a phase whose points take the wall's velocity reads the projectors (the water's
    // points keep FLIP's increment at walls: nodes_to_points).
    held.clear();
    if (!wall_velocity_to_points) return;
    held.assign(held_nodes.size(), Matrix::Zero());
    for (const NodalConstraint<dim>* c : constraints)
      for (std::size_t k = 0; k < c->nodes.size(); ++k)
        held[held_index(static_cast<std::size_t>(c->nodes[k]))] += wall_holds(*c, k);
    for (Matrix& sum : held) sum = range_projector<dim>(sum);
  }
  std::size_t bytes() const {
    return points.bytes() + shape.size() * sizeof(Shape) +
           held.size() * sizeof(Eigen::Matrix<double, dim, dim>) + held_nodes.size() * sizeof(int) +
           node_velocity.size() *
               (2 * sizeof(Vec) + sizeof(char) + nodal.threads() * Sums::kBytesPerNode);
  }
};

// A point that is the only mass of its phase at every node of its cell (to a relative 1e-9,
// the rounding of the nodal sums), none of them held by a velocity condition nor, when
// `other_mass` is given, carrying mass of the other phase, is a free body: a fragment of soil
// or a drop of water with nothing around it. No traction acts on it, so it carries no stress
// (no pressure), and an unconfined body relaxes to that within a wave's transit of itself,
// less than a step. The grid cannot show it: the MUSL remap gives every node of such a point
// the point's own velocity, its strain (its flux divergence) is zero, and a stress it left
// the flow with stayed frozen for the whole flight, to come out at its next contact (a grain
// thrown 29 % above the top of a collapsing column; scientific manual 4.6). Uses the nodal
// masses of the step's first scatter and the point's shape values from it.
template <int dim, class Points, class Sums>
bool is_free_body(const Phase<dim, Points, Sums>& phase, const Mesh<dim>& mesh, std::size_t p,
                  const std::vector<double>* other_mass = nullptr) {
  const auto& nodes = mesh.cell_nodes[phase.points.cell[p]];
  const std::vector<double>& nodal_mass = phase.nodal.sums().mass;
  const double mass = phase.points.mass[p];
  for (int i = 0; i <= dim; ++i) {
    const std::size_t node = static_cast<std::size_t>(nodes[i]);
    if (phase.is_held(node)) return false;
    if (other_mass && (*other_mass)[node] > kMassFloor) return false;
    if (nodal_mass[node] - phase.shape[p](i) * mass > 1e-9 * nodal_mass[node]) return false;
  }
  return true;
}

enum class Transfer { kMassMomentumForce, kMomentum };

// Step 1: mass, momentum, weight and internal force -V sigma . grad N (the weak form of
// div sigma, eq. 11 for the solid's effective stress; the viscous stress of eq. 17 for the
// water). `extra(sums, k, nodes, shape, grad)` adds what only one phase puts on the nodes.
// `pore_water` (liquid sums only; may be null): the points flagged in it also add their
// mass, momentum and force to the sums' pore_ arrays (two_phase.cpp), the same bits.
template <int dim, class Points, class Sums, class Extra>
void scatter_to_nodes(Phase<dim, Points, Sums>& phase, const Mesh<dim>& mesh,
                      const Eigen::Matrix<double, dim, 1>& gravity,
                      const std::vector<Voigt6>& stress, Transfer what, Extra extra,
                      const char* pore_water = nullptr) {
  using Vec = Eigen::Matrix<double, dim, 1>;
  Points& points = phase.points;
  const std::size_t n_points = points.size();
  if (what == Transfer::kMomentum) {
    phase.nodal.run(
        n_points, [](Sums& s) { return std::tie(s.momentum); },
        [&](Sums& b, std::size_t p) {
          const auto& nodes = mesh.cell_nodes[points.cell[p]];
          const Vec momentum = points.mass[p] * points.velocity[p];
          for (int i = 0; i <= dim; ++i) b.momentum[nodes[i]] += phase.shape[p](i) * momentum;
        });
    return;
  }
  phase.nodal.run(
      n_points, [](Sums& s) { return s.all(); },
      [&](Sums& b, std::size_t p) {
        const int cell = points.cell[p];
        const auto& nodes = mesh.cell_nodes[cell];
        const auto& grad = mesh.cell_shape_gradient[cell];
        const auto& n = phase.shape[p];
        const double m = points.mass[p];
        const double v = points.volume[p];
        const Vec momentum = m * points.velocity[p];
        const Vec weight = m * gravity;
        const Voigt6& sigma = stress[p];
        std::array<Vec, dim + 1> force;
        for (int i = 0; i <= dim; ++i) {
          const int node = nodes[i];
          force[i] = n(i) * weight - v * stress_dot(sigma, grad[i]);
          b.mass[node] += n(i) * m;
          b.momentum[node] += n(i) * momentum;
          b.force[node] += force[i];
        }
        if constexpr (requires { b.pore_mass; })
          if (pore_water && pore_water[p])
            for (int i = 0; i <= dim; ++i) {
              const int node = nodes[i];
              b.pore_mass[node] += n(i) * m;
              b.pore_momentum[node] += n(i) * momentum;
              b.pore_force[node] += force[i];
            }
        extra(b, p, nodes, n, grad);
      });
}

// Local (Cundall) damping: a force opposing the velocity, proportional to the unbalanced
// force, that vanishes at equilibrium (quasi-static stages).
template <class Vec>
void apply_local_damping(Vec& force, const Vec& velocity, double damping) {
  if (damping <= 0) return;
  for (int d = 0; d < force.size(); ++d) {
    const double sign = velocity(d) > 0 ? 1.0 : (velocity(d) < 0 ? -1.0 : 0.0);
    force(d) -= damping * std::abs(force(d)) * sign;
  }
}

// Step 2, the end of the nodal update: node_velocity holds the new velocity and
// node_acceleration the old one; applies the velocity conditions, then a = (v_new - v_old)/dt.
// The plain laws (no pore-pressure push: two_phase.cpp applies that before the drag);
// `coulomb`: see apply_constraints (boundary_conditions.hpp).
template <int dim, class Points, class Sums>
void finish_nodal_update(Phase<dim, Points, Sums>& phase, double dt, int threads,
                         bool coulomb = true) {
  apply_constraints<dim>(phase.constraints, phase.node_velocity, nullptr, coulomb);
  const std::size_t n_nodes = phase.node_velocity.size();
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i)
    phase.node_acceleration[i] = (phase.node_velocity[i] - phase.node_acceleration[i]) / dt;
}

// The nodal arrays a point takes its velocity and acceleration from.
template <class Vec>
struct NodalField {
  const Vec* velocity;
  const Vec* acceleration;
  // Added to the PIC share's velocity, not to the move, when given: XPIC(m) (xpic.hpp).
  const Vec* pic_correction = nullptr;
};

// Step 3: FLIP keeps the point's own velocity plus the grid's acceleration (little numerical
// dissipation), PIC takes the grid's velocity (stable, dissipative); the phase's damping sets
// the blend. The point moves with the grid velocity. `field_of(p)` names the nodal field
// point p reads (the water has two at the nodes it shares with a soil, two_phase.cpp).
// With `wall_velocity_to_points` (the grains), the components a wall prescribes at a node are
// taken from the grid at that node: the point's share N_i of them is the wall's velocity, not
// its own plus the node's change. A wall sets a velocity, not a force, so the change v_new -
// v_old at its node is not an acceleration that every point there underwent: FLIP handed each
// point the same arrest -v_old (the mean of heavy and light points), and a light, parted grain
// beside a heavy one kept its own velocity against the wall, carried it on and took it into the
// next contact (scientific manual 4.1; thin-front note, section 12). With v_old = v_new - dt a,
// the FLIP sum loses N_i P_i (v_p - v_old,i) at each held node i, P_i its held components.
template <int dim, class Points, class Sums, class FieldOf>
void nodes_to_points(Phase<dim, Points, Sums>& phase, const Mesh<dim>& mesh, double dt, int threads,
                     FieldOf field_of) {
  using Vec = Eigen::Matrix<double, dim, 1>;
  Points& points = phase.points;
  const std::size_t n_points = points.size();
  const double flip = phase.damping.flip_share(dt);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t p = 0; p < n_points; ++p) {
    const auto& nodes = mesh.cell_nodes[points.cell[p]];
    const auto& n = phase.shape[p];
    const NodalField<Vec> field = field_of(p);
    Vec acceleration = Vec::Zero(), velocity = Vec::Zero(), against_wall = Vec::Zero();
    for (int i = 0; i <= dim; ++i) {
      const int node = nodes[i];
      acceleration += n(i) * field.acceleration[node];
      velocity += n(i) * field.velocity[node];
      if (phase.wall_velocity_to_points && phase.is_held(node)) {
        const Vec old = field.velocity[node] - dt * field.acceleration[node];
        against_wall += n(i) * (phase.held_components(node) * (points.velocity[p] - old));
      }
    }
    Vec damped = velocity;
    if (field.pic_correction)
      for (int i = 0; i <= dim; ++i) damped += n(i) * field.pic_correction[nodes[i]];
    points.velocity[p] =
        flip * (points.velocity[p] + dt * acceleration - against_wall) + (1 - flip) * damped;
    points.position[p] += dt * velocity;
    if constexpr (requires { points.displacement; }) points.displacement[p] += dt * velocity;
  }
}

// Step 3 for a phase with one nodal field.
template <int dim, class Points, class Sums>
void nodes_to_points(Phase<dim, Points, Sums>& phase, const Mesh<dim>& mesh, double dt,
                     int threads) {
  using Vec = Eigen::Matrix<double, dim, 1>;
  const NodalField<Vec> own{phase.node_velocity.data(), phase.node_acceleration.data()};
  nodes_to_points(phase, mesh, dt, threads, [own](std::size_t) { return own; });
}

// Step 4 (MUSL): the nodal momentum of the updated point velocities, and the nodal velocity
// from it (zero where the phase has no mass; the caller applies the velocity conditions).
template <int dim, class Points, class Sums>
void remap_velocity(Phase<dim, Points, Sums>& phase, const Mesh<dim>& mesh, int threads) {
  scatter_to_nodes(phase, mesh, {}, {}, Transfer::kMomentum, [](auto&&...) {});
  const Sums& sums = phase.nodal.sums();
  const std::size_t n_nodes = phase.node_velocity.size();
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < n_nodes; ++i)
    phase.node_velocity[i] = velocity_from_momentum(sums.momentum[i], sums.mass[i]);
}

// What stops a run at a point.
enum class PointFault { kNone, kNotFinite, kTooFast, kLeftMesh };

// The first point (lowest index) that faulted in a parallel loop: the same point whatever the
// threads' timing.
struct FirstFault {
  long point = -1;
  PointFault kind = PointFault::kNone;
  void note(std::size_t p, PointFault fault) {
#pragma omp critical(lituya_first_fault)
    if (point < 0 || static_cast<long>(p) < point) {
      point = static_cast<long>(p);
      kind = fault;
    }
  }
};

// Step 5: point p's fields are `finite` or not; if they are and it is not faster than
// `max_velocity`, finds its new cell from the old one (walking through face neighbours) and
// refreshes its shape values. Returns the fault, kNone when the point was relocated.
template <int dim, class Points, class Sums>
PointFault relocate(Phase<dim, Points, Sums>& phase, const Mesh<dim>& mesh, std::size_t p,
                    double speed, bool finite, double max_velocity) {
  if (!finite || !std::isfinite(speed)) return PointFault::kNotFinite;
  if (speed > max_velocity) return PointFault::kTooFast;
  const int found = mesh.locate(phase.points.cell[p], phase.points.position[p], phase.shape[p]);
  if (found < 0) return PointFault::kLeftMesh;
  phase.points.cell[p] = found;
  return PointFault::kNone;
}

}  // namespace lituya::solver::detail
