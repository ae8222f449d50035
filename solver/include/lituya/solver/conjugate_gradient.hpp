#pragma once
// Preconditioned conjugate gradients on nodal vectors: the water's two projections
// (pressure_projection.cpp, pore_volume_projection.cpp) solve symmetric positive definite
// systems this way. Serial loops in a fixed order: the same bits for any thread count.
// Below it, a sparse matrix with its symmetric Gauss-Seidel preconditioner, its assembly from
// the cell matrices of a mesh (what the pore volume projection solves), and the points' mass
// matrix assembled that way (what the pressure projection solves).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace lituya::solver::detail {

struct ConjugateGradientScratch {
  std::vector<double> residual, preconditioned, direction, product;
  void resize(std::size_t n) {
    for (auto* v : {&residual, &preconditioned, &direction, &product}) v->assign(n, 0.0);
  }
};

// Solves A x = rhs starting from the x given (a warm start). apply(x, y) sets y = A x;
// precondition(r, z) sets z = P^-1 r for a symmetric positive definite P. Stops when |r| <=
// relative_tolerance |rhs|, when A stops being positive along a direction (round-off), or
// after max_iterations. Returns the iterations taken.
template <class Apply, class Precondition>
int preconditioned_conjugate_gradient(const Apply& apply, const Precondition& precondition,
                                      const std::vector<double>& rhs, std::vector<double>& x,
                                      ConjugateGradientScratch& s, double relative_tolerance,
                                      int max_iterations) {
  const std::size_t n = rhs.size();
  s.resize(n);
  apply(x, s.product);
  for (std::size_t i = 0; i < n; ++i) s.residual[i] = rhs[i] - s.product[i];
  precondition(s.residual, s.preconditioned);
  double rz = 0, rhs_norm = 0;
  for (std::size_t i = 0; i < n; ++i) {
    s.direction[i] = s.preconditioned[i];
    rz += s.residual[i] * s.preconditioned[i];
    rhs_norm += rhs[i] * rhs[i];
  }
  const double tolerance = relative_tolerance * relative_tolerance * rhs_norm;
  int iteration = 0;
  for (; iteration < max_iterations; ++iteration) {
    double rr = 0;
    for (std::size_t i = 0; i < n; ++i) rr += s.residual[i] * s.residual[i];
    if (rr <= tolerance) break;
    apply(s.direction, s.product);
    double pap = 0;
    for (std::size_t i = 0; i < n; ++i) pap += s.direction[i] * s.product[i];
    if (!(pap > 0)) break;
    const double alpha = rz / pap;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] += alpha * s.direction[i];
      s.residual[i] -= alpha * s.product[i];
    }
    precondition(s.residual, s.preconditioned);
    double rz_new = 0;
    for (std::size_t i = 0; i < n; ++i) rz_new += s.residual[i] * s.preconditioned[i];
    const double beta = rz_new / rz;
    rz = rz_new;
    for (std::size_t i = 0; i < n; ++i)
      s.direction[i] = s.preconditioned[i] + beta * s.direction[i];
  }
  return iteration;
}

// The same with a diagonal preconditioner: precondition(i, r) returns the preconditioned
// residual at i.
template <class Apply, class Precondition>
int conjugate_gradient(const Apply& apply, const Precondition& precondition,
                       const std::vector<double>& rhs, std::vector<double>& x,
                       ConjugateGradientScratch& s, double relative_tolerance, int max_iterations) {
  return preconditioned_conjugate_gradient(
      apply,
      [&](const std::vector<double>& r, std::vector<double>& z) {
        for (std::size_t i = 0; i < r.size(); ++i) z[i] = precondition(i, r[i]);
      },
      rhs, x, s, relative_tolerance, max_iterations);
}

// A sparse matrix in compressed rows, columns sorted within a row. multiply() gives each row
// to one thread, which sums it in column order: the same bits for any thread count, with no
// per-thread buffers.
struct SparseMatrix {
  std::vector<std::size_t> row_start{0};  // row r's entries: [row_start[r], row_start[r + 1])
  std::vector<int> column;
  std::vector<double> value;
  std::vector<std::size_t> diagonal;  // where row r's diagonal entry is (square matrices)

