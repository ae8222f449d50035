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

// sigma += D^e : d_eps (eq. 19 without plastic part).
void elastic_update(const ElasticConstants& elastic, Voigt6& stress, const Voigt6& strain_increment);

class MohrCoulomb {
 public:
  // Angles in degrees; cohesion and tensile strength in Pa.
  MohrCoulomb(double youngs_modulus, double poisson_ratio, double friction_angle_deg,
              double dilatancy_angle_deg, double cohesion, double tensile_strength);
  // Elastic predictor then return mapping in principal stresses (plane, edges, apex, tension
  // cut-off). Returns the equivalent plastic strain increment sqrt(2/3 d_eps_p : d_eps_p).
  double update(Voigt6& stress, const Voigt6& strain_increment) const;
  // f of eq. (21) written tension positive and scaled by 2:
  // f = (s_max - s_min) + (s_max + s_min) sin(phi) - 2 c cos(phi); f <= 0 is admissible.
  double yield_function(const Voigt6& stress) const;
  const ElasticConstants& elastic() const { return elastic_; }

 private:
  ElasticConstants elastic_;
  double sin_phi_, cos_phi_, sin_psi_, cohesion_, tensile_strength_;
};

}  // namespace lituya::solver
