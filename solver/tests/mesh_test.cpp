#include "lituya/solver/mesh.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using lituya::solver::make_box_mesh;
using lituya::solver::Mesh;

TEST(Mesh, BoxMesh2DVolumesAndNeighbours) {
  auto mesh = make_box_mesh<2>({0.0, 0.0}, {2.0, 1.0}, {8, 4});
  ASSERT_EQ(mesh.cell_count(), 64u);
  double total = 0;
  int boundary_faces = 0;
  for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
    EXPECT_GT(mesh.cell_volume[c], 0);
    total += mesh.cell_volume[c];
    for (int i = 0; i < 3; ++i) boundary_faces += mesh.cell_neighbour[c][i] < 0;
  }
  EXPECT_NEAR(total, 2.0, 1e-12);
  EXPECT_EQ(boundary_faces, 2 * (8 + 4));  // edges on the perimeter
}

TEST(Mesh, BoxMesh3DVolumesAndNeighbours) {
  auto mesh = make_box_mesh<3>({0.0, 0.0, 0.0}, {1.0, 2.0, 0.5}, {3, 4, 2});
  ASSERT_EQ(mesh.cell_count(), 6u * 24u);
  double total = 0;
  int boundary_faces = 0;
  for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
    EXPECT_GT(mesh.cell_volume[c], 0);
    total += mesh.cell_volume[c];
    for (int i = 0; i < 4; ++i) boundary_faces += mesh.cell_neighbour[c][i] < 0;
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  EXPECT_EQ(boundary_faces, 2 * 2 * (3 * 4 + 4 * 2 + 3 * 2));  // 2 triangles per box face
}

// Shape functions of a linear simplex sum to one and reproduce linear fields exactly, and
// their gradients give the exact gradient of a linear field.
template <int dim>
void check_linear_reproduction(const Mesh<dim>& mesh) {
  using Vec = Eigen::Matrix<double, dim, 1>;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Vec a;
  for (int d = 0; d < dim; ++d) a(d) = 0.3 + d;
  const double b = -1.7;
  for (int trial = 0; trial < 200; ++trial) {
    Vec x;
    for (int d = 0; d < dim; ++d) x(d) = 0.999 * u(rng);
    typename Mesh<dim>::Shape n;
    const int cell = mesh.locate(0, x, n);
    ASSERT_GE(cell, 0);
    EXPECT_NEAR(n.sum(), 1.0, 1e-12);
    EXPECT_GE(n.minCoeff(), -1e-12);
    double interpolated = 0;
    Vec gradient = Vec::Zero();
    for (int i = 0; i <= dim; ++i) {
      const Vec& xi = mesh.node_position[mesh.cell_nodes[cell][i]];
      interpolated += n(i) * (a.dot(xi) + b);
      gradient += (a.dot(xi) + b) * mesh.cell_shape_gradient[cell][i];
    }
    EXPECT_NEAR(interpolated, a.dot(x) + b, 1e-12);
    EXPECT_NEAR((gradient - a).norm(), 0.0, 1e-11);
  }
}

TEST(Mesh, LocateByWalkingAndLinearReproduction2D) {
  check_linear_reproduction<2>(make_box_mesh<2>({0.0, 0.0}, {1.0, 1.0}, {10, 10}));
}

TEST(Mesh, LocateByWalkingAndLinearReproduction3D) {
  check_linear_reproduction<3>(make_box_mesh<3>({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, {5, 5, 5}));
}

TEST(Mesh, PointOutsideIsNotLocated) {
  auto mesh = make_box_mesh<2>({0.0, 0.0}, {1.0, 1.0}, {4, 4});
  Mesh<2>::Shape n;
  EXPECT_EQ(mesh.locate(0, Eigen::Vector2d(1.2, 0.5), n), -1);
  EXPECT_EQ(mesh.locate(5, Eigen::Vector2d(0.5, -0.01), n), -1);
}

TEST(Mesh, InvertedCellIsReported) {
  Mesh<2> mesh;
  mesh.node_position = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  mesh.cell_nodes = {{0, 1, 2}, {1, 2, 3}};  // the second is clockwise
  EXPECT_EQ(mesh.build(), 1);
}

}  // namespace
