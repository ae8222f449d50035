#include "lituya/solver/boundary_conditions.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <unordered_map>

#include "lituya/common/input_error.hpp"

namespace lituya::solver {

namespace {
// Facets of one group whose normals differ by less than this angle (40 degrees) form one
// smooth wall at their shared nodes; a sharper angle is a corner (a box's corner, the toe of a
// slope): there the averaged normal would let the node slide along the bisector, out of one
// wall and into the other.
constexpr double kSmoothWallCosine = 0.766;

// Unnormalised facet normal (its length is the facet's length or area).
Eigen::Vector2d facet_normal(const Mesh<2>& mesh, const std::array<int, 2>& f) {
  const Eigen::Vector2d edge = mesh.node_position[f[1]] - mesh.node_position[f[0]];
  return Eigen::Vector2d(edge.y(), -edge.x());
}
Eigen::Vector3d facet_normal(const Mesh<3>& mesh, const std::array<int, 3>& f) {
  const Eigen::Vector3d a = mesh.node_position[f[1]] - mesh.node_position[f[0]];
  const Eigen::Vector3d b = mesh.node_position[f[2]] - mesh.node_position[f[0]];
  return 0.5 * a.cross(b);
}
}  // namespace

template <int dim>
NodalConstraint<dim> make_constraint(const BoundaryCondition& bc,
                                     const std::vector<std::array<int, dim>>& facets,
                                     const Mesh<dim>& mesh, const std::string& file) {
  using Vec = Eigen::Matrix<double, dim, 1>;
  NodalConstraint<dim> constraint;
  constraint.type = bc.type;
  constraint.phase = bc.phase;
  constraint.ramp_time = bc.ramp_time;
  constraint.friction = bc.friction;
  constraint.directions = bc.directions;
  if (facets.empty())
    throw InputError(
        file, 0,
        "boundary '" + bc.name + "': its group '" + bc.group + "' has no facets in the mesh");
  // Cells around each node, to find the cells adjacent to a facet.
  std::vector<std::vector<int>> cells_of_node(mesh.node_count());
  for (std::size_t c = 0; c < mesh.cell_count(); ++c)
    for (int n : mesh.cell_nodes[c]) cells_of_node[n].push_back(static_cast<int>(c));

  // Per node, the group's facet normals summed per wall (weighted by facet size): facets
  // that meet at an angle whose cosine exceeds kSmoothWallCosine are one smooth wall; at a
  // sharper angle (a corner) each wall keeps its own sum.
  std::unordered_map<int, std::vector<Vec>> walls;
  std::unordered_map<int, Vec> force_sum;
  std::vector<int> order;
  Vec traction = Vec::Zero();
  for (std::size_t d = 0; d < bc.traction.size() && d < dim; ++d) traction(d) = bc.traction[d];
  for (const auto& facet : facets) {
    Vec normal = facet_normal(mesh, facet);
    // A linear facet shares its integral of N t equally between its dim nodes.
    const Vec facet_force = traction * normal.norm() / dim;
    for (int n : facet) {
      auto [it, inserted] = force_sum.try_emplace(n, Vec::Zero());
      it->second += facet_force;
    }
    std::vector<int> adjacent;
    for (int c : cells_of_node[facet[0]]) {
      bool has_all = true;
      for (int n : facet)
        has_all = has_all && std::find(mesh.cell_nodes[c].begin(), mesh.cell_nodes[c].end(), n) !=
                                 mesh.cell_nodes[c].end();
      if (has_all) adjacent.push_back(c);
    }
    if (adjacent.empty())
      throw InputError(file, 0,
                       "boundary '" + bc.name + "': a facet of group '" + bc.group +
                           "' is not a face of any background cell");
    if (adjacent.size() > 1 && bc.type == BoundaryType::kContact)
      throw InputError(
          file, 0,
          "boundary '" + bc.name +
              "' (contact) lies inside the mesh, where there "
              "is no outside to point its normal to: use type \"roller\" or \"fixed\"");
    // Orient the normal away from the (first) adjacent cell's centroid: outward.
    Vec centroid = Vec::Zero();
    for (int n : mesh.cell_nodes[adjacent[0]]) centroid += mesh.node_position[n];
    centroid /= dim + 1;
    if (normal.dot(mesh.node_position[facet[0]] - centroid) < 0) normal = -normal;
    const Vec direction = normal.normalized();
    for (int n : facet) {
      auto [it, inserted] = walls.try_emplace(n);
      if (inserted) order.push_back(n);
      std::vector<Vec>& node_walls = it->second;
      auto same = std::find_if(node_walls.begin(), node_walls.end(), [&](const Vec& wall) {
        return wall.normalized().dot(direction) > kSmoothWallCosine;
      });
      if (same == node_walls.end())
        node_walls.push_back(normal);
      else
        *same += normal;
    }
  }
  std::sort(order.begin(), order.end());
  for (int n : order) {
    const std::vector<Vec>& node_walls = walls[n];
    auto push = [&](const Vec& normal) {
      constraint.nodes.push_back(n);
      constraint.normal.push_back(normal);
      if (bc.type == BoundaryType::kTraction) constraint.force.push_back(force_sum[n]);
    };
    if (bc.type == BoundaryType::kRoller) {
      // At a corner a roller allows only the motion tangential to every wall: the normals
      // made orthonormal (Gram-Schmidt), so removing the component along each in turn is the
      // exact projection.
      std::vector<Vec> basis;
      for (const Vec& wall : node_walls) {
        Vec normal = wall.normalized();
        for (const Vec& b : basis) normal -= normal.dot(b) * b;
        if (normal.norm() < 1e-6) continue;
        normal.normalize();
        basis.push_back(normal);
        push(normal);
      }
    } else if (bc.type == BoundaryType::kContact) {
      // A contact wall keeps each wall's own normal (one-sided, with friction).
      for (const Vec& wall : node_walls) push(wall.normalized());
    } else {
      // The other types do not use the direction of the wall: one entry per node.
      Vec sum = Vec::Zero();
      for (const Vec& wall : node_walls) sum += wall;
      push(sum.normalized());
    }
  }
  return constraint;
}

template <int dim>
void apply_constraints(const std::vector<const NodalConstraint<dim>*>& active,
                       std::vector<Eigen::Matrix<double, dim, 1>>& velocity,
                       const std::vector<Eigen::Matrix<double, dim, 1>>* wall_pore_pressure_push,
                       bool coulomb) {
  using Vec = Eigen::Matrix<double, dim, 1>;
  for (int pass = 0; pass < 2; ++pass) {
    for (const NodalConstraint<dim>* c : active) {
      const std::size_t n_nodes = c->nodes.size();
      switch (c->type) {
        case BoundaryType::kFixed:
          for (std::size_t k = 0; k < n_nodes; ++k) velocity[c->nodes[k]].setZero();
          break;
        case BoundaryType::kFixity:
          for (std::size_t k = 0; k < n_nodes; ++k)
            for (int d : c->directions) velocity[c->nodes[k]](d) = 0.0;
          break;
        case BoundaryType::kRoller:
          for (std::size_t k = 0; k < n_nodes; ++k) {
            Vec& v = velocity[c->nodes[k]];
            v -= v.dot(c->normal[k]) * c->normal[k];
          }
          break;
        case BoundaryType::kContact:
          for (std::size_t k = 0; k < n_nodes; ++k) {
            Vec& v = velocity[c->nodes[k]];
            const Vec& n = c->normal[k];
            const double approach = v.dot(n);
            // The wall's reaction to the pore pressure on the grains is given back once (the
            // first pass; the second only mends corners), with no friction. What is left is
            // the skeleton's own approach (header comment).
            const double pore_part =
                pass == 0 && wall_pore_pressure_push
                    ? std::max(0.0, (*wall_pore_pressure_push)[c->nodes[k]].dot(n))
                    : 0.0;
            const double skeleton = approach - pore_part;
            const Vec tangential = v - approach * n;
            if (skeleton <= 0) {
              // Separating: the wall does not pull. Saturated grains lift off at what their
              // skeleton gives them once the wall has pushed back the pore pressure.
              if (pore_part > 0) v = tangential + skeleton * n;
              continue;
            }
            const double slip = tangential.norm();
            // Coulomb: the tangential impulse is at most mu times the normal impulse, m times
            // the skeleton's approach; stick if that is enough to stop the slip.
            const double reduction = coulomb ? c->friction * skeleton : 0.0;
            v = slip > reduction ? Vec(tangential * (1.0 - reduction / slip)) : Vec::Zero();
          }
          break;
        case BoundaryType::kTraction:
          break;
      }
    }
  }
}

template NodalConstraint<2> make_constraint<2>(const BoundaryCondition&,
                                               const std::vector<std::array<int, 2>>&,
                                               const Mesh<2>&, const std::string&);
template NodalConstraint<3> make_constraint<3>(const BoundaryCondition&,
                                               const std::vector<std::array<int, 3>>&,
                                               const Mesh<3>&, const std::string&);
template void apply_constraints<2>(const std::vector<const NodalConstraint<2>*>&,
                                   std::vector<Eigen::Vector2d>&,
                                   const std::vector<Eigen::Vector2d>*, bool);
template void apply_constraints<3>(const std::vector<const NodalConstraint<3>*>&,
                                   std::vector<Eigen::Vector3d>&,
                                   const std::vector<Eigen::Vector3d>*, bool);

}  // namespace lituya::solver
