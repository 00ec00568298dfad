// The validation checks (src/dspbr/validate/) on correct test lobes (must pass) and on
// deliberately broken ones (must fail): every check is shown to be able to fail.
#include <gtest/gtest.h>

#include <cmath>

#include "dspbr/constants.h"
#include "dspbr/validate/chi2.h"
#include "dspbr/validate/furnace.h"
#include "dspbr/validate/lut_reference.h"
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

Furnace furnace(const Bsdf& b, const Vec3& v, const EnergyTolerances& tol = {}, int strata = 200,
                std::size_t samples = 40000) {
  Furnace f;
  f.eval = albedo_eval(b, v, strata, 7, 1);
  f.sampled = albedo_sampled(b, v, samples, 7, 2);
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
    EXPECT_TRUE(f.verdict.conserving() && f.verdict.estimators_agree());
  }
}

TEST(ValidateFurnace, GgxAlbedoMatchesQuadrature) {
  // Independent reference: E_m(0.6; r = 0.5) of the single-scattering BRDF (alpha = r^2 = 0.25)
  // by the library's reference quadrature over the half vector (validate/lut_reference.h).
  const double alpha = 0.25;
  const Vec3 v = dir(0.6, 0.0);
  const double ref = ggx_albedo_ref(0.6, 0.5).value;
  const Furnace f = furnace(GgxReflectionLobe(alpha), v);
  EXPECT_NEAR(f.eval.value.r, ref, 4 * f.eval.std_error.r);
  EXPECT_NEAR(f.sampled.total.value.r, ref, 4 * f.sampled.total.std_error.r);
  EXPECT_LT(ref, 1.0);
  EXPECT_TRUE(f.verdict.conserving() && f.verdict.estimators_agree());
}

TEST(ValidateFurnace, DeltaLobeCountedOnlyBySampling) {
  // Mirror (0.3) + Lambert (0.7): total 1; the eval estimator sees only the Lambert part.
  const Furnace f = furnace(MirrorPlusLambert(0.3, 0.4, 0.7), dir(0.8));
  EXPECT_NEAR(f.sampled.total.value.r, 1.0, 4 * f.sampled.total.std_error.r + 1e-12);
  EXPECT_NEAR(f.eval.value.r, 0.7, 4 * f.eval.std_error.r + 1e-12);
  EXPECT_TRUE(f.verdict.preserving() && f.verdict.conserving() && f.verdict.estimators_agree());
}

TEST(ValidateFurnace, EnergyGainingLobeFailsConservation) {
  const Furnace f = furnace(LambertLobe(1.05), dir(0.7));
  EXPECT_FALSE(f.verdict.conserving());
}

TEST(ValidateFurnace, EnergyGainingLobeFailsWithPowerAndIsNotJudgedWithout) {
  // Mirror 0.35 (chosen with probability 0.5) + Lambert 0.7: E = 1.05, beyond 1 + 0.01. The
  // lobe choice makes every estimate of the mirror part noisy (weights 0.7 or 0).
  const MirrorPlusLambert gain(0.35, 0.5, 0.7);
  const Furnace many = furnace(gain, dir(0.8));
  EXPECT_EQ(many.verdict.conservation.decision, Decision::Fail);
  EXPECT_NEAR(many.verdict.conservation.value, 1.05, many.verdict.conservation.band);
  // 16 samples: the band is far wider than the tolerance. The check could not have failed, so it
  // must not pass: NOT JUDGED, with the band and the tolerance in the reason.
  const Furnace few = furnace(gain, dir(0.8), {}, 2, 16);
  const BoundVerdict& c = few.verdict.conservation;
  EXPECT_EQ(c.decision, Decision::NotJudged);
  EXPECT_GT(c.band, 0.01 * 10);
  EXPECT_EQ(c.tolerance, 0.01);
  EXPECT_NE(c.reason().find("wider than the tolerance 0.01"), std::string::npos) << c.reason();
  // The same budget on a lobe without variance (Lambert, cosine sampling: weight exactly rho)
  // has a zero band, so it is judged: pass at 1, fail at 1.05.
  EXPECT_EQ(furnace(LambertLobe(1.0), dir(0.8), {}, 2, 16).verdict.conservation.decision, Decision::Pass);
  EXPECT_EQ(furnace(LambertLobe(1.05), dir(0.8), {}, 2, 16).verdict.conservation.decision, Decision::Fail);
}

TEST(ValidateFurnace, PassOnlyWhereTheBandLiesWithinTheTolerance) {
  // A correct mixture (mirror 0.3 + Lambert 0.7, E = 1): PASS with enough samples, where the
  // band of the narrower estimator is within the tolerance; NOT JUDGED with 16 samples.
  const MirrorPlusLambert one(0.3, 0.5, 0.7);
  const Furnace many = furnace(one, dir(0.8));
  for (const BoundVerdict* b : {&many.verdict.conservation, &many.verdict.preservation}) {
    EXPECT_EQ(b->decision, Decision::Pass);
    EXPECT_LE(b->band, b->tolerance);
  }
  const Furnace few = furnace(one, dir(0.8), {}, 2, 16);
  EXPECT_EQ(few.verdict.conservation.decision, Decision::NotJudged);
  EXPECT_EQ(few.verdict.preservation.decision, Decision::NotJudged);
  // Synthetic estimates: E = 1 +- 0.1 (one standard error) by both estimators: band 0.4.
  AlbedoEstimate e;
  e.value = Rgb(1.0);
  e.std_error = Rgb(0.1);
  SampledAlbedo s;
  s.total = s.non_delta = e;
  s.delta.value = Rgb(0.0);
  const EnergyVerdict v = judge_energy(e, s, EnergyTolerances{});
  EXPECT_EQ(v.conservation.decision, Decision::NotJudged);
  EXPECT_NEAR(v.conservation.band, 0.4, 1e-12);
  EXPECT_EQ(v.conservation.reason(), "band ±0.4 wider than the tolerance 0.01");
  EXPECT_EQ(v.agreement.decision, Decision::NotJudged);  // 4 hypot(0.1, 0.1) > 0.02
  // A gain of 2 bands is detected whatever the width.
  e.value = Rgb(1.0 + 0.01 + 0.8);
  s.total = e;
  EXPECT_EQ(judge_energy(e, s, EnergyTolerances{}).conservation.decision, Decision::Fail);
}

TEST(ValidateFurnace, LossyLobeFailsPreservationButConserves) {
  const Furnace f = furnace(LambertLobe(0.9), dir(0.7));
  EXPECT_FALSE(f.verdict.preserving());
  EXPECT_TRUE(f.verdict.conserving());
  EXPECT_TRUE(furnace(LambertLobe(1.0), dir(0.7)).verdict.preserving());
}

TEST(ValidateFurnace, WrongSampleWeightMakesEstimatorsDisagree) {
  const Furnace ok = furnace(GgxReflectionLobe(0.3), dir(0.5));
  EXPECT_TRUE(ok.verdict.estimators_agree());
  const Furnace bad = furnace(WeightScaledGgx(0.3, 1.1), dir(0.5));
  EXPECT_FALSE(bad.verdict.estimators_agree());
}

TEST(ValidateFurnace, SamplerMissingPartOfTheLobeMakesEstimatorsDisagree) {
  // The leaky sampler wastes 20% of its samples with zero weight: it under-counts the albedo.
  const Furnace bad = furnace(LeakyLambert(1.0, 0.2), dir(0.5));
  EXPECT_FALSE(bad.verdict.estimators_agree());
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
