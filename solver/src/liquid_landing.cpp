// Water that lands after a free flight merges into the water it lands in ([solver]
// liquid_landing = "merge", the default; scientific manual 10.4).
//
// Why: FLIP keeps each point's own velocity and adds the grid's change to it. A point that
// lands on the water (spray thrown out of a slide's impact zone, falling back on the rising
// wave) thus keeps its velocity relative to the water; the grid resists only through the
// pressure its compression raises, which turns that relative velocity around: an elastic
// deflection. Measured on Case B at 0.0075 and 0.005 m cells (stop 50): points thrown at
// 0.08-0.14 s land on the wave at 0.28-0.32 s, leave with 1.5-1.6 times their kinetic
// energy and skim ahead of the crest for 0.1-0.15 s; the finer the mesh, the more such
// spray (122 to 652 mm2 in flight at 0.20 s from 0.015 to 0.005 m cells), and the crest
// lost what it carried away. A drop that falls into water does not bounce: its motion
// relative to the water it meets is lost to the splash and the turbulence below it, an
// inelastic impact.
//
// What: water_in_flight.hpp finds, once a step, the bodies of water that rest on nothing. A
// point whose body was in flight at the last step and rests now has landed. After the
// node-to-point transfer of the step (step 3) a landed point and the water it meets collide
// perfectly inelastically, with the momentum of the whole kept:
// - the water it meets is the other liquid points at the nodes of its cell: their mass
//   M_i = sum_p N_i(x_p) m_p and momentum P_i = sum_p N_i(x_p) m_p v_p at each node i;
// - the landed point q takes their velocity as its cell's nodes see it,
//       v = sum_i N_i(x_q) P_i / sum_i N_i(x_q) M_i,
//   and hands its excess momentum J = m_q (v_q - v) to them, node i getting the share
//   w_i / sum_k w_k of it, w_i = N_i(x_q) M_i;
// - every point p of that water gains N_i(x_p) J_i / M_i at each such node: the sum over p
//   of m_p times the gain is J_i, so the step conserves momentum to rounding, and the energy
//   of the relative motion is what the impact loses.
// A point in flight, one that never left the water, and a landed point none of whose nodes
// holds other water (the far side of a drop several cells across, whose collision the grid
// resolves) are untouched. With the landed point's own share left in the nodal fields (it
// took the grid's velocity, or its excess went back to all points at its nodes), the drop,
// which dominates its own nodes at first contact, got most of its excess back: a drop smaller
// than a cell still bounced at -0.57 m/s (`LiquidLanding.*`). Taking the water's velocity from
// the nodal fields less the landed points' momentum divided by a tiny difference of masses and
// threw a point of Case B at 347 m/s (0.01 m cells); the sums above have no difference.
//
// Why at landing and not while in flight: a drop in flight is in free fall whatever the
// transfer (no pressure acts on it, phase.hpp, is_free_body), and the water a point flies
// alongside for a while is not what it merges into. Tried and lost in stop 50, with the
// crests of Case B: detecting a landing from the pressure (0 to > 0) acts on every surface
// point, which passes through p = 0 all the time (crests 21-30 % lower at 0.015 m cells);
// after at least 0.03 s at p = 0, it never acts (spray sheets press on themselves).
#include <algorithm>
#include <array>

#include <Eigen/Core>

#include "lituya/solver/simulation.hpp"

