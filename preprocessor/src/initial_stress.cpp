#include "lituya/pre/initial_stress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>

#include <Eigen/Dense>

namespace lituya::pre {

namespace {

// The part of a vertical line inside one cell. On the line (x, y, z) with x, z fixed, the
// barycentric coordinates of the cell are affine in y; the line is inside where all of them
// are non-negative, an interval [low, high] (empty when low > high).
template <int D>
std::pair<double, double> vertical_chord(const Mesh& mesh, std::size_t cell, double x, double z) {
  using Vector = Eigen::Matrix<double, D, 1>;
  using Matrix = Eigen::Matrix<double, D, D>;
  const std::int64_t* nodes = &mesh.cell_nodes[cell * (D + 1)];
  auto corner = [&](int i) {
    return Vector(Eigen::Map<const Vector>(&mesh.node_xyz[3 * static_cast<std::size_t>(nodes[i])]));
  };
  const Vector origin = corner(0);
  Matrix edges;
  for (int i = 0; i < D; ++i) edges.col(i) = corner(i + 1) - origin;
  const Matrix inverse = edges.inverse();
  // p(y) - origin = offset + y e_y, with offset = (x, 0, z) - origin
  Vector offset = -origin;
  offset[0] += x;
  if constexpr (D == 3) offset[2] += z;
  Vector up = Vector::Zero();
  up[1] = 1.0;
  Eigen::Matrix<double, D + 1, 1> a, b;  // lambda_k(y) = a_k + b_k y
  a.template tail<D>() = inverse * offset;
  b.template tail<D>() = inverse * up;
  a[0] = 1.0 - a.template tail<D>().sum();
  b[0] = -b.template tail<D>().sum();
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= D; ++k) {
    if (b[k] > 0)
      low = std::max(low, -a[k] / b[k]);
    else if (b[k] < 0)
      high = std::min(high, -a[k] / b[k]);
    else if (a[k] < 0)
      return {1.0, 0.0};  // parallel to a face, outside it
  }
  return {low, high};
}

}  // namespace

std::vector<double> overburden_pressure(const Mesh& mesh, const std::vector<double>& cell_density,
                                        const MaterialPoints& points, double gravity) {
  return overburden_pressure(mesh, cell_density, points.position, gravity);
}

std::vector<double> overburden_pressure(const Mesh& mesh, const std::vector<double>& cell_density,
                                        std::span<const double> position, double gravity) {
  const int dim = mesh.dimension;
  const int corners = mesh.nodes_per_cell();
  const std::size_t count = position.size() / 3;
  std::vector<double> overburden(count, 0.0);
  if (count == 0) return overburden;

  // Index the cells that carry material by the vertical columns their bounding boxes touch,
  // columns as wide as a typical cell, so each point looks at a few dozen cells.
  double column_width = 0;
  std::size_t material_cells = 0;
  for (std::size_t c = 0; c < mesh.cell_count(); ++c)
    if (cell_density[c] > 0) {
      column_width += std::pow(std::abs(signed_cell_measure(mesh, c)), 1.0 / dim);
      ++material_cells;
    }
  if (material_cells == 0) return overburden;
  column_width = 2.0 * column_width / static_cast<double>(material_cells);
  auto column = [&](double coordinate) {
    return static_cast<std::int64_t>(std::floor(coordinate / column_width));
  };
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>> columns;
  for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
    if (!(cell_density[c] > 0)) continue;
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (int i = 0; i < corners; ++i)
      for (int k = 0; k < 3; ++k) {
        const double v =
            mesh.node_xyz[3 * static_cast<std::size_t>(mesh.cell_nodes[c * corners + i]) + k];
        lo[k] = std::min(lo[k], v);
        hi[k] = std::max(hi[k], v);
      }
    for (std::int64_t ix = column(lo[0]); ix <= column(hi[0]); ++ix)
      for (std::int64_t iz = dim == 3 ? column(lo[2]) : 0; iz <= (dim == 3 ? column(hi[2]) : 0);
           ++iz)
        columns[{ix, iz}].push_back(c);
  }

  // A vertical line through a mesh edge (or a 3D face) would be counted by both cells that
  // share it; moving it by a negligible, fixed amount puts it inside exactly one of them.
  const double nudge = 1e-9 * column_width;
  for (std::size_t p = 0; p < count; ++p) {
    const double x = position[3 * p] + nudge;
    const double y = position[3 * p + 1];
    const double z = dim == 3 ? position[3 * p + 2] + 0.7 * nudge : 0.0;
    auto found = columns.find({column(x), dim == 3 ? column(z) : 0});
    if (found == columns.end()) continue;
    double weight = 0;  // integral of rho dy above the point, kg/m2
    for (std::size_t c : found->second) {
      auto [low, high] =
          dim == 2 ? vertical_chord<2>(mesh, c, x, z) : vertical_chord<3>(mesh, c, x, z);
      low = std::max(low, y);
      if (high > low) weight += cell_density[c] * (high - low);
    }
    overburden[p] = gravity * weight;
  }
  return overburden;
}

void set_k0_stress(MaterialPoints& points, const std::vector<double>& vertical_effective,
                   std::size_t begin, std::size_t end, double k0) {
  for (std::size_t p = begin; p < end; ++p) {
    double* stress = &points.stress[6 * p];
    const double vertical = -vertical_effective[p];  // compression is negative
    stress[0] = k0 * vertical;                       // xx
    stress[1] = vertical;                            // yy
    stress[2] = k0 * vertical;                       // zz (also out of plane in plane strain)
    stress[3] = stress[4] = stress[5] = 0.0;
  }
}

}  // namespace lituya::pre
