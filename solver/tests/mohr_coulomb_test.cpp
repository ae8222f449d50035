// Mohr-Coulomb return mapping, eqs. (19)-(22): closed-form returns (plane, edges, apex,
// tension cut-off), flow rule, classical stress paths (Davis 1968 simple shear, triaxial
// compression), invariance and robustness. Stresses tension positive, Pa.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "lituya/solver/mohr_coulomb.hpp"
#include "lituya/solver/principal_stresses.hpp"

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using lituya::solver::MohrCoulomb;
using lituya::solver::Voigt6;

constexpr double kPa = 1e3;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDeg = std::numbers::pi / 180;

Matrix3d stress_tensor(const Voigt6& s) {
  Matrix3d m;
  m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  return m;
}
Voigt6 stress_voigt(const Matrix3d& m) {
  Voigt6 s;
  s << m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(1, 2), m(0, 2);
  return s;
}
Matrix3d strain_tensor(const Voigt6& e) {  // engineering shears -> tensor
  Matrix3d m;
  m << e[0], e[3] / 2, e[5] / 2, e[3] / 2, e[1], e[4] / 2, e[5] / 2, e[4] / 2, e[2];
  return m;
}
Voigt6 strain_voigt(const Matrix3d& m) {
  Voigt6 e;
  e << m(0, 0), m(1, 1), m(2, 2), 2 * m(0, 1), 2 * m(1, 2), 2 * m(0, 2);
  return e;
}
Voigt6 rotate_stress(const Matrix3d& q, const Voigt6& s) {
  return stress_voigt(q * stress_tensor(s) * q.transpose());
}
Voigt6 rotate_strain(const Matrix3d& q, const Voigt6& e) {
  return strain_voigt(q * strain_tensor(e) * q.transpose());
}
Voigt6 diagonal(double a, double b, double c) {
  Voigt6 v = Voigt6::Zero();
  v[0] = a, v[1] = b, v[2] = c;
  return v;
}
// Principal values, descending, with Eigen's iterative (QR) solver: independent of the code
// under test.
Vector3d principal(const Voigt6& s) {
  Eigen::SelfAdjointEigenSolver<Matrix3d> solver(stress_tensor(s), Eigen::EigenvaluesOnly);
  const Vector3d ev = solver.eigenvalues();
  return {ev[2], ev[1], ev[0]};
}
Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}
double max_abs(const Voigt6& v) {
  return v.cwiseAbs().maxCoeff();
}

// Independent closed forms in the principal frame (tension positive, s1 >= s2 >= s3).
struct Reference {
  double g, lambda, sf, cf, sp, c;
  Reference(double e, double nu, double phi, double psi, double cohesion)
      : g(e / (2 * (1 + nu))),
        lambda(e * nu / ((1 + nu) * (1 - 2 * nu))),
        sf(std::sin(phi * kDeg)),
        cf(std::cos(phi * kDeg)),
        sp(std::sin(psi * kDeg)),
        c(cohesion) {}
  Matrix3d d() const {  // principal elastic stiffness
    return lambda * Matrix3d::Ones() + 2 * g * Matrix3d::Identity();
  }
  // a_ij, b_ij: gradients of f and g of the plane "s_i vs s_j" (i tensile, j compressive).
  Vector3d a(int i, int j) const {
    Vector3d v = Vector3d::Zero();
    v[i] = 1 + sf, v[j] = -(1 - sf);
    return v;
  }
  Vector3d b(int i, int j) const {
    Vector3d v = Vector3d::Zero();
    v[i] = 1 + sp, v[j] = -(1 - sp);
    return v;
  }
  double f(const Vector3d& s, int i, int j) const { return a(i, j).dot(s) - 2 * c * cf; }
  // Strain increment taking the principal stress s0 (diagonal) to the trial t.
  Voigt6 strain_between(const Vector3d& s0, const Vector3d& t) const {
    const Vector3d e = d().inverse() * (t - s0);
    return diagonal(e[0], e[1], e[2]);
  }
};

// Step with one unknown strain component: find x so that control(stress after
// update(stress, increment(x))) == target (secant iterations), then commit the step.
template <class Increment, class Control>
double mixed_step(const MohrCoulomb& model, Voigt6& stress, Increment increment, Control control,
                  double target, double stiffness) {
  auto residual = [&](double x) {
    Voigt6 s = stress;
    model.update(s, increment(x));
    return control(s) - target;
  };
  double x0 = 0, h0 = residual(x0);
  double x1 = x0 - h0 / stiffness, h1 = residual(x1);
  for (int it = 0; it < 60 && std::abs(h1) > 1e-11 * std::abs(target); ++it) {
    const double slope = (h1 - h0) / (x1 - x0);
    if (slope == 0) break;
    x0 = x1, h0 = h1;
    x1 = x1 - h1 / slope;
    h1 = residual(x1);
  }
  EXPECT_LE(std::abs(h1), 1e-9 * std::abs(target));
  return model.update(stress, increment(x1));
}

// ---------------------------------------------------------------------------------------------

TEST(MohrCoulomb, RejectsInvalidParameters) {
  EXPECT_THROW(MohrCoulomb(10e6, 0.3, 90, 0, 0, 0), std::invalid_argument);
  EXPECT_THROW(MohrCoulomb(10e6, 0.3, 30, 35, 0, 0), std::invalid_argument);  // psi > phi
  EXPECT_THROW(MohrCoulomb(10e6, 0.3, 30, -1, 0, 0), std::invalid_argument);
  EXPECT_THROW(MohrCoulomb(10e6, 0.3, 30, 0, -1, 0), std::invalid_argument);
  EXPECT_THROW(MohrCoulomb(10e6, 0.3, 30, 0, 0, -1), std::invalid_argument);
  EXPECT_THROW(MohrCoulomb(-1, 0.3, 30, 0, 0, 0), std::invalid_argument);
  EXPECT_NO_THROW(MohrCoulomb(10e6, 0.3, 0, 0, 10 * kPa, kInf));
}

