// Dispersion against the Cauchy derivation from the Fraunhofer lines (spec "Dispersion").
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dspbr/bsdf/dispersion.h"

using namespace dspbr;

// b = (eta_d - 1) / nu_d / (1/F^2 - 1/C^2) and a = eta_d - b / d^2 give the printed constants:
// 1 / (1/F^2 - 1/C^2) = 523655.09 (printed 523655) and 523655.09 / d^2 = 1.516844 (printed 1.5168).
TEST(Dispersion, PrintedConstantsMatchFraunhoferLines) {
  const double k = 1.0 / (1.0 / (kFraunhoferF * kFraunhoferF) - 1.0 / (kFraunhoferC * kFraunhoferC));
  EXPECT_EQ(std::round(k), 523655.0) << k;
  EXPECT_NEAR(k / (kFraunhoferD * kFraunhoferD), 1.5168, 0.5e-4) << k / (kFraunhoferD * kFraunhoferD);
}

// The resulting eta(lambda) reproduces its inputs: eta(d) = eta_d and the Abbe number
// (eta_d - 1) / (eta_F - eta_C) = nu_d, to the rounding of the printed constants (eta(d) - eta_d = 4.36e-5 (eta_d - 1) / nu_d; the Abbe number comes back as nu_d + 4.4e-5).
TEST(Dispersion, ReproducesIorAndAbbeNumber) {
  for (double eta_d : {1.33, 1.5, 1.7, 2.4})
    for (double nu : {20.0, 40.0, 60.0}) {
      const double ed = dispersion_ior(eta_d, nu, kFraunhoferD);
      const double ef = dispersion_ior(eta_d, nu, kFraunhoferF), ec = dispersion_ior(eta_d, nu, kFraunhoferC);
      EXPECT_NEAR(ed, eta_d, 4.4e-5 * (eta_d - 1) / nu);  // 523655 / d^2 - 1.5168 = 4.36e-5
      EXPECT_NEAR((ed - 1) / (ef - ec), nu, 5e-5 + 2e-7 * nu);  // = (nu + 4.36e-5) 523655.09 / 523655
      // Cauchy form a + b / lambda^2 with the exact a, b of the spec's derivation.
      const double b = (eta_d - 1) / nu / (1 / (kFraunhoferF * kFraunhoferF) - 1 / (kFraunhoferC * kFraunhoferC));
      const double a = eta_d - b / (kFraunhoferD * kFraunhoferD);
      for (double l : {400.0, 550.0, 700.0}) EXPECT_NEAR(dispersion_ior(eta_d, nu, l), a + b / (l * l), 1e-5);
      // Normal dispersion: blue refracts more than red.
      EXPECT_GT(dispersion_ior(eta_d, nu, 450.0), dispersion_ior(eta_d, nu, 650.0));
    }
}

TEST(Dispersion, DisabledAndClamped) {
  for (double l : {380.0, 587.56, 780.0}) {
    EXPECT_EQ(dispersion_ior(1.5, 0.0, l), 1.5);  // nu_d = 0: the plain IOR
    EXPECT_EQ(dispersion_ior(1.5, std::numeric_limits<double>::infinity(), l), 1.5);
  }
  Material m;
  m.ior = 1.45;
  EXPECT_EQ(dispersion_ior(m, 500.0), 1.45);  // default abbeNumber = 0
  m.abbeNumber = 30;
  EXPECT_GT(dispersion_ior(m, 500.0), 1.45);
  // Extreme dispersion: the red end would fall below 1; clamped to 1.
  EXPECT_EQ(dispersion_ior(1.05, 0.01, 780.0), 1.0);
  EXPECT_THROW(dispersion_ior(1.5, 40.0, 0.0), std::invalid_argument);
  EXPECT_THROW(dispersion_ior(1.5, 40.0, -500.0), std::invalid_argument);
}
