// The validation checks (src/dspbr/validate/) on correct test lobes (must pass) and on
// deliberately broken ones (must fail): every check is shown to be able to fail.
#include <gtest/gtest.h>

#include <cmath>

#include "dspbr/constants.h"
#include "dspbr/quadrature.h"
#include "dspbr/validate/chi2.h"
#include "dspbr/validate/furnace.h"
#include "dspbr/validate/reciprocity.h"
#include "dspbr/validate/stability.h"
#include "validate_doubles.h"

using namespace dspbr;
using namespace dspbr::validate;
using namespace dspbr::testing;

namespace {

Vec3 dir(double cos_t, double phi = 0.3) {
  const double s = std::sqrt(1 - cos_t * cos_t);
  return {s * std::cos(phi), s * std::sin(phi), cos_t};
}

Chi2Settings small_chi2() {
  Chi2Settings s;
  s.samples = 200000;
  s.theta_bins = 30;
  s.integration_order = 5;
  return s;
}

struct Furnace {
  AlbedoEstimate eval;
  SampledAlbedo sampled;
  EnergyVerdict verdict;
};

Furnace furnace(const Bsdf& b, const Vec3& v, const EnergyTolerances& tol = {}) {
  Furnace f;
  f.eval = albedo_eval(b, v, 200, 7, 1);
  f.sampled = albedo_sampled(b, v, 40000, 7, 2);
  f.verdict = judge_energy(f.eval, f.sampled, tol);
  return f;
}

}  // namespace

// ---------------------------------------------------------------- white furnace

TEST(ValidateFurnace, LambertAlbedoMatchesClosedForm) {
  // Integral of rho/pi |cos| over the hemisphere is rho: both estimators, every direction.
  for (double c : {1.0, 0.5, 0.05, -0.7}) {
    const Furnace f = furnace(LambertLobe(0.8), dir(c));
    EXPECT_NEAR(f.eval.value.r, 0.8, 4 * f.eval.std_error.r + 1e-12) << c;
    // Cosine sampling of a Lambert lobe has weight exactly rho: zero variance.
    EXPECT_NEAR(f.sampled.total.value.r, 0.8, 1e-12) << c;
    EXPECT_TRUE(f.verdict.conserving && f.verdict.estimators_agree);
  }
}

