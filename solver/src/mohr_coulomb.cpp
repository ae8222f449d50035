// Linear elasticity and Mohr-Coulomb elasto-plasticity with non-associated flow and a tension
// cut-off, eqs. (19)-(22) of the reference paper (Zhao et al., Water 2023, section 2.3).
//
// Conventions: Voigt order [xx, yy, zz, xy, yz, xz], stresses tension positive, strain
// increments with engineering shears. Principal stresses are sorted s1 >= s2 >= s3, so s1 is
// the most tensile and s3 the most compressive one.
//
// Yield function. The paper writes eq. (21) with compression negative and s1 <= s2 <= s3:
//   f_paper = 1/2 (s1 - s3) - 1/2 (s1 + s3) sin(phi) + c cos(phi).
// Renaming its s1 <-> s3 to our descending order and multiplying by -2 gives the usual
// tension-positive form used here (f <= 0 admissible, both vanish on the same surface):
//   f = (s1 - s3) + (s1 + s3) sin(phi) - 2 c cos(phi) = a . s - 2 c cos(phi),
//   a = (1 + sin(phi), 0, -(1 - sin(phi))).
// The plastic potential eq. (22) becomes g = (s1 - s3) + (s1 + s3) sin(psi) (same scaling), so
// the flow direction of eq. (20) on the main plane is b = dg/ds = (1 + sin(psi), 0,
// -(1 - sin(psi))). With psi < phi the flow is non-associated (b != a).
//
// Return mapping (eq. 19 integrated over the step with the elastic predictor
// s_trial = s + D : d_eps): the trial stress is decomposed into principal values t (the
// principal directions do not change during the return because D is isotropic and the flow
// directions are coaxial), then s = t - D sum_i dl_i b_i, dl_i >= 0, for the active planes
// i. In principal space with isotropic elasticity D b = lambda tr(b) (1,1,1) + 2 G b, and all
// planes are linear, so every return is a 1x1, 2x2 or closed-form vertex solve.
//
// Planes, in the sextant s1 >= s2 >= s3 (a_j the gradient, b_j the flow vector):
//   F1: s1 vs s3 (the main plane)     a1 = (1+sf, 0, -(1-sf)),  b1 = (1+sp, 0, -(1-sp))
//   F2: s2 vs s3 (active on s1 = s2)  a2 = (0, 1+sf, -(1-sf)),  b2 = (0, 1+sp, -(1-sp))
//   F3: s1 vs s2 (active on s2 = s3)  a3 = (1+sf, -(1-sf), 0),  b3 = (1+sp, -(1-sp), 0)
//   R1, R2, R3: s_i <= sigma_t, the tension cut-off (Rankine planes, associated flow e_i).
// sf = sin(phi), sp = sin(psi). F2 and F3 are the Mohr-Coulomb planes of the neighbouring
// sextants; using them on the edges is Koiter's rule for the corners of the pyramid.
//
// Tension cut-off. sigma_t = min(tensile_strength, c cot(phi)) (for phi = 0 there is no apex
// and sigma_t is the given value, possibly +inf = no cut-off). It is combined with the
// Mohr-Coulomb return (not applied afterwards), so the result satisfies both criteria and
// the discrete consistency conditions exactly. When sigma_t equals the apex value (always
// the case for c = 0: sigma_t = 0), the Rankine planes only touch the pyramid at its apex
// and merely widen the set of plastic flows there; that is what makes the apex return exist
// for psi = 0 (isochoric Mohr-Coulomb flow cannot absorb a volumetric tensile trial).
//
// Which return? Candidate active sets are tried in a fixed order, cheapest and most frequent
// first, and the first one satisfying the discrete Kuhn-Tucker conditions is taken:
// multipliers (or vertex flow cone coefficients) >= 0, and the result admissible and still
// ordered s1 >= s2 >= s3. The candidates' regions (face, edge and vertex "return regions"
// bounded by the planes spanned by the edges and the flow directions D b, as in Clausen,
// Damkilde & Andersen 2006/2007) tile the space outside the admissible set, so one candidate
// passes; on region boundaries neighbouring candidates give the same stress. For psi = phi
// the result is the closest admissible point in the energy norm (checked in the tests).
// Trying candidates instead of computing the boundary planes first costs a few extra flops
// for edge and vertex returns only, and needs no special case for phi = 0 or c = 0. Order:
//   1. main plane F1                      (1 multiplier)
//   2. edge s1 = s2: F1 + F2              (triaxial compression meridian, 2x2)
//   3. edge s2 = s3: F1 + F3              (triaxial extension meridian, 2x2)
//   with a cut-off below the apex:
//   4. Rankine plane R1                   (1 multiplier)
//   5. edge F1 + R1                       (2x2)
//   6. edge R1 + R2                       (2x2)
//   7. vertices (st, st, s3c) [F1 F2 R1 R2], (st, s3c, s3c) [F1 F3 R1], (st, st, st) [R1 R2 R3]
//      where s3c is s3 on F1 for s1 = st: the stress is known, only the flow cone is checked.
//   with the cut-off at the apex:
//   8. apex (st, st, st): all six Mohr-Coulomb planes and the three Rankine planes active.
// If roundoff makes every candidate miss by more than the tolerance, the one with the
// smallest violation is used.
#include "lituya/solver/mohr_coulomb.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "lituya/solver/principal_stresses.hpp"