  std::size_t rows() const { return row_start.size() - 1; }
  // y = A x (y sized by the caller).
  void multiply(const std::vector<double>& x, std::vector<double>& y, int threads) const {
    const std::size_t n = rows();
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t r = 0; r < n; ++r) {
      double sum = 0;
      for (std::size_t k = row_start[r]; k < row_start[r + 1]; ++k)
        sum += value[k] * x[static_cast<std::size_t>(column[k])];
      y[r] = sum;
    }
  }
  // z = P^-1 r for the symmetric Gauss-Seidel splitting P = (D + L) D^-1 (D + U) of a
  // symmetric matrix with a positive diagonal (P is then symmetric positive definite): a
  // forward sweep (D + L) y = r, then a backward one (D + U) z = D y, in place. Serial: each
  // row needs the rows before it (after it, going back).
  void symmetric_gauss_seidel(const std::vector<double>& r, std::vector<double>& z) const {
    const std::size_t n = rows();
    for (std::size_t i = 0; i < n; ++i) {
      double sum = r[i];
      for (std::size_t k = row_start[i]; k < diagonal[i]; ++k)
        sum -= value[k] * z[static_cast<std::size_t>(column[k])];
      z[i] = sum / value[diagonal[i]];
    }
    for (std::size_t i = n; i-- > 0;) {
      double sum = 0;
      for (std::size_t k = diagonal[i] + 1; k < row_start[i + 1]; ++k)
        sum += value[k] * z[static_cast<std::size_t>(column[k])];
      z[i] -= sum / value[diagonal[i]];
    }
  }
};

// Solves A x = rhs as preconditioned_conjugate_gradient does, preconditioned by A's symmetric
// Gauss-Seidel splitting (A symmetric with a positive diagonal), the multiply on `threads`.
// Far fewer iterations than with the diagonal, each dearer by two sweeps: both projections
// measured it (pressure_projection.cpp, pore_volume_projection.cpp).
inline int gauss_seidel_conjugate_gradient(const SparseMatrix& a, const std::vector<double>& rhs,
                                           std::vector<double>& x, ConjugateGradientScratch& s,
                                           double relative_tolerance, int max_iterations,
                                           int threads) {
  return preconditioned_conjugate_gradient(
      [&](const std::vector<double>& v, std::vector<double>& y) { a.multiply(v, y, threads); },
      [&](const std::vector<double>& r, std::vector<double>& z) { a.symmetric_gauss_seidel(r, z); },
      rhs, x, s, relative_tolerance, max_iterations);
}

// A symmetric matrix assembled from matrices of the linear simplex cells of a mesh,
//     A_IJ = sum over the cells c holding nodes I and J of a_c(i, j),
// i and j the corners of I and J in c, on the rows and columns of a chosen set of nodes:
// `nodes()[r]` is row r's node, in increasing node order. What both water projections solve
// (the points' mass matrix below; the pore water's Laplacian, pore_volume_projection.cpp).
//
// The node-node pattern of the mesh is made once (set_mesh); each assembly then sums row by
// row, one thread a row, over the row node's cells in cell order: the result has the same
// bits for any thread count, and the same as a serial loop over the cells adding into nodes.
template <int dim>
class MeshMatrix {
 public:
  static constexpr int kCorners = dim + 1;
  using CellNodes = std::array<int, kCorners>;

  bool has_mesh(std::size_t n_nodes, std::size_t n_cells) const {
    return corner_start_.size() == n_nodes + 1 && slot_.size() == n_cells * kCorners * kCorners;
  }
  // The last assembly's matrix, and row r's node.
  const SparseMatrix& matrix() const { return matrix_; }
  SparseMatrix& matrix() { return matrix_; }
  const std::vector<std::size_t>& nodes() const { return row_node_; }
  std::size_t node_count() const { return corner_start_.size() - 1; }

