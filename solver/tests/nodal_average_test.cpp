// The symmetric nodal average of the volumetric smoothing (nodal_average.hpp): it reproduces a
// constant field, it is self-adjoint in the points' weighted sum and does not amplify a field,
// and it repeats itself bit for bit on two threads.
#include "lituya/solver/nodal_average.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "lituya/solver/mesh.hpp"

namespace {

using namespace lituya::solver;

// Points scattered at random over part of a box mesh of 6 cells a side (some cells full, some
// with one point, most empty, as at a flow's front), with random weights.
template <int dim>
struct Cloud {
  using Vec = Eigen::Matrix<double, dim, 1>;
  Mesh<dim> mesh;
  std::vector<int> cell;
  std::vector<typename Mesh<dim>::Shape> shape;
  std::vector<double> weight;
  std::uint64_t state = 2024;
  double uniform() {  // in [0, 1): a 64-bit LCG (Knuth's MMIX constants)
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  }
  Cloud() {
    std::array<int, dim> cells;
    cells.fill(6);
    mesh = make_box_mesh<dim>(Vec::Zero(), Vec::Ones(), cells);
    for (int k = 0; k < 150 * (dim - 1); ++k) {
      Vec x;
      x(0) = 0.05 + 0.6 * uniform();
      x(1) = 0.05 + 0.5 * uniform() * uniform();  // thinning upwards, as a flow's surface
      if constexpr (dim == 3) x(2) = 0.05 + 0.9 * uniform();
      typename Mesh<dim>::Shape n;
      cell.push_back(mesh.locate_anywhere(x, n));
      shape.push_back(n);
      weight.push_back(0.5 + uniform());
    }
  }
  std::vector<double> random_field() {
    std::vector<double> f;
    for (std::size_t p = 0; p < cell.size(); ++p) f.push_back(uniform() - 0.5);
    return f;
  }
  std::vector<double> average(const std::vector<double>& f, int threads = 1) {
    detail::NodalScatter<detail::NodalAverageSums> scatter;
    scatter.allocate(threads, mesh.node_count());
    std::vector<double> out(f.size());
    detail::nodal_average<dim>(
        scatter, mesh, cell, shape, threads, [&](std::size_t p) { return weight[p]; },
        [&](std::size_t p) { return f[p]; }, [&](std::size_t p, double s) { out[p] = s; });
    return out;
  }
  double weighted_dot(const std::vector<double>& a, const std::vector<double>& b) const {
    double sum = 0;
    for (std::size_t p = 0; p < a.size(); ++p) sum += weight[p] * a[p] * b[p];
    return sum;
  }
};

template <int dim>
void check_reproduces_a_constant_field() {
  Cloud<dim> cloud;
  const std::vector<double> constant(cloud.cell.size(), -3.25);
  for (double s : cloud.average(constant)) EXPECT_NEAR(s, -3.25, 1e-13);
}
TEST(NodalAverage, ReproducesAConstantField) {
  check_reproduces_a_constant_field<2>();
  check_reproduces_a_constant_field<3>();
}

// sum w a (S b) = sum w b (S a) for any a, b: both are sum_i A_i B_i / W_i over the nodes.
// The smoothing's first form (a flat sum over a node's points, interpolated with N) fails it.
template <int dim>
void check_self_adjoint() {
  Cloud<dim> cloud;
  const auto a = cloud.random_field(), b = cloud.random_field();
  const double left = cloud.weighted_dot(a, cloud.average(b));
  const double right = cloud.weighted_dot(b, cloud.average(a));
  EXPECT_GT(std::abs(left), 1e-3);  // the fields are not orthogonal by accident
  EXPECT_NEAR(left, right, 1e-12 * std::abs(left));
}
TEST(NodalAverage, IsSelfAdjointInTheWeightedSum) {
  check_self_adjoint<2>();
  check_self_adjoint<3>();
}

// It smooths: the weighted sum of squares does not grow (Jensen's inequality at the nodes and
// at the points, nodal_average.hpp).
template <int dim>
void check_does_not_amplify() {
  Cloud<dim> cloud;
  const auto f = cloud.random_field();
  const auto s = cloud.average(f);
  EXPECT_LT(cloud.weighted_dot(s, s), cloud.weighted_dot(f, f));
}
TEST(NodalAverage, DoesNotAmplifyAField) {
  check_does_not_amplify<2>();
  check_does_not_amplify<3>();
}

// Per-thread sums added in a fixed order (nodal_scatter.hpp): two runs on two threads give the
// same bits; one thread differs from two by round-off only.
TEST(NodalAverage, TwoThreadRunsRepeatBitForBit) {
  Cloud<2> cloud;
  const auto f = cloud.random_field();
  EXPECT_EQ(cloud.average(f, 2), cloud.average(f, 2));
  const auto one = cloud.average(f, 1), two = cloud.average(f, 2);
  for (std::size_t p = 0; p < f.size(); ++p) EXPECT_NEAR(one[p], two[p], 1e-14);
}

}  // namespace
