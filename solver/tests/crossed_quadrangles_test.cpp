// The quadrangles of a crossed mesh and the removal of their free pressure pattern
// (crossed_quadrangles.hpp).
#include "lituya/solver/crossed_quadrangles.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>

namespace lituya::solver {
namespace {

using Vec = Mesh<2>::Vec;

// A 2 x 2 grid of unit-square quadrangles with corners `corner(i, j)`, each cut into four
// triangles at `centre(quadrangle corners)`; with `crossed` false each is cut along one diagonal
// instead.
template <class Corner, class Centre>
Mesh<2> quadrangle_grid(Corner corner, Centre centre, bool crossed) {
  Mesh<2> mesh;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i) mesh.node_position.push_back(corner(i, j));
  auto id = [](int i, int j) { return j * 3 + i; };
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const std::array<int, 4> q{id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
      if (!crossed) {
        mesh.cell_nodes.push_back({q[0], q[1], q[2]});
        mesh.cell_nodes.push_back({q[0], q[2], q[3]});
        continue;
      }
      const int o = static_cast<int>(mesh.node_position.size());
      mesh.node_position.push_back(centre(mesh.node_position[q[0]], mesh.node_position[q[1]],
                                          mesh.node_position[q[2]], mesh.node_position[q[3]]));
      for (int k = 0; k < 4; ++k) mesh.cell_nodes.push_back({q[k], q[(k + 1) % 4], o});
    }
  EXPECT_EQ(mesh.build(), -1);
  return mesh;
}

// Where the diagonals a-c and b-d cross.
Vec diagonals_crossing(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  Eigen::Matrix2d m;
  m.col(0) = c - a;
  m.col(1) = b - d;
  const Eigen::Vector2d st = m.inverse() * (b - a);
  return a + st(0) * (c - a);
}

Vec mean_of_corners(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  return (a + b + c + d) / 4;
}

// An irregular grid: the corners moved off the unit lattice (every quadrangle convex).
Vec irregular(int i, int j) {
  return Vec(i + 0.2 * std::sin(1.3 * i + 2.1 * j), j + 0.15 * std::cos(0.7 * i + 1.9 * j));
}

// The nodal force of per-cell sums S: F_i = sum_T S_T grad N_i|_T.
std::vector<Vec> nodal_force(const Mesh<2>& mesh, const std::vector<double>& cell_sum) {
  std::vector<Vec> force(mesh.node_count(), Vec::Zero());
  for (std::size_t c = 0; c < mesh.cell_count(); ++c)
    for (int i = 0; i < 3; ++i)
      force[mesh.cell_nodes[c][i]] += cell_sum[c] * mesh.cell_shape_gradient[c][i];
  return force;
}

TEST(CrossedQuadrangles, FoundWhereTheDiagonalsCrossAndNowhereElse) {
  const Mesh<2> crossed = quadrangle_grid(irregular, diagonals_crossing, true);
  const CrossedQuadrangles q = find_crossed_quadrangles(crossed);
  ASSERT_EQ(q.cells.size(), 4u);
  for (std::size_t c = 0; c < crossed.cell_count(); ++c) EXPECT_GE(q.cell_quadrangle[c], 0);
  for (std::size_t m = 0; m < q.cells.size(); ++m) {
    // A unit pattern that pushes no node.
    std::vector<double> sum(crossed.cell_count(), 0.0);
    double norm = 0;
    for (int t = 0; t < 4; ++t) {
      sum[q.cells[m][t]] = q.free_pattern[m][t];
      norm += q.free_pattern[m][t] * q.free_pattern[m][t];
    }
    EXPECT_NEAR(norm, 1.0, 1e-12);
    for (const Vec& f : nodal_force(crossed, sum)) EXPECT_LT(f.norm(), 1e-12);
  }
  // Centres at the mean of the corners (not on the diagonals of these irregular quadrangles):
  // the four constraints are independent, no pattern is free. A plain mesh has no centres.
  EXPECT_TRUE(find_crossed_quadrangles(quadrangle_grid(irregular, mean_of_corners, true)).empty());
  EXPECT_TRUE(
      find_crossed_quadrangles(quadrangle_grid(irregular, diagonals_crossing, false)).empty());
}

TEST(CrossedQuadrangles, RemovingThePatternChangesNoForce) {
  const Mesh<2> mesh = quadrangle_grid(irregular, diagonals_crossing, true);
  const CrossedQuadrangles q = find_crossed_quadrangles(mesh);
  // Two points in each cell, of volumes 0.1 and 0.3 (cell scale 1.5), carrying a linear
  // pressure plus 40 Pa of the free pattern over the cell's scaled volume; quadrangle 3 has an
  // empty cell and keeps its pattern.
  std::vector<int> point_cell;
  std::vector<double> volume, pressure, linear_part;
  const std::vector<double> scale(mesh.cell_count(), 1.5);
  for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
    const int m = q.cell_quadrangle[c], t = q.cell_slot[c];
    if (m == 3 && t == 0) continue;
    Vec centroid = Vec::Zero();
    for (int node : mesh.cell_nodes[c]) centroid += mesh.node_position[node] / 3;
    const double p = 1000.0 + 200.0 * centroid(0) - 500.0 * centroid(1);
    for (double v : {0.1, 0.3}) {
      point_cell.push_back(static_cast<int>(c));
      volume.push_back(v);
      linear_part.push_back(p);
      pressure.push_back(p + 40.0 * q.free_pattern[m][t] / (1.5 * 0.4));
    }
  }
  auto cell_sums = [&](const std::vector<double>& p) {
    std::vector<double> s(mesh.cell_count(), 0.0);
    for (std::size_t k = 0; k < p.size(); ++k)
      s[point_cell[k]] += scale[point_cell[k]] * volume[k] * p[k];
    return s;
  };
  const std::vector<Vec> before = nodal_force(mesh, cell_sums(pressure));
  FreePatternScratch scratch;
  const std::size_t changed =
      remove_free_pressure_pattern(q, point_cell, scale, volume, pressure, scratch);
  EXPECT_EQ(changed, 24u);  // three full quadrangles, four cells, two points each
  const std::vector<Vec> after = nodal_force(mesh, cell_sums(pressure));
  for (std::size_t i = 0; i < mesh.node_count(); ++i)
    EXPECT_LT((after[i] - before[i]).norm(), 1e-9) << "node " << i;
  // What is left of each full quadrangle's sums carries no pattern; the linear part is kept
  // where it carried none (its projection on c is what the filter takes too).
  const std::vector<double> s = cell_sums(pressure), lin = cell_sums(linear_part);
  for (int m = 0; m < 3; ++m) {
    double amplitude = 0, linear_amplitude = 0;
    for (int t = 0; t < 4; ++t) {
      amplitude += q.free_pattern[m][t] * s[q.cells[m][t]];
      linear_amplitude += q.free_pattern[m][t] * lin[q.cells[m][t]];
    }
    EXPECT_NEAR(amplitude, 0.0, 1e-9);
    for (int t = 0; t < 4; ++t) {
      const int c = q.cells[m][t];
      EXPECT_NEAR(s[c], lin[c] - linear_amplitude * q.free_pattern[m][t], 1e-9);
    }
  }
  // The quadrangle with an empty cell is left alone, to the bit.
  for (std::size_t k = 0; k < pressure.size(); ++k) {
    if (q.cell_quadrangle[point_cell[k]] != 3) continue;
    const double carried = 40.0 * q.free_pattern[3][q.cell_slot[point_cell[k]]] / (1.5 * 0.4);
    EXPECT_EQ(pressure[k], linear_part[k] + carried);
  }
  // A second pass finds nothing more to take.
  const std::vector<double> once = pressure;
  remove_free_pressure_pattern(q, point_cell, scale, volume, pressure, scratch);
  for (std::size_t k = 0; k < pressure.size(); ++k) EXPECT_NEAR(pressure[k], once[k], 1e-9);
}

}  // namespace
}  // namespace lituya::solver
