// Isotropic linear elasticity, eq. (19) without plastic strain: closed-form responses.
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "lituya/solver/mohr_coulomb.hpp"

namespace {

using lituya::solver::elastic_update;
using lituya::solver::ElasticConstants;
using lituya::solver::Voigt6;

TEST(LinearElastic, LameConstantsFromYoungPoisson) {
  // E = 10 MPa, nu = 0.25: G = E / 2.5 = 4 MPa, lambda = E nu / (1.25 * 0.5) = 4 MPa.
  const ElasticConstants c = ElasticConstants::from_young_poisson(10e6, 0.25);
  EXPECT_DOUBLE_EQ(c.shear_modulus, 4e6);
  EXPECT_DOUBLE_EQ(c.lame_lambda, 4e6);
  EXPECT_DOUBLE_EQ(c.constrained_modulus(), 12e6);
  // nu = 0: lambda = 0, G = E / 2.
  const ElasticConstants c0 = ElasticConstants::from_young_poisson(3e6, 0.0);
  EXPECT_DOUBLE_EQ(c0.shear_modulus, 1.5e6);
  EXPECT_DOUBLE_EQ(c0.lame_lambda, 0.0);
}

TEST(LinearElastic, RejectsInvalidConstants) {
  EXPECT_THROW(ElasticConstants::from_young_poisson(0.0, 0.3), std::invalid_argument);
  EXPECT_THROW(ElasticConstants::from_young_poisson(1e6, 0.5), std::invalid_argument);
  EXPECT_THROW(ElasticConstants::from_young_poisson(1e6, -1.0), std::invalid_argument);
}

// The solver's finiteness check looks at the stress: a NaN or inf in any strain component
// must reach it, also with lambda = 0 (nu = 0), where the volumetric term is 0 * inf = NaN.
TEST(LinearElastic, NonFiniteStrainGivesANonFiniteStress) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double nu : {0.0, 0.3}) {
    const ElasticConstants c = ElasticConstants::from_young_poisson(20e6, nu);
    for (int k = 0; k < 6; ++k) {
      for (double bad : {std::numeric_limits<double>::quiet_NaN(), inf, -inf}) {
        Voigt6 stress = Voigt6::Constant(-1e5), strain = Voigt6::Constant(1e-4);
        strain[k] = bad;
        elastic_update(c, stress, strain);
        EXPECT_FALSE(stress.allFinite()) << "nu " << nu << ", component " << k << " = " << bad;
      }
    }
  }
}

TEST(LinearElastic, UniaxialStrainIncrement) {
  const ElasticConstants c = ElasticConstants::from_young_poisson(20e6, 0.3);
  const double lambda = 20e6 * 0.3 / (1.3 * 0.4), g = 20e6 / 2.6;
  const double eps = -2.5e-4;
  Voigt6 stress;
  stress << -1e3, -2e3, -3e3, 4e2, -5e2, 6e2;
  const Voigt6 initial = stress;
  Voigt6 de = Voigt6::Zero();
  de[0] = eps;
  elastic_update(c, stress, de);
  EXPECT_NEAR(stress[0] - initial[0], (lambda + 2 * g) * eps, 1e-9);
  EXPECT_NEAR(stress[1] - initial[1], lambda * eps, 1e-9);
  EXPECT_NEAR(stress[2] - initial[2], lambda * eps, 1e-9);
  for (int i = 3; i < 6; ++i) EXPECT_EQ(stress[i], initial[i]);
  // The same along z.
  stress = initial;
  de = Voigt6::Zero();
  de[2] = eps;
  elastic_update(c, stress, de);
  EXPECT_NEAR(stress[2] - initial[2], (lambda + 2 * g) * eps, 1e-9);
  EXPECT_NEAR(stress[0] - initial[0], lambda * eps, 1e-9);
}

TEST(LinearElastic, PureShearUsesEngineeringStrain) {
  const ElasticConstants c = ElasticConstants::from_young_poisson(10e6, 0.25);  // G = 4 MPa
  for (int k = 3; k < 6; ++k) {
    Voigt6 stress = Voigt6::Zero();
    Voigt6 de = Voigt6::Zero();
    de[k] = 1e-3;  // gamma = 2 eps
    elastic_update(c, stress, de);
    for (int i = 0; i < 6; ++i) EXPECT_DOUBLE_EQ(stress[i], i == k ? 4e3 : 0.0);
  }
}

TEST(LinearElastic, IsotropicCompressionUsesBulkModulus) {
  const ElasticConstants c = ElasticConstants::from_young_poisson(10e6, 0.25);
  const double bulk = c.lame_lambda + 2.0 / 3.0 * c.shear_modulus;  // 6.667 MPa
  Voigt6 stress = Voigt6::Zero();
  Voigt6 de;
  de << -1e-4, -1e-4, -1e-4, 0, 0, 0;
  elastic_update(c, stress, de);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(stress[i], 3 * bulk * -1e-4, 1e-9);
  for (int i = 3; i < 6; ++i) EXPECT_EQ(stress[i], 0.0);
}

}  // namespace
