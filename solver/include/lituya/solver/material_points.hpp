#pragma once
// The solid material points (soil skeleton). Besides what every point set carries
// (point_set.hpp), each point has its displacement and its effective stress sigma' (eq. 19).
#include <vector>

#include <Eigen/Core>

#include "lituya/solver/mohr_coulomb.hpp"
#include "lituya/solver/point_set.hpp"

namespace lituya::solver {

template <int dim>
struct MaterialPoints : PointSet<dim> {
  using Vec = typename PointSet<dim>::Vec;

  std::vector<Vec> displacement;       // m, since the last reset
  std::vector<Voigt6> stress;          // effective stress, Pa, tension positive
  std::vector<double> plastic_strain;  // equivalent plastic strain

  void resize(std::size_t n) {
    this->resize_common(n);
    displacement.resize(n, Vec::Zero());
    stress.resize(n, Voigt6::Zero());
    plastic_strain.resize(n, 0.0);
  }
  // Bytes of point storage (for the memory-per-point report).
  std::size_t bytes() const {
    return this->size() *
           (this->kCommonBytesPerPoint + sizeof(Vec) + sizeof(Voigt6) + sizeof(double));
  }
};

}  // namespace lituya::solver
