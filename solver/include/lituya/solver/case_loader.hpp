#pragma once
// Reads a case folder written by `lituya pre` (geometry.vtu, points.vtu, liquid_points.vtu plus the
// TOML files read by read_case) into the solver's mesh, points and boundary node sets, checking
// that every cell is positively oriented and every point lies in the mesh.
#include <vector>

#include "lituya/solver/boundary_conditions.hpp"
#include "lituya/solver/case_description.hpp"
#include "lituya/solver/liquid_points.hpp"
#include "lituya/solver/material_points.hpp"
#include "lituya/solver/mesh.hpp"

namespace lituya::solver {

template <int dim>
struct LoadedCase {
  Mesh<dim> mesh;
  MaterialPoints<dim> points;
  LiquidPoints<dim> liquid;                       // empty in a dry case
  std::vector<NodalConstraint<dim>> constraints;  // one per description.boundaries entry
};

template <int dim>
LoadedCase<dim> load_case(const CaseDescription& description);

}  // namespace lituya::solver
