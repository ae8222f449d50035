#pragma once
// The liquid material points (water), the second point set of the two-layer two-phase MPM
// (section 2 of the paper, Figure 1): alone in a cell they are free water (n = 1); where they
// share cells with solid points they are pore water, and the porosity they see is the one the
// solid points define. Stored as a structure of arrays, like the solid points.
//
// Each point carries a fixed mass of water (eq. 4 is exact in MPM) and the intrinsic liquid
// pressure p_w of eqs. (7), (8), stored compression positive (a hydrostatic column has
// p = rho_w g depth > 0); the paper's sigma_w = -p I + viscous stress, eq. (17).
#include <vector>

#include <Eigen/Core>

#include "lituya/solver/mohr_coulomb.hpp"

namespace lituya::solver {

template <int dim>
struct LiquidPoints {
  using Vec = Eigen::Matrix<double, dim, 1>;

  std::vector<Vec> position;           // m
  std::vector<Vec> velocity;           // m/s
  std::vector<double> mass;            // kg (per metre of thickness in 2D)
  std::vector<double> volume;          // m3 of water (not of mixture), m2 in 2D
  std::vector<double> pressure;        // Pa, compression positive, >= 0 (no tension)
  std::vector<Voigt6> viscous_stress;  // Pa, mu (grad v + grad v^T), eq. (17)
  std::vector<double> porosity;        // n seen by the point (1 in free water)
  std::vector<int> material;           // index into the case's materials (a water material)
  std::vector<int> cell;               // containing background cell
  std::vector<int> id;                 // index in liquid_points.vtu

  std::size_t size() const { return position.size(); }
  bool empty() const { return position.empty(); }
  void resize(std::size_t n) {
    position.resize(n, Vec::Zero());
    velocity.resize(n, Vec::Zero());
    mass.resize(n, 0.0);
    volume.resize(n, 0.0);
    pressure.resize(n, 0.0);
    viscous_stress.resize(n, Voigt6::Zero());
    porosity.resize(n, 1.0);
    material.resize(n, 0);
    cell.resize(n, 0);
    id.resize(n, 0);
  }
  std::size_t bytes() const {
    return size() * (2 * sizeof(Vec) + 4 * sizeof(double) + sizeof(Voigt6) + 3 * sizeof(int));
  }
};

}  // namespace lituya::solver