TEST(MohrCoulomb, YieldFunctionIsMinusTwiceThePaperForm) {
  const MohrCoulomb model(10e6, 0.3, 30, 0, 10 * kPa, kInf);
  // s = (-100, -200, -300) kPa: f = 200 + (-400) 0.5 - 2 * 10 cos 30 = -17.3205 kPa.
  const double expected = -20 * kPa * std::cos(30 * kDeg);
  const Voigt6 s = diagonal(-200 * kPa, -300 * kPa, -100 * kPa);
  EXPECT_NEAR(model.yield_function(s), expected, 1e-9);
  // Paper eq. (21), compression negative, sigma1 <= sigma3:
  // f = 1/2 (s1 - s3) - 1/2 (s1 + s3) sin(phi) + c cos(phi) with s1 = -300, s3 = -100.
  const double paper = 0.5 * (-200 * kPa) - 0.5 * (-400 * kPa) * std::sin(30 * kDeg) +
                       10 * kPa * std::cos(30 * kDeg);
  EXPECT_NEAR(model.yield_function(s), -2 * paper, 1e-9);
  // Invariant under rotation (3D principal values).
  std::mt19937 rng(7);
  EXPECT_NEAR(model.yield_function(rotate_stress(random_rotation(rng), s)), expected, 1e-8);
}

TEST(MohrCoulomb, ElasticInsideTheSurfaceIsHooke) {
  const MohrCoulomb model(10e6, 0.3, 30, 5, 5 * kPa, 2 * kPa);
  std::mt19937 rng(3);
  const Matrix3d q = random_rotation(rng);
  Voigt6 de;
  de << -1e-4, 2e-5, -3e-5, 1e-5, 0, 0;
  for (const Matrix3d& rot : {Matrix3d(Matrix3d::Identity()), q}) {
    const Voigt6 s0 = rotate_stress(rot, diagonal(-100 * kPa, -120 * kPa, -80 * kPa));
    const Voigt6 d = rotate_strain(rot, de);
    Voigt6 s = s0, expected = s0;
    lituya::solver::elastic_update(model.elastic(), expected, d);
    EXPECT_EQ(model.update(s, d), 0.0);
    EXPECT_LE((s - expected).cwiseAbs().maxCoeff(), 1e-9 * max_abs(expected));
  }
}

TEST(MohrCoulomb, ReturnToMainPlaneMatchesClosedForm) {
  const double e = 10e6, nu = 0.3, phi = 30, psi = 10, c = 10 * kPa;
  const MohrCoulomb model(e, nu, phi, psi, c, kInf);
  const Reference ref(e, nu, phi, psi, c);
  const Vector3d s0(-100 * kPa, -100 * kPa, -100 * kPa);
  const Vector3d t(-60 * kPa, -100 * kPa, -220 * kPa);  // f(t) = 2.68 kPa
  ASSERT_GT(ref.f(t, 0, 2), 0);
  const Vector3d a = ref.a(0, 2), b = ref.b(0, 2);
  const double dl = ref.f(t, 0, 2) / a.dot(ref.d() * b);
  const Vector3d expected = t - dl * ref.d() * b;
  ASSERT_GT(expected[0], expected[1]);  // the plane return keeps the order: a plane case
  ASSERT_GT(expected[1], expected[2]);
  const double eq_plastic = dl * std::sqrt(2.0 / 3.0) * b.norm();

  std::mt19937 rng(11);
  const Matrix3d q = random_rotation(rng);
  for (const Matrix3d& rot : {Matrix3d(Matrix3d::Identity()), q}) {
    Voigt6 s = rotate_stress(rot, diagonal(s0[0], s0[1], s0[2]));
    const double eps_p = model.update(s, rotate_strain(rot, ref.strain_between(s0, t)));
    const Voigt6 want = rotate_stress(rot, diagonal(expected[0], expected[1], expected[2]));
    EXPECT_LE((s - want).cwiseAbs().maxCoeff(), 1e-9 * 100 * kPa);
    EXPECT_NEAR(eps_p, eq_plastic, 1e-9 * eq_plastic);
    EXPECT_NEAR(model.yield_function(s), 0.0, 1e-9 * 100 * kPa);
  }
}

// Two active planes: solve [a_i . D b_j] dl = f_i(t) independently.
Vector3d edge_return(const Reference& ref, const Vector3d& t, int i1, int j1, int i2, int j2,
                     double& dl1, double& dl2) {
  const Eigen::Vector3d db1 = ref.d() * ref.b(i1, j1), db2 = ref.d() * ref.b(i2, j2);
  Eigen::Matrix2d m;
  m << ref.a(i1, j1).dot(db1), ref.a(i1, j1).dot(db2), ref.a(i2, j2).dot(db1),
      ref.a(i2, j2).dot(db2);
  const Eigen::Vector2d dl = m.inverse() * Eigen::Vector2d(ref.f(t, i1, j1), ref.f(t, i2, j2));
  dl1 = dl[0], dl2 = dl[1];
  return t - dl[0] * db1 - dl[1] * db2;
}

TEST(MohrCoulomb, EdgeReturnsTriaxialCompressionAndExtension) {
  const double e = 10e6, nu = 0.3, phi = 30, psi = 10, c = 10 * kPa;
  const MohrCoulomb model(e, nu, phi, psi, c, kInf);
  const Reference ref(e, nu, phi, psi, c);
  const Vector3d s0(-100 * kPa, -100 * kPa, -100 * kPa);
  std::mt19937 rng(5);
  const Matrix3d q = random_rotation(rng);
  struct Case {
    Vector3d t;
    int i2, j2;  // second active plane: (1, 2) = s2 vs s3 on s1 = s2, (0, 1) on s2 = s3
  };
  // Triaxial compression (lateral s1 = s2 = -100 kPa, axial s3 = -400 kPa), a slightly
  // perturbed one (the plane return would break the ordering), and triaxial extension.
  const Case cases[] = {{{-100 * kPa, -100 * kPa, -400 * kPa}, 1, 2},
                        {{-99 * kPa, -100 * kPa, -400 * kPa}, 1, 2},
                        {{-100 * kPa, -400 * kPa, -400 * kPa}, 0, 1},
                        {{-100 * kPa, -398 * kPa, -400 * kPa}, 0, 1}};
  for (const Case& k : cases) {
    double dl1, dl2;
    const Vector3d expected = edge_return(ref, k.t, 0, 2, k.i2, k.j2, dl1, dl2);
    ASSERT_GT(dl1, 0);
    ASSERT_GT(dl2, 0);
    // On both planes: F1 = 0 and the neighbouring plane = 0, i.e. two equal principal values.
    EXPECT_NEAR(ref.f(expected, 0, 2), 0, 1e-6);
    EXPECT_NEAR(ref.f(expected, k.i2, k.j2), 0, 1e-6);
    for (const Matrix3d& rot : {Matrix3d(Matrix3d::Identity()), q}) {
      Voigt6 s = rotate_stress(rot, diagonal(s0[0], s0[1], s0[2]));
      EXPECT_GT(model.update(s, rotate_strain(rot, ref.strain_between(s0, k.t))), 0);
      const Vector3d got = principal(s);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expected[i], 1e-9 * 400 * kPa);
      if (k.i2 == 1) {
        EXPECT_NEAR(got[0], got[1], 1e-9 * 400 * kPa);
      } else {
        EXPECT_NEAR(got[1], got[2], 1e-9 * 400 * kPa);
      }
      EXPECT_NEAR(model.yield_function(s), 0.0, 1e-9 * 400 * kPa);
    }
  }
}

