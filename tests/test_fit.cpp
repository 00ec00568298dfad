// The committed fits (fits/*.json, fits/dspbr_fits.hpp) against independent references:
//  - each fit stays within its stated error bound on a fresh grid (points not used by `dspbr fit`),
//    with the exact quantity computed here another way (sheen_lambda_exact; deterministic
//    Gauss-Legendre albedos of tests/test_lut_reference.h, not the QMC integrators the fits used);
//  - the generated header and the library evaluate the same functions;
//  - Ceres converges from the documented starting points (small, fast versions of the fits).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../fits/dspbr_fits.hpp"
#include "dspbr/fit/albedo_fit.h"
#include "dspbr/fit/albedo_forms.h"
#include "dspbr/fit/fits_header.h"
#include "dspbr/fit/flake_fit.h"
#include "dspbr/fit/sheen_lambda_fit.h"
#include "dspbr/fresnel.h"
#include "dspbr/sheen.h"
#include "test_lut_reference.h"

using namespace dspbr;
using namespace dspbr::fit;
using nlohmann::json;

namespace {

json load_fit(const std::string& name) {
  std::ifstream in(std::string(DSPBR_SOURCE_DIR) + "/fits/" + name + ".json");
  EXPECT_TRUE(in.good()) << "fits/" << name << ".json missing: run dspbr fit --out fits";
  return json::parse(in);
}

AlbedoFitParams albedo_params(const json& d) {
  AlbedoFitParams p;
  const auto& c = d["coefficients"];
  auto copy = [](const json& a, auto& dst) {
    EXPECT_EQ(a.size(), dst.size());
    for (size_t i = 0; i < dst.size() && i < a.size(); ++i) dst[i] = a[i].get<double>();
  };
  copy(c["ggx_E"], p.ggx_E);
  copy(c["ggx_E_avg"], p.ggx_E_avg);
  copy(c["ggx_E5"], p.ggx_E5);
  copy(c["ggx_E5_avg"], p.ggx_E5_avg);
  copy(c["sheen_E"], p.sheen_E);
  return p;
}

// Exact albedos by deterministic quadrature (independent of lut/albedo.h).
double exact_ggx_E(double mu, double r) { return lutref::ggx_albedo_quad(mu, r, 1.0, 32, 16); }
double exact_ggx_E5(double mu, double r) { return lutref::ggx_albedo_quad(mu, r, 0.0, 32, 16); }
double exact_ggx_E_avg(double r) {
  return lutref::cosine_average([&](double mu) { return exact_ggx_E(mu, r); }, 6);
}

// The stated bounds were measured against QMC references (4096 samples, standard error up to
// ~1e-4 at grazing cells); a fresh-point error may exceed the stated maximum by that noise.
constexpr double kReferenceNoise = 5e-4;

}  // namespace

TEST(FitSheenLambda, WithinStatedBoundOnFreshGrid) {
  const json d = load_fit("sheen_lambda");
  std::vector<double> q;
  for (const auto& x : d["coefficients"]) q.push_back(x.get<double>());
  ASSERT_EQ(q.size(), size_t(kSheenRichFormParams));
  const double stated = d["error"]["models"]["ours_rich"]["lambda_rel_error"]["max"].get<double>();
  const double a_min = d["domain"]["alpha_b"][0].get<double>();
  double worst = 0;
  for (double a : {a_min * 1.37, 0.011, 0.043, 0.13, 0.37, 0.71, 0.97})
    for (double mu : {0.0013, 0.0071, 0.033, 0.17, 0.41, 0.52, 0.77, 0.93, 0.995}) {
      const double exact = sheen_lambda_exact(mu, a);
      worst = std::max(worst, std::abs(sheen_lambda_rich(mu, a, q.data()) / exact - 1.0));
    }
  EXPECT_LE(worst, 1.1 * stated);  // between grid points the smooth error may grow a little
  EXPECT_LT(stated, 0.02);         // the headline: Lambda within 2% (spec's coefficients: ~60%)
  // Exact limits of the form: 0 at normal incidence, +inf at grazing, finite and positive between.
  EXPECT_EQ(sheen_lambda_rich(1.0, 0.3, q.data()), 0.0);
  EXPECT_TRUE(std::isinf(sheen_lambda_rich(0.0, 0.3, q.data())));
  // tiny positive cosines: finite, positive, no NaN (library and float header)
  for (double mu : {1e-30, 1e-12, 1e-7})
    for (double a : {a_min, 1.0}) {
      const double l = sheen_lambda_rich(mu, a, q.data());
      const float h = dspbr_fit_sheen_lambda(float(mu), float(a));
      EXPECT_TRUE(std::isfinite(l) && l > 0) << mu << " " << a;
      EXPECT_TRUE(std::isfinite(h) && h > 0) << mu << " " << a;
    }
}

