#pragma once
// Preconditioned conjugate gradients, matrix-free, on nodal vectors: the water's two
// projections (pressure_projection.cpp, pore_volume_projection.cpp) solve symmetric positive
// definite systems this way. Serial loops in a fixed order: the same bits for any thread count.
#include <cstddef>
#include <vector>

namespace lituya::solver::detail {

struct ConjugateGradientScratch {
  std::vector<double> residual, preconditioned, direction, product;
  void resize(std::size_t n) {
    for (auto* v : {&residual, &preconditioned, &direction, &product}) v->assign(n, 0.0);
  }
};

// Solves A x = rhs starting from the x given (a warm start). apply(x, y) sets y = A x;
// precondition(i, r) returns the preconditioned residual at i. Stops when |r| <=
// relative_tolerance |rhs|, when A stops being positive along a direction (round-off), or
// after max_iterations. Returns the iterations taken.
template <class Apply, class Precondition>
int conjugate_gradient(const Apply& apply, const Precondition& precondition,
                       const std::vector<double>& rhs, std::vector<double>& x,
                       ConjugateGradientScratch& s, double relative_tolerance, int max_iterations) {
  const std::size_t n = rhs.size();
  s.resize(n);
  apply(x, s.product);
  double rz = 0, rhs_norm = 0;
  for (std::size_t i = 0; i < n; ++i) {
    s.residual[i] = rhs[i] - s.product[i];
    s.preconditioned[i] = precondition(i, s.residual[i]);
    s.direction[i] = s.preconditioned[i];
    rz += s.residual[i] * s.preconditioned[i];
    rhs_norm += rhs[i] * rhs[i];
  }
  const double tolerance = relative_tolerance * relative_tolerance * rhs_norm;
  int iteration = 0;
  for (; iteration < max_iterations; ++iteration) {
    double rr = 0;
    for (std::size_t i = 0; i < n; ++i) rr += s.residual[i] * s.residual[i];
    if (rr <= tolerance) break;
    apply(s.direction, s.product);
    double pap = 0;
    for (std::size_t i = 0; i < n; ++i) pap += s.direction[i] * s.product[i];
    if (!(pap > 0)) break;
    const double alpha = rz / pap;
    double rz_new = 0;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] += alpha * s.direction[i];
      s.residual[i] -= alpha * s.product[i];
      s.preconditioned[i] = precondition(i, s.residual[i]);
      rz_new += s.residual[i] * s.preconditioned[i];
    }
    const double beta = rz_new / rz;
    rz = rz_new;
    for (std::size_t i = 0; i < n; ++i)
      s.direction[i] = s.preconditioned[i] + beta * s.direction[i];
  }
  return iteration;
}

}  // namespace lituya::solver::detail