TEST(MohrCoulomb, ApexReturn) {
  std::mt19937 rng(13);
  const Matrix3d q = random_rotation(rng);
  // c = 0: cut-off = apex = 0. Isotropic tension from zero stress (2D with eps_zz = 0 and 3D):
  // exactly zero stress and all the strain is plastic.
  {
    const MohrCoulomb model(10e6, 0.3, 30, 0, 0, 0);
    Voigt6 s = Voigt6::Zero();
    const double eps_p = model.update(s, diagonal(1e-3, 1e-3, 1e-3));
    for (int i = 0; i < 6; ++i) EXPECT_EQ(s[i], 0.0);
    EXPECT_NEAR(eps_p, std::sqrt(2.0) * 1e-3, 1e-15);  // sqrt(2/3 * 3 e^2)
    s = Voigt6::Zero();
    model.update(s, diagonal(1e-3, 1e-3, 0));
    for (int i = 0; i < 6; ++i) EXPECT_EQ(s[i], 0.0);
    // From a compressed, rotated state and a rotated increment with a large tensile part.
    s = rotate_stress(q, diagonal(-50 * kPa, -80 * kPa, -60 * kPa));
    Voigt6 de;
    de << 4e-2, 3e-2, 5e-2, 1e-3, -2e-3, 5e-4;
    model.update(s, de);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(s[i], 0.0);
  }
  // c > 0, no cut-off below the apex: s = c cot(phi) isotropic.
  {
    const double c = 10 * kPa, apex = c / std::tan(30 * kDeg);
    const MohrCoulomb model(10e6, 0.3, 30, 0, c, kInf);
    for (const Matrix3d& rot : {Matrix3d(Matrix3d::Identity()), q}) {
      Voigt6 s = rotate_stress(rot, diagonal(-20 * kPa, -30 * kPa, -25 * kPa));
      model.update(s, rotate_strain(rot, diagonal(1e-2, 1.1e-2, 0.9e-2)));
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(s[i], apex, 1e-12 * apex);
      for (int i = 3; i < 6; ++i) EXPECT_NEAR(s[i], 0.0, 1e-12 * apex);
    }
  }
  // c > 0 with a cut-off below the apex: the Rankine vertex s = sigma_t isotropic.
  {
    const double st = 4 * kPa;
    const MohrCoulomb model(10e6, 0.3, 30, 10, 10 * kPa, st);
    for (const Matrix3d& rot : {Matrix3d(Matrix3d::Identity()), q}) {
      Voigt6 s = rotate_stress(rot, diagonal(-20 * kPa, -30 * kPa, -25 * kPa));
      model.update(s, rotate_strain(rot, diagonal(1e-2, 1.1e-2, 0.9e-2)));
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(s[i], st, 1e-12 * st);
      for (int i = 3; i < 6; ++i) EXPECT_NEAR(s[i], 0.0, 1e-12 * st);
    }
  }
}

TEST(MohrCoulomb, TensionCutOffPlaneAndCorner) {
  const double e = 10e6, nu = 0.2, phi = 30, psi = 10, c = 20 * kPa, st = 5 * kPa;
  const MohrCoulomb model(e, nu, phi, psi, c, st);
  const Reference ref(e, nu, phi, psi, c);
  std::mt19937 rng(17);
  const Matrix3d q = random_rotation(rng);
  // Uniaxial tensile strain from zero stress: trial (15, 3.75, 3.75) kPa, only s1 > sigma_t.
  // Rankine plane: dl = (15 - 5) / (lambda + 2G), s2 = s3 = 3.75 - lambda dl = 1.25 kPa.
  {
    const double eps = 15 * kPa / (ref.lambda + 2 * ref.g);
    for (const Matrix3d& rot : {Matrix3d(Matrix3d::Identity()), q}) {
      Voigt6 s = Voigt6::Zero();
      const double eps_p = model.update(s, rotate_strain(rot, diagonal(eps, 0, 0)));
      const Voigt6 want = rotate_stress(rot, diagonal(st, 1.25 * kPa, 1.25 * kPa));
      EXPECT_LE((s - want).cwiseAbs().maxCoeff(), 1e-9 * 15 * kPa);
      // Plastic strain e1 dl (associated Rankine flow): sqrt(2/3) dl.
      EXPECT_NEAR(eps_p, std::sqrt(2.0 / 3.0) * 10 * kPa / (ref.lambda + 2 * ref.g), 1e-15);
    }
  }
  // Tension and compression, returning to the edge where the yield plane meets the cut-off:
  // s1 = sigma_t, s3 = s3c with F1 = 0, i.e. s3c = (sigma_t (1 + sf) - 2 c cf) / (1 - sf), and
  // s2 anywhere between. The trial is built from that answer and positive multipliers of the
  // two flows b1 (Mohr-Coulomb) and e1 (Rankine): t = x + dl_f D b1 + dl_r D e1.
  {
    const double s3c = (st * (1 + ref.sf) - 2 * c * ref.cf) / (1 - ref.sf);
    const Vector3d expected(st, -20 * kPa, s3c);
    const Matrix3d d = ref.d();
    const double dl_f = 1e-3, dl_r = 0.5e-3;
    const Vector3d t = expected + dl_f * d * ref.b(0, 2) + dl_r * d.col(0);
    EXPECT_NEAR(ref.f(expected, 0, 2), 0, 1e-9);
    const Vector3d s0 = Vector3d::Zero();
    for (const Matrix3d& rot : {Matrix3d(Matrix3d::Identity()), q}) {
      Voigt6 s = Voigt6::Zero();
      const double eps_p = model.update(s, rotate_strain(rot, ref.strain_between(s0, t)));
      const Vector3d got = principal(s);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expected[i], 1e-9 * 100 * kPa);
      EXPECT_NEAR(model.yield_function(s), 0.0, 1e-9 * 100 * kPa);
      const Vector3d eps = dl_f * ref.b(0, 2) + dl_r * Vector3d::UnitX();
      EXPECT_NEAR(eps_p, std::sqrt(2.0 / 3.0) * eps.norm(), 1e-12);
    }
  }
}

