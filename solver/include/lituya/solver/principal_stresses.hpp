#pragma once
// Principal values and directions of a symmetric stress tensor in Voigt order
// [xx, yy, zz, xy, yz, xz] (true tensor components, not engineering shears). Header-only
// because these are called per material point per time step from the Mohr-Coulomb update
// (return mapping in principal stresses, eqs. (19)-(22) of the reference paper).
//
// Closed forms only (no iterations, no allocation):
//  - solve_deviatoric_cubic / principal_values_fast: trigonometric solution of the
//    characteristic cubic of the deviator. Cheap, but near a repeated principal value the
//    cubic is ill-conditioned and the pair of close values carries an error up to ~1e-8 of
//    the deviatoric magnitude. Used to decide quickly, with a safety margin, that a trial
//    stress is inside the yield surface.
//  - principal_decomposition: values and directions, accurate to machine precision also for
//    repeated principal stresses (the states on the edges of the Mohr-Coulomb pyramid are
//    exactly that): the simple root of the cubic and its direction, then Mohr's circle in the
//    orthogonal plane. Eigen's SelfAdjointEigenSolver::computeDirect is the same kind of
//    closed form but keeps the cubic's ~1e-8 error on a close pair (which would leave stress
//    states off the yield surface by more than 1e-9) and measured 2x slower here
//    (computeDirect ~105 ns vs ~50 ns for this one, values and vectors).
//  - principal_values: Mohr's circle when yz = xz = 0 (zz is then principal), otherwise
//    principal_decomposition.
#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lituya::solver {

// Closed-form (trigonometric) solution of the characteristic cubic of the deviator. An
// extremely small or large deviator is scaled by its largest entry so that nothing over- or
// underflows in the cubes and the cross products below.
struct DeviatoricCubic {
  double mean = 0;              // I1 / 3
  double scale = 0;             // 1, or max |deviator entry| if extreme; 0 if isotropic
  double dev[6] = {};           // deviator / scale, Voigt order
  double e[3] = {};             // deviatoric principal values / scale, descending
  bool top_is_distinct = true;  // e[0] is further from e[1] than e[2] is
  double value(int i) const { return mean + scale * e[i]; }
};

inline DeviatoricCubic solve_deviatoric_cubic(const Eigen::Matrix<double, 6, 1>& s) {
  DeviatoricCubic c;
  c.mean = (s[0] + s[1] + s[2]) / 3.0;
  double* d = c.dev;
  d[0] = s[0] - c.mean, d[1] = s[1] - c.mean, d[2] = s[2] - c.mean;
  d[3] = s[3], d[4] = s[4], d[5] = s[5];
  const double largest = std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2]), std::abs(d[3]),
                                   std::abs(d[4]), std::abs(d[5])});
  if (!(largest > 0.0)) return c;  // isotropic: scale = 0, e = 0
  // Fourth powers appear below (squared norms of cross products): rescale only outside a
  // range that is safe for them, so that ordinary stresses do not pay for a division.
  if (largest > 1e-60 && largest < 1e60) {
    c.scale = 1.0;
  } else {
    c.scale = largest;
    const double inv_scale = 1.0 / largest;
    for (double& x : c.dev) x *= inv_scale;
  }
  const double j2 =
      0.5 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + d[3] * d[3] + d[4] * d[4] + d[5] * d[5];
  const double j3 = d[0] * d[1] * d[2] + 2.0 * d[3] * d[4] * d[5] - d[0] * d[4] * d[4] -
                    d[1] * d[5] * d[5] - d[2] * d[3] * d[3];
  // Deviatoric principal values 2 r cos(theta - 2 pi k / 3), r = sqrt(J2 / 3), with
  // cos(3 theta) = J3 / (2 r^3), theta in [0, pi / 3].
  const double r = std::sqrt(j2 / 3.0);
  const double cos3 = std::clamp(j3 / (2.0 * r * r * r), -1.0, 1.0);
  const double theta = std::acos(cos3) / 3.0;
  const double ct = std::cos(theta), st = std::sin(theta);
  const double sqrt3 = 1.7320508075688772;
  c.e[0] = 2.0 * r * ct;
  c.e[1] = -r * (ct - sqrt3 * st);
  c.e[2] = -r * (ct + sqrt3 * st);
  c.top_is_distinct = c.e[0] - c.e[1] >= c.e[1] - c.e[2];
  return c;
}

// Principal values, descending (s[0] >= s[1] >= s[2]), closed-form cubic. See the header
// comment for the accuracy near repeated values.
inline Eigen::Vector3d principal_values_fast(const Eigen::Matrix<double, 6, 1>& s) {
  const DeviatoricCubic c = solve_deviatoric_cubic(s);
  return {c.value(0), c.value(1), c.value(2)};
}