namespace lituya::solver {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
// Relative tolerance of the Kuhn-Tucker checks of the return candidates (scaled by the
// stress magnitude). Candidates are closed-form, so their roundoff is a few ulps times the
// condition of D (lambda / G); 1e-10 leaves room for nearly incompressible settings while
// keeping the returned stress on the surface well within 1e-9 of the stress magnitude.
constexpr double kReturnTolerance = 1e-10;
// The trigonometric principal values used for the quick elastic check in 3D can be off by
// ~1e-8 sqrt(J2) near repeated values; trial states closer than this margin to the yield or
// cut-off surfaces take the accurate decomposition instead.
constexpr double kFastCheckMargin = 1e-6;

double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
}  // namespace

double rough_wall_friction(double friction_angle_deg, double dilatancy_angle_deg) {
  const double deg = std::numbers::pi / 180;
  const double sin_phi = std::sin(friction_angle_deg * deg);
  const double sin_psi = std::sin(dilatancy_angle_deg * deg);
  const double cos_psi = std::cos(dilatancy_angle_deg * deg);
  return sin_phi * cos_psi / (1.0 - sin_phi * sin_psi);
}

ElasticConstants ElasticConstants::from_young_poisson(double youngs_modulus, double poisson_ratio) {
  if (!(youngs_modulus > 0) || !(poisson_ratio > -1 && poisson_ratio < 0.5)) {
    throw std::invalid_argument(
        "elastic constants: need Young's modulus > 0 and -1 < Poisson's ratio < 0.5, got E = " +
        std::to_string(youngs_modulus) + ", nu = " + std::to_string(poisson_ratio));
  }
  ElasticConstants c;
  c.shear_modulus = youngs_modulus / (2 * (1 + poisson_ratio));
  c.lame_lambda = youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
  return c;
}

void elastic_update(const ElasticConstants& elastic, Voigt6& stress,
                    const Voigt6& strain_increment) {
  // Isotropic Hooke's law, eq. (19) with d_eps_p = 0: d_sigma = lambda tr(d_eps) I + 2 G d_eps;
  // the shear entries are engineering strains, hence G (not 2 G) times gamma.
  const double g = elastic.shear_modulus;
  const double volumetric =
      elastic.lame_lambda * (strain_increment[0] + strain_increment[1] + strain_increment[2]);
  stress[0] += volumetric + 2 * g * strain_increment[0];
  stress[1] += volumetric + 2 * g * strain_increment[1];
  stress[2] += volumetric + 2 * g * strain_increment[2];
  stress[3] += g * strain_increment[3];
  stress[4] += g * strain_increment[4];
  stress[5] += g * strain_increment[5];
}

