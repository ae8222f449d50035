#pragma once
// The liquid material points (water), the second point set of the two-layer two-phase MPM
// (section 2 of the paper, Figure 1): alone in a cell they are free water (n = 1); where they
// share cells with solid points they are pore water, and the porosity they see is the one the
// solid points define.
//
// Each point carries a fixed mass of water (eq. 4 is exact in MPM), its volume of water (not
// of mixture) and the intrinsic liquid pressure p_w of eqs. (7), (8), stored compression
// positive (a hydrostatic column has p = rho_w g depth > 0); the paper's sigma_w = -p I +
// viscous stress, eq. (17).
#include <vector>

#include <Eigen/Core>

#include "lituya/solver/mohr_coulomb.hpp"
#include "lituya/solver/point_set.hpp"

namespace lituya::solver {

template <int dim>
struct LiquidPoints : PointSet<dim> {
  std::vector<double> pressure;        // Pa, compression positive, >= 0 (no tension)
  std::vector<Voigt6> viscous_stress;  // Pa, mu (grad v + grad v^T), eq. (17)
  std::vector<double> porosity;        // n seen by the point (1 in free water)
  // 1 while the point's body of water rests on nothing (water_in_flight.hpp): spray. A point
  // whose flag goes from 1 to 0 has landed (liquid_landing.cpp).
  std::vector<char> in_flight;

  void resize(std::size_t n) {
    this->resize_common(n);
    pressure.resize(n, 0.0);
    viscous_stress.resize(n, Voigt6::Zero());
    porosity.resize(n, 1.0);
    in_flight.resize(n, 0);
  }
  std::size_t bytes() const {
    return this->size() *
           (this->kCommonBytesPerPoint + 2 * sizeof(double) + sizeof(Voigt6) + sizeof(char));
  }
};

}  // namespace lituya::solver
