// The validation run (validate/suite.h) end to end on test doubles, and one DSPBR energy statement
// of the report checked from first principles.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/quadrature.h"
#include "dspbr/validate/furnace.h"
#include "dspbr/validate/lut_reference.h"
#include "dspbr/validate/suite.h"
#include "validate_doubles.h"

using namespace dspbr;
using namespace dspbr::validate;
using namespace dspbr::testing;

namespace {

SuiteSettings tiny_settings() {
  SuiteSettings s = SuiteSettings::defaults(true);
  s.progress = false;
  s.chi2.samples = 20000;
  s.chi2.theta_bins = 12;
  s.image_res = 8;
  s.image_spp = 4;
  return s;
}

Catalog doubles_catalog() {
  Catalog cat;
  auto add = [&](const std::string& name, std::shared_ptr<const Bsdf> b, EnergyClaim claim) {
    BsdfCase c;
    c.name = name;
    c.component = "test";
    c.bsdf = std::move(b);
    c.claim = claim;
    cat.cases.push_back(c);
  };
  add("lambert", std::make_shared<LambertLobe>(1.0), EnergyClaim::Preserving);
  add("ggx", std::make_shared<GgxReflectionLobe>(0.3), EnergyClaim::Conserving);
  add("gaining lambert", std::make_shared<LambertLobe>(1.1), EnergyClaim::Conserving);
  add("non-reciprocal", std::make_shared<NonReciprocalLambert>(0.5, 0.3), EnergyClaim::Conserving);
  cat.stability.push_back({"test", "unguarded", std::make_shared<UnguardedGgx>(0.3)});
  FurnaceRow row;
  row.name = "lambert";
  row.parameter = "albedo";
  row.values = {1.0};
  row.bsdfs = {std::make_shared<LambertLobe>(1.0)};
  cat.furnace_rows.push_back(row);
  return cat;
}

}  // namespace

TEST(ValidateSuite, FlagsEachBrokenDoubleAndWritesTheData) {
  const std::string dir = ::testing::TempDir() + "/validate_suite_a";
  const SuiteResult r = run_suite(doubles_catalog(), nullptr, tiny_settings(), dir);
  auto failed_with = [&](const std::string& check, const std::string& what) {
    for (const std::string& f : r.failures)
      if (f.rfind(check, 0) == 0 && f.find(what) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(failed_with("furnace: conservation", "gaining lambert"));
  EXPECT_TRUE(failed_with("reciprocity", "non-reciprocal"));
  EXPECT_TRUE(failed_with("stability", "test"));
  EXPECT_FALSE(failed_with("furnace: preservation", "lambert"));
  EXPECT_FALSE(failed_with("sampling", "ggx"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/data/report.json"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/images/furnace_lambert.exr"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/images/furnace_lambert.png"));
  EXPECT_EQ(r.report["tables"]["available"], false);
}

TEST(ValidateSuite, SameSeedSameReport) {
  const SuiteSettings s = tiny_settings();
  const SuiteResult a = run_suite(doubles_catalog(), nullptr, s, ::testing::TempDir() + "/validate_suite_b");
  const SuiteResult b = run_suite(doubles_catalog(), nullptr, s, ::testing::TempDir() + "/validate_suite_c");
  EXPECT_EQ(a.report.dump(), b.report.dump());
}

// The report's statement that the spec's sheen layering loses energy (docs/validation.md): with a
// Lambertian base (specular = 0), the spec's ShinyCore gives
//   E(v) = E_b(v) + 2 Integral_0^1 (1 - max(E_b(v), E_b(l))) mu_l dmu_l,
// computed here from independent sheen albedos (lut_reference.h, no table), and the reference
// BSDF's furnace albedo must match it: at normal incidence and alpha_b = 0.25 it is about 0.88.
TEST(ValidateSuite, SheenLayeringLossMatchesTheSpecFormula) {
  Material m;
  m.specular = 0;  // B = B_u: Lambertian base of albedo 1
  m.sheenColor = Rgb(1.0);
  m.sheenRoughness = 0.5;
  const MaterialBsdf bsdf(m);
  const double alpha_b = 0.25, mu_v = 1.0;
  const RefQuadrature q{12};
  const double ev = sheen_albedo_ref(mu_v, alpha_b, false, q).value;
  const QuadratureRule rule = gauss_legendre(24);
  const double predicted = ev + integrate_gl(
                                    [&](double mu) {
                                      const double el = sheen_albedo_ref(std::max(mu, 1e-6), alpha_b, false, q).value;
                                      return 2.0 * (1.0 - std::max(ev, el)) * mu;
                                    },
                                    0.0, 1.0, 2, rule);
  const SampledAlbedo e = albedo_sampled(bsdf, Vec3{0, 0, 1}, 40000, 3, 1);
  EXPECT_LT(predicted, 0.95);  // a real loss, not noise
  // Tolerance: 4 sigma + 5e-3 for the table interpolation of E_b inside the BSDF.
  EXPECT_NEAR(e.total.value.g, predicted, 4 * e.total.std_error.g + 5e-3);
}
