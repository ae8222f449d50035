#include "lituya/pre/seeding.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <stdexcept>
#include <tuple>

#include <gtest/gtest.h>

namespace lituya::pre {
namespace {

// One skewed cell, so that a pattern that only works on the reference cell would show.
Mesh single_cell(int dimension) {
  Mesh mesh;
  mesh.dimension = dimension;
  if (dimension == 2) {
    mesh.node_xyz = {0.1, 0.2, 0, 1.3, 0.5, 0, 0.4, 1.1, 0};
    mesh.cell_nodes = {0, 1, 2};
  } else {
    mesh.node_xyz = {0.1, 0.2, 0.0, 1.3, 0.5, 0.1, 0.4, 1.1, 0.2, 0.3, 0.4, 0.9};
    mesh.cell_nodes = {0, 1, 2, 3};
  }
  mesh.cell_element_tags = {1};
  return mesh;
}

struct Case {
  int dimension;
  int points_per_cell;
};

class SeedingPattern : public ::testing::TestWithParam<Case> {};

TEST_P(SeedingPattern, PointsAreInsideAndAverageToTheCentroid) {
  const auto [dimension, n] = GetParam();
  const auto pattern = seed_pattern(dimension, n);
  ASSERT_EQ(static_cast<int>(pattern.size()), n);
  std::array<double, 4> mean{0, 0, 0, 0};
  for (const auto& b : pattern) {
    double sum = 0;
    for (int i = 0; i <= dimension; ++i) {
      EXPECT_GT(b[i], 0.0);  // strictly inside the cell
      sum += b[i];
      mean[i] += b[i] / n;
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    for (int i = dimension + 1; i < 4; ++i) EXPECT_EQ(b[i], 0.0);
  }
  for (int i = 0; i <= dimension; ++i) EXPECT_NEAR(mean[i], 1.0 / (dimension + 1), 1e-14);
  // No two points coincide.
  for (std::size_t a = 0; a < pattern.size(); ++a)
    for (std::size_t b = a + 1; b < pattern.size(); ++b) {
      double d = 0;
      for (int i = 0; i < 4; ++i) d += std::abs(pattern[a][i] - pattern[b][i]);
      EXPECT_GT(d, 1e-3);
    }
}

TEST_P(SeedingPattern, SeededCellKeepsVolumeMassAndCentroid) {
  const auto [dimension, n] = GetParam();
  const Mesh mesh = single_cell(dimension);
  const double volume = signed_cell_measure(mesh, 0);
  ASSERT_GT(volume, 0);
  MaterialPoints points;
  seed_cells(mesh, {0}, n, 1260.0, 3, points);
  ASSERT_EQ(points.size(), static_cast<std::size_t>(n));
  const double total_volume = std::accumulate(points.volume.begin(), points.volume.end(), 0.0);
  const double total_mass = std::accumulate(points.mass.begin(), points.mass.end(), 0.0);
  EXPECT_NEAR(total_volume, volume, 1e-14);
  EXPECT_NEAR(total_mass, 1260.0 * volume, 1e-11);
  const std::vector<double> centroid = cell_centroid(mesh, 0);
  for (int k = 0; k < 3; ++k) {
    double mean = 0;
    for (std::size_t p = 0; p < points.size(); ++p) mean += points.position[3 * p + k] / n;
    EXPECT_NEAR(mean, centroid[k], 1e-14);
  }
  for (std::size_t p = 0; p < points.size(); ++p) {
    EXPECT_EQ(points.material[p], 3);
    EXPECT_EQ(points.cell[p], 0);
    EXPECT_DOUBLE_EQ(points.volume[p], volume / n);
    for (int k = 0; k < 6; ++k) EXPECT_EQ(points.stress[6 * p + k], 0.0);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(points.velocity[3 * p + k], 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(AllPatterns, SeedingPattern,
                         ::testing::Values(Case{2, 1}, Case{2, 3}, Case{2, 4}, Case{2, 9},
                                           Case{2, 16}, Case{3, 1}, Case{3, 4}, Case{3, 8}),
                         [](const auto& info) {
                           return std::to_string(info.param.dimension) + "D_" +
                                  std::to_string(info.param.points_per_cell);
                         });

// The subdivision patterns put one point in each of k^2 equal sub-triangles: each point's
// share of the cell is the same, which a check on the sub-triangle membership confirms.
TEST(SeedingPattern, SubdivisionPutsOnePointPerSubTriangle) {
  for (int k : {2, 3, 4}) {
    const auto pattern = seed_pattern(2, k * k);
    std::set<std::tuple<int, int, bool>> cells;
    for (const auto& b : pattern) {
      const double xi = b[1] * k, eta = b[2] * k;
      const int i = static_cast<int>(std::floor(xi)), j = static_cast<int>(std::floor(eta));
      const bool upward = (xi - i) + (eta - j) < 1.0;
      EXPECT_TRUE(cells.insert({i, j, upward}).second);
    }
    EXPECT_EQ(static_cast<int>(cells.size()), k * k);
  }
}

TEST(SeedingPattern, RedRefinementCentroidsAreThoseOfTheEightChildren) {
  // Corner children: 5/8 at their own vertex, 1/8 at the three others.
  const auto pattern = seed_pattern(3, 8);
  int corners = 0;
  for (const auto& b : pattern) {
    const double largest = *std::max_element(b.begin(), b.end());
    if (std::abs(largest - 0.625) < 1e-14) ++corners;
  }
  EXPECT_EQ(corners, 4);
}

TEST(SeedingPattern, UnsupportedCountsAreRejected) {
  for (int n : {0, 2, 5, 8, 25}) EXPECT_FALSE(is_supported_points_per_cell(2, n)) << n;
  for (int n : {0, 2, 3, 5, 9, 27}) EXPECT_FALSE(is_supported_points_per_cell(3, n)) << n;
  EXPECT_THROW(seed_pattern(2, 5), std::invalid_argument);
  EXPECT_THROW(seed_pattern(3, 3), std::invalid_argument);
  EXPECT_EQ(supported_points_per_cell(2), "1, 3, 4, 9, 16");
  EXPECT_EQ(supported_points_per_cell(3), "1, 4, 8");
}

}  // namespace
}  // namespace lituya::pre
