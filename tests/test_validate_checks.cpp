// The validation checks (src/dspbr/validate/) on correct test lobes (must pass) and on
// deliberately broken ones (must fail): every check is shown to be able to fail.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "dspbr/constants.h"
#include "dspbr/lutgen/microfacet_quadrature.h"
#include "dspbr/validate/albedo_quadrature.h"
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
  QuadratureAlbedo quad;
  SampledAlbedo sampled;
  EnergyVerdict verdict;
};

Furnace furnace(const Bsdf& b, const Vec3& v, const EnergyTolerances& tol = {}, std::size_t samples = 40000) {
  Furnace f;
  f.quad = albedo_quadrature(b, v, 1.0, 1e-6);
  f.sampled = albedo_sampled(b, v, samples, 7, 2);
  f.verdict = judge_energy(f.quad, f.sampled, tol);
  return f;
}

// A cone BSDF (spec "Flake BSDF"): 1 / Omega inside the cone of half-angle theta_c about
// reflect(v, n_f), 0 outside; sampled uniformly in the cone.
class ConeLobe : public Bsdf {
 public:
  ConeLobe(const Vec3& n_f, double cos_cone) : n_f_(n_f), cos_(cos_cone) {}
  double omega() const { return 2 * kPi * (1 - cos_); }
  Vec3 axis(const Vec3& v) const { return reflect(v, n_f_); }
  Rgb eval(const Vec3& v, const Vec3& l) const override {
    return Rgb(dot(l, axis(v)) > cos_ && l.z > 0 ? 1 / omega() : 0.0);
  }
  double pdf(const Vec3& v, const Vec3& l) const override { return dot(l, axis(v)) > cos_ ? 1 / omega() : 0.0; }
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    const double c = 1 - u.y * (1 - cos_), s = std::sqrt(std::max(0.0, 1 - c * c)), phi = 2 * kPi * u.z;
    const Vec3 a = axis(v);
    const Vec3 t = normalize(std::abs(a.z) < 0.9 ? cross(a, Vec3{0, 0, 1}) : cross(a, Vec3{1, 0, 0}));
    const Vec3 l = c * a + s * (std::cos(phi) * t + std::sin(phi) * cross(a, t));
    if (l.z <= 0) return {};
    return make_sample(*this, v, l, kLobeReflection | kLobeGlossy);
  }
  uint32_t flags() const override { return kLobeReflection | kLobeGlossy; }

 private:
  Vec3 n_f_;
  double cos_;
};

}  // namespace

// ---------------------------------------------------------------- white furnace

TEST(ValidateFurnace, LambertAlbedoMatchesClosedForm) {
  // Integral of rho/pi |cos| over the hemisphere is rho: both estimators, every direction.
  for (double c : {1.0, 0.5, 0.05, -0.7}) {
    const Furnace f = furnace(LambertLobe(0.8), dir(c));
    EXPECT_NEAR(f.quad.value.r, 0.8, f.quad.error + 1e-12) << c;
    EXPECT_LT(f.quad.error, 1e-6) << c;
    // Cosine sampling of a Lambert lobe has weight exactly rho: zero variance.
    EXPECT_NEAR(f.sampled.total.value.r, 0.8, 1e-12) << c;
    EXPECT_TRUE(f.verdict.conserving() && f.verdict.estimators_agree());
  }
}

TEST(ValidateFurnace, GgxAlbedoMatchesQuadrature) {
  // Independent reference: E_m(mu; alpha = r^2) of the single-scattering BRDF by the table
  // integrator's quadrature over the half vector in the GGX CDF variable, to 1e-10
  // (lutgen/microfacet_quadrature.h), against the furnace's quadrature of eval over l in log-polar
  // coordinates about the mirror direction: from a wide lobe to alpha = 0.0025, from normal to
  // grazing view, each within the errors both state.
  for (double r : {1.0, 0.5, 0.2, 0.05}) {
    for (double mu : {1.0, 0.6, 0.1, 0.02}) {
      const QuadResult<2> ref = ggx_moments_quadrature(mu, r * r, 1e-10);
      const Furnace f = furnace(GgxReflectionLobe(r * r), dir(mu, 0.0));
      EXPECT_NEAR(f.quad.value.r, ref.value[0], f.quad.error + ref.error) << "r " << r << " mu " << mu;
      EXPECT_LT(f.quad.error, 1e-6) << "r " << r << " mu " << mu;
    }
  }
  const Furnace f = furnace(GgxReflectionLobe(0.25), dir(0.6, 0.0));
  EXPECT_NEAR(f.sampled.total.value.r, f.quad.value.r, 4 * f.sampled.total.std_error.r);
  EXPECT_TRUE(f.verdict.conserving() && f.verdict.estimators_agree());
}

