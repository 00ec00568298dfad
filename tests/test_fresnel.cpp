// Fresnel terms: limits and closed forms.
#include <gtest/gtest.h>

#include "dspbr/fresnel.h"
#include "dspbr/quadrature.h"

using namespace dspbr;

TEST(Fresnel, SchlickLimits) {
  EXPECT_DOUBLE_EQ(fresnel_schlick(1.0, 0.04, 1.0), 0.04);  // normal incidence
  EXPECT_DOUBLE_EQ(fresnel_schlick(0.0, 0.04, 1.0), 1.0);   // grazing
  EXPECT_DOUBLE_EQ(fresnel_schlick(-1.0, 0.04, 1.0), 0.04); // |cos|
  EXPECT_NEAR(f0_from_ior(1.0, 1.5), 0.04, 1e-15);
  EXPECT_EQ(f0_from_ior(1.0, 1.0), 0.0);
}

TEST(Fresnel, RefractiveVersionHandlesTotalInternalReflection) {
  // From inside glass (1.5 -> 1): critical angle asin(1/1.5); beyond it F_d = 1, even with f90 = 0.
  const double crit = std::sqrt(1 - 1 / 2.25);
  EXPECT_EQ(fresnel_schlick_d(crit * 0.99, 0.04, 0.0, 1.5, 1.0), 1.0);
  EXPECT_LT(fresnel_schlick_d(crit * 1.01 + 0.01, 0.04, 1.0, 1.5, 1.0), 1.0);
  // Entering the denser medium it is plain Schlick.
  EXPECT_EQ(fresnel_schlick_d(0.3, 0.04, 1.0, 1.0, 1.5), fresnel_schlick(0.3, 0.04, 1.0));
  // Inside, at normal incidence, the transmitted cosine is 1.
  EXPECT_DOUBLE_EQ(fresnel_schlick_d(1.0, 0.04, 1.0, 1.5, 1.0), 0.04);
}

// F_m,avg = 2 Int F(mu) mu dmu: 20/21 f0 + 1/21 f90, checked by quadrature.
TEST(Fresnel, AverageMatchesQuadrature) {
  const QuadratureRule r = gauss_legendre(32);
  for (double f0 : {0.0, 0.04, 0.5, 1.0}) {
    const double I = integrate_gl([&](double mu) { return 2 * fresnel_schlick(mu, f0, 1.0) * mu; }, 0, 1, 4, r);
    EXPECT_NEAR(fresnel_avg(f0, 1.0), I, 1e-14);
  }
  // F_ms limits: white (f0 = f90 = 1) gives E_avg / E_avg = 1; black gives 0.
  EXPECT_NEAR(fresnel_ms(1.0, 1.0, 0.7), 1.0, 1e-15);
  EXPECT_EQ(fresnel_ms(0.0, 0.0, 0.7), 0.0);
}
