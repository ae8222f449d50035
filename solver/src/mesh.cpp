#include "lituya/solver/mesh.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <unordered_map>

namespace lituya::solver {

namespace {
// Key of a face (dim sorted node indices) for neighbour search.
template <int dim>
std::uint64_t face_key(std::array<int, dim> nodes) {
  std::sort(nodes.begin(), nodes.end());
  std::uint64_t key = 0;
  for (int n : nodes) key = key * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(n) + 1;
  return key;
}
}  // namespace

template <int dim>
int Mesh<dim>::build() {
  const std::size_t n_cells = cell_nodes.size();
  cell_neighbour.assign(n_cells, {});
  cell_inverse_jacobian.resize(n_cells);
  cell_shape_gradient.resize(n_cells);
  cell_volume.resize(n_cells);
  cell_min_height.resize(n_cells);
  int first_invalid = -1;
  for (std::size_t c = 0; c < n_cells; ++c) {
    Eigen::Matrix<double, dim, dim> jacobian;
    const Vec& x0 = node_position[cell_nodes[c][0]];
    for (int k = 0; k < dim; ++k) jacobian.col(k) = node_position[cell_nodes[c][k + 1]] - x0;
    const double det = jacobian.determinant();
    cell_volume[c] = det / (dim == 2 ? 2.0 : 6.0);
    if (!(cell_volume[c] > 0)) {
      if (first_invalid < 0) first_invalid = static_cast<int>(c);
      cell_inverse_jacobian[c].setZero();
      continue;
    }
    cell_inverse_jacobian[c] = jacobian.inverse();
    // grad lambda_k (k >= 1) is row k-1 of J^-1; grad lambda_0 = -sum of the others.
    Vec sum = Vec::Zero();
    for (int k = 0; k < dim; ++k) {
      cell_shape_gradient[c][k + 1] = cell_inverse_jacobian[c].row(k).transpose();
      sum += cell_shape_gradient[c][k + 1];
    }
    cell_shape_gradient[c][0] = -sum;
    // Altitude to node i is 1 / |grad lambda_i|; the smallest one limits the time step.
    double min_height = 1e300;
    for (int i = 0; i <= dim; ++i)
      min_height = std::min(min_height, 1.0 / cell_shape_gradient[c][i].norm());
    cell_min_height[c] = min_height;
  }
  // Neighbours: the face opposite local node i is shared with at most one other cell.
  std::unordered_map<std::uint64_t, std::pair<int, int>> face_owner;
  face_owner.reserve(n_cells * (dim + 1));
  for (std::size_t c = 0; c < n_cells; ++c) {
    for (int i = 0; i <= dim; ++i) {
      std::array<int, dim> face;
      for (int k = 0, j = 0; k <= dim; ++k)
        if (k != i) face[j++] = cell_nodes[c][k];
      const std::uint64_t key = face_key<dim>(face);
      auto [it, inserted] = face_owner.try_emplace(key, static_cast<int>(c), i);
      cell_neighbour[c][i] = -1;
      if (!inserted) {
        cell_neighbour[c][i] = it->second.first;
        cell_neighbour[it->second.first][it->second.second] = static_cast<int>(c);
      }
    }
  }
  return first_invalid;
}

template <int dim>
int Mesh<dim>::locate_anywhere(const Vec& x, Shape& shape) const {
  for (std::size_t c = 0; c < cell_nodes.size(); ++c) {
    shape = shape_values(static_cast<int>(c), x);
    if (shape.minCoeff() >= -1e-12) return static_cast<int>(c);
  }
  return -1;
}

template <>
Mesh<2> make_box_mesh<2>(const Eigen::Vector2d& origin, const Eigen::Vector2d& size,
                         const std::array<int, 2>& cells) {
  Mesh<2> mesh;
  const int nx = cells[0], ny = cells[1];
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      mesh.node_position.push_back(origin + Eigen::Vector2d(size.x() * i / nx, size.y() * j / ny));
  auto node = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      // Alternate the diagonal so the mesh has no preferred direction.
      if ((i + j) % 2 == 0) {
        mesh.cell_nodes.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1)});
        mesh.cell_nodes.push_back({node(i, j), node(i + 1, j + 1), node(i, j + 1)});
      } else {
        mesh.cell_nodes.push_back({node(i, j), node(i + 1, j), node(i, j + 1)});
        mesh.cell_nodes.push_back({node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
      }
    }
  mesh.build();
  return mesh;
}

template <>
Mesh<3> make_box_mesh<3>(const Eigen::Vector3d& origin, const Eigen::Vector3d& size,
                         const std::array<int, 3>& cells) {
  Mesh<3> mesh;
  const int nx = cells[0], ny = cells[1], nz = cells[2];
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.node_position.push_back(
            origin + Eigen::Vector3d(size.x() * i / nx, size.y() * j / ny, size.z() * k / nz));
  auto node = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  // Six tetrahedra around the main diagonal of each hexahedron (Kuhn triangulation): the
  // faces match between neighbouring boxes.
  static const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& path : paths) {
          std::array<int, 3> at{i, j, k};
          std::array<int, 4> tet;
          tet[0] = node(at[0], at[1], at[2]);
          for (int s = 0; s < 3; ++s) {
            at[path[s]] += 1;
            tet[s + 1] = node(at[0], at[1], at[2]);
          }
          // Orient positively.
          Eigen::Matrix3d jac;
          for (int c = 0; c < 3; ++c)
            jac.col(c) = mesh.node_position[tet[c + 1]] - mesh.node_position[tet[0]];
          if (jac.determinant() < 0) std::swap(tet[1], tet[2]);
          mesh.cell_nodes.push_back(tet);
        }
  mesh.build();
  return mesh;
}

template struct Mesh<2>;
template struct Mesh<3>;

}  // namespace lituya::solver