Matrix3d rotation_about_z(double angle) {
  return Eigen::AngleAxisd(angle, Vector3d::UnitZ()).toRotationMatrix();
}

// Corners of the cut-off below the apex (c = 20 kPa, phi = 30, psi = 10, sigma_t = 5 kPa):
// each trial is built from the expected corner x and positive multipliers of the flows
// active there, t = x + D sum(dl_i flow_i), so the return must land exactly on x:
//  - edge R1 + R2:   x = (st, st, -30 kPa),  flows e1, e2
//  - vertex A:       x = (st, st, s3c),      flows b(1,3), b(2,3), e1, e2
//  - vertex B:       x = (st, s3c, s3c),     flows b(1,3), b(1,2), e1
//  - vertex C:       x = (st, st, st),       flows e1, e2, e3
// with s3c = (st (1 + sf) - 2 c cf) / (1 - sf), s3 on the yield plane for s1 = st.
TEST(MohrCoulomb, TensionCutOffEdgesAndVertices) {
  const double e = 10e6, nu = 0.2, phi = 30, psi = 10, c = 20 * kPa, st = 5 * kPa;
  const MohrCoulomb model(e, nu, phi, psi, c, st);
  const Reference ref(e, nu, phi, psi, c);
  const Matrix3d d = ref.d();
  const double s3c = (st * (1 + ref.sf) - 2 * c * ref.cf) / (1 - ref.sf);
  const Vector3d e1 = Vector3d::UnitX(), e2 = Vector3d::UnitY(), e3 = Vector3d::UnitZ();
  struct Case {
    const char* name;
    Vector3d x, flow;  // flow: sum of dl_i flow_i (plastic strain increment)
  };
  const double k = 1e-3;
  const Case cases[] = {
      {"edge R1+R2", {st, st, -30 * kPa}, k * (1.0 * e1 + 0.5 * e2)},
      {"vertex A", {st, st, s3c}, k * (ref.b(0, 2) + 0.3 * ref.b(1, 2) + 0.2 * e1 + 0.1 * e2)},
      {"vertex A, MC flows only", {st, st, s3c}, k * (ref.b(0, 2) + ref.b(1, 2))},
      {"vertex B", {st, s3c, s3c}, k * (ref.b(0, 2) + 0.4 * ref.b(0, 1) + 0.2 * e1)},
      {"vertex B, MC flows only", {st, s3c, s3c}, k * (0.5 * ref.b(0, 2) + ref.b(0, 1))},
      {"vertex C", {st, st, st}, k * (0.2 * e1 + 0.5 * e2 + 1.0 * e3)},
  };
  std::mt19937 rng(47);
  const Matrix3d q = random_rotation(rng);
  for (const Case& cs : cases) {
    const Vector3d t = cs.x + d * cs.flow;
    for (const Matrix3d& rot : {Matrix3d(Matrix3d::Identity()), q}) {
      Voigt6 s = Voigt6::Zero();
      const double eps_p =
          model.update(s, rotate_strain(rot, ref.strain_between(Vector3d::Zero(), t)));
      const Vector3d got = principal(s);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], cs.x[i], 1e-9 * 100 * kPa) << cs.name;
      EXPECT_NEAR(eps_p, std::sqrt(2.0 / 3.0) * cs.flow.norm(), 1e-12) << cs.name;
    }
  }
}

// With c > 0 and the cut-off at the apex c cot(phi), the apex takes any plastic strain in the
// cone of the Mohr-Coulomb flows b(i, j) and the Rankine flows e_i; built as above.
TEST(MohrCoulomb, ApexFlowCone) {
  const double e = 10e6, nu = 0.3, phi = 30, psi = 10, c = 10 * kPa;
  const MohrCoulomb model(e, nu, phi, psi, c, kInf);
  const Reference ref(e, nu, phi, psi, c);
  const Vector3d apex = Vector3d::Constant(c / std::tan(phi * kDeg));
  const double k = 1e-3;
  // Mohr-Coulomb flows only (volumetric 2 sin(psi) per unit, less than isotropic tension):
  // compressive s3 direction with dilatant flow; and a mixed one.
  const Vector3d flows[] = {k * (ref.b(0, 2) + ref.b(1, 2)), k * (ref.b(0, 2) + 0.5 * ref.b(0, 1)),
                            k * (ref.b(0, 2) + 0.5 * Vector3d::UnitY())};
  for (const Vector3d& flow : flows) {
    const Vector3d t = apex + ref.d() * flow;
    Voigt6 s = Voigt6::Zero();
    const double eps_p = model.update(s, ref.strain_between(Vector3d::Zero(), t));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(s[i], apex[i], 1e-9 * 100 * kPa);
    EXPECT_NEAR(eps_p, std::sqrt(2.0 / 3.0) * flow.norm(), 1e-12);
  }
}

