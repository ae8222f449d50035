// XPIC(m) (xpic.hpp): the damped share it gives the points against its definition,
// [I - (I - P)^m] v_p, built here from dense matrices.
#include "lituya/solver/xpic.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace lituya::solver {
namespace {

using Vec = Mesh<2>::Vec;
using Shape = Mesh<2>::Shape;

// A 3 x 2 grid of unit squares, each cut into four triangles at its centre (a crossed mesh).
Mesh<2> crossed_grid() {
  Mesh<2> mesh;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 3; ++i) mesh.node_position.push_back(Vec(i, j));
  auto id = [](int i, int j) { return j * 4 + i; };
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const int o = static_cast<int>(mesh.node_position.size());
      mesh.node_position.push_back(Vec(i + 0.5, j + 0.5));
      const std::array<int, 4> q{id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
      for (int k = 0; k < 4; ++k) mesh.cell_nodes.push_back({q[k], q[(k + 1) % 4], o});
    }
  EXPECT_EQ(mesh.build(), -1);
  return mesh;
}

struct Points {
  std::vector<int> cell;
  std::vector<Shape> shape;
  std::vector<double> mass;
  std::vector<Vec> velocity;
  std::vector<char> selected;
};

// `per_cell` points at random places in every cell, random masses and velocities; every
// seventh point is not selected (it reads another field).
Points random_points(const Mesh<2>& mesh, int per_cell, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), signed_unit(-1.0, 1.0);
  Points p;
  for (std::size_t c = 0; c < mesh.cell_count(); ++c)
    for (int k = 0; k < per_cell; ++k) {
      double a = unit(random), b = unit(random);
      if (a + b > 1) a = 1 - a, b = 1 - b;
      Shape n(1 - a - b, a, b);
      p.cell.push_back(static_cast<int>(c));
      p.shape.push_back(n);
      p.mass.push_back(0.5 + unit(random));
      p.velocity.push_back(Vec(signed_unit(random), signed_unit(random)));
      p.selected.push_back(p.cell.size() % 7 != 0);
    }
  return p;
}

// S (points x nodes) over the selected points, and the mapped nodal velocity v^n.
Eigen::MatrixXd shape_matrix(const Mesh<2>& mesh, const Points& p) {
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(p.cell.size()),
                                            static_cast<Eigen::Index>(mesh.node_count()));
  for (std::size_t q = 0; q < p.cell.size(); ++q)
    if (p.selected[q])
      for (int a = 0; a < 3; ++a)
        s(static_cast<Eigen::Index>(q), mesh.cell_nodes[p.cell[q]][a]) = p.shape[q](a);
  return s;
}

std::vector<Vec> mapped_velocity(const Mesh<2>& mesh, const Points& p) {
  std::vector<Vec> momentum(mesh.node_count(), Vec::Zero());
  std::vector<double> mass(mesh.node_count(), 0.0);
  for (std::size_t q = 0; q < p.cell.size(); ++q) {
    if (!p.selected[q]) continue;
    for (int a = 0; a < 3; ++a) {
      const int node = mesh.cell_nodes[p.cell[q]][a];
      momentum[node] += p.shape[q](a) * p.mass[q] * p.velocity[q];
      mass[node] += p.shape[q](a) * p.mass[q];
    }
  }
  for (std::size_t i = 0; i < momentum.size(); ++i) momentum[i] /= mass[i];
  return momentum;
}

// The PIC share's velocity at each point: S (v^L + c).
std::vector<Vec> damped_share(const Mesh<2>& mesh, const Points& p, const std::vector<Vec>& v,
                              const std::vector<Vec>& c) {
  std::vector<Vec> out(p.cell.size(), Vec::Zero());
  for (std::size_t q = 0; q < p.cell.size(); ++q)
    for (int a = 0; a < 3; ++a) {
      const int node = mesh.cell_nodes[p.cell[q]][a];
      out[q] += p.shape[q](a) * (v[node] + c[node]);
    }
  return out;
}

