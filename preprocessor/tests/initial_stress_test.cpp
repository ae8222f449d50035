#include "lituya/pre/initial_stress.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "lituya/pre/gmsh_mesh.hpp"
#include "lituya/pre/seeding.hpp"
#include "test_support.hpp"

namespace lituya::pre {
namespace {

constexpr double kGravity = 9.81;
constexpr double kDensity = 1260.0;  // dry density of Case A's layer, kg/m3

// A width x height block of nx x ny squares, each split into two triangles.
Mesh structured_block(double width, double height, int nx, int ny) {
  Mesh mesh;
  mesh.dimension = 2;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      mesh.node_xyz.insert(mesh.node_xyz.end(), {width * i / nx, height * j / ny, 0.0});
  auto node = [&](int i, int j) { return static_cast<std::int64_t>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh.cell_nodes.insert(mesh.cell_nodes.end(),
                             {node(i, j), node(i + 1, j), node(i + 1, j + 1)});
      mesh.cell_nodes.insert(mesh.cell_nodes.end(),
                             {node(i, j), node(i + 1, j + 1), node(i, j + 1)});
      mesh.cell_element_tags.insert(mesh.cell_element_tags.end(), 2, 0);
    }
  return mesh;
}

std::vector<std::size_t> all_cells(const Mesh& mesh) {
  std::vector<std::size_t> cells(mesh.cell_count());
  for (std::size_t c = 0; c < cells.size(); ++c) cells[c] = c;
  return cells;
}

// Seeds 4 points per cell of `cells` and returns the overburden of every point.
std::vector<double> seeded_overburden(const Mesh& mesh, const std::vector<std::size_t>& cells,
                                      MaterialPoints& points) {
  seed_cells(mesh, cells, mesh.dimension == 2 ? 4 : 8, kDensity, 0, points);
  std::vector<double> density(mesh.cell_count(), 0.0);
  for (std::size_t c : cells) density[c] = kDensity;
  return overburden_pressure(mesh, density, points, kGravity);
}

TEST(InitialStress, K0OnAStructuredBlock) {
  const double width = 0.5, height = 0.3;
  const Mesh mesh = structured_block(width, height, 25, 15);
  MaterialPoints points;
  const auto overburden = seeded_overburden(mesh, all_cells(mesh), points);
  const double k0 = 1.0 - std::sin(23.0 * M_PI / 180.0);
  set_k0_stress(points, overburden, 0, points.size(), k0);
  for (std::size_t p = 0; p < points.size(); ++p) {
    const double* s = &points.stress[6 * p];
    const double exact = -kDensity * kGravity * (height - points.position[3 * p + 1]);
    EXPECT_NEAR(s[1], exact, 1e-9 * kDensity * kGravity * height);
    EXPECT_DOUBLE_EQ(s[0], k0 * s[1]);
    EXPECT_DOUBLE_EQ(s[2], k0 * s[1]);
    EXPECT_EQ(s[3], 0.0);
    EXPECT_EQ(s[4], 0.0);
    EXPECT_EQ(s[5], 0.0);
  }
}

TEST(InitialStress, UnstructuredBlock) {
  // The 1 m x 1 m "soil" square of the test geometry, meshed by gmsh; "air" beside it is
  // empty and must not count.
  const Mesh mesh = read_gmsh_mesh(testing::test_data("two_squares.geo"), {2, 0.05, false});
  MaterialPoints points;
  const auto overburden =
      seeded_overburden(mesh, mesh.group_cells[*mesh.find_group("soil", 2)], points);
  for (std::size_t p = 0; p < points.size(); ++p)
    EXPECT_NEAR(overburden[p], kDensity * kGravity * (1.0 - points.position[3 * p + 1]), 1e-8);
}

TEST(InitialStress, TetrahedraOfACube) {
  const Mesh mesh = read_gmsh_mesh(testing::test_data("cube.geo"), {3, 0.25, false});
  MaterialPoints points;
  const auto overburden = seeded_overburden(mesh, all_cells(mesh), points);
  for (std::size_t p = 0; p < points.size(); ++p)
    EXPECT_NEAR(overburden[p], kDensity * kGravity * (1.0 - points.position[3 * p + 1]), 1e-8);
}

TEST(InitialStress, LayersAndAGap) {
  // Rows of 0.1 m: density 1000 below y = 0.3, nothing in [0.3, 0.5], 2000 above 0.5 (to the
  // top at 0.8). The gap carries no weight.
  const Mesh mesh = structured_block(0.4, 0.8, 4, 8);
  std::vector<double> density(mesh.cell_count());
  for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
    const double y = cell_centroid(mesh, c)[1];
    density[c] = y < 0.3 ? 1000.0 : y < 0.5 ? 0.0 : 2000.0;
  }
  MaterialPoints points;
  // Points on the vertical mesh lines x = 0.1, 0.2 (the line runs along cell edges) and
  // inside cells.
  for (double x : {0.1, 0.2, 0.1234}) {
    for (double y : {0.05, 0.3, 0.4, 0.65}) {
      const double xyz[3] = {x, y, 0.0};
      points.add(xyz, 1.0, 1.0, 0, 0);
    }
  }
  const auto overburden = overburden_pressure(mesh, density, points, 10.0);
  const double top = 2000.0 * 0.3 * 10.0;  // the upper layer's full weight
  for (std::size_t p = 0; p < points.size(); p += 4) {
    EXPECT_NEAR(overburden[p + 0], top + 1000.0 * 0.25 * 10.0, 1e-8);
    EXPECT_NEAR(overburden[p + 1], top, 1e-8);
    EXPECT_NEAR(overburden[p + 2], top, 1e-8);
    EXPECT_NEAR(overburden[p + 3], 2000.0 * 0.15 * 10.0, 1e-8);
  }
}

TEST(InitialStress, OnlyTheGivenRangeIsSet) {
  MaterialPoints points;
  const double xyz[3] = {0, 0, 0};
  for (int i = 0; i < 4; ++i) points.add(xyz, 1.0, 1.0, 0, 0);
  set_k0_stress(points, {1, 2, 3, 4}, 1, 3, 0.5);
  EXPECT_EQ(points.stress[6 * 0 + 1], 0.0);
  EXPECT_EQ(points.stress[6 * 1 + 1], -2.0);
  EXPECT_EQ(points.stress[6 * 2 + 0], -1.5);
  EXPECT_EQ(points.stress[6 * 3 + 1], 0.0);
}

}  // namespace
}  // namespace lituya::pre