TEST(MohrCoulomb, ZeroDilatancyGivesNoPlasticVolumeChange) {
  // psi = 0: the plastic strain is purely deviatoric, so the mean stress responds elastically
  // to the whole volumetric strain increment, d p = K tr(d_eps), although the return changes
  // the deviator. Trial (-60, -100, -220) kPa from (-100, -100, -100) kPa: plane return.
  const double e = 10e6, nu = 0.3, c = 5 * kPa;
  const MohrCoulomb model(e, nu, 30, 0, c, kInf);
  const Reference ref(e, nu, 30, 0, c);
  const double bulk = ref.lambda + 2.0 / 3.0 * ref.g;
  const Vector3d s0 = Vector3d::Constant(-100 * kPa);
  const Vector3d t(-60 * kPa, -100 * kPa, -220 * kPa);
  ASSERT_GT(ref.f(t, 0, 2), 0);
  std::mt19937 rng(19);
  // In-plane rotation (fast path) and a general one (3D path).
  for (const Matrix3d& rot : {rotation_about_z(0.3), random_rotation(rng)}) {
    const Voigt6 start = rotate_stress(rot, diagonal(s0[0], s0[1], s0[2]));
    const Voigt6 de = rotate_strain(rot, ref.strain_between(s0, t));
    Voigt6 trial = start, s = start;
    lituya::solver::elastic_update(model.elastic(), trial, de);
    ASSERT_GT(model.update(s, de), 0);
    const double mean_change = (s[0] + s[1] + s[2] - start[0] - start[1] - start[2]) / 3;
    EXPECT_GT((s - trial).cwiseAbs().maxCoeff(), 1 * kPa);  // the return did change the stress
    EXPECT_NEAR(mean_change, bulk * (de[0] + de[1] + de[2]), 1e-9 * 100 * kPa);
    EXPECT_NEAR(model.yield_function(s), 0.0, 1e-9 * 100 * kPa);
  }
}

TEST(MohrCoulomb, PlasticStrainFollowsThePotential) {
  // d_eps_p = D^-1 (sigma_trial - sigma) is coaxial and proportional to
  // b = (1 + sin psi, 0, -(1 - sin psi)) for a plane return: associated (normal to f) when
  // psi = phi; the equivalent plastic strain is sqrt(2/3) |d_eps_p|.
  std::mt19937 rng(23);
  const Vector3d s0 = Vector3d::Constant(-100 * kPa);
  const Vector3d t(-60 * kPa, -100 * kPa, -220 * kPa);
  for (double psi : {30.0, 12.0}) {
    const MohrCoulomb model(10e6, 0.3, 30, psi, 5 * kPa, kInf);
    const Reference ref(10e6, 0.3, 30, psi, 5 * kPa);
    const Matrix3d q = random_rotation(rng);
    const Voigt6 start = rotate_stress(q, diagonal(s0[0], s0[1], s0[2]));
    const Voigt6 de = rotate_strain(q, ref.strain_between(s0, t));
    Voigt6 trial = start, s = start;
    lituya::solver::elastic_update(model.elastic(), trial, de);
    const double eps_eq = model.update(s, de);
    ASSERT_GT(eps_eq, 0);
    // Plastic strain tensor from the stress difference with the isotropic compliance.
    const Matrix3d ds = stress_tensor(trial - s);
    const Matrix3d dp =
        (ds - ref.lambda / (3 * ref.lambda + 2 * ref.g) * ds.trace() * Matrix3d::Identity()) /
        (2 * ref.g);
    EXPECT_NEAR(eps_eq, std::sqrt(2.0 / 3.0 * (dp.array() * dp.array()).sum()), 1e-12);
    // In the trial frame: principal plastic strains proportional to b.
    Eigen::SelfAdjointEigenSolver<Matrix3d> eig(stress_tensor(trial));
    const Matrix3d v = eig.eigenvectors();  // ascending: columns s3, s2, s1
    const Matrix3d dpp = v.transpose() * dp * v;
    const Vector3d b = ref.b(0, 2);
    const double scale = dpp(2, 2) / b[0];
    EXPECT_GT(scale, 0);
    EXPECT_NEAR(dpp(0, 0), scale * b[2], 1e-9 * std::abs(scale));
    EXPECT_NEAR(dpp(1, 1), 0.0, 1e-9 * std::abs(scale));
    EXPECT_NEAR(dpp(0, 1), 0.0, 1e-9 * std::abs(scale));
    EXPECT_NEAR(dpp(0, 2), 0.0, 1e-9 * std::abs(scale));
    // Volumetric plastic strain 2 dl sin(psi).
    EXPECT_NEAR(dp.trace(), 2 * scale * ref.sp, 1e-9 * std::abs(scale));
    if (psi == 30.0) {  // normality: proportional to a = df/dsigma
      const Vector3d a = ref.a(0, 2);
      EXPECT_NEAR(dpp(0, 0) / dpp(2, 2), a[2] / a[0], 1e-9);
    }
  }
}

double davis_ratio(double phi, double psi) {
  const double sf = std::sin(phi * kDeg), sp = std::sin(psi * kDeg);
  return sf * std::cos(psi * kDeg) / (1 - sf * sp);
}

TEST(MohrCoulomb, SimpleShearUnderConstantNormalStressReachesDavis) {
  // Plane strain, eps_xx = eps_zz = 0, gamma_xy imposed, sigma_yy held at -100 kPa by
  // iterating on eps_yy. Ultimate tau / |sigma_yy| = sin(phi) cos(psi) / (1 - sin(phi)
  // sin(psi)) (Davis 1968): 0.5 for (30, 0), 0.539 for (30, 10), tan(30) for (30, 30).
  for (auto [phi, psi] : {std::pair{30.0, 0.0}, std::pair{30.0, 10.0}, std::pair{30.0, 30.0}}) {
    const MohrCoulomb model(10e6, 0.3, phi, psi, 0, 0);
    const double sn = -100 * kPa;
    Voigt6 s = diagonal(sn, sn, sn);
    const double dgamma = 2e-5;
    for (int step = 0; step < 15000; ++step) {
      mixed_step(
          model, s,
          [&](double x) {
            Voigt6 de = Voigt6::Zero();
            de[1] = x, de[3] = dgamma;
            return de;
          },
          [](const Voigt6& st) { return st[1]; }, sn, model.elastic().constrained_modulus());
    }
    EXPECT_NEAR(s[3] / -s[1], davis_ratio(phi, psi), 1e-4 * davis_ratio(phi, psi))
        << "phi " << phi << " psi " << psi;
    // The friction of a `contact` wall with `rough = <soil>` is this ultimate ratio.
    EXPECT_NEAR(lituya::solver::rough_wall_friction(phi, psi), s[3] / -s[1],
                1e-4 * davis_ratio(phi, psi));
    EXPECT_NEAR(s[1], sn, 1e-6 * kPa);
    EXPECT_EQ(s[4], 0.0);
    EXPECT_EQ(s[5], 0.0);
  }
  EXPECT_NEAR(davis_ratio(30, 0), 0.5, 1e-15);
  EXPECT_NEAR(lituya::solver::rough_wall_friction(30, 30), std::tan(30 * kDeg), 1e-15);
  EXPECT_NEAR(lituya::solver::rough_wall_friction(15, 0), std::sin(15 * kDeg), 1e-15);
}