  // Once per mesh: the corners of the cells around each node, the node-node pattern of the
  // mesh (each node's neighbours, itself included, sorted) and where each pair of corners of a
  // cell falls in it.
  void set_mesh(const std::vector<CellNodes>& cell_nodes, std::size_t n_nodes) {
    const std::size_t n_cells = cell_nodes.size();
    // Corners by node, by cell within a node (a counting sort).
    corner_start_.assign(n_nodes + 1, 0);
    for (const CellNodes& nodes : cell_nodes)
      for (int node : nodes) ++corner_start_[static_cast<std::size_t>(node) + 1];
    std::partial_sum(corner_start_.begin(), corner_start_.end(), corner_start_.begin());
    corner_.resize(n_cells * kCorners);
    std::vector<std::size_t> next(corner_start_.begin(), corner_start_.end() - 1);
    for (std::size_t c = 0; c < n_cells; ++c)
      for (int i = 0; i < kCorners; ++i)
        corner_[next[static_cast<std::size_t>(cell_nodes[c][i])]++] =
            static_cast<std::uint32_t>(c * kCorners + i);
    // The pattern.
    pattern_.row_start.assign(n_nodes + 1, 0);
    pattern_.column.clear();
    std::vector<int> row;
    for (std::size_t node = 0; node < n_nodes; ++node) {
      row.clear();
      for (std::size_t k = corner_start_[node]; k < corner_start_[node + 1]; ++k) {
        const CellNodes& nodes = cell_nodes[corner_[k] / kCorners];
        row.insert(row.end(), nodes.begin(), nodes.end());
      }
      std::sort(row.begin(), row.end());
      row.erase(std::unique(row.begin(), row.end()), row.end());
      pattern_.column.insert(pattern_.column.end(), row.begin(), row.end());
      pattern_.row_start[node + 1] = pattern_.column.size();
    }
    // slot_[(c * kCorners + i) * kCorners + j]: entry (node i, node j) of cell c.
    slot_.resize(n_cells * kCorners * kCorners);
    for (std::size_t c = 0; c < n_cells; ++c)
      for (int i = 0; i < kCorners; ++i) {
        const auto begin = pattern_.column.begin() +
                           static_cast<std::ptrdiff_t>(pattern_.row_start[cell_nodes[c][i]]);
        const auto end = pattern_.column.begin() +
                         static_cast<std::ptrdiff_t>(pattern_.row_start[cell_nodes[c][i] + 1]);
        for (int j = 0; j < kCorners; ++j)
          slot_[(c * kCorners + i) * kCorners + j] = static_cast<std::uint32_t>(
              std::lower_bound(begin, end, cell_nodes[c][j]) - pattern_.column.begin());
      }
  }

  // Calls f(c, i) for each cell c around `node`, in cell order, i the node's corner in c. A
  // nodal sum made through it by a loop over the nodes (any schedule) adds in the order of a
  // serial loop over the cells, and so has its bits, on any thread count. set_mesh() first.
  template <class F>
  void for_each_cell_around(std::size_t node, const F& f) const {
    for (std::size_t k = corner_start_[node]; k < corner_start_[node + 1]; ++k)
      f(std::size_t{corner_[k] / kCorners}, static_cast<int>(corner_[k] % kCorners));
  }