TEST(ValidateFurnace, QuadratureSplitsAtANamedConeJump) {
  // A cone of half-angle 7 degrees about reflect(v, n_f), wholly above the horizon:
  // E = Integral over the cone of l.z dl / Omega = a.z pi sin^2(theta_c) / Omega (a: its axis).
  const double cos_cone = std::cos(7 * kPi / 180);
  const Vec3 n_f = normalize(Vec3{0.3, -0.2, 1.0});
  const ConeLobe cone(n_f, cos_cone);
  for (double c : {1.0, 0.7, 0.4}) {
    const Vec3 v = dir(c);
    const Vec3 a = cone.axis(v);
    ASSERT_GT(a.z, std::sin(7 * kPi / 180)) << c;
    const double exact = a.z * kPi * (1 - cos_cone * cos_cone) / cone.omega();
    const QuadratureAlbedo q = albedo_quadrature(cone, v, 1.0, 1e-6, {{a, cos_cone}});
    EXPECT_NEAR(q.value.r, exact, q.error + 1e-12) << c;
    EXPECT_LT(q.error, 1e-6) << c;
    // Without the cone named, the rule's panels straddle the jump: no longer within 1e-6.
    const QuadratureAlbedo blind = albedo_quadrature(cone, v, 1.0, 1e-6);
    EXPECT_GT(std::abs(blind.value.r - exact) + blind.error, 1e-6) << c;
  }
}

TEST(ValidateFurnace, TransmissionPeakObeysSnell) {
  for (double eta : {1.0, 1.0 / 1.5, 1.5}) {
    for (double c : {0.9, 0.5, -0.5, -0.02}) {
      const Vec3 v = dir(c, 0.4);
      const Vec3 t = transmission_peak(v, eta);
      EXPECT_NEAR(length(t), 1.0, 1e-12);
      EXPECT_LT(t.z * v.z, 0.0 + 1e-15) << eta << " " << c;  // the other side (or the horizon)
      const double sin_v = std::sqrt(1 - c * c), sin_t = std::sqrt(std::max(0.0, 1 - t.z * t.z));
      if (eta * sin_v < 1) {
        EXPECT_NEAR(sin_t, eta * sin_v, 1e-12) << eta << " " << c;  // Snell: eta_v sin_v = eta_t sin_t
        EXPECT_LE(t.x * v.x + t.y * v.y, 0.0);                     // the plane of incidence, across the normal
      } else {
        EXPECT_EQ(t.z, 0.0);  // total internal reflection: the horizon
      }
    }
  }
}

TEST(ValidateFurnace, DeltaLobeCountedOnlyBySampling) {
  // Mirror (0.3) + Lambert (0.7): total 1; the quadrature sees only the Lambert part.
  const Furnace f = furnace(MirrorPlusLambert(0.3, 0.4, 0.7), dir(0.8));
  EXPECT_NEAR(f.sampled.total.value.r, 1.0, 4 * f.sampled.total.std_error.r + 1e-12);
  EXPECT_NEAR(f.quad.value.r, 0.7, f.quad.error + 1e-12);
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
  const Furnace few = furnace(gain, dir(0.8), {}, 16);
  const BoundVerdict& c = few.verdict.conservation;
  EXPECT_EQ(c.decision, Decision::NotJudged);
  EXPECT_GT(c.band, 0.01 * 10);
  EXPECT_EQ(c.tolerance, 0.01);
  EXPECT_NE(c.reason().find("wider than the tolerance 0.01"), std::string::npos) << c.reason();
  // The same budget on a lobe without variance (Lambert, cosine sampling: weight exactly rho)
  // has a zero band, so it is judged: pass at 1, fail at 1.05.
  EXPECT_EQ(furnace(LambertLobe(1.0), dir(0.8), {}, 16).verdict.conservation.decision, Decision::Pass);
  EXPECT_EQ(furnace(LambertLobe(1.05), dir(0.8), {}, 16).verdict.conservation.decision, Decision::Fail);
}