TEST(MohrCoulomb, TriaxialCompressionPeakDeviator) {
  // Axial strain along z in 5e-5 steps, lateral stress held at -100 kPa. At failure
  // (triaxial compression, lateral s1 = s2, axial s3):
  // s3 = (s1 (1 + sin phi) - 2 c cos phi) / (1 - sin phi); c = 0: s3 / s1 = 3 for phi = 30.
  // The same in a rotated frame (general 3D path).
  std::mt19937 rng(29);
  const Matrix3d q = random_rotation(rng);
  for (double c : {0.0, 10 * kPa}) {
    for (const Matrix3d& rot : {Matrix3d(Matrix3d::Identity()), q}) {
      const MohrCoulomb model(10e6, 0.3, 30, 5, c, kInf);
      const double lateral = -100 * kPa;
      const double sf = std::sin(30 * kDeg);
      const double axial_failure = (lateral * (1 + sf) - 2 * c * std::cos(30 * kDeg)) / (1 - sf);
      Voigt6 s = rotate_stress(rot, diagonal(lateral, lateral, lateral));
      double peak_q = 0;
      for (int step = 0; step < 1000; ++step) {
        mixed_step(
            model, s, [&](double x) { return rotate_strain(rot, diagonal(x, x, -5e-5)); },
            [&](const Voigt6& st) { return rotate_stress(rot.transpose(), st)[0]; }, lateral,
            model.elastic().constrained_modulus());
        const Voigt6 local = rotate_stress(rot.transpose(), s);
        peak_q = std::max(peak_q, local[0] - local[2]);
        EXPECT_NEAR(local[1], local[0], 1e-9 * 100 * kPa);  // axisymmetric
      }
      EXPECT_NEAR(peak_q, lateral - axial_failure, 1e-8 * 100 * kPa) << "c = " << c;
      EXPECT_NEAR(lateral - axial_failure, c == 0 ? 200 * kPa : 234.6410161513775 * kPa, 1e-6);
    }
  }
}

TEST(MohrCoulomb, RotationInvarianceAndPlaneStrainFastPath) {
  const MohrCoulomb model(10e6, 0.3, 35, 8, 5 * kPa, 2 * kPa);
  std::mt19937 rng(31);
  std::normal_distribution<double> n(0, 1);
  // (a) 3D: random rotations of a random path.
  {
    Voigt6 s = rotate_stress(random_rotation(rng), diagonal(-50 * kPa, -80 * kPa, -120 * kPa));
    int plastic = 0;
    for (int step = 0; step < 300; ++step) {
      Voigt6 de;
      for (int i = 0; i < 6; ++i) de[i] = 3e-3 * n(rng);
      const Matrix3d q = random_rotation(rng);
      Voigt6 rotated = rotate_stress(q, s);
      const double e1 = model.update(s, de);
      const double e2 = model.update(rotated, rotate_strain(q, de));
      const double scale = std::max(max_abs(s), 10 * kPa);
      EXPECT_LE((rotate_stress(q, s) - rotated).cwiseAbs().maxCoeff(), 1e-9 * scale);
      EXPECT_NEAR(e1, e2, 1e-9 * std::max(e1, 1e-6));
      plastic += e1 > 0;
    }
    EXPECT_GT(plastic, 50);
  }
  // (b) plane strain (fast path) against the same path seen in a rotated frame, where the
  // out-of-plane shears are non-zero (general 3D path). Compared step by step.
  {
    const Matrix3d q = random_rotation(rng);
    Voigt6 s2 = diagonal(-60 * kPa, -90 * kPa, -75 * kPa);
    Voigt6 s3 = rotate_stress(q, s2);
    int plastic = 0;
    for (int step = 0; step < 300; ++step) {
      Voigt6 de = Voigt6::Zero();
      // Shear with some compaction, so the state keeps coming back to the yield surface.
      de[0] = 3e-3 * n(rng) - 5e-4, de[1] = 3e-3 * n(rng) - 5e-4, de[3] = 3e-3 * (n(rng) + 1);
      const double e2 = model.update(s2, de);
      const double e3 = model.update(s3, rotate_strain(q, de));
      plastic += e2 > 0;
      ASSERT_EQ(s2[4], 0.0);
      ASSERT_EQ(s2[5], 0.0);
      const double scale = std::max(max_abs(s2), 10 * kPa);
      EXPECT_LE((rotate_stress(q, s2) - s3).cwiseAbs().maxCoeff(), 1e-9 * scale);
      EXPECT_NEAR(e2, e3, 1e-9 * std::max(e2, 1e-6));
    }
    EXPECT_GT(plastic, 50);  // the path does exercise the return mapping
  }
}