  // Assembles A on the rows (and columns) of the nodes with in_row(node) true. The cells with
  // block_of_cell(c) = e >= 0 contribute a_c(i, j) = block(e, i, j), which must be symmetric
  // in (i, j) to the last bit for A to be; the others contribute nothing. set_mesh() first.
  template <class BlockOfCell, class InRow, class Block>
  void assemble(const BlockOfCell& block_of_cell, const InRow& in_row, const Block& block,
                int threads) {
    const std::size_t n_nodes = node_count();
    // 1. The rows, numbered in node order.
    row_of_node_.assign(n_nodes, -1);
    row_node_.clear();
    for (std::size_t node = 0; node < n_nodes; ++node)
      if (in_row(node)) {
        row_of_node_[node] = static_cast<int>(row_node_.size());
        row_node_.push_back(node);
      }
    const std::size_t n_rows = row_node_.size();
    // 2. Their pattern: the mesh's, less the columns of the nodes left out (zero entries).
    //    `entry_` maps a mesh pattern entry of such a row to the matrix's (or -1).
    matrix_.row_start.assign(n_rows + 1, 0);
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t r = 0; r < n_rows; ++r) {
      std::size_t count = 0;
      for (std::size_t k = pattern_.row_start[row_node_[r]];
           k < pattern_.row_start[row_node_[r] + 1]; ++k)
        count += row_of_node_[static_cast<std::size_t>(pattern_.column[k])] >= 0;
      matrix_.row_start[r + 1] = count;
    }
    std::partial_sum(matrix_.row_start.begin(), matrix_.row_start.end(), matrix_.row_start.begin());
    matrix_.column.resize(matrix_.row_start[n_rows]);
    matrix_.value.resize(matrix_.row_start[n_rows]);
    matrix_.diagonal.resize(n_rows);
    entry_.resize(pattern_.column.size());
    // 3. The values: each row summed by one thread over the node's cells in cell order.
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t r = 0; r < n_rows; ++r) {
      const std::size_t node = row_node_[r];
      std::size_t out = matrix_.row_start[r];
      for (std::size_t k = pattern_.row_start[node]; k < pattern_.row_start[node + 1]; ++k) {
        const int column = row_of_node_[static_cast<std::size_t>(pattern_.column[k])];
        if (column < 0) {
          entry_[k] = -1;
        } else {
          entry_[k] = static_cast<int>(out);
          if (static_cast<std::size_t>(column) == r) matrix_.diagonal[r] = out;
          matrix_.column[out] = column;
          matrix_.value[out++] = 0;
        }
      }
      for (std::size_t k = corner_start_[node]; k < corner_start_[node + 1]; ++k) {
        const int e = block_of_cell(std::size_t{corner_[k] / kCorners});
        if (e < 0) continue;
        const int i = static_cast<int>(corner_[k] % kCorners);
        for (int j = 0; j < kCorners; ++j) {
          const int at = entry_[slot_[std::size_t{corner_[k]} * kCorners + j]];
          if (at >= 0) matrix_.value[static_cast<std::size_t>(at)] += block(e, i, j);
        }
      }
    }
  }

 private:
  // From set_mesh. 32-bit indices where there is one per cell corner or pair of corners (half
  // the memory; a mesh would need 10^9 cells to overflow them).
  std::vector<std::size_t> corner_start_;
  std::vector<std::uint32_t> corner_;  // by node: c * kCorners + i
  SparseMatrix pattern_;               // values unused
  std::vector<std::uint32_t> slot_;
  // Rebuilt by each assembly.
  std::vector<std::size_t> row_node_;
  std::vector<int> row_of_node_, entry_;
  SparseMatrix matrix_;
};

// The points' mass matrix on the linear simplex cells of a mesh,
//     M_IJ = sum_q V_q N_I(x_q) N_J(x_q),
// with its lumped diagonal m_I = sum_q V_q N_I(x_q) and a right-hand side
// b_I = sum_q V_q N_I(x_q) f_q, assembled in one pass over the points. Applying M matrix-free
// costs a gather and a scatter over all points; assembled, it is one short row per node
// (7 entries on a structured triangle mesh, about 15 on tetrahedra), several times cheaper
// once a solve takes more than a few iterations.
//
// Only the nodes that carry water (m_I > 0) get a row: `nodes()[r]` is row r's node, in
// increasing node order. A node with m_I = 0 has N_I = 0 at every point of its cells, so its
// row and column are zero and leaving it out changes nothing but the work.
//
// Every sum is made by one thread in an order fixed by the mesh and the point order (points
// by cell, cells by node): the result has the same bits for any thread count.
template <int dim>
class PointMassMatrix : public MeshMatrix<dim> {
 public:
  using MeshMatrix<dim>::kCorners;
  using typename MeshMatrix<dim>::CellNodes;