// The spec's coefficients and the 2017 original are far off; the report says so (and the
// comparison is reproducible here on a few points).
TEST(FitSheenLambda, ReportedComparisonReproduces) {
  const json d = load_fit("sheen_lambda");
  const auto& m = d["error"]["models"];
  EXPECT_GT(m["spec"]["lambda_rel_error"]["max"].get<double>(), 0.2);
  EXPECT_GT(m["ck17"]["lambda_rel_error"]["max"].get<double>(), 0.5);
  // CK17 at alpha_b = 1/64, mu = 0.5: the 2017 curve underestimates Lambda by more than 30 %.
  const double exact = sheen_lambda_exact(0.5, 1.0 / 64);
  EXPECT_LT(sheen_lambda_ck17(0.5, 1.0 / 64) / exact, 0.7);
}

// The sheen albedo quadrature used for the downstream comparison matches the independent
// (mu_l, phi) quadrature of test_lut_reference.h.
TEST(FitSheenLambda, AlbedoQuadratureMatchesReference) {
  for (double a : {0.05, 0.4})
    for (double mu : {0.1, 0.6}) {
      const double ours = sheen_albedo_quadrature(mu, a, [](double x, double al) { return sheen_lambda(x, al); });
      const double ref = lutref::sheen_albedo_quad(mu, [&](const Vec3& v, const Vec3& l) { return sheen_brdf(v, l, a); });
      EXPECT_NEAR(ours, ref, 2e-4) << a << " " << mu;
    }
}

TEST(FitSheenLambda, CeresConvergesFromDocumentedStart) {
  SheenLambdaFitSettings s;
  s.n_alpha = 8;
  s.n_mu = 16;
  s.minimax.lawson_rounds = 3;
  FitContext ctx;
  ctx.threads = 1;
  const auto r = fit_sheen_lambda(s, ctx);
  EXPECT_TRUE(r.rich_summary.converged);
  // From the constant start (error ~100 % at small alpha_b) to a few percent on this coarse grid.
  EXPECT_LT(std::expm1(r.rich_summary.max_abs_residual), 0.03);
  const auto start = sheen_rich_start();
  EXPECT_GT(std::abs(sheen_lambda_rich(0.3, 1.0 / 128, start.data()) / sheen_lambda_exact(0.3, 1.0 / 128) - 1), 0.3);
}

// S(x; y1, y2) - target, for the convergence test.
struct DualPolyResidual {
  double x, y1, y2, target;
  template <class T>
  bool operator()(const T* q, T* r) const {
    r[0] = dual_poly2<T>(q, x, y1, y2) - T(target);
    return true;
  }
};

// The E_m form from the documented start (constant 1), on a small grid of quadrature values.
TEST(FitAlbedo, CeresConvergesFromDocumentedStart) {
  std::vector<DualPolyResidual> res;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      const double r = (i + 0.5) / 12, mu = 0.01 + 0.99 * j / 11.0;
      res.push_back({r, ggx_albedo_u(mu, r), mu, exact_ggx_E(mu, r)});
    }
  auto q = albedo_fit_start().ggx_E;
  const MinimaxSummary s = fit_minimax<kDualParams>(res, q, MinimaxOptions{1, 300, 1e-3});
  EXPECT_TRUE(s.converged);
  EXPECT_LT(s.max_abs_residual, 3e-3);  // from errors up to ~0.6 (E_m(grazing, r = 1) vs 1)
}