TEST(Xpic, DampedShareIsTheDefinitionsProjection) {
  // Expected: for the selected points, S(dt a) + [I - (I - P)^m] v_p with P = S M^-1 S^T W
  // (W the points' masses, M the nodal masses), the point-space form of Hammerquist and
  // Nairn's XPIC(m); m = 1 is PIC, S v^L. A dense computation, independent of the nodal
  // recursion in xpic.hpp.
  const Mesh<2> mesh = crossed_grid();
  const Points p = random_points(mesh, 3, 7);
  const Eigen::MatrixXd s = shape_matrix(mesh, p);
  const Eigen::Index np = s.rows(), nn = s.cols();
  Eigen::VectorXd w(np);
  for (Eigen::Index q = 0; q < np; ++q) w(q) = p.selected[q] ? p.mass[q] : 0.0;
  const Eigen::VectorXd nodal_mass = s.transpose() * w;
  const Eigen::MatrixXd projection =
      s * nodal_mass.cwiseInverse().asDiagonal() * s.transpose() * w.asDiagonal();
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(np, np);

  const std::vector<Vec> mapped = mapped_velocity(mesh, p);
  const double dt = 1e-3;
  std::vector<Vec> acceleration(mapped.size()), updated(mapped.size());
  for (std::size_t i = 0; i < mapped.size(); ++i) {
    acceleration[i] = Vec(std::sin(1.0 + i), std::cos(2.0 * i));
    updated[i] = mapped[i] + dt * acceleration[i];
  }
  for (int order : {1, 2, 3, 5}) {
    Xpic<2> xpic;
    xpic.allocate(1, static_cast<std::size_t>(nn));
    std::vector<Vec> correction(mapped.size(), Vec::Zero());
    if (order > 1)
      correction =
          xpic.update(order, mesh, p.cell, p.shape, p.mass, updated.data(), acceleration.data(), dt,
                      [&](std::size_t q) { return p.selected[q] != 0; });
    const std::vector<Vec> got = damped_share(mesh, p, updated, correction);
    Eigen::MatrixXd residual = identity;
    for (int k = 0; k < order; ++k) residual = residual * (identity - projection);
    for (int d = 0; d < 2; ++d) {
      Eigen::VectorXd v(np), grid_increment(nn);
      for (Eigen::Index q = 0; q < np; ++q) v(q) = p.velocity[q](d);
      for (Eigen::Index i = 0; i < nn; ++i) grid_increment(i) = dt * acceleration[i](d);
      const Eigen::VectorXd expected = s * grid_increment + (identity - residual) * v;
      for (Eigen::Index q = 0; q < np; ++q) {
        if (!p.selected[q]) continue;
        EXPECT_NEAR(got[q](d), expected(q), 1e-12) << "order " << order << ", point " << q;
      }
    }
  }
}

TEST(Xpic, HigherOrdersTakeLessOfAVelocityTheGridResolves) {
  // What the blend is for: a point velocity that is a nodal field interpolated, v = S u, is
  // one the grid represents; PIC still takes part of it (the lumped map M^-1 S^T W S keeps each
  // mode only to a fraction 0 < lambda <= 1), XPIC(m) takes (1 - lambda)^m of each mode, so
  // the change of v falls with every order. Expected: a strictly falling RMS change, PIC's at
  // least 1 % for this grid-scale pattern.
  const Mesh<2> mesh = crossed_grid();
  Points p = random_points(mesh, 3, 11);
  for (char& s : p.selected) s = 1;
  std::vector<Vec> nodal(mesh.node_count());
  for (std::size_t i = 0; i < nodal.size(); ++i)
    nodal[i] = Vec(std::sin(3.0 * i), std::cos(5.0 * i));
  for (std::size_t q = 0; q < p.cell.size(); ++q) {
    p.velocity[q] = Vec::Zero();
    for (int a = 0; a < 3; ++a)
      p.velocity[q] += p.shape[q](a) * nodal[mesh.cell_nodes[p.cell[q]][a]];
  }
  const std::vector<Vec> zero(mesh.node_count(), Vec::Zero());
  const std::vector<Vec> mapped = mapped_velocity(mesh, p);
  std::vector<double> change;
  for (int order : {1, 2, 3, 4}) {
    Xpic<2> xpic;
    xpic.allocate(1, mesh.node_count());
    std::vector<Vec> correction(mapped.size(), Vec::Zero());
    if (order > 1)
      correction = xpic.update(order, mesh, p.cell, p.shape, p.mass, mapped.data(), zero.data(),
                               0.0, [](std::size_t) { return true; });
    const std::vector<Vec> got = damped_share(mesh, p, mapped, correction);
    double squared = 0, norm = 0;
    for (std::size_t q = 0; q < got.size(); ++q) {
      squared += (got[q] - p.velocity[q]).squaredNorm();
      norm += p.velocity[q].squaredNorm();
    }
    change.push_back(std::sqrt(squared / norm));
  }
  EXPECT_GT(change[0], 0.01);
  for (std::size_t k = 1; k < change.size(); ++k)
    EXPECT_LT(change[k], change[k - 1]) << "order " << k + 1;
}

TEST(Xpic, TwoThreadsRepeatBitForBit) {
  // The scatters are summed per thread in a fixed order (nodal_scatter.hpp): two runs on two
  // threads give the same bits, and one thread the same values to rounding.
  const Mesh<2> mesh = crossed_grid();
  const Points p = random_points(mesh, 9, 3);
  const std::vector<Vec> mapped = mapped_velocity(mesh, p);
  const std::vector<Vec> zero(mesh.node_count(), Vec::Zero());
  auto run = [&](int threads) {
    Xpic<2> xpic;
    xpic.allocate(threads, mesh.node_count());
    return xpic.update(3, mesh, p.cell, p.shape, p.mass, mapped.data(), zero.data(), 0.0,
                       [&](std::size_t q) { return p.selected[q] != 0; });
  };
  const std::vector<Vec> first = run(2), second = run(2), serial = run(1);
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i](0), second[i](0));
    EXPECT_EQ(first[i](1), second[i](1));
    EXPECT_NEAR(first[i](0), serial[i](0), 1e-13);
    EXPECT_NEAR(first[i](1), serial[i](1), 1e-13);
  }
}

}  // namespace
}  // namespace lituya::solver
