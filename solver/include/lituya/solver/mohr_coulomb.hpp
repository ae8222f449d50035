#pragma once
// Linear elasticity and Mohr-Coulomb elasto-plasticity, eqs. (19)-(22) of the reference paper.
// Stress and strain in Voigt order [xx, yy, zz, xy, yz, xz]; stresses tension positive (Pa);
// strain increments with engineering shear components (gamma_xy = 2 eps_xy).
// (Interface fixed by the solver; implementation in src/mohr_coulomb.cpp.)
#include <Eigen/Core>

namespace lituya::solver {

using Voigt6 = Eigen::Matrix<double, 6, 1>;

struct ElasticConstants {
  double shear_modulus = 0;  // G = E / (2 (1 + nu))
  double lame_lambda = 0;    // lambda = E nu / ((1 + nu)(1 - 2 nu))
  static ElasticConstants from_young_poisson(double youngs_modulus, double poisson_ratio);
  // P-wave modulus lambda + 2G, for the time step.
  double constrained_modulus() const { return lame_lambda + 2 * shear_modulus; }
};

// sigma += D^e : d_eps (eq. 19 without plastic part). A NaN or inf in the stress or the
// increment gives a non-finite stress (plain IEEE arithmetic, every input has a non-zero
// coefficient), which the solver's finiteness check relies on.
void elastic_update(const ElasticConstants& elastic, Voigt6& stress,
                    const Voigt6& strain_increment);

// The friction coefficient of a rough rigid wall under a Mohr-Coulomb soil: the stress ratio
// tau / sigma'_n on a plane of velocity discontinuity in a soil sheared at its strength,
// tan(phi*) = sin(phi) cos(psi) / (1 - sin(phi) sin(psi)) (Davis 1968): sin(phi) for psi = 0,
// tan(phi) for associated flow (psi = phi). A no-slip wall tends to it as the cells shrink
// (user manual 2.4); a `contact` wall with `rough = "<soil>"` uses it directly. Angles in
// degrees. The soil's cohesion has a share c cos(phi) cos(psi) / (1 - sin(phi) sin(psi)) on
// that plane, which a Coulomb wall does not carry.
double rough_wall_friction(double friction_angle_deg, double dilatancy_angle_deg);

class MohrCoulomb {
 public:
  // Angles in degrees; cohesion and tensile strength in Pa.
  MohrCoulomb(double youngs_modulus, double poisson_ratio, double friction_angle_deg,
              double dilatancy_angle_deg, double cohesion, double tensile_strength);
  // Elastic predictor then return mapping in principal stresses (plane, edges, apex, tension
  // cut-off). Returns the equivalent plastic strain increment sqrt(2/3 d_eps_p : d_eps_p).
  // A NaN or inf in the stress or the increment gives a non-finite stress and returns NaN.
  double update(Voigt6& stress, const Voigt6& strain_increment) const;
  // f of eq. (21) written tension positive and scaled by 2:
  // f = (s_max - s_min) + (s_max + s_min) sin(phi) - 2 c cos(phi); f <= 0 is admissible.
  double yield_function(const Voigt6& stress) const;
  const ElasticConstants& elastic() const { return elastic_; }

 private:
  // Return mapping of the trial principal stresses t[0] >= t[1] >= t[2] to r (same order).
  void return_principal(const double t[3], double r[3]) const;
  // sqrt(2/3 d_eps_p : d_eps_p) with d_eps_p = D^-1 (t - r), coaxial principal values.
  double equivalent_plastic_strain(const double t[3], const double r[3]) const;
  // f of the sorted principal stresses s[0] >= s[1] >= s[2].
  double yield_sorted(const double s[3]) const {
    return s[0] * (1 + sin_phi_) - s[2] * (1 - sin_phi_) - two_c_cos_phi_;
  }

  ElasticConstants elastic_;
  // tensile_strength_ is the effective cut-off: min(input, c cot(phi)), +inf if none.
  double sin_phi_, cos_phi_, sin_psi_, cohesion_, tensile_strength_;
  // Precomputed in the constructor (see mohr_coulomb.cpp for the notation).
  enum class Cutoff { none, at_apex, below_apex };
  Cutoff cutoff_ = Cutoff::none;
  double two_c_cos_phi_ = 0;  // 2 c cos(phi)
  double s3_corner_ = 0;      // s3 on the yield plane where s1 = tensile_strength_
  double lambda_ratio_ = 0;   // lambda / (3 lambda + 2 G), for D^-1
  double db1_[3] = {}, db2_[3] = {}, db3_[3] = {};  // D b for the three flow vectors
  double m_ = 0, n12_ = 0, n13_ = 0;                // a_i . D b_j, see return_principal
  double a1_de1_ = 0, det_f1_r1_ = 0;               // for the yield plane / cut-off edge
};

}  // namespace lituya::solver