TEST(FitAlbedo, WithinStatedBoundsOnFreshGrid) {
  const json d = load_fit("albedo");
  const AlbedoFitParams p = albedo_params(d);
  const auto& e = d["error"];
  double w_em = 0, w_base = 0, w_avg = 0, w_base_avg = 0;
  for (double r : {0.07, 0.23, 0.46, 0.66, 0.89}) {
    const double ea = exact_ggx_E_avg(r);
    const double e5a = lutref::cosine_average([&](double mu) { return exact_ggx_E5(mu, r); }, 6);
    w_avg = std::max(w_avg, std::abs(fit_ggx_E_avg(r, p) - ea));
    for (double f0 : {0.04, 0.6}) {
      const double base_avg = f0 * ea + (1 - f0) * e5a + fresnel_ms(f0, 1.0, ea) * (1 - ea);
      w_base_avg = std::max(w_base_avg, std::abs(fit_base_E_avg(r, f0, p) - base_avg));
    }
    for (double mu : {0.013, 0.09, 0.31, 0.58, 0.86, 0.99}) {
      const double em = exact_ggx_E(mu, r), e5 = exact_ggx_E5(mu, r);
      w_em = std::max(w_em, std::abs(fit_ggx_E(mu, r, p) - em));
      for (double f0 : {0.04, 0.6}) {
        const double base = f0 * em + (1 - f0) * e5 + fresnel_ms(f0, 1.0, ea) * (1 - em);
        w_base = std::max(w_base, std::abs(fit_base_E(mu, r, f0, p) - base));
      }
    }
  }
  EXPECT_LE(w_em, e["ggx_E"]["max"].get<double>() + kReferenceNoise);
  EXPECT_LE(w_avg, e["ggx_E_avg"]["max"].get<double>() + kReferenceNoise);
  EXPECT_LE(w_base, e["base_E"]["max"].get<double>() + kReferenceNoise);
  EXPECT_LE(w_base_avg, e["base_E_avg"]["max"].get<double>() + kReferenceNoise);
}

TEST(FitAlbedo, SheenWithinStatedBoundOnFreshGrid) {
  const json d = load_fit("albedo");
  const AlbedoFitParams p = albedo_params(d);
  double worst = 0;
  for (double a : {0.02, 0.09, 0.3, 0.75})
    for (double mu : {0.04, 0.27, 0.55, 0.91}) {
      const double ref = lutref::sheen_albedo_quad(mu, [&](const Vec3& v, const Vec3& l) { return sheen_brdf(v, l, a); });
      worst = std::max(worst, std::abs(fit_sheen_E(mu, a, p) - ref));
    }
  EXPECT_LE(worst, d["error"]["sheen_E"]["max"].get<double>() + kReferenceNoise);
}

// Limits the forms keep exactly or nearly: the mirror (r = 0) reflects everything, E_5 at r = 0
// is (1 - mu)^5, and every fitted albedo stays in [0, 1] over the whole domain.
TEST(FitAlbedo, LimitsAndRange) {
  const AlbedoFitParams p = albedo_params(load_fit("albedo"));
  for (double mu : {0.05, 0.3, 0.8}) {
    EXPECT_NEAR(fit_ggx_E(mu, 0.0, p), 1.0, 5e-3) << mu;
    EXPECT_NEAR(fit_ggx_E5(mu, 0.0, p), std::pow(1 - mu, 5), 5e-3) << mu;
  }
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      const double x = i / 20.0, mu = j / 20.0;
      for (double v : {fit_ggx_E(mu, x, p), fit_base_E(mu, x, 0.5, p), fit_sheen_E(mu, x, p), fit_base_E_avg(x, 1.0, p)}) {
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0);
      }
    }
}

TEST(FitFlakes, FormulaMatchesAFreshPerRoughnessFit) {
  const json d = load_fit("flake_roughness");
  std::array<double, 3> a{};
  for (size_t i = 0; i < 3; ++i) a[i] = d["coefficients"][i].get<double>();
  // r_f = 0.35 and 0.75 are not among the fitted roughnesses; the per-r_f fit runs here from the
  // documented start (r_eq = r_f, scales 1), on the quick direction set.
  for (double rf : {0.35, 0.75}) {
    const FlakeLobeFit f = fit_flake_lobe(rf, true);
    EXPECT_TRUE(f.converged) << rf;
    EXPECT_NEAR(flake_roughness_formula(rf, a), f.r_eq, 2 * d["formula_error"]["max"].get<double>() + 0.01) << rf;
  }
}