MohrCoulomb::MohrCoulomb(double youngs_modulus, double poisson_ratio, double friction_angle_deg,
                         double dilatancy_angle_deg, double cohesion, double tensile_strength)
    : elastic_(ElasticConstants::from_young_poisson(youngs_modulus, poisson_ratio)) {
  if (!(friction_angle_deg >= 0 && friction_angle_deg < 90)) {
    throw std::invalid_argument("Mohr-Coulomb: friction angle must be in [0, 90) degrees, got " +
                                std::to_string(friction_angle_deg));
  }
  if (!(dilatancy_angle_deg >= 0 && dilatancy_angle_deg <= friction_angle_deg)) {
    throw std::invalid_argument(
        "Mohr-Coulomb: dilatancy angle must be in [0, friction angle] degrees, got " +
        std::to_string(dilatancy_angle_deg));
  }
  if (!(cohesion >= 0) || !(cohesion < kInf)) {
    throw std::invalid_argument("Mohr-Coulomb: cohesion must be finite and >= 0, got " +
                                std::to_string(cohesion));
  }
  if (!(tensile_strength >= 0)) {  // +inf allowed: no cut-off beyond the apex
    throw std::invalid_argument("Mohr-Coulomb: tensile strength must be >= 0, got " +
                                std::to_string(tensile_strength));
  }
  const double deg = std::numbers::pi / 180;
  sin_phi_ = std::sin(friction_angle_deg * deg);
  cos_phi_ = std::cos(friction_angle_deg * deg);
  sin_psi_ = std::sin(dilatancy_angle_deg * deg);
  cohesion_ = cohesion;
  two_c_cos_phi_ = 2 * cohesion * cos_phi_;

  // Apex of the pyramid at s1 = s2 = s3 = c cot(phi); none for phi = 0 (Tresca prism), where
  // writing c cot(phi) would divide by zero (or give 0 * inf for c = 0).
  const double apex = sin_phi_ > 0 ? cohesion * cos_phi_ / sin_phi_ : kInf;
  if (apex < kInf && tensile_strength >= apex * (1 - 1e-12)) {
    cutoff_ = Cutoff::at_apex;
    tensile_strength_ = apex;
  } else if (tensile_strength < kInf) {
    cutoff_ = Cutoff::below_apex;
    tensile_strength_ = tensile_strength;
    // F1 = 0 with s1 = sigma_t: sigma_t (1 + sf) - s3 (1 - sf) = 2 c cos(phi).
    s3_corner_ = (tensile_strength_ * (1 + sin_phi_) - two_c_cos_phi_) / (1 - sin_phi_);
  } else {
    cutoff_ = Cutoff::none;
    tensile_strength_ = kInf;
  }

  // D b_j = lambda tr(b_j) (1, 1, 1) + 2 G b_j and the couplings a_i . D b_j. By symmetry
  // a1.Db1 = a2.Db2 = a3.Db3 = m, a1.Db2 = a2.Db1 = n12, a1.Db3 = a3.Db1 = n13.
  const double g = elastic_.shear_modulus, lambda = elastic_.lame_lambda;
  const double sf = sin_phi_, sp = sin_psi_;
  const double b1[3] = {1 + sp, 0, -(1 - sp)};
  const double b2[3] = {0, 1 + sp, -(1 - sp)};
  const double b3[3] = {1 + sp, -(1 - sp), 0};
  const double a1[3] = {1 + sf, 0, -(1 - sf)};
  const double volumetric = lambda * 2 * sp;  // lambda tr(b_j), the same for all j
  for (int i = 0; i < 3; ++i) {
    db1_[i] = volumetric + 2 * g * b1[i];
    db2_[i] = volumetric + 2 * g * b2[i];
    db3_[i] = volumetric + 2 * g * b3[i];
  }
  m_ = dot3(a1, db1_);
  n12_ = dot3(a1, db2_);
  n13_ = dot3(a1, db3_);
  // F1 + R1 edge: a1 . D e1 and the determinant of [[m, a1.De1], [Db1_1, lambda + 2G]],
  // which equals 4 G (lambda + G)(1 - sf)(1 - sp) > 0.
  a1_de1_ = (1 + sf) * (lambda + 2 * g) - (1 - sf) * lambda;
  det_f1_r1_ = m_ * (lambda + 2 * g) - a1_de1_ * db1_[0];
  lambda_ratio_ = lambda / (3 * lambda + 2 * g);
}

