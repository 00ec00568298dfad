// Emission against hand-computed values, limits and a photometric closure by hemisphere quadrature
// (the luminous exitance of rho_e equals the emission value).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dspbr/bsdf/emission.h"
#include "dspbr/constants.h"
#include "dspbr/quadrature.h"

using namespace dspbr;

namespace {

// Integral over the upper hemisphere of lum(L_e(v)) (v.n) dv: the luminous exitance in lm/m^2.
double exitance(const Rgb& rho_e, const Vec3& n_c, double clearcoat) {
  const QuadratureRule r = gauss_legendre(32);
  double sum = 0;
  for (std::size_t i = 0; i < r.x.size(); ++i) {
    const double mu = 0.5 * (r.x[i] + 1), wmu = 0.5 * r.w[i];
    for (int p = 0; p < 64; ++p) {
      const double phi = 2 * kPi * (p + 0.5) / 64, s = std::sqrt(1 - mu * mu);
      const Vec3 v{s * std::cos(phi), s * std::sin(phi), mu};
      sum += wmu * (2 * kPi / 64) * emission_radiance(rho_e, v, n_c, clearcoat).luminance() * mu;
    }
  }
  return sum;
}
}  // namespace

TEST(Emission, HandComputedLuminance) {
  // lx, not normalized: rho_e = l_v l_c / pi.
  const Rgb a = emission_rho_e(Rgb(1.0), kPi, EmissionMode::LuminousEmittance, false, 0.0);
  EXPECT_NEAR(a.r, 1.0, 1e-15);
  // lx, normalized: lum(0.5, 0.2, 0.1) = 0.2126729 * 0.5 + 0.7151522 * 0.2 + 0.072175 * 0.1 = 0.25658439.
  const Rgb b = emission_rho_e(Rgb(0.5, 0.2, 0.1), 100.0, EmissionMode::LuminousEmittance, true, 0.0);
  EXPECT_NEAR(b.r, 100.0 / kPi * 0.5 / 0.25658439, 1e-9);
  EXPECT_NEAR(b.b, 100.0 / kPi * 0.1 / 0.25658439, 1e-9);
  // lm over an object of 4 m^2: rho_e = l_v l_c / (pi area).
  const Rgb c = emission_rho_e(Rgb(2.0, 1.0, 0.0), 100.0, EmissionMode::LuminousPower, false, 4.0);
  EXPECT_NEAR(c.r, 200.0 / (4 * kPi), 1e-12);
  EXPECT_EQ(c.b, 0.0);
  Material m;  // defaults: value 0 -> no emission
  EXPECT_EQ(emission_rho_e(m, 1.0).g, 0.0);
}

// With normalization the light emits exactly its value: exitance = l_v (lx), area * exitance = l_v (lm).
TEST(Emission, PhotometricClosure) {
  const Vec3 n{0, 0, 1};
  const Rgb lx = emission_rho_e(Rgb(0.9, 0.3, 0.05), 250.0, EmissionMode::LuminousEmittance, true, 0.0);
  EXPECT_NEAR(exitance(lx, n, 0.0), 250.0, 1e-9);
  const double area = 0.37;
  const Rgb lm = emission_rho_e(Rgb(0.1, 0.2, 0.8), 800.0, EmissionMode::LuminousPower, true, area);
  EXPECT_NEAR(area * exitance(lm, n, 0.0), 800.0, 1e-9);
  // A clearcoat removes what it reflects: exitance = l_v (1 - c Integral F_c cos / pi) = l_v (1 - c F_avg),
  // F_avg = 0.04 * 20/21 + 1/21 for Schlick's F (spec eq. fr_avg).
  const double f_avg = 0.04 * 20.0 / 21.0 + 1.0 / 21.0;
  EXPECT_NEAR(exitance(lx, n, 0.6), 250.0 * (1 - 0.6 * f_avg), 1e-6);
}

TEST(Emission, DirectionalLimits) {
  const Rgb rho(2.0, 1.0, 0.5);
  const Vec3 n{0, 0, 1};
  // Below or on the horizon: nothing.
  EXPECT_EQ(emission_radiance(rho, {0.6, 0.0, -0.8}, n, 0.0).r, 0.0);
  EXPECT_EQ(emission_radiance(rho, {1.0, 0.0, 0.0}, n, 0.0).r, 0.0);
  // No clearcoat: Lambertian, direction independent.
  EXPECT_EQ(emission_radiance(rho, {0.0, 0.6, 0.8}, n, 0.0).g, 1.0);
  // Full clearcoat at normal incidence: 1 - 0.04; towards grazing F_c -> 1 and L_e -> 0.
  EXPECT_NEAR(emission_radiance(rho, n, n, 1.0).r, 2.0 * 0.96, 1e-15);
  const Vec3 grazing = normalize(Vec3{1.0, 0.0, 1e-9});
  EXPECT_NEAR(emission_radiance(rho, grazing, n, 1.0).r, 0.0, 1e-8);
  // Tilted clearcoat normal: F_c uses v.n_c.
  const Vec3 nc = normalize(Vec3{0.3, 0.0, 1.0}), v = normalize(Vec3{0.3, 0.0, 1.0});
  EXPECT_NEAR(emission_radiance(rho, v, nc, 0.5).b, 0.5 * (1 - 0.5 * 0.04), 1e-15);
}

TEST(Emission, BadInputAndBlackColour) {
  // Normalizing black: documented 0, no NaN.
  const Rgb z = emission_rho_e(Rgb(0.0), 100.0, EmissionMode::LuminousEmittance, true, 0.0);
  EXPECT_EQ(z.r, 0.0);
  EXPECT_EQ(z.g, 0.0);
  EXPECT_THROW(emission_rho_e(Rgb(1.0), 10.0, EmissionMode::LuminousPower, false, 0.0), std::invalid_argument);
  EXPECT_THROW(emission_rho_e(Rgb(1.0), 10.0, EmissionMode::LuminousPower, false, -1.0), std::invalid_argument);
  EXPECT_THROW(emission_rho_e(Rgb(1.0), -1.0, EmissionMode::LuminousEmittance, false, 0.0), std::invalid_argument);
  EXPECT_THROW(emission_rho_e(Rgb(1.0, -0.1, 0.0), 1.0, EmissionMode::LuminousEmittance, false, 0.0),
               std::invalid_argument);
  // lx ignores the area entirely.
  EXPECT_NO_THROW(emission_rho_e(Rgb(1.0), 10.0, EmissionMode::LuminousEmittance, false, -1.0));
}