// The aggregate flake BRDF integrates the cone BSDF over the GGX normal density; for the view at
// normal incidence and near-mirror flakes its albedo tends to 1 (every flake reflects into the
// upper hemisphere), checked against the quick direction set's integral.
TEST(FitFlakes, AggregateAlbedoNearOneForSmoothFlakesAtNormalIncidence) {
  const FlakeLobeFit f = fit_flake_lobe(0.05, true);
  ASSERT_FALSE(f.views.empty());
  EXPECT_NEAR(f.views.front().cos_view, 1.0, 1e-12);
  EXPECT_NEAR(f.views.front().albedo_aggregate, 1.0, 0.03);
}

// At r_f = 1 the flake normals are (nearly: alpha_ggx = 0.998) cosine distributed (GGX with
// alpha = 1 has D = 1/pi); at normal view a normal at theta_n reflects to cos(2 theta_n), so the
// albedo is Integral_{cos^2 > 1/2} (2 c^2 - 1) 2 c dc = 1/4 (the cone only blurs directions).
TEST(FitFlakes, AggregateAlbedoMatchesClosedFormAtRoughOne) {
  const FlakeLobeFit f = fit_flake_lobe(1.0, true);
  ASSERT_FALSE(f.views.empty());
  EXPECT_NEAR(f.views.front().cos_view, 1.0, 1e-12);
  EXPECT_NEAR(f.views.front().albedo_aggregate, 0.25, 0.01);
}

TEST(FitHeader, HeaderMatchesLibrary) {
  const json sl = load_fit("sheen_lambda"), al = load_fit("albedo"), fl = load_fit("flake_roughness");
  std::vector<double> q;
  for (const auto& x : sl["coefficients"]) q.push_back(x.get<double>());
  const AlbedoFitParams p = albedo_params(al);
  std::array<double, 3> a{};
  for (size_t i = 0; i < 3; ++i) a[i] = fl["coefficients"][i].get<double>();
  // float (header) vs double (library): agreement to float rounding of the evaluation.
  for (int i = 0; i <= 16; ++i)
    for (int j = 1; j <= 16; ++j) {
      const double x = i / 16.0, mu = j / 16.0;
      const double ab = std::max(1.0 / 256, x);
      if (mu < 1.0) {
        const double lib = sheen_lambda_rich(mu, ab, q.data());
        EXPECT_NEAR(dspbr_fit_sheen_lambda(float(mu), float(ab)), lib, 1e-5 * (1 + lib)) << mu << " " << ab;
      }
      EXPECT_NEAR(dspbr_fit_ggx_E(float(mu), float(x)), fit_ggx_E(mu, x, p), 2e-5);
      EXPECT_NEAR(dspbr_fit_base_E(float(mu), float(x), 0.3f), fit_base_E(mu, x, 0.3, p), 2e-5);
      EXPECT_NEAR(dspbr_fit_sheen_E(float(mu), float(ab)), fit_sheen_E(mu, ab, p), 2e-5);
    }
  for (int i = 0; i <= 16; ++i) {
    const double r = i / 16.0;
    EXPECT_NEAR(dspbr_fit_ggx_E_avg(float(r)), fit_ggx_E_avg(r, p), 2e-5);
    EXPECT_NEAR(dspbr_fit_base_E_avg(float(r), 0.7f), fit_base_E_avg(r, 0.7, p), 2e-5);
    if (r >= 0.05) EXPECT_NEAR(dspbr_fit_flake_roughness(float(r)), flake_roughness_formula(r, a), 2e-6);
  }
}

TEST(FitHeader, CommittedHeaderIsGeneratedFromCommittedJson) {
  std::ifstream in(std::string(DSPBR_SOURCE_DIR) + "/fits/dspbr_fits.hpp");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, generate_fits_header(load_fit("sheen_lambda"), load_fit("albedo"), load_fit("flake_roughness")));
}
