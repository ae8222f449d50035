#pragma once
// XPIC(m), the extended PIC transfer of Hammerquist and Nairn (2017, Comput. Methods Appl.
// Mech. Eng. 318, 724-738), for one nodal velocity field ([solver] liquid_xpic_order;
// scientific manual 4.1).
//
// Why: the FLIP/PIC blend of nodes_to_points damps, at the rate 1 / tau, the part of a point's
// velocity that the grid does not see, v_p - S v^n (S: nodes to points, v^n the nodal field
// mapped from the points). With linear cells a resolved, smooth motion is not fully seen
// either: the map points -> nodes -> points, P, keeps a grid-scale mode only to a fraction
// lambda < 1 and a smooth one to nearly 1, and the blend takes 1 - lambda of each, so it also
// takes the height of resolved waves. XPIC(m) takes (1 - lambda)^m instead: the unseen part
// goes as fast, what the grid resolves far more slowly. On a crossed mesh a standing wave grows
// a rotational noise that the plain blend stops only by also taking the wave; with XPIC(2) at
// one grid time and nine points per cell the noise stays flat and the wave keeps its height
// (verification/standing_wave/README.md, stop 56).
// What: the damped share of the blend takes the nodal field v^L + c instead of v^L, with
//     c = V - v^n,   V = sum_{k=1..m} (-1)^(k+1) C(m, k) A^(k-1) v^n,
//     (A u)_i = sum_p N_i(x_p) m_p sum_j N_j(x_p) u_j / m_i,
// v^n = v^L - dt a the step's mapped velocity (before the nodal update), m_i the field's
// nodal mass. Then S V = [I - (I - P)^m] v_p for the points' velocities v_p, and m = 1 is
// the plain blend (c = 0). The point's move is not changed. Costs m - 1 more scatters of the
// field's points a step, each summed per thread in a fixed order (nodal_scatter.hpp): the
// same bits on any run with the same number of threads.
#include <Eigen/Dense>
#include <cstddef>
#include <tuple>
#include <vector>

#include "lituya/solver/mesh.hpp"
#include "lituya/solver/nodal_scatter.hpp"
#include "lituya/solver/phase.hpp"

namespace lituya::solver {

template <int dim>
class Xpic {
 public:
  using Vec = Eigen::Matrix<double, dim, 1>;
  using Shape = typename Mesh<dim>::Shape;

  void allocate(int threads, std::size_t n_nodes) {
    scatter_.allocate(threads, n_nodes);
    mapped_.assign(n_nodes, Vec::Zero());
    term_.assign(n_nodes, Vec::Zero());
    sum_.assign(n_nodes, Vec::Zero());
    correction_.assign(n_nodes, Vec::Zero());
  }

  // The correction c of the header for the nodal field (velocity, acceleration) after the
  // step's nodal update, from the points p < cell.size() for which uses(p) holds (the points
  // that read this field), with their cells, shape values and masses at the step's start.
  // Nodes without mass (below detail::kMassFloor) get c = 0. Returns c, one entry per node.
  template <class Uses>
  const std::vector<Vec>& update(int order, const Mesh<dim>& mesh, const std::vector<int>& cell,
                                 const std::vector<Shape>& shape, const std::vector<double>& mass,
                                 const Vec* velocity, const Vec* acceleration, double dt,
                                 Uses uses) {
    const std::size_t n_nodes = correction_.size();
    const int threads = scatter_.threads();
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t i = 0; i < n_nodes; ++i) {
      mapped_[i] = velocity[i] - dt * acceleration[i];
      term_[i] = mapped_[i];
      sum_[i] = Vec::Zero();
    }
    double binomial = 1;  // C(order, k)
    for (int k = 1; k <= order; ++k) {
      binomial = binomial * (order - k + 1) / k;
      const double sign = k % 2 == 1 ? 1.0 : -1.0;
#pragma omp parallel for num_threads(threads) schedule(static)
      for (std::size_t i = 0; i < n_nodes; ++i) sum_[i] += (sign * binomial) * term_[i];
      if (k == order) break;
      apply_map(mesh, cell, shape, mass, uses, k == 1);
    }
    const std::vector<double>& nodal_mass = scatter_.sums().mass;
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t i = 0; i < n_nodes; ++i)
      correction_[i] = nodal_mass[i] > detail::kMassFloor ? Vec(sum_[i] - mapped_[i]) : Vec::Zero();
    return correction_;
  }

 private:
  struct Sums {
    std::vector<Vec> momentum;
    std::vector<double> mass;
    void assign(std::size_t n) {
      momentum.assign(n, Vec::Zero());
      mass.assign(n, 0.0);
    }
  };

  // term <- A term. The first call also sums the nodal mass of the selected points.
  template <class Uses>
  void apply_map(const Mesh<dim>& mesh, const std::vector<int>& cell,
                 const std::vector<Shape>& shape, const std::vector<double>& mass, Uses uses,
                 bool with_mass) {
    auto body = [&](Sums& b, std::size_t p) {
      if (!uses(p)) return;
      const auto& nodes = mesh.cell_nodes[static_cast<std::size_t>(cell[p])];
      Vec at_point = Vec::Zero();
      for (int a = 0; a <= dim; ++a) at_point += shape[p](a) * term_[nodes[a]];
      for (int a = 0; a <= dim; ++a) {
        const double w = shape[p](a) * mass[p];
        b.momentum[nodes[a]] += w * at_point;
        if (with_mass) b.mass[nodes[a]] += w;
      }
    };
    if (with_mass)
      scatter_.run(
          cell.size(), [](Sums& b) { return std::tie(b.momentum, b.mass); }, body);
    else
      scatter_.run(
          cell.size(), [](Sums& b) { return std::tie(b.momentum); }, body);
    const Sums& s = scatter_.sums();
    const std::size_t n_nodes = term_.size();
#pragma omp parallel for num_threads(scatter_.threads()) schedule(static)
    for (std::size_t i = 0; i < n_nodes; ++i)
      term_[i] = detail::velocity_from_momentum(s.momentum[i], s.mass[i]);
  }

  detail::NodalScatter<Sums> scatter_;
  std::vector<Vec> mapped_, term_, sum_, correction_;
};

}  // namespace lituya::solver
