#pragma once
// The background mesh: linear triangles (2D plane strain) or linear tetrahedra (3D), as in
// Anura3D. On a linear simplex the shape functions are the barycentric coordinates of the
// point, and their gradients are constant per cell, so both are precomputed once here and a
// material point is located by walking from its last cell through face neighbours (no global
// search per step).
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace lituya::solver {

template <int dim>
struct Mesh {
  static_assert(dim == 2 || dim == 3);
  static constexpr int kNodesPerCell = dim + 1;
  using Vec = Eigen::Matrix<double, dim, 1>;
  using Shape = Eigen::Matrix<double, dim + 1, 1>;
  using CellNodes = std::array<int, dim + 1>;

  std::vector<Vec> node_position;
  std::vector<CellNodes> cell_nodes;
  // cell_neighbour[c][i]: the cell across the face opposite local node i, -1 on the boundary.
  std::vector<CellNodes> cell_neighbour;
  // Barycentric map: (lambda_1..lambda_dim) = inverse_jacobian * (x - x_node0).
  std::vector<Eigen::Matrix<double, dim, dim>> cell_inverse_jacobian;
  // Gradients of the dim + 1 shape functions (constant on a linear simplex).
  std::vector<std::array<Vec, dim + 1>> cell_shape_gradient;
  std::vector<double> cell_volume;      // m2 in 2D (per metre of thickness), m3 in 3D
  std::vector<double> cell_min_height;  // smallest altitude, the length in the Courant limit

  std::size_t node_count() const { return node_position.size(); }
  std::size_t cell_count() const { return cell_nodes.size(); }

  // The mesh volume each node stands for: the integral of its shape function, V_cell / (dim + 1)
  // from every cell around it (the lumped volume of the porosity, eq. 5, and of the probes).
  std::vector<double> lumped_node_volume() const {
    std::vector<double> volume(node_count(), 0.0);
    for (std::size_t c = 0; c < cell_count(); ++c)
      for (int node : cell_nodes[c]) volume[node] += cell_volume[c] / (dim + 1);
    return volume;
  }

  // Computes neighbours, inverse Jacobians, gradients, volumes and heights from
  // node_position and cell_nodes. Returns the index of the first cell with non-positive
  // volume (inverted or degenerate), or -1 when all are valid.
  int build();

  // Barycentric coordinates of x in cell c.
  Shape shape_values(int cell, const Vec& x) const {
    const Vec local = cell_inverse_jacobian[cell] * (x - node_position[cell_nodes[cell][0]]);
    Shape n;
    n(0) = 1.0 - local.sum();
    n.template tail<dim>() = local;
    return n;
  }

  // Walks from `start` towards x through face neighbours. Returns the containing cell and its
  // shape values in `shape`, or -1 if the walk leaves the mesh (x outside the domain).
  int locate(int start, const Vec& x, Shape& shape) const {
    constexpr double kTolerance = -1e-12;
    int cell = start;
    for (int walk = 0; walk < 100000; ++walk) {
      shape = shape_values(cell, x);
      if (shape.minCoeff() >= kTolerance) return cell;
      // Leave through the face with the most negative coordinate that has a neighbour: a
      // point just outside a boundary face may still lie in a neighbour across another face.
      int next = -1;
      double most_negative = kTolerance;
      for (int i = 0; i <= dim; ++i)
        if (shape(i) < most_negative && cell_neighbour[cell][i] >= 0) {
          most_negative = shape(i);
          next = cell_neighbour[cell][i];
        }
      if (next < 0) return -1;
      cell = next;
    }
    return -1;
  }

  // Brute-force search (used only when a point has no valid starting cell).
  int locate_anywhere(const Vec& x, Shape& shape) const;
};

// A structured mesh of a box [origin, origin + size] with `cells` divisions per axis, each
// box cut into 2 triangles (2D) or 6 tetrahedra (3D). For tests and benchmarks.
template <int dim>
Mesh<dim> make_box_mesh(const Eigen::Matrix<double, dim, 1>& origin,
                        const Eigen::Matrix<double, dim, 1>& size,
                        const std::array<int, dim>& cells);

extern template struct Mesh<2>;
extern template struct Mesh<3>;

}  // namespace lituya::solver