TEST(ValidateFurnace, GgxAlbedoMatchesQuadrature) {
  // Independent reference: Gauss-Legendre in (theta_l, phi_l) of the single-scattering BRDF.
  const double alpha = 0.25;
  const Vec3 v = dir(0.6, 0.0);
  const QuadratureRule rule = gauss_legendre(16);
  double ref = 0;
  const int pt = 64, pp = 64;
  for (int a = 0; a < pt; ++a)
    for (size_t i = 0; i < rule.x.size(); ++i) {
      const double th = (a + 0.5 + 0.5 * rule.x[i]) * (kPi / 2) / pt;
      const double wt = 0.5 * rule.w[i] * (kPi / 2) / pt;
      for (int b = 0; b < pp; ++b)
        for (size_t j = 0; j < rule.x.size(); ++j) {
          const double ph = (b + 0.5 + 0.5 * rule.x[j]) * 2 * kPi / pp;
          const double wp = 0.5 * rule.w[j] * 2 * kPi / pp;
          const Vec3 l{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
          ref += wt * wp * GgxDistribution(alpha, alpha).M_r(v, l) * l.z * std::sin(th);
        }
    }
  const Furnace f = furnace(GgxReflectionLobe(alpha), v);
  EXPECT_NEAR(f.eval.value.r, ref, 4 * f.eval.std_error.r);
  EXPECT_NEAR(f.sampled.total.value.r, ref, 4 * f.sampled.total.std_error.r);
  EXPECT_LT(ref, 1.0);
  EXPECT_TRUE(f.verdict.conserving && f.verdict.estimators_agree);
}

TEST(ValidateFurnace, DeltaLobeCountedOnlyBySampling) {
  // Mirror (0.3) + Lambert (0.7): total 1; the eval estimator sees only the Lambert part.
  const Furnace f = furnace(MirrorPlusLambert(0.3, 0.4, 0.7), dir(0.8));
  EXPECT_NEAR(f.sampled.total.value.r, 1.0, 4 * f.sampled.total.std_error.r + 1e-12);
  EXPECT_NEAR(f.eval.value.r, 0.7, 4 * f.eval.std_error.r + 1e-12);
  EXPECT_TRUE(f.verdict.preserving && f.verdict.conserving && f.verdict.estimators_agree);
}

TEST(ValidateFurnace, EnergyGainingLobeFailsConservation) {
  const Furnace f = furnace(LambertLobe(1.05), dir(0.7));
  EXPECT_FALSE(f.verdict.conserving);
}

TEST(ValidateFurnace, LossyLobeFailsPreservationButConserves) {
  const Furnace f = furnace(LambertLobe(0.9), dir(0.7));
  EXPECT_FALSE(f.verdict.preserving);
  EXPECT_TRUE(f.verdict.conserving);
  EXPECT_TRUE(furnace(LambertLobe(1.0), dir(0.7)).verdict.preserving);
}

TEST(ValidateFurnace, WrongSampleWeightMakesEstimatorsDisagree) {
  const Furnace ok = furnace(GgxReflectionLobe(0.3), dir(0.5));
  EXPECT_TRUE(ok.verdict.estimators_agree);
  const Furnace bad = furnace(WeightScaledGgx(0.3, 1.1), dir(0.5));
  EXPECT_FALSE(bad.verdict.estimators_agree);
}

TEST(ValidateFurnace, SamplerMissingPartOfTheLobeMakesEstimatorsDisagree) {
  // The leaky sampler wastes 20% of its samples with zero weight: it under-counts the albedo.
  const Furnace bad = furnace(LeakyLambert(1.0, 0.2), dir(0.5));
  EXPECT_FALSE(bad.verdict.estimators_agree);
}

// ---------------------------------------------------------------- reciprocity

TEST(ValidateReciprocity, ReciprocalLobesPass) {
  ReciprocitySettings s;
  s.pairs = 5000;
  for (const Bsdf* b : std::initializer_list<const Bsdf*>{new LambertLobe(0.5), new GgxReflectionLobe(0.2)}) {
    const ReciprocityResult r = reciprocity_check(*b, s);
    EXPECT_GT(r.reflection_upper.pairs, 1000u);
    EXPECT_LT(r.reflection_upper.max_rel_dev, 1e-12);
    delete b;
  }
}

TEST(ValidateReciprocity, NonReciprocalTermIsCaught) {
  ReciprocitySettings s;
  s.pairs = 2000;
  const ReciprocityResult r = reciprocity_check(NonReciprocalLambert(0.5, 0.2), s);
  EXPECT_GT(r.reflection_upper.max_rel_dev, 0.1);
}

TEST(ValidateReciprocity, EtaSquaredRuleForRefraction) {
  ReciprocitySettings s;
  s.pairs = 2000;
  s.eta_above = 1.0;
  s.eta_below = 1.5;
  // Radiance-scaled transmission obeys the eta^2 rule but not plain symmetry...
  const ReciprocityResult good = reciprocity_check(DiffuseTransmission(0.5, 1.0, 1.5, true), s);
  EXPECT_LT(good.transmission_eta2.max_rel_dev, 1e-12);
  EXPECT_NEAR(good.transmission_plain.max_rel_dev, 1 - 1 / 2.25, 1e-12);
  // ...and a transmission term without the eta^2 factor breaks the rule.
  const ReciprocityResult bad = reciprocity_check(DiffuseTransmission(0.5, 1.0, 1.5, false), s);
  EXPECT_NEAR(bad.transmission_eta2.max_rel_dev, 1 - 1 / 2.25, 1e-12);
}

// ---------------------------------------------------------------- chi-square and pdf

TEST(ValidateChi2, SurvivalFunctionMatchesClosedForms) {
  // Even dof: Q(k/2, x/2) = exp(-x/2) sum_{j<k/2} (x/2)^j / j!.
  for (int k : {2, 4, 10}) {
    for (double x : {0.5, 3.0, 12.0}) {
      double term = 1, sum = 0;
      for (int j = 0; j < k / 2; ++j) {
        sum += term;
        term *= 0.5 * x / (j + 1);
      }
      EXPECT_NEAR(chi2_survival(x, k), std::exp(-0.5 * x) * sum, 1e-13);
    }
  }
  // dof = 1: P(chi2 > x) = erfc(sqrt(x/2)).
  EXPECT_NEAR(chi2_survival(3.84, 1), std::erfc(std::sqrt(1.92)), 1e-13);
}

TEST(ValidateChi2, SidakCorrection) {
  EXPECT_NEAR(sidak_alpha(0.01, 1), 0.01, 1e-15);
  // m tests at level a_1 give family-wise level 1 - (1 - a_1)^m = alpha.
  EXPECT_NEAR(1 - std::pow(1 - sidak_alpha(0.01, 40), 40), 0.01, 1e-13);
}

TEST(ValidateChi2, CorrectLobesPass) {
  const Chi2Settings s = small_chi2();
  for (double c : {1.0, 0.6, 0.05}) {
    const Chi2Result l = chi2_test(LambertLobe(1.0), dir(c), s);
    EXPECT_TRUE(l.passed()) << "lambert c=" << c << " p=" << l.p_value;
    EXPECT_NEAR(l.pdf_integral, 1.0, 2e-3);
    const Chi2Result g = chi2_test(GgxReflectionLobe(0.3), dir(c), s);
    EXPECT_TRUE(g.passed()) << "ggx c=" << c << " p=" << g.p_value << " int=" << g.pdf_integral;
    // VNDF reflections below the horizon are failed samples: Integral pdf = 1 - P(invalid).
    EXPECT_NEAR(g.pdf_integral, 1.0 - double(g.invalid) / s.samples, g.pdf_integral_tol);
  }
}

TEST(ValidateChi2, DeltaFractionMatchesMissingPdfMass) {
  const Chi2Result r = chi2_test(MirrorPlusLambert(0.5, 0.3, 0.5), dir(0.7), small_chi2());
  EXPECT_TRUE(r.passed()) << r.p_value;
  EXPECT_NEAR(r.pdf_integral, 0.7, 2e-3);
  EXPECT_NEAR(double(r.delta) / r.samples, 0.3, 5e-3);
}

TEST(ValidateChi2, PdfOffByAFactorIsCaught) {
  const Chi2Result r = chi2_test(PdfScaledGgx(0.3, 1.1), dir(0.6), small_chi2());
  EXPECT_FALSE(r.chi2_passed);
  EXPECT_FALSE(r.integral_passed);
  EXPECT_FALSE(r.consistency_passed);  // sample.pdf != pdf()
}

TEST(ValidateChi2, WrongDistributionIsCaughtByTheHistogramAlone) {
  const Chi2Result r = chi2_test(WrongDistributionLambert(1.0), dir(0.6), small_chi2());
  EXPECT_FALSE(r.chi2_passed);
  EXPECT_TRUE(r.support_passed);
  EXPECT_TRUE(r.integral_passed);
  EXPECT_TRUE(r.consistency_passed);
}

TEST(ValidateChi2, SamplesOutsideTheSupportAreCaught) {
  const Chi2Result r = chi2_test(LeakyLambert(1.0, 0.01), dir(0.6), small_chi2());
  EXPECT_FALSE(r.support_passed);
  EXPECT_GT(r.outside_support, 1000u);
}

TEST(ValidateChi2, WrongWeightIsCaught) {
  const Chi2Result r = chi2_test(WeightScaledGgx(0.3, 1.01), dir(0.6), small_chi2());
  EXPECT_FALSE(r.consistency_passed);
  EXPECT_NEAR(r.max_weight_rel_dev, 0.01 / 1.01, 1e-9);
}

TEST(ValidateChi2, DeterministicForAGivenSeed) {
  const Chi2Settings s = small_chi2();
  const Chi2Result a = chi2_test(GgxReflectionLobe(0.3), dir(0.6), s);
  const Chi2Result b = chi2_test(GgxReflectionLobe(0.3), dir(0.6), s);
  EXPECT_EQ(a.statistic, b.statistic);
  EXPECT_EQ(a.invalid, b.invalid);
}

// ---------------------------------------------------------------- stability

TEST(ValidateStability, GuardedLobesAreClean) {
  StabilitySettings s;
  s.random_directions = 2000;
  for (double a : {1e-4, 0.3, 1.0}) {
    const StabilityCounts c = stability_scan(GgxReflectionLobe(a), s);
    EXPECT_EQ(c.nan + c.inf + c.negative + c.bad_direction, 0u) << a;
  }
  EXPECT_EQ(stability_scan(LambertLobe(1.0), s).total_failures(), 0u);
}

TEST(ValidateStability, MissingGrazingGuardIsCaught) {
  StabilitySettings s;
  const StabilityCounts c = stability_scan(UnguardedGgx(0.3), s);
  EXPECT_GT(c.nan + c.inf, 0u);
}

TEST(ValidateStability, FireflyWeightsAreCounted) {
  StabilitySettings s;
  s.weight_bound = 10;
  EXPECT_EQ(stability_scan(LambertLobe(1.0), s).above_bound, 0u);
  EXPECT_GT(stability_scan(WeightScaledGgx(0.3, 20.0), s).above_bound, 0u);
}