double MohrCoulomb::yield_function(const Voigt6& stress) const {
  const Eigen::Vector3d s = principal_values(stress);
  const double sorted[3] = {s[0], s[1], s[2]};
  return yield_sorted(sorted);
}

double MohrCoulomb::equivalent_plastic_strain(const double t[3], const double r[3]) const {
  // d_eps_p = D^-1 (t - r) = (d - lambda / (3 lambda + 2 G) tr(d) I) / (2 G), principal values
  // of a tensor coaxial with the stress, so the tensor norm is the sum of their squares.
  const double d[3] = {t[0] - r[0], t[1] - r[1], t[2] - r[2]};
  const double iso = lambda_ratio_ * (d[0] + d[1] + d[2]);
  const double inv_2g = 0.5 / elastic_.shear_modulus;
  const double p0 = (d[0] - iso) * inv_2g, p1 = (d[1] - iso) * inv_2g, p2 = (d[2] - iso) * inv_2g;
  return std::sqrt(2.0 / 3.0 * (p0 * p0 + p1 * p1 + p2 * p2));
}

void MohrCoulomb::return_principal(const double t[3], double r[3]) const {
  const double g = elastic_.shear_modulus, lambda = elastic_.lame_lambda;
  const double a_mod = lambda + 2 * g;  // (D e_i)_i
  const double sf = sin_phi_, sp = sin_psi_, st = tensile_strength_;
  const double f1 = yield_sorted(t);

  double scale = std::max({std::abs(t[0]), std::abs(t[2]), two_c_cos_phi_});
  if (cutoff_ != Cutoff::none) scale = std::max(scale, std::abs(st));
  const double tol = kReturnTolerance * scale;

  // Kuhn-Tucker check of a candidate x (sorted principal stresses) whose multipliers or
  // flow-cone coefficients, scaled to stress units, have the smallest value `flow_min`.
  double best_violation = kInf;
  auto accept = [&](double x0, double x1, double x2, double flow_min) {
    const double x[3] = {x0, x1, x2};
    const double violation = std::max({-flow_min, x1 - x0, x2 - x1, yield_sorted(x), x0 - st});
    if (violation < best_violation) {
      best_violation = violation;
      r[0] = x0;
      r[1] = x1;
      r[2] = x2;
    }
    return violation <= tol;
  };

  if (f1 > 0) {
    // 1. Main plane: a1 . (t - dl D b1) = 2 c cos(phi)  =>  dl = f(t) / (a1 . D b1).
    {
      const double dl = f1 / m_;
      if (accept(t[0] - dl * db1_[0], t[1] - dl * db1_[1], t[2] - dl * db1_[2], 0)) return;
    }
    // 2. Edge s1 = s2 (triaxial compression in this tension-positive ordering): F1 = F2 = 0,
    //    [[m, n12], [n12, m]] (dl1, dl2) = (f1(t), f2(t)).
    {
      const double f2 = t[1] * (1 + sf) - t[2] * (1 - sf) - two_c_cos_phi_;
      const double det = m_ * m_ - n12_ * n12_;
      const double dl1 = (m_ * f1 - n12_ * f2) / det, dl2 = (m_ * f2 - n12_ * f1) / det;
      if (accept(t[0] - dl1 * db1_[0] - dl2 * db2_[0], t[1] - dl1 * db1_[1] - dl2 * db2_[1],
                 t[2] - dl1 * db1_[2] - dl2 * db2_[2], 2 * g * std::min(dl1, dl2)))
        return;
    }
    // 3. Edge s2 = s3 (triaxial extension): F1 = F3 = 0.
    {
      const double f3 = t[0] * (1 + sf) - t[1] * (1 - sf) - two_c_cos_phi_;
      const double det = m_ * m_ - n13_ * n13_;
      const double dl1 = (m_ * f1 - n13_ * f3) / det, dl3 = (m_ * f3 - n13_ * f1) / det;
      if (accept(t[0] - dl1 * db1_[0] - dl3 * db3_[0], t[1] - dl1 * db1_[1] - dl3 * db3_[1],
                 t[2] - dl1 * db1_[2] - dl3 * db3_[2], 2 * g * std::min(dl1, dl3)))
        return;
    }
  }

  // Plastic strain of a vertex return x, scaled by 2 G: q = 2 G D^-1 (t - x).
  auto vertex_flow = [&](const double x[3], double q[3]) {
    const double d[3] = {t[0] - x[0], t[1] - x[1], t[2] - x[2]};
    const double iso = lambda_ratio_ * (d[0] + d[1] + d[2]);
    for (int i = 0; i < 3; ++i) q[i] = d[i] - iso;
  };

  if (cutoff_ == Cutoff::at_apex) {
    // 8. Apex. The plastic strain q must lie in the cone spanned by the six Mohr-Coulomb flow
    //    vectors (1 + sp) e_i - (1 - sp) e_j and the Rankine flows e_i. Its dual cone is
    //    spanned by the vectors with entries in {rho, 1}, rho = (1 - sp) / (1 + sp), so q is
    //    in the cone iff rho sum(q_i > 0) + sum(q_i < 0) >= 0.
    const double x[3] = {st, st, st};
    double q[3];
    vertex_flow(x, q);
    const double rho = (1 - sp) / (1 + sp);
    double pos = 0, neg = 0;
    for (double qi : q) (qi > 0 ? pos : neg) += qi;
    if (accept(st, st, st, rho * pos + neg)) return;
    return;  // best candidate already in r
  }
  if (cutoff_ == Cutoff::none) return;  // Tresca prism without cut-off: candidates 1-3 cover it

  // Tension cut-off below the apex.
  // 4. Rankine plane R1: s1 = st, dl = (t1 - st) / (lambda + 2G); s2, s3 drop by lambda dl.
  {
    const double dl = (t[0] - st) / a_mod;
    if (accept(st, t[1] - lambda * dl, t[2] - lambda * dl, 2 * g * dl)) return;
  }
  // 5. Edge F1 + R1: s1 = st on the yield plane; flows b1 and e1,
  //    [[m, a1.De1], [(Db1)_1, lambda + 2G]] (dl_f, dl_r) = (f1(t), t1 - st).
  {
    const double rr = t[0] - st;
    const double dlf = (a_mod * f1 - a1_de1_ * rr) / det_f1_r1_;
    const double dlr = (m_ * rr - db1_[0] * f1) / det_f1_r1_;
    if (accept(st, t[1] - dlf * db1_[1] - dlr * lambda, t[2] - dlf * db1_[2] - dlr * lambda,
               2 * g * std::min(dlf, dlr)))
      return;
  }
  // 6. Edge R1 + R2: s1 = s2 = st, [[l + 2G, l], [l, l + 2G]] (dl1, dl2) = (t1 - st, t2 - st).
  {
    const double r1 = t[0] - st, r2 = t[1] - st;
    const double det = a_mod * a_mod - lambda * lambda;
    const double dl1 = (a_mod * r1 - lambda * r2) / det, dl2 = (a_mod * r2 - lambda * r1) / det;
    if (accept(st, st, t[2] - lambda * (dl1 + dl2), 2 * g * std::min(dl1, dl2))) return;
  }
  // 7. Vertices; the stress is fixed, check that q = 2G D^-1 (t - x) lies in the flow cone.
  {
    // (st, st, s3c), flows b1, b2, e1, e2: q = al1 b1 + al2 b2 + be1 e1 + be2 e2 needs
    // al1 + al2 = -q3 / (1 - sp) >= 0, q1 >= 0, q2 >= 0 and (al1 + al2)(1 + sp) <= q1 + q2.
    const double x[3] = {st, st, s3_corner_};
    double q[3];
    vertex_flow(x, q);
    const double al = -q[2] / (1 - sp);
    if (accept(x[0], x[1], x[2], std::min({q[0], q[1], al, q[0] + q[1] - al * (1 + sp)}))) return;
  }
  {
    // (st, s3c, s3c), flows b1, b3, e1: al1 = -q3 / (1 - sp), al3 = -q2 / (1 - sp),
    // be1 = q1 - (al1 + al3)(1 + sp), all >= 0.
    const double x[3] = {st, s3_corner_, s3_corner_};
    double q[3];
    vertex_flow(x, q);
    const double al1 = -q[2] / (1 - sp), al3 = -q[1] / (1 - sp);
    if (accept(x[0], x[1], x[2], std::min({al1, al3, q[0] - (al1 + al3) * (1 + sp)}))) return;
  }
  {
    // (st, st, st), flows e1, e2, e3: q >= 0.
    const double x[3] = {st, st, st};
    double q[3];
    vertex_flow(x, q);
    accept(st, st, st, std::min({q[0], q[1], q[2]}));
  }
}