// Random walk through stress space for several parameter sets: after every update the stress
// is admissible (f <= 1e-9 of the stress magnitude, principal stresses <= cut-off), elastic
// steps are exact Hooke, and an update with a zero increment changes nothing.
TEST(MohrCoulomb, RandomIncrementsAlwaysAdmissible) {
  struct Material {
    double phi, psi, c, st;
  };
  const Material materials[] = {
      {30, 0, 0, 0},                // cohesionless sand
      {40, 40, 0, kInf},            // associated, cut-off at the apex (= 0)
      {35, 10, 20 * kPa, 5 * kPa},  // cut-off below the apex
      {25, 5, 10 * kPa, kInf},      // cut-off at the apex c cot(phi)
      {0, 0, 50 * kPa, kInf},       // Tresca, no cut-off
      {0, 0, 50 * kPa, 20 * kPa},   // Tresca with cut-off
      {20, 0, 10 * kPa, 0},         // cohesive, zero tensile strength
  };
  std::mt19937 rng(2023);
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const Material& mat : materials) {
    const MohrCoulomb model(10e6, 0.3, mat.phi, mat.psi, mat.c, mat.st);
    const double apex = mat.phi > 0 ? mat.c / std::tan(mat.phi * kDeg) : kInf;
    const double cutoff = std::min(mat.st, apex);
    for (int plane = 0; plane < 2; ++plane) {
      Voigt6 s = Voigt6::Zero();
      int plastic = 0;
      for (int step = 0; step < 4000; ++step) {
        Voigt6 de;
        // Mixture of small and large increments, biased to compression or tension at times.
        const double size = std::pow(10.0, -5 + 3 * (0.5 + 0.5 * u(rng)));
        const double bias = step % 7 == 0 ? 3 * u(rng) : 0;
        for (int i = 0; i < 6; ++i) de[i] = size * (n(rng) + (i < 3 ? bias : 0));
        if (plane) de[2] = de[4] = de[5] = 0;
        if (step % 500 == 0) s = Voigt6::Zero();  // restart from the stress-free state
        Voigt6 trial = s;
        lituya::solver::elastic_update(model.elastic(), trial, de);
        const double eps_p = model.update(s, de);
        const double scale = std::max({max_abs(trial), max_abs(s), mat.c, 1.0});
        const double f = model.yield_function(s);
        ASSERT_LE(f, 1e-9 * scale) << "material phi " << mat.phi << " step " << step;
        ASSERT_LE(principal(s)[0], cutoff + 1e-9 * scale);
        ASSERT_GE(eps_p, 0.0);
        if (plane) {
          ASSERT_TRUE(s[4] == 0.0 && s[5] == 0.0);
        }
        if (eps_p == 0.0) {
          EXPECT_LE((s - trial).cwiseAbs().maxCoeff(), 1e-12 * scale);
        } else {
          // A plastic state lies on the yield surface or on the cut-off.
          ++plastic;
          const double on_surface = std::min(std::abs(f), std::abs(principal(s)[0] - cutoff));
          EXPECT_LE(on_surface, 1e-9 * scale) << "phi " << mat.phi << " step " << step;
        }
        Voigt6 again = s;
        model.update(again, Voigt6::Zero());
        ASSERT_LE((again - s).cwiseAbs().maxCoeff(), 1e-9 * scale);
      }
      EXPECT_GT(plastic, 200) << "phi " << mat.phi;
    }
  }
}

// With psi = phi the return is the closest admissible point in the energy norm, which fixes
// the return region (plane, edge, apex, cut-off) independently of how the code picks it:
// (t - r)^T D^-1 (y - r) <= 0 for every admissible y (principal values, sorted).
TEST(MohrCoulomb, AssociatedReturnIsTheClosestPointInEnergyNorm) {
  struct Material {
    double phi, c, st;
  };
  const Material materials[] = {{30, 0, 0},
                                {35, 20 * kPa, 5 * kPa},
                                {25, 10 * kPa, kInf},
                                {0, 50 * kPa, 20 * kPa},
                                {0, 50 * kPa, kInf}};
  std::mt19937 rng(43);
  std::normal_distribution<double> n(0, 1);
  for (const Material& mat : materials) {
    const MohrCoulomb model(10e6, 0.3, mat.phi, mat.phi, mat.c, mat.st);
    const Reference ref(10e6, 0.3, mat.phi, mat.phi, mat.c);
    const double cutoff = std::min(mat.st, mat.phi > 0 ? mat.c / std::tan(mat.phi * kDeg) : kInf);
    const Matrix3d compliance = ref.d().inverse();
    int plastic = 0;
    for (int k = 0; k < 300; ++k) {
      const double size = 100 * kPa;
      const Voigt6 trial = rotate_stress(random_rotation(rng),
                                         diagonal(size * n(rng), size * n(rng), size * n(rng)));
      Voigt6 s = trial;
      if (model.update(s, Voigt6::Zero()) == 0) continue;
      ++plastic;
      const Vector3d t = principal(trial), r = principal(s);
      const Vector3d w = compliance * (t - r);
      for (int j = 0; j < 200; ++j) {
        Vector3d y(size * n(rng), size * n(rng), size * n(rng));
        std::sort(y.data(), y.data() + 3, std::greater<>());
        if (ref.f(y, 0, 2) > 0 || y[0] > cutoff) continue;
        ASSERT_LE(w.dot(y - r), 1e-9 * w.norm() * size) << "phi " << mat.phi;
      }
    }
    EXPECT_GT(plastic, 50);
  }
}