namespace lituya::solver {

template <int dim>
void Simulation<dim>::merge_landed_liquid() {
  LiquidPoints<dim>& liquid = water_.points;
  const std::size_t n_liquid = liquid.size();
  // The bodies from the cells the step's scatter used (the shape values are still theirs).
  water_in_flight_.find(mesh_, liquid.cell, water_.held_node, solid_.nodal.sums().mass,
                        detail::kMassFloor);
  landed_.clear();
  for (std::size_t q = 0; q < n_liquid; ++q) {
    const char now = water_in_flight_.cell_in_flight(liquid.cell[q]);
    if (liquid.in_flight[q] && !now) landed_.push_back(q);
    liquid.in_flight[q] = now;
  }
  if (landed_.empty()) return;
  landed_point_count_ += static_cast<long>(landed_.size());

  // The nodes of the landed points' cells, and the water already there: the mass and momentum
  // (velocities after this step's update) of the other points at those nodes. Serially, in
  // point order: the same sums whatever the threads.
  const std::size_t n_nodes = mesh_.node_count();
  landing_node_.resize(n_nodes, 0);
  body_mass_.resize(n_nodes, 0.0);
  body_momentum_.resize(n_nodes, Vec::Zero());
  landing_impulse_.resize(n_nodes, Vec::Zero());
  for (std::size_t q : landed_)
    for (int node : mesh_.cell_nodes[liquid.cell[q]]) landing_node_[node] = 1;
  // landed_ is in increasing order; asked only of points at a landing node.
  auto landed_now = [&](std::size_t q) {
    return std::binary_search(landed_.begin(), landed_.end(), q);
  };
  auto at_landing_node = [&](std::size_t q) {
    for (int node : mesh_.cell_nodes[liquid.cell[q]])
      if (landing_node_[node]) return true;
    return false;
  };
  for (std::size_t q = 0; q < n_liquid; ++q) {
    if (!at_landing_node(q) || landed_now(q)) continue;
    const auto& nodes = mesh_.cell_nodes[liquid.cell[q]];
    for (int i = 0; i <= dim; ++i)
      if (landing_node_[nodes[i]]) {
        const double m = water_.shape[q](i) * liquid.mass[q];
        body_mass_[nodes[i]] += m;
        body_momentum_[nodes[i]] += m * liquid.velocity[q];
      }
  }
  for (std::size_t q : landed_) {
    const auto& nodes = mesh_.cell_nodes[liquid.cell[q]];
    // The velocity of the water it lands in: that water's momentum at its nodes over its mass
    // there, each node weighted by the point's shape value. A landed point none of whose nodes
    // holds such water (the far side of a drop several cells big, which the grid resolves)
    // keeps its velocity.
    std::array<double, dim + 1> weight{};
    Vec momentum = Vec::Zero();
    double mass = 0;
    for (int i = 0; i <= dim; ++i) {
      weight[i] = water_.shape[q](i) * body_mass_[nodes[i]];
      momentum += water_.shape[q](i) * body_momentum_[nodes[i]];
      mass += weight[i];
    }
    if (!(mass > detail::kMassFloor)) continue;
    const Vec water_velocity = momentum / mass;
    const Vec excess = liquid.mass[q] * (liquid.velocity[q] - water_velocity);
    liquid.velocity[q] = water_velocity;
    // The excess goes to the water it meets: to its nodes in proportion to that water's mass.
    for (int i = 0; i <= dim; ++i) landing_impulse_[nodes[i]] += weight[i] / mass * excess;
  }
  // Every point of that water at such a node gains N_i J_i / m_i, m_i the water's mass there
  // (the sum of N_i m over the same points): the gains' momentum is J_i.
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::size_t q = 0; q < n_liquid; ++q) {
    if (!at_landing_node(q) || landed_now(q)) continue;
    const auto& nodes = mesh_.cell_nodes[liquid.cell[q]];
    for (int i = 0; i <= dim; ++i) {
      const int node = nodes[i];
      if (landing_node_[node] && body_mass_[node] > detail::kMassFloor)
        liquid.velocity[q] += water_.shape[q](i) / body_mass_[node] * landing_impulse_[node];
    }
  }
  for (std::size_t q : landed_)
    for (int node : mesh_.cell_nodes[liquid.cell[q]]) {
      landing_impulse_[node] = Vec::Zero();
      body_momentum_[node] = Vec::Zero();
      body_mass_[node] = 0;
      landing_node_[node] = 0;
    }
}

template void Simulation<2>::merge_landed_liquid();
template void Simulation<3>::merge_landed_liquid();

}  // namespace lituya::solver