double MohrCoulomb::update(Voigt6& stress, const Voigt6& strain_increment) const {
  // Elastic predictor: eq. (19) with the whole increment taken as elastic.
  Voigt6 trial = stress;
  elastic_update(elastic_, trial, strain_increment);
  // A NaN or inf in the stress or the increment leaves a NaN or inf in the trial stress. The
  // return mapping must not see it: its comparisons are all false for NaN, so it would skip
  // every candidate and return a finite stress (uninitialised or the apex), and the solver's
  // finiteness check, which looks at the stress, would miss the broken step. One check here
  // keeps the stress non-finite.
  if (!trial.allFinite()) {
    stress = trial;
    return std::numeric_limits<double>::quiet_NaN();
  }

  if (trial[4] == 0.0 && trial[5] == 0.0) {
    // Fast path (2D plane strain, or any state with yz = xz = 0): zz is a principal direction
    // and the in-plane pair comes from Mohr's circle, centre cn and radius rad.
    const double cn = 0.5 * (trial[0] + trial[1]);
    const double half_diff = 0.5 * (trial[0] - trial[1]);
    const double rad = std::sqrt(half_diff * half_diff + trial[3] * trial[3]);
    const double sa = cn + rad, sb = cn - rad, sz = trial[2];
    // Elastic check first: f only needs the extreme values (branch-free max / min).
    {
      const double extremes[3] = {std::max(sa, sz), 0.0, std::min(sb, sz)};
      if (yield_sorted(extremes) <= 0 && extremes[0] <= tensile_strength_) {
        stress = trial;
        return 0;
      }
    }
    double t[3];
    int z_position;  // where sz sits in the sorted triple
    if (sz >= sa) {
      t[0] = sz, t[1] = sa, t[2] = sb, z_position = 0;
    } else if (sz <= sb) {
      t[0] = sa, t[1] = sb, t[2] = sz, z_position = 2;
    } else {
      t[0] = sa, t[1] = sz, t[2] = sb, z_position = 1;
    }
    double r[3];
    return_principal(t, r);
    const double ra = z_position == 0 ? r[1] : r[0];
    const double rb = z_position == 2 ? r[1] : r[2];
    const double rz = r[z_position];
    // Same principal directions: in-plane angle 2 theta from the trial circle.
    const double cos2 = rad > 0 ? half_diff / rad : 1.0;
    const double sin2 = rad > 0 ? trial[3] / rad : 0.0;
    const double new_centre = 0.5 * (ra + rb), new_radius = 0.5 * (ra - rb);
    stress[0] = new_centre + new_radius * cos2;
    stress[1] = new_centre - new_radius * cos2;
    stress[2] = rz;
    stress[3] = new_radius * sin2;
    stress[4] = 0;
    stress[5] = 0;
    return equivalent_plastic_strain(t, r);
  }

  // General 3D path. Quick elastic check first, without solving the cubic: with the mean p
  // and J2, s1 - s3 <= 2 sqrt(J2), |s2 - p| <= sqrt(J2 / 3) and s1 <= p + 2 sqrt(J2 / 3), so
  // f <= 2 sqrt(J2) + sin(phi) (2 p + sqrt(J2 / 3)) - 2 c cos(phi).
  const double mean = (trial[0] + trial[1] + trial[2]) / 3.0;
  const double dx = trial[0] - mean, dy = trial[1] - mean, dz = trial[2] - mean;
  const double j2 = 0.5 * (dx * dx + dy * dy + dz * dz) + trial[3] * trial[3] +
                    trial[4] * trial[4] + trial[5] * trial[5];
  const double sqrt_j2 = std::sqrt(j2);
  const double sqrt_j2_3 = sqrt_j2 * 0.5773502691896258;  // sqrt(J2 / 3)
  if (2 * sqrt_j2 + sin_phi_ * (2 * mean + sqrt_j2_3) - two_c_cos_phi_ <= 0 &&
      mean + 2 * sqrt_j2_3 <= tensile_strength_) {
    stress = trial;
    return 0;
  }
  // Principal values from the cubic: cheap, but off by up to ~1e-8 sqrt(J2) near repeated
  // values, hence the margin; states closer to the surfaces get the accurate values.
  const DeviatoricCubic cubic = solve_deviatoric_cubic(trial);
  {
    const double sorted[3] = {cubic.value(0), 0.0, cubic.value(2)};
    const double margin = kFastCheckMargin * sqrt_j2;
    if (yield_sorted(sorted) <= -margin && sorted[0] <= tensile_strength_ - margin) {
      stress = trial;
      return 0;
    }
  }
  Eigen::Vector3d values;
  Eigen::Matrix3d vectors;
  principal_decomposition(cubic, values, vectors);
  const double t[3] = {values[0], values[1], values[2]};
  if (yield_sorted(t) <= 0 && t[0] <= tensile_strength_) {
    stress = trial;
    return 0;
  }
  double r[3];
  return_principal(t, r);
  // sigma = sum r_i v_i v_i^T = r2 I + (r1 - r2) v1 v1^T + (r3 - r2) v3 v3^T (v orthonormal);
  // this form is exact for isotropic results (apex, vertices), and on an edge one of the two
  // differences vanishes, so only the direction of the distinct value (the well-defined one)
  // enters.
  const Eigen::Vector3d v1 = vectors.col(0), v3 = vectors.col(2);
  const double d1 = r[0] - r[1], d3 = r[2] - r[1];
  stress[0] = r[1] + d1 * v1[0] * v1[0] + d3 * v3[0] * v3[0];
  stress[1] = r[1] + d1 * v1[1] * v1[1] + d3 * v3[1] * v3[1];
  stress[2] = r[1] + d1 * v1[2] * v1[2] + d3 * v3[2] * v3[2];
  stress[3] = d1 * v1[0] * v1[1] + d3 * v3[0] * v3[1];
  stress[4] = d1 * v1[1] * v1[2] + d3 * v3[1] * v3[2];
  stress[5] = d1 * v1[0] * v1[2] + d3 * v3[0] * v3[2];
  return equivalent_plastic_strain(t, r);
}

}  // namespace lituya::solver
