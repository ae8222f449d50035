#include "lituya/solver/boundary_conditions.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>
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

namespace {

// One wall's law at one node (entry k of constraint c), as in the header. `pass` 0 gives back
// the pore-pressure push at a contact wall; pass 1 only mends corners.
template <int dim>
void apply_wall(const NodalConstraint<dim>& c, std::size_t k, Eigen::Matrix<double, dim, 1>& v,
                int pass, const std::vector<Eigen::Matrix<double, dim, 1>>* wall_pore_pressure_push,
                bool coulomb) {
  using Vec = Eigen::Matrix<double, dim, 1>;
  switch (c.type) {
    case BoundaryType::kFixed:
      v.setZero();
      break;
    case BoundaryType::kFixity:
      for (int d : c.directions) v(d) = 0.0;
      break;
    case BoundaryType::kRoller:
      v -= v.dot(c.normal[k]) * c.normal[k];
      break;
    case BoundaryType::kContact: {
      const Vec& n = c.normal[k];
      const double approach = v.dot(n);
      // The wall's reaction to the pore pressure on the grains is given back once (the
      // first pass; the second only mends corners), with no friction. What is left is
      // the skeleton's own approach (header comment).
      const double pore_part = pass == 0 && wall_pore_pressure_push
                                   ? std::max(0.0, (*wall_pore_pressure_push)[c.nodes[k]].dot(n))
                                   : 0.0;
      const double skeleton = approach - pore_part;
      const Vec tangential = v - approach * n;
      if (skeleton <= 0) {
        // Separating: the wall does not pull. Saturated grains lift off at what their
        // skeleton gives them once the wall has pushed back the pore pressure.
        if (pore_part > 0) v = tangential + skeleton * n;
        return;
      }
      const double slip = tangential.norm();
      // Coulomb: the tangential impulse is at most mu times the normal impulse, m times
      // the skeleton's approach; stick if that is enough to stop the slip.
      const double reduction = coulomb ? c.friction * skeleton : 0.0;
      v = slip > reduction ? Vec(tangential * (1.0 - reduction / slip)) : Vec::Zero();
      break;
    }
    case BoundaryType::kTraction:
      break;
  }
}

// One wall condition of a node on several walls.
template <int dim>
struct CornerEntry {
  int node;
  const NodalConstraint<dim>* constraint;
  std::size_t k;
};

// A node on walls that meet at an angle other than 90 degrees: the walls' laws one after
// the other are not the walls' reaction there. At the toe of a slope (a contact slope at 45
// degrees over a roller bed) a velocity into the corner, projected on the slope and then
// on the bed, came out along the bed, away from the slope, as fast as it went in: an
// impulse no wall gives (a wall pushes along its own normal, and only while the node stays on
// it). On Case B's crossed meshes the toe node, holding almost no water, was thrown along the
// bed at thousands of m/s each step, the water points beside it took a share of it, and the
// corner's pressure reached MPa (issue 8). Here the node takes the admissible velocity
// nearest to its own, the walls' frictionless reaction: the projection onto {held rows of
// fixities and rollers zero, n . v <= 0 at each contact}, found by trying each set of active
// contacts (a few walls at most) and keeping the nearest admissible candidate. The pore push
// of a contact is given back first (apply_wall's pass 0), and Coulomb's law then reduces
// what slip is left by mu times each active contact's normal velocity removed.
// At most this many contact walls at one node take part in the search (2^6 candidate sets);
// more have never been seen (a 3D box vertex has three).
constexpr int kMaxCornerContacts = 6;

template <int dim>
void apply_corner(const CornerEntry<dim>* entries, std::size_t count,
                  Eigen::Matrix<double, dim, 1>& v,
                  const std::vector<Eigen::Matrix<double, dim, 1>>* wall_pore_pressure_push,
                  bool coulomb) {
  using Vec = Eigen::Matrix<double, dim, 1>;
  using Matrix = Eigen::Matrix<double, dim, dim>;
  Matrix held = Matrix::Zero();  // what fixities, rollers and `fixed` hold (two-sided)
  std::array<const Vec*, kMaxCornerContacts> normal{};
  std::array<double, kMaxCornerContacts> friction{};
  int contacts = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const NodalConstraint<dim>& c = *entries[i].constraint;
    if (c.type != BoundaryType::kContact) {
      held += wall_holds(c, entries[i].k);
      continue;
    }
    const Vec& n = c.normal[entries[i].k];
    if (wall_pore_pressure_push)
      v -= std::max(0.0, (*wall_pore_pressure_push)[entries[i].node].dot(n)) * n;
    if (contacts < kMaxCornerContacts) {
      normal[contacts] = &n;
      friction[contacts++] = c.friction;
    }
  }
  const double tolerance = 1e-12 * v.norm();
  Vec best = Vec::Zero();
  double best_distance = std::numeric_limits<double>::infinity();
  unsigned best_set = 0;
  for (unsigned set = 0; set < (1u << contacts); ++set) {
    Matrix sum = held;
    for (int j = 0; j < contacts; ++j)
      if (set >> j & 1u) sum += *normal[j] * normal[j]->transpose();
    const Vec w = v - range_projector<dim>(sum) * v;
    bool admissible = true;
    for (int j = 0; j < contacts; ++j) admissible = admissible && w.dot(*normal[j]) <= tolerance;
    const double distance = (w - v).squaredNorm();
    if (admissible && distance < best_distance) {
      best = w;
      best_distance = distance;
      best_set = set;
    }
  }
  // Coulomb on what slips: each active contact's multiplier lambda_k, the normal velocity it
  // removed, from (I - P_held)(v - w) = sum_k lambda_k (I - P_held) n_k (least squares; unique
  // where w != 0, and fixed-size storage: no allocation).
  const double slip = best.norm();
  if (coulomb && slip > 0 && best_set != 0) {
    const Matrix free = Matrix::Identity() - range_projector<dim>(held);
    Eigen::Matrix<double, dim, Eigen::Dynamic, 0, dim, kMaxCornerContacts> active(dim, 0);
    std::array<double, kMaxCornerContacts> active_friction{};
    for (int j = 0; j < contacts; ++j)
      if (best_set >> j & 1u) {
        active.conservativeResize(Eigen::NoChange, active.cols() + 1);
        active.col(active.cols() - 1) = free * *normal[j];
        active_friction[static_cast<std::size_t>(active.cols() - 1)] = friction[j];
      }
    const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxCornerContacts, 1> multiplier =
        active.completeOrthogonalDecomposition().solve(Vec(free * (v - best)));
    double reduction = 0;
    for (Eigen::Index j = 0; j < active.cols(); ++j)
      reduction += active_friction[static_cast<std::size_t>(j)] * std::max(0.0, multiplier(j));
    best = slip > reduction ? Vec(best * (1.0 - reduction / slip)) : Vec::Zero();
  }
  v = best;
}