TEST(ValidateFurnace, PassOnlyWhereTheBandLiesWithinTheTolerance) {
  // A correct mixture (mirror 0.3 + Lambert 0.7, E = 1): PASS with enough samples, where the
  // band of the narrower estimator is within the tolerance; NOT JUDGED with 16 samples.
  const MirrorPlusLambert one(0.3, 0.5, 0.7);
  const Furnace many = furnace(one, dir(0.8), {}, 160000);
  for (const BoundVerdict* b : {&many.verdict.conservation, &many.verdict.preservation}) {
    EXPECT_EQ(b->decision, Decision::Pass);
    EXPECT_LE(b->band, b->tolerance);
  }
  const Furnace few = furnace(one, dir(0.8), {}, 16);
  EXPECT_EQ(few.verdict.conservation.decision, Decision::NotJudged);
  EXPECT_EQ(few.verdict.preservation.decision, Decision::NotJudged);
  // Synthetic estimates: E = 1 +- 0.1 (one standard error, sampled) and 1 +- 0.4 (the
  // quadrature's stated error): band 0.4 either way.
  AlbedoEstimate e;
  e.value = Rgb(1.0);
  e.std_error = Rgb(0.1);
  SampledAlbedo s;
  s.total = s.non_delta = e;
  s.delta.value = Rgb(0.0);
  QuadratureAlbedo q;
  q.value = Rgb(1.0);
  q.error = 0.4;
  const EnergyVerdict v = judge_energy(q, s, EnergyTolerances{});
  EXPECT_EQ(v.conservation.decision, Decision::NotJudged);
  EXPECT_NEAR(v.conservation.band, 0.4, 1e-12);
  EXPECT_EQ(v.conservation.reason(), "band ±0.4 wider than the tolerance 0.01");
  EXPECT_EQ(v.agreement.decision, Decision::NotJudged);  // 4 x 0.1 + 0.4 > 0.02
  EXPECT_FALSE(v.conservation.beyond);  // E = 1: within the bound, band aside
  // E = 1.05 with the same bands: still NOT JUDGED, but beyond 1 + 0.01 (the report marks it).
  q.value = e.value = Rgb(1.05);
  s.total = e;
  const EnergyVerdict beyond = judge_energy(q, s, EnergyTolerances{});
  EXPECT_EQ(beyond.conservation.decision, Decision::NotJudged);
  EXPECT_TRUE(beyond.conservation.beyond);
  // A gain of 2 bands is detected whatever the width.
  q.value = e.value = Rgb(1.0 + 0.01 + 0.8);
  s.total = e;
  EXPECT_EQ(judge_energy(q, s, EnergyTolerances{}).conservation.decision, Decision::Fail);
  // The agreement's widest band is relative where the albedo exceeds 1: E = 4 +- 0.01 (band 0.04)
  // is judged (0.04 <= 0.02 x 4), and so is E = 1 +- 0.004 (band 0.016); E = 1 +- 0.01 is not.
  for (const auto& [value, se, judged] : {std::tuple{4.0, 0.01, true}, {1.0, 0.004, true}, {1.0, 0.01, false}}) {
    s.total.value = s.non_delta.value = q.value = Rgb(value);
    s.total.std_error = s.non_delta.std_error = Rgb(se);
    q.error = 0;
    EXPECT_EQ(judge_energy(q, s, EnergyTolerances{}).agreement.decision == Decision::Pass, judged) << value << " " << se;
  }
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
