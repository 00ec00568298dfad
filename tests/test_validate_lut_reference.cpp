// The independent LUT reference values (h-space Gauss-Legendre, validate/lut_reference.h)
// against closed forms and against a different integral (l-space quadrature of the BRDFs).
#include <gtest/gtest.h>

#include <cmath>

#include "dspbr/constants.h"
#include "dspbr/frame.h"
#include "dspbr/ggx.h"
#include "dspbr/quadrature.h"
#include "dspbr/sheen.h"
#include "dspbr/validate/lut_reference.h"
#include "light_space_albedo.h"

using namespace dspbr;
using namespace dspbr::validate;

namespace {

// Integral over the upper hemisphere of brdf(v, l) l.z dl in (theta_l, phi_l), v in the xz plane
// (light_space_albedo.h: 96 panels in theta, 96 in phi over [0, 2 pi], 8 nodes each).
template <class F>
double l_space_albedo(F&& brdf, double mu) {
  return test::light_space_albedo(brdf, mu, 96, 96, test::MuGrading::Polar);
}
}  // namespace

TEST(ValidateLutReference, GgxAlbedoMatchesLightSpaceQuadrature) {
  for (double r : {0.4, 0.8, 1.0}) {
    for (double mu : {0.95, 0.5, 0.1}) {
      const double a = roughness_to_alpha(r);
      const double ref = l_space_albedo([&](const Vec3& v, const Vec3& l) { return GgxDistribution(a, a).M_r(v, l); }, mu);
      const RefValue e = ggx_albedo_ref(mu, r, RefQuadrature{32});
      EXPECT_NEAR(e.value, ref, 2e-5) << r << " " << mu;
      EXPECT_LT(e.error, 1e-4);
      EXPECT_LE(e.value, 1.0);
    }
  }
}

TEST(ValidateLutReference, MirrorLimitAndWhiteFresnelClosedForms) {
  EXPECT_DOUBLE_EQ(ggx_albedo_ref(0.3, 0.0).value, 1.0);
  // Small roughness: almost no masking loss away from grazing.
  EXPECT_NEAR(ggx_albedo_ref(0.8, 0.05, RefQuadrature{16}).value, 1.0, 1e-3);
  // f0 = 1: F = 1 and F_ms(1, 1) = 1, so E = E_m + (1 - E_m) = 1 exactly (spec "Diffuse BRDF").
  for (double r : {0.3, 1.0}) {
    EXPECT_NEAR(base_albedo_ref(0.4, r, 1.0, RefQuadrature{16}).value, 1.0, 1e-9);
    EXPECT_NEAR(base_albedo_avg_ref(r, 1.0, RefQuadrature{16}).value, 1.0, 1e-9);
  }
}

TEST(ValidateLutReference, AverageIsTheCosineWeightedMeanOfTheDirectionalAlbedo) {
  // Independent: Gauss-Legendre over mu of l-space albedos.
  const double r = 0.7, a = roughness_to_alpha(r);
  const QuadratureRule rule = gauss_legendre(12);
  double avg = 0;
  for (size_t i = 0; i < rule.x.size(); ++i) {
    const double mu = 0.5 * (1 + rule.x[i]);
    avg += rule.w[i] * 0.5 * 2 * mu *
           l_space_albedo([&](const Vec3& v, const Vec3& l) { return GgxDistribution(a, a).M_r(v, l); }, mu);
  }
  EXPECT_NEAR(ggx_albedo_avg_ref(r, RefQuadrature{32}).value, avg, 2e-4);
}

TEST(ValidateLutReference, SheenAlbedosMatchLightSpaceQuadrature) {
  for (double ab : {0.1, 0.5, 1.0}) {
    for (double mu : {0.9, 0.3}) {
      const double ref_main = l_space_albedo([&](const Vec3& v, const Vec3& l) { return sheen_brdf(v, l, ab); }, mu);
      const double ref_alt = l_space_albedo([&](const Vec3& v, const Vec3& l) { return sheen_brdf_ash(v, l, ab); }, mu);
      EXPECT_NEAR(sheen_albedo_ref(mu, ab, false, RefQuadrature{32}).value, ref_main, 2e-4) << ab << " " << mu;
      EXPECT_NEAR(sheen_albedo_ref(mu, ab, true, RefQuadrature{32}).value, ref_alt, 2e-4) << ab << " " << mu;
    }
  }
}