TEST(MohrCoulomb, TrescaAndCohesionlessFromZeroStress) {
  const double e = 10e6, nu = 0.3;
  // Compressive strain with a deviatoric part (axial -2e-3, lateral 5e-4): tr = -1e-3.
  const Voigt6 compress = diagonal(5e-4, 5e-4, -2e-3);
  std::mt19937 rng(37);
  const Matrix3d q = random_rotation(rng);
  for (const Matrix3d& rot : {Matrix3d(Matrix3d::Identity()), q}) {
    // Tresca (phi = 0), c = 5 kPa: triaxial-compression edge, isochoric flow keeps the mean
    // stress p = K eps_v: s1 = s2 = p + 2c/3, s3 = p - 4c/3.
    {
      const double c = 5 * kPa;
      const MohrCoulomb model(e, nu, 0, 0, c, kInf);
      const double bulk = model.elastic().lame_lambda + 2.0 / 3.0 * model.elastic().shear_modulus;
      const double p = bulk * -1e-3;
      Voigt6 s = Voigt6::Zero();
      EXPECT_GT(model.update(s, rotate_strain(rot, compress)), 0);
      const Vector3d got = principal(s);
      EXPECT_NEAR(got[0], p + 2 * c / 3, 1e-9 * 1e4 * kPa);
      EXPECT_NEAR(got[1], p + 2 * c / 3, 1e-9 * 1e4 * kPa);
      EXPECT_NEAR(got[2], p - 4 * c / 3, 1e-9 * 1e4 * kPa);
    }
    // Cohesionless sand, phi = 30, psi = 0: on the edge s1 = s2 with s3 = 3 s1 and the mean
    // stress kept: s1 = 3 p / 5, s3 = 9 p / 5.
    {
      const MohrCoulomb model(e, nu, 30, 0, 0, 0);
      const double bulk = model.elastic().lame_lambda + 2.0 / 3.0 * model.elastic().shear_modulus;
      const double p = bulk * -1e-3;
      Voigt6 s = Voigt6::Zero();
      EXPECT_GT(model.update(s, rotate_strain(rot, compress)), 0);
      const Vector3d got = principal(s);
      EXPECT_NEAR(got[0], 0.6 * p, 1e-9 * 1e4 * kPa);
      EXPECT_NEAR(got[1], 0.6 * p, 1e-9 * 1e4 * kPa);
      EXPECT_NEAR(got[2], 1.8 * p, 1e-9 * 1e4 * kPa);
      // Pure shear from zero stress: no strength at zero pressure, back to exactly zero... up
      // to roundoff, and admissible.
      s = Voigt6::Zero();
      Voigt6 shear = Voigt6::Zero();
      shear[3] = 1e-3;
      model.update(s, rotate_strain(rot, shear));
      EXPECT_LE(max_abs(s), 1e-9 * 1e4 * kPa);
      EXPECT_LE(model.yield_function(s), 1e-9 * 1e4 * kPa);
    }
    // phi = 0 and c = 0 (no strength at all): the stress becomes isotropic, p = K eps_v.
    {
      const MohrCoulomb model(e, nu, 0, 0, 0, kInf);
      const double bulk = model.elastic().lame_lambda + 2.0 / 3.0 * model.elastic().shear_modulus;
      Voigt6 s = Voigt6::Zero();
      model.update(s, rotate_strain(rot, compress));
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(s[i], bulk * -1e-3, 1e-9 * 1e4 * kPa);
      for (int i = 3; i < 6; ++i) EXPECT_NEAR(s[i], 0, 1e-9 * 1e4 * kPa);
    }
  }
}

// A NaN or inf strain increment (or stress) must give a non-finite stress: the solver detects
// a broken step by the stress alone. Before the check in update(), the return mapping's
// comparisons were all false for NaN and it returned a finite stress (e.g. the apex).
TEST(MohrCoulomb, NonFiniteInputGivesANonFiniteStress) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const MohrCoulomb models[] = {
      MohrCoulomb(10e6, 0.3, 30, 0, 0, 0),                // cohesionless: cut-off at the apex
      MohrCoulomb(10e6, 0.3, 30, 10, 10 * kPa, kInf),     // no cut-off
      MohrCoulomb(10e6, 0.3, 30, 10, 10 * kPa, 2 * kPa),  // cut-off below the apex
      MohrCoulomb(10e6, 0.0, 0, 0, 10 * kPa, kInf)};      // Tresca, lambda = 0
  const Voigt6 starts[] = {diagonal(-100 * kPa, -120 * kPa, -80 * kPa), Voigt6::Zero()};
  for (const MohrCoulomb& model : models) {
    for (const Voigt6& start : starts) {
      for (int k = 0; k < 6; ++k) {  // k < 4 keeps yz = xz = 0: the plane strain fast path
        for (double bad : {nan, kInf, -kInf}) {
          Voigt6 de;
          de << -1e-3, 2e-4, 0, 5e-4, 0, 0;  // plastic for every model
          de[k] = bad;
          Voigt6 s = start;
          const double plastic = model.update(s, de);
          EXPECT_FALSE(s.allFinite()) << "component " << k << " = " << bad << ": " << s.transpose();
          EXPECT_TRUE(std::isnan(plastic)) << "component " << k << " = " << bad;
          Voigt6 broken = start;  // a stress that is already broken stays broken
          broken[k] = bad;
          de[k] = 0;
          model.update(broken, de);
          EXPECT_FALSE(broken.allFinite()) << "stress component " << k << " = " << bad;
        }
      }
    }
  }
}

TEST(PrincipalStresses, AccurateForRepeatedValues) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 2000; ++k) {
    const Matrix3d q = random_rotation(rng);
    // Two values equal or within 1e-13 ... 1e-3 of each other, and an offset mean.
    const double gap = std::pow(10.0, -13 + 10 * (0.5 + 0.5 * u(rng)));
    const double split = (k % 3 == 0) ? 0.0 : gap;
    Vector3d lam(u(rng), 0, 0);
    lam[1] = lam[0] + split;
    lam[2] = u(rng);
    lam.array() += 5 * u(rng);
    const Voigt6 s = stress_voigt(q * lam.asDiagonal() * q.transpose());
    Vector3d values;
    Matrix3d vectors;
    lituya::solver::principal_decomposition(s, values, vectors);
    Vector3d sorted = lam;
    std::sort(sorted.data(), sorted.data() + 3, std::greater<>());
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(values[i], sorted[i], 1e-14 * 8);
    EXPECT_LE((vectors.transpose() * vectors - Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-14);
    const Matrix3d back = vectors * values.asDiagonal() * vectors.transpose();
    EXPECT_LE((back - stress_tensor(s)).cwiseAbs().maxCoeff(), 1e-14 * 8);
    // The fast closed form: exact enough away from repeated values only.
    const Vector3d fast = lituya::solver::principal_values_fast(s);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(fast[i], sorted[i], 1e-7);
  }
  // No over- or underflow for extreme magnitudes (the deviator is scaled internally).
  for (double magnitude : {1e-200, 1e200}) {
    const Matrix3d q = random_rotation(rng);
    const Vector3d lam(3 * magnitude, magnitude, magnitude);
    const Voigt6 s = stress_voigt(q * lam.asDiagonal() * q.transpose());
    Vector3d values;
    Matrix3d vectors;
    lituya::solver::principal_decomposition(s, values, vectors);
    EXPECT_NEAR(values[0] / magnitude, 3, 1e-14);
    EXPECT_NEAR(values[1] / magnitude, 1, 1e-14);
    EXPECT_NEAR(values[2] / magnitude, 1, 1e-14);
    EXPECT_NEAR(std::abs(vectors.col(0).dot(q.col(0))), 1, 1e-14);
  }
}

}  // namespace
