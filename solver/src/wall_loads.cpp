// Boundary forces: what the material pushes on each held boundary with.
//
// The nodal update gives every node the velocity of its explicit forces f (stress, gravity,
// pore pressure, local damping), and then the boundary conditions change it. What a wall
// adds is therefore the rest of the momentum change: over a step, the reaction on the
// material at node i is
//     R_i = sum over the phases of m (v_new - v_old) / dt  -  f_i,
// the sum taken over the grains and both water fields. The drag of eq. (23) and the coupling
// at a soil's surface exchange momentum between the phases only (they are solved as momentum-
// conserving pairs), so they cancel in the sum. The force on the wall is -R_i. A sponge zone
// (a damping of the water, not a wall) at a wall node would count as a wall force; sponges lie
// away from the walls they absorb for.
//
// Each node's force is split along its wall's outward normal nu (normal = -R . nu, positive
// where the material presses) and across it (the tangential part: at a contact wall, the
// Coulomb friction). At a contact wall with water, the wall's reaction W_i to the pore
// pressure (two_phase.cpp, wall_pore_pressure_load: the boundary term of the weak form of
// eqs. 15, 16) is summed as well, so that normal - pore_pressure is the effective normal force
// that Coulomb's law acts on (eq. 14; boundary_conditions.hpp). A node on several walls (a
// corner: a bed meeting a tank wall) shares its force: each wall takes the part along its own
// normal, and the rest goes to the walls that can push across their normal (fixed, fixity,
// contact with friction). Counted in both, the tank wall's water pressure at the corner node
// added 55 N/m of "friction" to a bed whose friction was 85 N/m
// (verification/saturated_block_fine).
//
// The explicit forces are not stored: they are recomputed at the wall nodes from the nodal
// sums, which the update leaves as they were, by the functions the update itself calls
// (dry_node_step, two_phase_node_step), so the sums cost no memory per node.
// The sums are impulses, so that a caller can average them over any stretch of steps (the
// nodal forces of an explicit scheme ring from step to step): each row of the stage history
// takes them and writes their mean since the row before (probe_recorder.cpp); a checkpoint
// holds what has been summed since. They read the state and change nothing else, in a fixed
// order, so they cost a loop over the wall nodes and leave every result unchanged to the last
// bit (the 138 VTU files of verification/saturated_block_fine, byte for byte).
#include <algorithm>

#include <Eigen/Dense>

#include "lituya/solver/simulation.hpp"

