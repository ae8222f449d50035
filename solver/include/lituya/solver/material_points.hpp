#pragma once
// The solid material points (soil skeleton), stored as a structure of arrays so the hot loops
// stream through memory. Each point carries its mass for the whole run (mass conservation,
// eq. (3), is exact in MPM) and its effective stress sigma' (eq. 19).
#include <vector>

#include <Eigen/Core>

#include "lituya/solver/mohr_coulomb.hpp"

namespace lituya::solver {

template <int dim>
struct MaterialPoints {
  using Vec = Eigen::Matrix<double, dim, 1>;

  std::vector<Vec> position;           // m
  std::vector<Vec> velocity;           // m/s
  std::vector<Vec> displacement;       // m, since the last reset
  std::vector<double> mass;            // kg (per metre of thickness in 2D)
  std::vector<double> volume;          // m3 (m2 in 2D)
  std::vector<Voigt6> stress;          // effective stress, Pa, tension positive
  std::vector<double> plastic_strain;  // equivalent plastic strain
  std::vector<int> material;           // index into the case's materials
  std::vector<int> cell;               // containing background cell
  std::vector<int> id;                 // index in points.vtu (points may be reordered)

  std::size_t size() const { return position.size(); }
  void resize(std::size_t n) {
    position.resize(n, Vec::Zero());
    velocity.resize(n, Vec::Zero());
    displacement.resize(n, Vec::Zero());
    mass.resize(n, 0.0);
    volume.resize(n, 0.0);
    stress.resize(n, Voigt6::Zero());
    plastic_strain.resize(n, 0.0);
    material.resize(n, 0);
    cell.resize(n, 0);
    id.resize(n, 0);
  }
  // Bytes of point storage (for the memory-per-point report).
  std::size_t bytes() const {
    return size() * (3 * sizeof(Vec) + 3 * sizeof(double) + sizeof(Voigt6) + 3 * sizeof(int));
  }
};

}  // namespace lituya::solver
