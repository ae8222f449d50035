#pragma once
// Which water is in free flight: the spray a slide throws out of the impact zone, a sheet
// that leaves a crest. Used to merge such water into the body it lands on
// (liquid_landing.cpp).
//
// A body of water is a set of cells holding liquid points that are linked through shared
// nodes: the grid couples two points exactly when their cells share a node (their masses and
// momenta meet there), so a body is what the grid treats as one continuum. A body rests on
// something when one of its nodes is held by a velocity condition of the water (a wall, the
// floor) or carries grains (a soil, a slide). A body that rests on nothing is in free flight:
// nothing but gravity acts on it. The rule has no length or time constant, and a second pool
// is as much a body as the first (no "largest cluster").
//
// Found by union-find over the nodes of the wet cells, serially, so the result does not
// depend on the threads: O(points + wet cells + nodes) per call.
#include <cstddef>
#include <numeric>
#include <vector>

#include "lituya/solver/mesh.hpp"

namespace lituya::solver::detail {

template <int dim>
class WaterInFlight {
 public:
  // After find(): cell_in_flight(c) is 1 when cell c holds water whose body has no node with
  // held_node[i] != 0 or solid_mass[i] > solid_mass_floor, 0 otherwise (a dry cell too).
  // solid_mass may be empty (no grains in the scene). point_cell: the cell of every liquid
  // point.
  void find(const Mesh<dim>& mesh, const std::vector<int>& point_cell,
            const std::vector<char>& held_node, const std::vector<double>& solid_mass,
            double solid_mass_floor) {
    const std::size_t n_nodes = mesh.node_count();
    const std::size_t n_cells = mesh.cell_count();
    wet_cell_.assign(n_cells, 0);
    for (int c : point_cell) wet_cell_[static_cast<std::size_t>(c)] = 1;
    parent_.resize(n_nodes);
    std::iota(parent_.begin(), parent_.end(), 0);
    for (std::size_t c = 0; c < n_cells; ++c) {
      if (!wet_cell_[c]) continue;
      const auto& nodes = mesh.cell_nodes[c];
      for (int i = 1; i <= dim; ++i) unite(nodes[0], nodes[i]);
    }
    // A root stands for its body: mark it when any wet node of the body rests on something.
    resting_.assign(n_nodes, 0);
    for (std::size_t c = 0; c < n_cells; ++c) {
      if (!wet_cell_[c]) continue;
      for (int node : mesh.cell_nodes[c]) {
        const std::size_t i = static_cast<std::size_t>(node);
        if (held_node[i] || (!solid_mass.empty() && solid_mass[i] > solid_mass_floor))
          resting_[static_cast<std::size_t>(root(node))] = 1;
      }
    }
    // wet_cell_ becomes the answer: 1 for a wet cell of a body in flight.
    for (std::size_t c = 0; c < n_cells; ++c)
      if (wet_cell_[c])
        wet_cell_[c] = resting_[static_cast<std::size_t>(root(mesh.cell_nodes[c][0]))] ? 0 : 1;
  }
  char cell_in_flight(int cell) const { return wet_cell_[static_cast<std::size_t>(cell)]; }

 private:
  // Path halving: each visited node points to its grandparent.
  int root(int i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }
  void unite(int a, int b) {
    a = root(a);
    b = root(b);
    if (a == b) return;
    // The smaller index becomes the root: the same partition gives the same roots whatever
    // the order of the unions.
    if (a < b)
      parent_[b] = a;
    else
      parent_[a] = b;
  }
  std::vector<char> wet_cell_, resting_;
  std::vector<int> parent_;
};

}  // namespace lituya::solver::detail