namespace lituya::solver {

using detail::kMassFloor;

template <int dim>
double Simulation<dim>::take_wall_impulses(std::vector<WallImpulse>& impulses) {
  impulses = wall_impulse_;
  std::fill(wall_impulse_.begin(), wall_impulse_.end(), WallImpulse{});
  const double time = wall_impulse_time_;
  wall_impulse_time_ = 0;
  return time;
}

// The wall nodes of the stage's boundaries, and what splits each node's force between them.
// The sums are not touched: run_stage starts them afresh at a stage's start, and a run going
// on from a checkpoint keeps the checkpoint's.
template <int dim>
void Simulation<dim>::collect_wall_nodes() {
  using Normals = Eigen::Matrix<double, dim, Eigen::Dynamic>;
  if (wall_impulse_.size() != constraints_.size())
    wall_impulse_.assign(constraints_.size(), WallImpulse{});
  // The held conditions (a condition on both phases is in both lists), in the case's order.
  std::vector<char> held(constraints_.size(), 0);
  for (const auto* list : {&solid_.constraints, &water_.constraints})
    for (const NodalConstraint<dim>* c : *list)
      held[static_cast<std::size_t>(c - constraints_.data())] = 1;
  // Every (node, condition, normal) entry, grouped by node in node order.
  wall_entries_.clear();
  for (std::size_t b = 0; b < constraints_.size(); ++b) {
    if (!held[b]) continue;
    const NodalConstraint<dim>& c = constraints_[b];
    for (std::size_t k = 0; k < c.nodes.size(); ++k)
      wall_entries_.push_back({c.nodes[k], b, c.normal[k], c.normal[k], 0.0});
  }
  std::stable_sort(wall_entries_.begin(), wall_entries_.end(),
                   [](const WallEntry& a, const WallEntry& b) { return a.node < b.node; });
  wall_nodes_.clear();
  for (std::size_t e = 0; e < wall_entries_.size(); ++e)
    if (wall_nodes_.empty() || wall_nodes_.back().node != wall_entries_[e].node)
      wall_nodes_.push_back({wall_entries_[e].node, e, 1, false});
    else
      ++wall_nodes_.back().count;
  // A node on several walls (a corner) shares its force: each wall takes the part along its own
  // normal, by least squares (the normals need not be orthogonal), a row of the normals'
  // pseudo-inverse; the rest, across them all (the friction, or the grip of a fixed wall),
  // goes in equal shares to the walls that can take it, or to all where none can. One wall:
  // the plain projection on its normal, and all the rest.
  const auto grips = [&](const WallEntry& entry) {
    const NodalConstraint<dim>& c = constraints_[entry.boundary];
    return c.type == BoundaryType::kFixed || c.type == BoundaryType::kFixity ||
           (c.type == BoundaryType::kContact && c.friction > 0);
  };
  for (WallNode& wall_node : wall_nodes_) {
    WallEntry* entries = wall_entries_.data() + wall_node.first;
    const std::size_t count = wall_node.count;
    std::size_t gripping = 0;
    for (std::size_t e = 0; e < count; ++e) {
      gripping += grips(entries[e]);
      wall_node.contact |=
          has_liquid_ && constraints_[entries[e].boundary].type == BoundaryType::kContact;
    }
    for (std::size_t e = 0; e < count; ++e)
      entries[e].tangential_share =
          gripping == 0 ? 1.0 / static_cast<double>(count)
                        : (grips(entries[e]) ? 1.0 / static_cast<double>(gripping) : 0.0);
    if (count == 1) continue;
    Normals normals(dim, static_cast<Eigen::Index>(count));
    for (std::size_t e = 0; e < count; ++e)
      normals.col(static_cast<Eigen::Index>(e)) = entries[e].normal;
    const Eigen::MatrixXd inverse = normals.completeOrthogonalDecomposition().pseudoInverse();
    for (std::size_t e = 0; e < count; ++e)
      entries[e].dual = inverse.row(static_cast<Eigen::Index>(e)).transpose();
  }
}

template <int dim>
void Simulation<dim>::accumulate_wall_impulses(double dt, double damping) {
  wall_impulse_time_ += dt;
  for (const WallNode& wall_node : wall_nodes_) {
    const auto node = static_cast<std::size_t>(wall_node.node);
    // The step's explicit forces, recomputed from the nodal sums as the update computed them
    // (the sums are not changed by the update), and the momentum change of each field.
    Vec force = Vec::Zero();
    bool wet = false;
    if (has_liquid_) {
      const NodeStep n = two_phase_node_step(node, damping);
      if (n.ms > kMassFloor) force += n.fs - n.ms * solid_.node_acceleration[node];
      if (n.mf > kMassFloor) force += n.ff - n.mf * water_.node_acceleration[node];
      if (n.mp > kMassFloor) force += n.fp - n.mp * pore_water_acceleration_[node];
      wet = n.mf + n.mp > kMassFloor;
    } else if (solid_.nodal.sums().mass[node] > kMassFloor) {
      const NodeStep n = dry_node_step(node, damping);
      force = n.fs - n.ms * solid_.node_acceleration[node];
    }
    // `force` is -R, the force on the walls; split as collect_wall_nodes says.
    const WallEntry* entries = wall_entries_.data() + wall_node.first;
    const bool pore_pressure = wet && wall_node.contact;
    const Vec pore_load =
        pore_pressure ? wall_pore_pressure_load(wall_node.node) : Vec(Vec::Zero());
    Vec across = force;
    for (std::size_t e = 0; e < wall_node.count; ++e)
      across -= entries[e].dual.dot(force) * entries[e].normal;
    for (std::size_t e = 0; e < wall_node.count; ++e) {
      const WallEntry& entry = entries[e];
      WallImpulse& sum = wall_impulse_[entry.boundary];
      const double normal = entry.dual.dot(force);
      sum.normal += dt * normal;
      sum.tangential += dt * entry.tangential_share * across;
      sum.force += dt * (normal * entry.normal + entry.tangential_share * across);
      if (pore_pressure && constraints_[entry.boundary].type == BoundaryType::kContact)
        sum.pore_pressure += dt * entry.dual.dot(pore_load);
    }
  }
}

template double Simulation<2>::take_wall_impulses(std::vector<WallImpulse>&);
template double Simulation<3>::take_wall_impulses(std::vector<WallImpulse>&);
template void Simulation<2>::collect_wall_nodes();
template void Simulation<3>::collect_wall_nodes();
template void Simulation<2>::accumulate_wall_impulses(double, double);
template void Simulation<3>::accumulate_wall_impulses(double, double);

}  // namespace lituya::solver
