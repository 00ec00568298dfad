// The validation run (validate/suite.h) end to end on test doubles, and one DSPBR energy statement
// of the report checked from first principles.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <tbb/global_control.h>

#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/lutgen/generate.h"
#include "dspbr/quadrature.h"
#include "dspbr/validate/furnace.h"
#include "dspbr/validate/lut_reference.h"
#include "dspbr/validate/suite.h"
#include "test_params_run.h"
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

// Bit-identical whatever the thread count, except the "run" part (date, threads, command line).
TEST(ValidateSuite, SameSeedSameReport) {
  const SuiteSettings s = tiny_settings();
  SuiteResult a;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    a = run_suite(doubles_catalog(), nullptr, s, ::testing::TempDir() + "/validate_suite_b");
  }
  SuiteResult b = run_suite(doubles_catalog(), nullptr, s, ::testing::TempDir() + "/validate_suite_c");
  EXPECT_EQ(a.report["run"]["threads"], 1);
  a.report.erase("run");
  b.report.erase("run");
  EXPECT_EQ(a.report.dump(), b.report.dump());
  EXPECT_TRUE(a.report["provenance"].contains("git_commit"));
}

// A failure that matches a waiver (waivers.h; here the alternative sheen's gain, matched by case
// name) is WAIVED with its reason and does not count; the same failure elsewhere still does.
TEST(ValidateSuite, WaivedFailuresAreListedButDoNotCount) {
  Catalog cat = doubles_catalog();
  BsdfCase c;
  c.name = "white sheen (alternative visibility) stand-in";
  c.component = "test";
  c.bsdf = std::make_shared<LambertLobe>(1.1);
  cat.cases.push_back(c);
  const SuiteResult r = run_suite(cat, nullptr, tiny_settings(), ::testing::TempDir() + "/validate_suite_w");
  auto has = [](const std::vector<std::string>& lines, const std::string& what) {
    for (const std::string& f : lines)
      if (f.find(what) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(has(r.waived, "stand-in"));
  EXPECT_FALSE(has(r.failures, "stand-in"));
  EXPECT_TRUE(has(r.failures, "gaining lambert"));
  int failed = 0, waived = 0;
  for (const auto& row : r.report["summary"]) {
    failed += row["failed"].get<int>();
    waived += row["waived"].get<int>();
  }
  EXPECT_EQ(failed, r.failed_checks);
  EXPECT_EQ(waived, int(r.waived.size()));
  EXPECT_GT(waived, 0);
}

namespace {
// An 8 x 8 GGX_E made by `integrator` (plain MC: 65536 samples per cell, no adaptive stop).
LutSet ggx_e_only(Integrator integrator) {
  LutOptions o;
  o.tables = {"GGX_E"};
  o.sizes["GGX_E"] = {8, 8};
  o.integrator = integrator;
  o.samples = 65536;
  o.target_error = 0;
  o.progress = false;
  LutSet set;
  set.ggx_e = generate_luts(o).at(0);
  return set;
}
int table_failures(const SuiteResult& r) {
  for (const auto& row : r.report["summary"])
    if (row["check"] == "tables: LUT vs independent reference") return row["failed"].get<int>();
  return -1;
}
}  // namespace

// Broken double of the table check: a plain-MC GGX_E whose noise is as large as its values (5.6
// at the first cell, where the albedo is below 1). On the quick run's cells (the corners) its own
// standard errors are so large that an allowance widened by them ("2e-3 + 4 se") passes every
// cell; the fixed allowance must fail it. The same layout integrated by QMC passes.
TEST(ValidateSuite, TableCheckFailsANoisyTableWhateverItsOwnErrorEstimate) {
  SuiteSettings s = tiny_settings();
  ASSERT_EQ(s.lut_cells_per_axis, 2);  // the quick run's spread: indices 0 and 7 of each axis
  const LutSet noisy = ggx_e_only(Integrator::Mc);
  const SuiteResult bad = run_suite(Catalog{}, &noisy, s, ::testing::TempDir() + "/validate_suite_t1");
  EXPECT_EQ(table_failures(bad), 1);
  const auto& cells = bad.report["tables"]["tables"][0]["cells"];
  bool fooled_old_rule = true, far_off = false;
  for (const auto& c : cells) {
    const double err = c["abs_error"], se = c["table_se"];
    if (!(err <= s.lut_tol + 4 * se + c["reference_err"].get<double>())) fooled_old_rule = false;
    if (err > 0.1) far_off = true;
  }
  EXPECT_TRUE(fooled_old_rule);  // the double is the one that fooled "2e-3 + 4 se"
  EXPECT_TRUE(far_off);
  const LutSet good = ggx_e_only(Integrator::Qmc);
  const SuiteResult ok = run_suite(Catalog{}, &good, s, ::testing::TempDir() + "/validate_suite_t2");
  EXPECT_EQ(table_failures(ok), 0);
}

TEST(ValidateSuite, MissingTablesAreNamed) {
  EXPECT_EQ(missing_tables(LutSet{}).size(), 6u);
  EXPECT_TRUE(missing_tables(LutSet::published()).empty());
  LutSet partial = LutSet::published();
  partial.sheen_ash_e = Table{};
  EXPECT_EQ(missing_tables(partial), std::vector<std::string>{"Sheen_ash_E"});
}

// The catalog's BSDFs read the tables they are given (`dspbr validate --luts`), not the built-in
// ones: with GGX_E scaled by 0.7 the multiple-scattering term of the rough white metal grows, and
// its albedo moves far beyond the noise.
TEST(ValidateSuite, CatalogBsdfsUseTheGivenTables) {
  LutSet scaled = LutSet::published();
  for (double& v : scaled.ggx_e.values) v *= 0.7;
  CatalogOptions co;
  co.quick = true;
  co.random_materials = 0;
  const Catalog builtin = dspbr_catalog(co);
  co.luts = &scaled;
  const Catalog given = dspbr_catalog(co);
  auto albedo = [](const Catalog& cat) {
    for (const BsdfCase& c : cat.cases)
      if (c.name == "metallic r=1") return albedo_sampled(*c.bsdf, Vec3{0, 0, 1}, 20000, 5, 1).total;
    ADD_FAILURE() << "no case 'metallic r=1'";
    return AlbedoEstimate{};
  };
  const AlbedoEstimate a = albedo(builtin), b = albedo(given);
  EXPECT_GT(std::abs(a.value.g - b.value.g), 10 * std::hypot(a.std_error.g, b.std_error.g));
}

// Bad table files are usage errors (exit 2) on one line naming the file: no tables at all, or only
// some of the six (here the plain-MC GGX_E of `dspbr lut --tables GGX_E`).
TEST(ValidateCli, EmptyOrIncompleteTableFileIsAnError) {
  const std::string dir = ::testing::TempDir() + "/validate_cli_luts";
  std::filesystem::create_directories(dir);
  const std::string empty = dir + "/empty.json";
  std::ofstream(empty) << R"({"format": "dspbr_luts", "version": 1, "model": "DSPBR 2025x", "tables": {}})";
  ToolRun r = run_dspbr("validate --quick --no-html --out '" + dir + "/out' --luts '" + empty + "'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(count_lines_with(r.output, "error"), 1) << r.output;
  EXPECT_NE(r.output.find(empty), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/data/report.json"));

  ToolRun lut = run_dspbr("lut --out '" + dir + "/mc' --tables GGX_E --size GGX_E=8x8 --integrator mc --samples 65536 "
                          "--target-error 0");
  ASSERT_EQ(lut.status, 0) << lut.output;
  r = run_dspbr("validate --quick --no-html --out '" + dir + "/out' --luts '" + dir + "/mc/dspbr_luts.json'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("dspbr_luts.json: incomplete table file: missing or empty GGX_E_avg"), std::string::npos)
      << r.output;
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
