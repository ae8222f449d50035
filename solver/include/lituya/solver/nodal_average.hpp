#pragma once
// The symmetric nodal average of a point field, the operator of the volumetric smoothing
// (scientific manual 4.5):
//   (S f)_p = sum_i N_i(x_p) F_i,   F_i = sum_q N_i(x_q) w_q f_q / sum_q N_i(x_q) w_q,
// over the nodes i of point p's cell and the points q of the cells around node i. It
// reproduces a constant field exactly, does not amplify a field (sum w (S f)^2 <= sum w f^2),
// and is self-adjoint in the points' weighted sum, sum_p w_p a_p (S b)_p = sum_p w_p b_p (S a)_p.
// The smoothing's first form, a flat sum over a node's points interpolated back with N, is not
// symmetric; it fed FLIP noise until a point left the mesh (verification/sliding_block), which
// this form does not. Internal to the solver library.
#include <cstddef>
#include <tuple>
#include <vector>

#include "lituya/solver/mesh.hpp"
#include "lituya/solver/nodal_scatter.hpp"

namespace lituya::solver::detail {

struct NodalAverageSums {
  std::vector<double> weight, moment;  // sum N w, sum N w f
  void assign(std::size_t n) {
    weight.assign(n, 0.0);
    moment.assign(n, 0.0);
  }
};

// Calls store(p, (S f)_p) for every point; weight(p) is w_p, value(p) is f_p.
template <int dim, class Weight, class Value, class Store>
void nodal_average(NodalScatter<NodalAverageSums>& scatter, const Mesh<dim>& mesh,
                   const std::vector<int>& cell,
                   const std::vector<typename Mesh<dim>::Shape>& shape, int threads, Weight weight,
                   Value value, Store store) {
  const std::size_t n_points = cell.size();
  scatter.run(
      n_points, [](NodalAverageSums& sums) { return std::tie(sums.weight, sums.moment); },
      [&](NodalAverageSums& sums, std::size_t p) {
        const auto& nodes = mesh.cell_nodes[cell[p]];
        const double w = weight(p);
        const double wf = w * value(p);
        for (int i = 0; i <= dim; ++i) {
          sums.weight[nodes[i]] += shape[p](i) * w;
          sums.moment[nodes[i]] += shape[p](i) * wf;
        }
      });
  const NodalAverageSums& sums = scatter.sums();
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t p = 0; p < n_points; ++p) {
    const auto& nodes = mesh.cell_nodes[cell[p]];
    double smoothed = 0;
    for (int i = 0; i <= dim; ++i) {
      // A node that no point weighs (every N = 0 there) is read by no point with a weight.
      const double w = sums.weight[nodes[i]];
      if (w > 0) smoothed += shape[p](i) * sums.moment[nodes[i]] / w;
    }
    store(p, smoothed);
  }
}

}  // namespace lituya::solver::detail
