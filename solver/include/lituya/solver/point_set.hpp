#pragma once
// What every set of material points carries, solid or liquid: where each point is, how fast it
// moves, the mass and volume it stands for, its material and the background cell that holds
// it. The two point sets of the two-layer two-phase MPM (section 2 of the paper, Figure 1)
// add their own fields (material_points.hpp, liquid_points.hpp); the transfers between points
// and nodes need only these, so they are written once for both (phase_transfers.hpp).
// Stored as a structure of arrays so the hot loops stream through memory.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace lituya::solver {

template <int dim>
struct PointSet {
  using Vec = Eigen::Matrix<double, dim, 1>;

  std::vector<Vec> position;   // m
  std::vector<Vec> velocity;   // m/s
  std::vector<double> mass;    // kg (per metre of thickness in 2D), fixed for the run (eqs. 3, 4)
  std::vector<double> volume;  // m3 (m2 in 2D)
  std::vector<int> material;   // index into the case's materials
  std::vector<int> cell;       // containing background cell
  std::vector<int> id;         // index in the points file (points may be reordered)

  std::size_t size() const { return position.size(); }
  bool empty() const { return position.empty(); }

 protected:
  void resize_common(std::size_t n) {
    position.resize(n, Vec::Zero());
    velocity.resize(n, Vec::Zero());
    mass.resize(n, 0.0);
    volume.resize(n, 0.0);
    material.resize(n, 0);
    cell.resize(n, 0);
    id.resize(n, 0);
  }
  static constexpr std::size_t kCommonBytesPerPoint =
      2 * sizeof(Vec) + 2 * sizeof(double) + 3 * sizeof(int);
};

}  // namespace lituya::solver
