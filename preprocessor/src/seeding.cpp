#include "lituya/pre/seeding.hpp"

#include <cmath>
#include <stdexcept>

namespace lituya::pre {

namespace {
using Barycentric = std::array<double, 4>;

// Centroids of the k^2 triangles of a uniform k-subdivision of the reference triangle
// (0,0), (1,0), (0,1): k(k+1)/2 "upward" and k(k-1)/2 "downward" triangles, all of area
// 1/k^2 of the cell, so every point stands for the same volume.
std::vector<Barycentric> subdivided_triangle(int k) {
  std::vector<Barycentric> pattern;
  auto add = [&](double xi, double eta) { pattern.push_back({1.0 - xi - eta, xi, eta, 0.0}); };
  for (int j = 0; j < k; ++j)
    for (int i = 0; i + j < k; ++i) {
      add((i + 1.0 / 3.0) / k, (j + 1.0 / 3.0) / k);
      if (i + j + 2 <= k) add((i + 2.0 / 3.0) / k, (j + 2.0 / 3.0) / k);
    }
  return pattern;
}

// Centroids of the 8 children of the midpoint (red) refinement of a tetrahedron: 4 corner
// tetrahedra and 4 that split the inner octahedron along the diagonal m02-m13. All 8 have
// volume V/8.
std::vector<Barycentric> red_refined_tetrahedron() {
  auto vertex = [](int i) {
    Barycentric b{0, 0, 0, 0};
    b[i] = 1;
    return b;
  };
  auto midpoint = [&](int i, int j) {
    Barycentric b{0, 0, 0, 0};
    b[i] = b[j] = 0.5;
    return b;
  };
  auto centroid = [](const Barycentric& a, const Barycentric& b, const Barycentric& c,
                     const Barycentric& d) {
    Barycentric m;
    for (int i = 0; i < 4; ++i) m[i] = 0.25 * (a[i] + b[i] + c[i] + d[i]);
    return m;
  };
  std::vector<Barycentric> pattern;
  for (int i = 0; i < 4; ++i) {
    std::vector<Barycentric> corner{vertex(i)};
    for (int j = 0; j < 4; ++j)
      if (j != i) corner.push_back(midpoint(i, j));
    pattern.push_back(centroid(corner[0], corner[1], corner[2], corner[3]));
  }
  // The octahedron's equator around the diagonal m02-m13, in cyclic order.
  const Barycentric equator[4] = {midpoint(0, 1), midpoint(1, 2), midpoint(2, 3), midpoint(3, 0)};
  for (int e = 0; e < 4; ++e)
    pattern.push_back(centroid(midpoint(0, 2), midpoint(1, 3), equator[e], equator[(e + 1) % 4]));
  return pattern;
}
}  // namespace

bool is_supported_points_per_cell(int dimension, int n) {
  if (dimension == 2) return n == 1 || n == 3 || n == 4 || n == 9 || n == 16;
  if (dimension == 3) return n == 1 || n == 4 || n == 8;
  return false;
}

std::string supported_points_per_cell(int dimension) {
  return dimension == 2 ? "1, 3, 4, 9, 16" : "1, 4, 8";
}

std::vector<Barycentric> seed_pattern(int dimension, int n) {
  if (!is_supported_points_per_cell(dimension, n))
    throw std::invalid_argument("no seeding pattern with " + std::to_string(n) +
                                " points per cell in " + std::to_string(dimension) + "D");
  if (dimension == 2) {
    if (n == 1) return {{1.0 / 3, 1.0 / 3, 1.0 / 3, 0}};
    if (n == 3) {
      // Degree-2 Gauss rule: equal weights, so equal volumes per point.
      return {{2.0 / 3, 1.0 / 6, 1.0 / 6, 0},
              {1.0 / 6, 2.0 / 3, 1.0 / 6, 0},
              {1.0 / 6, 1.0 / 6, 2.0 / 3, 0}};
    }
    return subdivided_triangle(static_cast<int>(std::lround(std::sqrt(n))));
  }
  if (n == 1) return {{0.25, 0.25, 0.25, 0.25}};
  if (n == 4) {
    // Degree-2 Gauss rule for tetrahedra: a = (5 + 3 sqrt 5) / 20, b = (5 - sqrt 5) / 20.
    const double a = 0.5854101966249685, b = 0.1381966011250105;
    return {{a, b, b, b}, {b, a, b, b}, {b, b, a, b}, {b, b, b, a}};
  }
  return red_refined_tetrahedron();
}

namespace {
// Calls add(xyz, mixture_volume, cell) for the `points_per_cell` seeding positions of each of
// `cells`; each position stands for an equal share of its cell's volume.
template <typename Add>
void for_each_seed(const Mesh& mesh, const std::vector<std::size_t>& cells, int points_per_cell,
                   Add add) {
  const std::vector<Barycentric> pattern = seed_pattern(mesh.dimension, points_per_cell);
  const int corners = mesh.nodes_per_cell();
  for (std::size_t cell : cells) {
    const double volume = signed_cell_measure(mesh, cell) / points_per_cell;
    const std::int64_t* nodes = &mesh.cell_nodes[cell * corners];
    for (const Barycentric& weights : pattern) {
      double xyz[3] = {0, 0, 0};
      for (int c = 0; c < corners; ++c)
        for (int k = 0; k < 3; ++k)
          xyz[k] += weights[c] * mesh.node_xyz[3 * static_cast<std::size_t>(nodes[c]) + k];
      add(xyz, volume, static_cast<std::int32_t>(cell));
    }
  }
}
}  // namespace

void seed_cells(const Mesh& mesh, const std::vector<std::size_t>& cells, int points_per_cell,
                double dry_density, std::int32_t material_id, MaterialPoints& points) {
  for_each_seed(mesh, cells, points_per_cell,
                [&](const double xyz[3], double volume, std::int32_t cell) {
                  points.add(xyz, volume, dry_density * volume, material_id, cell);
                });
}

void seed_liquid_cells(const Mesh& mesh, const std::vector<std::size_t>& cells, int points_per_cell,
                       double porosity, double liquid_density, std::int32_t material_id,
                       LiquidPoints& points) {
  for_each_seed(mesh, cells, points_per_cell,
                [&](const double xyz[3], double volume, std::int32_t cell) {
                  const double water_volume = porosity * volume;
                  points.add(xyz, water_volume, liquid_density * water_volume, material_id, cell);
                });
}

}  // namespace lituya::pre
