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

// Adds a test case of component "test" to `cat`.
void add_case(Catalog& cat, const std::string& name, std::shared_ptr<const Bsdf> b, EnergyClaim claim) {
  BsdfCase c;
  c.name = name;
  c.component = "test";
  c.bsdf = std::move(b);
  c.claim = claim;
  cat.cases.push_back(c);
}

Catalog doubles_catalog() {
  Catalog cat;
  auto add = [&](const std::string& name, std::shared_ptr<const Bsdf> b, EnergyClaim claim) {
    add_case(cat, name, std::move(b), claim);
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

// A failure of check `check` (the start of its line) whose line names `what`.
bool has_failure(const SuiteResult& r, const std::string& check, const std::string& what) {
  for (const std::string& f : r.failures)
    if (f.rfind(check, 0) == 0 && f.find(what) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(ValidateSuite, FlagsEachBrokenDoubleAndWritesTheData) {
  const std::string dir = ::testing::TempDir() + "/validate_suite_a";
  const SuiteResult r = run_suite(doubles_catalog(), nullptr, tiny_settings(), dir);
  auto failed_with = [&](const std::string& check, const std::string& what) { return has_failure(r, check, what); };
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
// at the first cell, where the albedo is below 1). On the corner cells its own standard errors are
// so large that an allowance widened by them ("2e-3 + 4 se") passes every cell; the fixed allowance
// must fail it. The same layout integrated by QMC passes.
TEST(ValidateSuite, TableCheckFailsANoisyTableWhateverItsOwnErrorEstimate) {
  SuiteSettings s = tiny_settings();
  s.lut_cells_per_axis = 2;  // the corners: indices 0 and 7 of each axis
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

namespace {
const nlohmann::json* checked_table(const SuiteResult& r, Lut id) {
  for (const auto& t : r.report["tables"]["tables"])
    if (t["name"] == lut_name(id)) return &t;
  return nullptr;
}
}  // namespace

// The table check covers every table the BSDF cases read: with the built-in renderer set, each
// table of the registry's renderer layout (GGX_beta, GGX_B_avg and the four glass tables
// included), the values its lookups return at its samples against the reference quadrature, and
// they pass; a renderer table scaled by 0.95 fails.
TEST(ValidateSuite, TableCheckCoversEveryRendererTable) {
  const SuiteSettings s = tiny_settings();
  const LutSet& ren = LutSet::builtin();
  ASSERT_EQ(ren.layout, LutLayout::Renderer);
  const SuiteResult r = run_suite(Catalog{}, &ren, s, ::testing::TempDir() + "/validate_suite_t3");
  EXPECT_EQ(table_failures(r), 0);
  EXPECT_EQ(r.report["tables"]["layout"], "renderer");
  for (const LutInfo& info : lut_registry()) {
    if ((info.layouts & kRendererLayout) == 0) continue;
    const nlohmann::json* t = checked_table(r, info.id);
    ASSERT_NE(t, nullptr) << info.name;
    EXPECT_EQ((*t)["verdict"], "PASS") << info.name << ": " << (*t)["max_abs_error"];
    EXPECT_GT((*t)["nodes"].get<int>(), 0) << info.name;
    EXPECT_LE((*t)["max_abs_error"].get<double>(), (*t)["tolerance"].get<double>()) << info.name;
    EXPECT_EQ((*t)["tolerance"].get<double>(), info.average ? s.renderer_avg_lut_tol : s.renderer_lut_tol) << info.name;
  }
  LutSet broken = ren;
  for (double& v : broken.renderer.table(Lut::GgxBAvg).values) v *= 0.95;
  const SuiteResult b = run_suite(Catalog{}, &broken, s, ::testing::TempDir() + "/validate_suite_t4");
  EXPECT_EQ(table_failures(b), 1);
  EXPECT_EQ((*checked_table(b, Lut::GgxBAvg))["verdict"], "FAIL");
}

// A case whose furnace band is wider than the tolerance (mirror 0.3 chosen with probability 0.5
// + Lambert 0.7, E = 1, 256 samples: band about 4 x 0.35 / 16) is NOT JUDGED, not PASS: counted
// in the summary and the banner, with band and tolerance in its row. The zero-variance Lambert
// beside it is judged (PASS).
TEST(ValidateSuite, WideFurnaceBandIsNotJudgedAndCounted) {
  Catalog cat;
  for (const auto& [name, bsdf] : std::vector<std::pair<std::string, std::shared_ptr<const Bsdf>>>{
           {"noisy mixture", std::make_shared<MirrorPlusLambert>(0.3, 0.5, 0.7)},
           {"lambert", std::make_shared<LambertLobe>(1.0)}}) {
    BsdfCase c;
    c.name = name;
    c.component = "test";
    c.bsdf = bsdf;
    c.claim = EnergyClaim::Preserving;
    cat.cases.push_back(c);
  }
  SuiteSettings s = tiny_settings();
  s.furnace_samples = s.furnace_samples_max = 256;  // no growth: the band stays wide
  s.furnace_cos = {0.8};
  const SuiteResult r = run_suite(cat, nullptr, s, ::testing::TempDir() + "/validate_suite_nj");
  EXPECT_EQ(r.failed_checks, 0);
  int nj_conservation = -1;
  for (const auto& row : r.report["summary"])
    if (row["check"] == "furnace: conservation (E <= 1 + tol)") {
      nj_conservation = row["not_judged"];
      EXPECT_EQ(row["passed"], 1);
    }
  EXPECT_EQ(nj_conservation, 1);
  const auto& rows = r.report["energy"]["rows"];
  ASSERT_EQ(rows.size(), 2u);
  const auto& noisy = rows[0]["judged"]["conservation"];
  EXPECT_EQ(noisy["status"], "NOT JUDGED");
  EXPECT_GT(noisy["band"].get<double>(), noisy["tolerance"].get<double>());
  EXPECT_NE(noisy["reason"].get<std::string>().find("wider than the tolerance"), std::string::npos);
  const auto& lambert = rows[1]["judged"]["conservation"];
  EXPECT_EQ(lambert["status"], "PASS");
  EXPECT_LE(lambert["band"].get<double>(), lambert["tolerance"].get<double>());
  // Only the judged case has an albedo range the report may attribute to the BSDF.
  EXPECT_FALSE(r.report["energy"]["cases"][0].contains("judged_min"));
  EXPECT_TRUE(r.report["energy"]["cases"][1].contains("judged_min"));
  const std::string banner = r.report["banner"];
  EXPECT_EQ(banner.rfind("QUICK run", 0), 0u) << banner;
  EXPECT_NE(banner.find("NOT JUDGED"), std::string::npos) << banner;
  EXPECT_NE(banner.find("furnace: conservation (E <= 1 + tol) (1 of 2)"), std::string::npos) << banner;
}

namespace {

// A BSDF that loses `loss` of its energy at grazing views (|cos theta_v| < 0.15) and nowhere else:
// eval and the sample weights scaled alike, so that its estimators agree.
class GrazingLoss : public Bsdf {
 public:
  GrazingLoss(std::shared_ptr<const Bsdf> b, double loss) : b_(std::move(b)), loss_(loss) {}
  double k(const Vec3& v) const { return std::abs(v.z) < 0.15 ? 1 - loss_ : 1; }
  Rgb eval(const Vec3& v, const Vec3& l) const override { return b_->eval(v, l) * k(v); }
  double pdf(const Vec3& v, const Vec3& l) const override { return b_->pdf(v, l); }
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    BsdfSample s = b_->sample(v, u);
    s.weight = s.weight * k(v);
    return s;
  }
  uint32_t flags() const override { return b_->flags(); }

 private:
  std::shared_ptr<const Bsdf> b_;
  double loss_;
};

}  // namespace

// The issue's planted fault: white metal at one roughness (0.5), which preserves energy, made to
// lose 1.5% at grazing views. The full run's furnace FAILs it at cos 0.1 and 0.02 and nowhere
// else (the quadrature's band is ~1e-5, the preservation tolerance 0.005); the same metal without
// the loss passes every furnace verdict with power.
TEST(ValidateSuite, PlantedGrazingLossFailsTheFullRun) {
  Material m;
  m.metallic = 1;
  m.roughness = 0.5;
  const auto metal = std::make_shared<MaterialBsdf>(m);
  for (double loss : {0.015, 0.0}) {
    Catalog cat;
    BsdfCase c;
    c.name = "white metal r=0.5";
    c.component = "test";
    c.bsdf = std::make_shared<GrazingLoss>(metal, loss);
    c.claim = EnergyClaim::Preserving;
    c.chi2 = false;
    cat.cases.push_back(c);
    SuiteSettings s = SuiteSettings::defaults(false);
    s.progress = false;
    const SuiteResult r = run_suite(cat, nullptr, s, ::testing::TempDir() + "/validate_suite_planted");
    std::vector<std::string> failed_views;
    for (const std::string& f : r.failures) {
      if (f.rfind("reciprocity", 0) == 0) continue;  // a loss that depends on v alone is not reciprocal either
      EXPECT_EQ(f.rfind("furnace: preservation", 0), 0u) << f;
      failed_views.push_back(f.substr(f.find("at cos="), 11));
    }
    if (loss > 0) {
      EXPECT_EQ(failed_views, (std::vector<std::string>{"at cos=0.1:", "at cos=0.02"})) << loss;
    } else {
      EXPECT_TRUE(failed_views.empty());
    }
    for (const auto& row : r.report["energy"]["rows"])
      for (const auto& [check, v] : row["judged"].items())
        EXPECT_NE(v["status"], "NOT JUDGED") << check << " " << row["cos"];
  }
}

// Another implementation's section (suite.h, OtherImplementation; `dspbr validate`'s shader
// library): its own furnace, chi-square, stability and conformance verdicts, named apart, each able
// to fail: a preserving claim on a Lambert of albedo 0.9, a stability case that returns NaN, and a
// conformance group with a failing vector fail; the correct ones beside them pass.
TEST(ValidateSuite, AnotherImplementationsVerdictsCountAndCanFail) {
  OtherImplementation other;
  other.name = "test implementation";
  add_case(other.catalog, "white lambert", std::make_shared<LambertLobe>(1.0), EnergyClaim::Preserving);
  add_case(other.catalog, "lossy lambert", std::make_shared<LambertLobe>(0.9), EnergyClaim::Preserving);
  other.catalog.stability.push_back({"test", "unguarded", std::make_shared<UnguardedGgx>(0.3), std::nullopt, {}});
  other.vector_set = "two groups";
  other.conformance = [] {
    return std::vector<ConformanceGroup>{{"good", 10, 0, 0.5, "good/00"}, {"bad", 10, 2, 3.0, "bad/07"}};
  };
  const SuiteResult r =
      run_suite(doubles_catalog(), nullptr, tiny_settings(), ::testing::TempDir() + "/validate_suite_other", &other);
  auto failed_with = [&](const std::string& check, const std::string& what) { return has_failure(r, check, what); };
  EXPECT_TRUE(failed_with("shader library: furnace: preservation", "lossy lambert"));
  EXPECT_FALSE(failed_with("shader library: furnace", "white lambert"));
  EXPECT_TRUE(failed_with("shader library: stability", "test"));
  EXPECT_TRUE(failed_with("shader library: conformance", "bad: 2 of 10 vectors fail"));
  EXPECT_FALSE(failed_with("shader library: conformance", "good"));
  // The reference's own verdicts keep their names.
  EXPECT_TRUE(failed_with("furnace: conservation", "gaining lambert"));
  const auto& lib = r.report["shader_library"];
  EXPECT_EQ(lib["conformance"]["vectors"], 20);
  EXPECT_EQ(lib["conformance"]["failed"], 2);
  EXPECT_EQ(lib["energy"]["cases"].size(), 2u);
  EXPECT_EQ(lib["chi2"]["tests"].size(), 2 * tiny_settings().chi2_cos.size());
  int failed = 0;
  for (const auto& row : r.report["summary"]) failed += row["failed"].get<int>();
  EXPECT_EQ(failed, r.failed_checks);
}
