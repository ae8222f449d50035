// The free pressure pattern of a crossed mesh's quadrangles, and its removal.
//
// Why: the liquid points carry their pressure (eq. 8) and the force sees it cell by cell,
// F_i = sum_T S_T grad N_i|_T, S_T the cell's sum of (scaled) p V. On a crossed mesh the four
// triangles around a quadrangle's centre have dependent volume constraints; that is why such
// a mesh does not lock (user manual 2.1). The same dependence leaves one pattern c of the four
// sums with sum_T c_T grad N_i|_T = 0 at all five nodes: a pressure in that pattern pushes
// nothing. The flow never builds it (eq. 8 adds -K dt (B v)_T to S_T, and B v is orthogonal to
// c because B^T c = 0), but points that cross from one triangle to the next carry their
// pressure with them, and what they carry in is partly that pattern. Nothing acts on it, so it
// accumulates, and later crossings turn some of it into forces no flow asked for. On Case B's
// crossed 0.02 m mesh the deposit burst at 1.0 s (beads from 0.2 to 4.42 J/m, water at
// 18.6 m/s) and the toe jetted at 9.8 m/s; with the pattern removed, 1.52 J/m and 6.4 m/s
// late, 5.9 m/s at the toe (scientific manual, section 3, "The free pressure pattern"). The
// toe's other mechanism, water closed in at zero pressure (stop 41), it does not touch.
// What: after each pressure update the pattern is removed from every quadrangle whose four
// cells hold water, S <- S - (c . S) c, which changes no nodal force at that instant.
#include "lituya/solver/crossed_quadrangles.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <map>

namespace lituya::solver {

namespace {
// The unit null vector of B^T for the four cells around `centre`, B^T the 10 x 4 matrix of their
// shape function gradients at the five nodes (rows: node, component; columns: cells). Returns
// false when B^T has no null space (the centre is not where the diagonals cross).
bool free_pattern_of(const Mesh<2>& mesh, const std::array<int, 4>& cells, int centre,
                     const std::array<int, 4>& ring, std::array<double, 4>& pattern) {
  const std::array<int, 5> nodes{ring[0], ring[1], ring[2], ring[3], centre};
  Eigen::Matrix<double, 10, 4> bt = Eigen::Matrix<double, 10, 4>::Zero();
  for (int t = 0; t < 4; ++t) {
    const auto& cell_nodes = mesh.cell_nodes[cells[t]];
    for (int i = 0; i < 3; ++i) {
      const auto row = std::find(nodes.begin(), nodes.end(), cell_nodes[i]) - nodes.begin();
      bt.block<2, 1>(2 * row, t) = mesh.cell_shape_gradient[cells[t]][i];
    }
  }
  const Eigen::JacobiSVD<Eigen::Matrix<double, 10, 4>> svd(bt, Eigen::ComputeFullV);
  const Eigen::Vector4d singular = svd.singularValues();
  if (!(singular(3) < 1e-8 * singular(0))) return false;
  for (int t = 0; t < 4; ++t) pattern[t] = svd.matrixV()(t, 3);
  return true;
}
}  // namespace

CrossedQuadrangles find_crossed_quadrangles(const Mesh<2>& mesh) {
  const std::size_t n_nodes = mesh.node_count();
  std::vector<std::vector<int>> incident(n_nodes);
  for (std::size_t c = 0; c < mesh.cell_count(); ++c)
    for (int node : mesh.cell_nodes[c]) incident[node].push_back(static_cast<int>(c));
  CrossedQuadrangles q;
  q.cell_quadrangle.assign(mesh.cell_count(), -1);
  q.cell_slot.assign(mesh.cell_count(), -1);
  for (std::size_t o = 0; o < n_nodes; ++o) {
    if (incident[o].size() != 4) continue;
    // Its four neighbours, each in two of the four cells.
    std::map<int, int> shared;
    for (int c : incident[o])
      for (int node : mesh.cell_nodes[c])
        if (node != static_cast<int>(o)) ++shared[node];
    if (shared.size() != 4) continue;
    std::array<int, 4> ring{};
    std::array<Mesh<2>::Vec, 4> direction;
    int k = 0;
    bool twice = true;
    for (const auto& [node, count] : shared) {
      twice = twice && count == 2;
      ring[k] = node;
      direction[k++] = (mesh.node_position[node] - mesh.node_position[o]).normalized();
    }
    if (!twice) continue;
    // On two straight lines: two opposite pairs of directions.
    int opposite = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (direction[a].dot(direction[b]) < -1.0 + 1e-9) ++opposite;
    if (opposite != 2) continue;
    const std::array<int, 4> cells{incident[o][0], incident[o][1], incident[o][2], incident[o][3]};
    std::array<double, 4> pattern{};
    if (!free_pattern_of(mesh, cells, static_cast<int>(o), ring, pattern)) continue;
    const int id = static_cast<int>(q.cells.size());
    for (int t = 0; t < 4; ++t) {
      q.cell_quadrangle[cells[t]] = id;
      q.cell_slot[cells[t]] = t;
    }
    q.cells.push_back(cells);
    q.free_pattern.push_back(pattern);
  }
  return q;
}

std::size_t remove_free_pressure_pattern(const CrossedQuadrangles& quadrangles,
                                         const std::vector<int>& point_cell,
                                         const std::vector<double>& cell_scale,
                                         const std::vector<double>& volume,
                                         std::vector<double>& pressure,
                                         FreePatternScratch& scratch) {
  const std::size_t n_cells = quadrangles.cell_quadrangle.size();
  std::vector<double>&sum = scratch.sum, &weight = scratch.weight, &change = scratch.change;
  sum.assign(n_cells, 0.0);
  weight.assign(n_cells, 0.0);
  change.assign(n_cells, 0.0);
  for (std::size_t p = 0; p < point_cell.size(); ++p) {
    const int c = point_cell[p];
    if (quadrangles.cell_quadrangle[c] < 0) continue;
    const double w = cell_scale[c] * volume[p];
    sum[c] += w * pressure[p];
    weight[c] += w;
  }
  // Per quadrangle the pattern's amplitude c . S (c is a unit vector); per cell the pressure
  // change that removes its part, -amplitude c_T / (sum of scale_T V over the cell's points).
  for (std::size_t m = 0; m < quadrangles.cells.size(); ++m) {
    double amplitude = 0;
    bool filled = true;
    for (int t = 0; t < 4; ++t) {
      const int c = quadrangles.cells[m][t];
      filled = filled && weight[c] > 0;
      amplitude += quadrangles.free_pattern[m][t] * sum[c];
    }
    if (!filled) continue;
    for (int t = 0; t < 4; ++t) {
      const int c = quadrangles.cells[m][t];
      change[c] = -amplitude * quadrangles.free_pattern[m][t] / weight[c];
    }
  }
  std::size_t changed = 0;
  for (std::size_t p = 0; p < point_cell.size(); ++p) {
    const double dp = change[point_cell[p]];
    if (dp == 0) continue;
    pressure[p] = std::max(0.0, pressure[p] + dp);
    ++changed;
  }
  return changed;
}

}  // namespace lituya::solver
