#pragma once
// Boundary conditions on nodal velocities, applied after every grid update: fixities (no
// slip or selected global components), rollers (zero normal velocity on a wall of any
// inclination) and Coulomb contact with a rigid wall (no penetration, separation allowed,
// tangential velocity reduced by mu times the normal velocity jump; the nodal form of
// Coulomb friction, so a block on an incline accelerates at g (sin(theta) - mu cos(theta))).
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "lituya/solver/case_description.hpp"
#include "lituya/solver/mesh.hpp"

namespace lituya::solver {

template <int dim>
struct NodalConstraint {
  using Vec = Eigen::Matrix<double, dim, 1>;
  BoundaryType type = BoundaryType::kFixed;
  BoundaryPhase phase = BoundaryPhase::kBoth;
  double friction = 0;
  std::vector<int> directions;  // fixity
  std::vector<int> nodes;
  std::vector<Vec> normal;  // per node: unit outward normal of the group's facets
  std::vector<Vec> force;   // traction only: per node, the integral of N t over the facets (N)
  double ramp_time = 0;     // traction only: s, the load rises linearly over it
};

// Builds the node set and outward normals of one boundary condition from its group's facets.
// Throws InputError (naming `file`) if the group has no facets or a contact boundary lies
// inside the mesh.
template <int dim>
NodalConstraint<dim> make_constraint(const BoundaryCondition& bc,
                                     const std::vector<std::array<int, dim>>& facets,
                                     const Mesh<dim>& mesh, const std::string& file);

// What entry k of a wall condition holds at its node, as a sum of n n^T: all components for
// `fixed`, the listed axes for a fixity, the normal for a roller or a contact wall (a
// contact's normal counts as held also where the node leaves it), nothing for a traction.
template <int dim>
Eigen::Matrix<double, dim, dim> wall_holds(const NodalConstraint<dim>& c, std::size_t k) {
  using Matrix = Eigen::Matrix<double, dim, dim>;
  Matrix sum = Matrix::Zero();
  switch (c.type) {
    case BoundaryType::kFixed:
      sum = Matrix::Identity();
      break;
    case BoundaryType::kFixity:
      for (int d : c.directions) sum(d, d) = 1.0;
      break;
    case BoundaryType::kRoller:
    case BoundaryType::kContact:
      sum = c.normal[k] * c.normal[k].transpose();
      break;
    case BoundaryType::kTraction:
      break;
  }
  return sum;
}

// The orthogonal projector onto the range of a sum of n n^T (symmetric, positive): the
// components a node on several walls has held.
template <int dim>
Eigen::Matrix<double, dim, dim> range_projector(const Eigen::Matrix<double, dim, dim>& sum) {
  using Matrix = Eigen::Matrix<double, dim, dim>;
  const Eigen::SelfAdjointEigenSolver<Matrix> eigen(sum);
  Matrix projector = Matrix::Zero();
  for (int j = 0; j < dim; ++j)
    if (eigen.eigenvalues()(j) > 1e-6 * dim)
      projector += eigen.eigenvectors().col(j) * eigen.eigenvectors().col(j).transpose();
  return projector;
}

// Applies the active constraints to nodal velocities. Tractions are skipped (they are forces).
// A node on one wall, or on walls at right angles, takes each wall's law in turn (twice over);
// a node where walls meet at another angle (a slope's toe) takes the admissible velocity
// nearest to its own, the walls' frictionless reaction, then Coulomb's reduction of what slips
// (boundary_conditions.cpp, apply_corner).
// `wall_pore_pressure_push` (may be null; two-phase cases): per contact node, the velocity
// dt (1 - s) W / m_s (1 - s the grains' share of the pore-pressure force; two_phase.cpp) that the
// wall's reaction W to the grains' share of the pore pressure gives
// them. A contact wall always gives it back (the water between the grains carries the pressure
// to the wall, also where the grains lift off), without friction; what is left of the grains'
// approach is the skeleton's own push. It presses (the wall stops it, friction mu times it) or
// pulls away (the grains lift off: an effective stress has no tension at a wall). Coulomb
// friction on a saturated soil thus acts on the effective normal stress only (sigma'_n =
// sigma_n - p, eq. 14). Until December 2026 the wall held every node whose grains approached
// it and took friction from the positive part of approach less push only: where the skeleton
// pulled, its tension was lost instead of carried as lift-off, and a ringing block on a
// submerged incline got twice its effective-stress friction (verification/saturated_block).
// `coulomb` false (the liquid phase): a contact wall stops penetration but has no friction;
// water slides along a wall, Coulomb's law is for the grains.
template <int dim>
void apply_constraints(
    const std::vector<const NodalConstraint<dim>*>& active,
    std::vector<Eigen::Matrix<double, dim, 1>>& velocity,
    const std::vector<Eigen::Matrix<double, dim, 1>>* wall_pore_pressure_push = nullptr,
    bool coulomb = true);

}  // namespace lituya::solver