// Whether the walls at a corner node take the laws one after the other exactly: each pair of
// the walls' held projectors commutes (orthogonal walls, or the same wall twice; `fixed`
// commutes with anything). Kept there as it was, to the bit.
template <int dim>
bool walls_orthogonal(const CornerEntry<dim>* entries, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = i + 1; j < count; ++j) {
      const auto a = wall_holds(*entries[i].constraint, entries[i].k);
      const auto b = wall_holds(*entries[j].constraint, entries[j].k);
      if ((a * b - b * a).norm() > 1e-9) return false;
    }
  return true;
}

}  // namespace

template <int dim>
void apply_constraints(const std::vector<const NodalConstraint<dim>*>& active,
                       std::vector<Eigen::Matrix<double, dim, 1>>& velocity,
                       const std::vector<Eigen::Matrix<double, dim, 1>>* wall_pore_pressure_push,
                       bool coulomb) {
  // How many wall conditions each node has. Scratch kept between calls (this runs several
  // times a step, serially): zero again on return.
  thread_local std::vector<unsigned char> walls_at;
  thread_local std::vector<CornerEntry<dim>> corner;
  if (walls_at.size() < velocity.size()) walls_at.resize(velocity.size(), 0);
  for (const NodalConstraint<dim>* c : active)
    if (c->type != BoundaryType::kTraction)
      for (int node : c->nodes)
        if (walls_at[node] < 255) ++walls_at[node];
  // A node on one wall takes that wall's law (twice, as it always has: the second pass changes
  // nothing there but the last bits of a contact's slip).
  corner.clear();
  for (const NodalConstraint<dim>* c : active) {
    if (c->type == BoundaryType::kTraction) continue;
    for (std::size_t k = 0; k < c->nodes.size(); ++k) {
      const int node = c->nodes[k];
      if (walls_at[node] > 1) {
        corner.push_back({node, c, k});
        continue;
      }
      for (int pass = 0; pass < 2; ++pass)
        apply_wall(*c, k, velocity[node], pass, wall_pore_pressure_push, coulomb);
    }
  }
  for (const NodalConstraint<dim>* c : active)
    if (c->type != BoundaryType::kTraction)
      for (int node : c->nodes) walls_at[node] = 0;
  // Nodes on several walls, each with its entries in the order of `active`.
  std::stable_sort(
      corner.begin(), corner.end(),
      [](const CornerEntry<dim>& a, const CornerEntry<dim>& b) { return a.node < b.node; });
  for (std::size_t first = 0; first < corner.size();) {
    std::size_t last = first;
    while (last < corner.size() && corner[last].node == corner[first].node) ++last;
    const CornerEntry<dim>* entries = corner.data() + first;
    const std::size_t count = last - first;
    Eigen::Matrix<double, dim, 1>& v = velocity[corner[first].node];
    if (walls_orthogonal(entries, count)) {
      for (int pass = 0; pass < 2; ++pass)
        for (std::size_t i = 0; i < count; ++i)
          apply_wall(*entries[i].constraint, entries[i].k, v, pass, wall_pore_pressure_push,
                     coulomb);
    } else {
      apply_corner(entries, count, v, wall_pore_pressure_push, coulomb);
    }
    first = last;
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