  // Assembles M (rows of the nodes with m_I > 0), m and b from the points: `cell[q]` the
  // point's cell, `shape[q]` its shape values there, `volume[q]` V_q, `values[q]` f_q.
  // `lumped` and `rhs` receive m and b on all nodes. set_mesh() must have been called.
  template <class Shape>
  void assemble(const std::vector<CellNodes>& cell_nodes, const std::vector<int>& cell,
                const std::vector<Shape>& shape, const std::vector<double>& volume,
                const std::vector<double>& values, int threads, std::vector<double>& lumped,
                std::vector<double>& rhs) {
    const std::size_t n_cells = cell_nodes.size(), n_nodes = this->node_count();
    // 1. The points of each cell, in point order (a counting sort): each cell's sums below
    //    are then made by one thread in a fixed order.
    cell_start_.assign(n_cells + 1, 0);
    for (int c : cell) ++cell_start_[static_cast<std::size_t>(c) + 1];
    std::partial_sum(cell_start_.begin(), cell_start_.end(), cell_start_.begin());
    cell_point_.resize(cell.size());
    next_.assign(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t q = 0; q < cell.size(); ++q)
      cell_point_[next_[static_cast<std::size_t>(cell[q])]++] = q;
    // The cells holding points get a block of element sums each.
    element_of_cell_.assign(n_cells, -1);
    std::size_t n_elements = 0;
    for (std::size_t c = 0; c < n_cells; ++c)
      if (cell_start_[c + 1] > cell_start_[c]) element_of_cell_[c] = static_cast<int>(n_elements++);
    element_cell_.resize(n_elements);
    for (std::size_t c = 0; c < n_cells; ++c)
      if (element_of_cell_[c] >= 0)
        element_cell_[static_cast<std::size_t>(element_of_cell_[c])] = c;
    element_.resize(n_elements);
    // 2. Per cell: sum V N_i N_j (upper triangle computed, then mirrored, so that M is
    //    symmetric to the last bit), sum V N_i and sum V N_i f.
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t e = 0; e < n_elements; ++e) {
      const std::size_t c = element_cell_[e];
      Element& sums = element_[e];
      sums = Element{};
      for (std::size_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const std::size_t q = cell_point_[k];
        const Shape& n = shape[q];
        for (int i = 0; i < kCorners; ++i) {
          const double vn = volume[q] * n(i);
          sums.lumped[i] += vn;
          sums.rhs[i] += vn * values[q];
          for (int j = i; j < kCorners; ++j) sums.matrix[i][j] += vn * n(j);
        }
      }
      for (int i = 0; i < kCorners; ++i)
        for (int j = 0; j < i; ++j) sums.matrix[i][j] = sums.matrix[j][i];
    }
    // 3. Per node: m and b, summed over the node's cells in cell order.
    lumped.resize(n_nodes);
    rhs.resize(n_nodes);
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t node = 0; node < n_nodes; ++node) {
      double m = 0, b = 0;
      this->for_each_cell_around(node, [&](std::size_t c, int i) {
        const int e = element_of_cell_[c];
        if (e < 0) return;
        m += element_[static_cast<std::size_t>(e)].lumped[i];
        b += element_[static_cast<std::size_t>(e)].rhs[i];
      });
      lumped[node] = m;
      rhs[node] = b;
    }
    // 4. M on the rows of the nodes with m > 0.
    MeshMatrix<dim>::assemble(
        [&](std::size_t c) { return element_of_cell_[c]; },
        [&](std::size_t node) { return lumped[node] > 0; },
        [&](int e, int i, int j) { return element_[static_cast<std::size_t>(e)].matrix[i][j]; },
        threads);
  }

 private:
  struct Element {  // one cell's sums over its points
    std::array<std::array<double, kCorners>, kCorners> matrix{};
    std::array<double, kCorners> lumped{}, rhs{};
  };
  // Rebuilt by each assembly.
  std::vector<std::size_t> cell_start_, cell_point_, next_, element_cell_;
  std::vector<int> element_of_cell_;
  std::vector<Element> element_;
};

}  // namespace lituya::solver::detail