// Principal values (descending) and unit principal directions (columns of `vectors`, in the
// same order, orthonormal to machine precision) from the cubic's solution.
//
// The value furthest from the other two is accurate from the cubic (a simple root), and so is
// its direction, the kernel of the rank-2 matrix (dev - e I): the cross product of two of its
// rows. The other two follow from the 2x2 block of the deviator in the plane orthogonal to
// it, by Mohr's circle, which stays accurate when they are close or equal (where the cubic
// loses half the digits, and Eigen's computeDirect with it).
inline void principal_decomposition(const DeviatoricCubic& c, Eigen::Vector3d& values,
                                    Eigen::Matrix3d& vectors) {
  using Eigen::Vector3d;
  if (!(c.scale > 0.0)) {
    values.setConstant(c.mean);
    vectors.setIdentity();
    return;
  }
  const double* d = c.dev;
  const double ed = c.top_is_distinct ? c.e[0] : c.e[2];
  const Vector3d r0(d[0] - ed, d[3], d[5]), r1(d[3], d[1] - ed, d[4]), r2(d[5], d[4], d[2] - ed);
  // Kernel: the largest of the three cross products of the rows.
  const Vector3d c01 = r0.cross(r1), c02 = r0.cross(r2), c12 = r1.cross(r2);
  const double n01 = c01.squaredNorm(), n02 = c02.squaredNorm(), n12 = c12.squaredNorm();
  Vector3d vd;
  if (n01 >= n02 && n01 >= n12) {
    vd = c01 * (1.0 / std::sqrt(n01));
  } else if (n02 >= n12) {
    vd = c02 * (1.0 / std::sqrt(n02));
  } else {
    vd = c12 * (1.0 / std::sqrt(n12));
  }
  // The plane orthogonal to vd: the largest row of (dev - e I), orthogonal to its kernel to
  // roundoff (the rows span the range of a symmetric matrix), so no re-orthogonalisation and
  // the two normalisations are independent.
  const double m0 = r0.squaredNorm(), m1 = r1.squaredNorm(), m2 = r2.squaredNorm();
  const Vector3d u = (m0 >= m1 && m0 >= m2) ? Vector3d(r0 * (1.0 / std::sqrt(m0)))
                                            : (m1 >= m2 ? Vector3d(r1 * (1.0 / std::sqrt(m1)))
                                                        : Vector3d(r2 * (1.0 / std::sqrt(m2))));
  const Vector3d w = vd.cross(u);
  // Deviator times a vector.
  auto apply = [d](const Vector3d& x) {
    return Vector3d(d[0] * x[0] + d[3] * x[1] + d[5] * x[2],
                    d[3] * x[0] + d[1] * x[1] + d[4] * x[2],
                    d[5] * x[0] + d[4] * x[1] + d[2] * x[2]);
  };
  const Vector3d du = apply(u), dw = apply(w);
  const double a = u.dot(du), b = u.dot(dw), g = w.dot(dw);
  const double lambda_d = vd.dot(apply(vd));
  // Mohr's circle of the 2x2 block [[a, b], [b, g]] in the (u, w) basis.
  const double centre = 0.5 * (a + g), half = 0.5 * (a - g);
  const double radius = std::sqrt(half * half + b * b);
  // Direction of the larger value at angle t from u: cos 2t = half / radius, sin 2t = b / radius,
  // computed with the half-angle formula on the well-conditioned side.
  double ct = 1.0, st = 0.0;
  if (radius > 0) {
    const double inv_radius = 1.0 / radius;
    const double cos2 = half * inv_radius, sin2 = b * inv_radius;
    if (cos2 >= 0) {
      ct = std::sqrt(0.5 * (1 + cos2));
      st = 0.5 * sin2 / ct;
    } else {
      st = std::copysign(std::sqrt(0.5 * (1 - cos2)), sin2);
      ct = 0.5 * sin2 / st;
    }
  }
  const Vector3d v_hi = ct * u + st * w, v_lo = -st * u + ct * w;
  if (c.top_is_distinct) {
    values = Vector3d(lambda_d, centre + radius, centre - radius) * c.scale;
    vectors.col(0) = vd;
    vectors.col(1) = v_hi;
    vectors.col(2) = v_lo;
  } else {
    values = Vector3d(centre + radius, centre - radius, lambda_d) * c.scale;
    vectors.col(0) = v_hi;
    vectors.col(1) = v_lo;
    vectors.col(2) = vd;
  }
  values.array() += c.mean;
}

inline void principal_decomposition(const Eigen::Matrix<double, 6, 1>& s, Eigen::Vector3d& values,
                                    Eigen::Matrix3d& vectors) {
  principal_decomposition(solve_deviatoric_cubic(s), values, vectors);
}

// Principal values, descending, accurate to machine precision.
inline Eigen::Vector3d principal_values(const Eigen::Matrix<double, 6, 1>& s) {
  if (s[4] == 0.0 && s[5] == 0.0) {
    // zz is a principal direction; the in-plane pair from Mohr's circle.
    const double c = 0.5 * (s[0] + s[1]);
    const double radius = std::hypot(0.5 * (s[0] - s[1]), s[3]);
    double v[3] = {c + radius, c - radius, s[2]};
    if (v[1] < v[2]) std::swap(v[1], v[2]);
    if (v[0] < v[1]) std::swap(v[0], v[1]);
    return {v[0], v[1], v[2]};
  }
  Eigen::Vector3d values;
  Eigen::Matrix3d vectors;
  principal_decomposition(s, values, vectors);
  return values;
}

}  // namespace lituya::solver
