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
#include "dspbr/constants.h"
#include "dspbr/fit/albedo_fit.h"
#include "dspbr/fit/albedo_forms.h"
#include "dspbr/fit/fits_header.h"
#include "dspbr/fit/fits_shader.h"
#include "dspbr/fit/flake_fit.h"
#include "dspbr/fit/sheen_lambda_fit.h"
#include "dspbr/bsdf/flakes.h"
#include "dspbr/frame.h"
#include "dspbr/fresnel.h"
#include "dspbr/ggx.h"
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
  copy(c["sheen_ash_E"], p.sheen_ash_E);
  return p;
}

// Exact albedos by deterministic quadrature (independent of lutgen/albedo.h and of the
// validate/lut_reference.h quadrature the fits were made against).
double exact_ggx_E(double mu, double r) { return lutref::ggx_albedo_quad(mu, r, 1.0, 32, 16); }
double exact_ggx_E5(double mu, double r) { return lutref::ggx_albedo_quad(mu, r, 0.0, 32, 16); }
double exact_ggx_E_avg(double r) {
  return lutref::cosine_average([&](double mu) { return exact_ggx_E(mu, r); }, 3);
}

// 2 Integral_0^1 g(mu) mu dmu with mu = t^4 (dmu = 4 t^3 dt), uniform Gauss-Legendre panels in t:
// the nodes crowd towards grazing, where the fitted albedos have their boundary layer (width ~ r^2).
template <class G>
double cosine_average_t4(G&& g, int panels = 64) {
  static const QuadratureRule rule = gauss_legendre(8);
  return integrate_gl([&](double t) { const double mu = t * t * t * t; return 2.0 * mu * g(mu) * 4.0 * t * t * t; }, 0.0, 1.0,
                      panels, rule);
}

// Whole-domain fresh points (not on the fit or report grids): cos theta down to 1e-3, roughness
// from 0 (the mirror) with small values where E_m's boundary layer is thinnest.
const std::vector<double> kFreshR = {0.0, 0.011, 0.023, 0.047, 0.13, 0.29, 0.46, 0.66, 0.89, 1.0};
const std::vector<double> kFreshMu = {0.001, 0.0027, 0.011, 0.052, 0.19, 0.43, 0.71, 0.93, 1.0};

// Disagreement of the test references with the fits' reference quadrature on these points:
// lutref (32 x 16 panels) moves by < 6e-5 with three times the panels, and lutref and
// validate/lut_reference.h differ by up to 2.4e-4 (grazing view); well below the fit errors.
constexpr double kReferenceNoise = 2.5e-4;

// The targets of the albedo fits (max and mean absolute error over the whole domain).
constexpr double kTargetMax = 3e-3, kTargetMean = 5e-4;

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

// The E_m form from the documented start (constant), on a small grid of quadrature values.
TEST(FitAlbedo, CeresConvergesFromDocumentedStart) {
  std::vector<DualPolyResidual> res;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      const double r = (i + 0.5) / 12, mu = 0.01 + 0.99 * j / 11.0;
      // E_m = 1 - (1 - u) S: fit S to (1 - E_m) / (1 - u)
      const double omu = r * r / (mu + r * r);
      res.push_back({r, ggx_albedo_u(mu, r), mu, (1.0 - exact_ggx_E(mu, r)) / omu});
    }
  auto q = albedo_fit_start().ggx_E;
  const MinimaxSummary s = fit_minimax<kDualParams>(res, q, MinimaxOptions{1, 300, 1e-3});
  EXPECT_TRUE(s.converged);
  EXPECT_LT(s.max_abs_residual, 3e-3);  // from errors of S up to ~0.5
}

TEST(FitAlbedo, WithinStatedBoundsOnFreshGrid) {
  const json d = load_fit("albedo");
  const AlbedoFitParams p = albedo_params(d);
  const auto& e = d["error"];
  ErrorStats em, base, avg, base_avg;
  for (double r : kFreshR) {
    const double ea = exact_ggx_E_avg(r);
    const double e5a = lutref::cosine_average([&](double mu) { return exact_ggx_E5(mu, r); }, 3);
    avg.add(fit_ggx_E_avg(r, p) - ea);
    for (double f0 : {0.04, 0.6}) {
      const double exact = f0 * ea + (1 - f0) * e5a + fresnel_ms(f0, 1.0, ea) * (1 - ea);
      base_avg.add(fit_base_E_avg(r, f0, p) - exact);
    }
    for (double mu : kFreshMu) {
      const double e_m = exact_ggx_E(mu, r), e5 = exact_ggx_E5(mu, r);
      em.add(fit_ggx_E(mu, r, p) - e_m);
      for (double f0 : {0.04, 0.6}) {
        const double exact = f0 * e_m + (1 - f0) * e5 + fresnel_ms(f0, 1.0, ea) * (1 - e_m);
        base.add(fit_base_E(mu, r, f0, p) - exact);
      }
    }
  }
  EXPECT_LE(em.max, e["ggx_E"]["max"].get<double>() + kReferenceNoise);
  EXPECT_LE(avg.max, e["ggx_E_avg"]["max"].get<double>() + kReferenceNoise);
  EXPECT_LE(base.max, e["base_E"]["max"].get<double>() + kReferenceNoise);
  EXPECT_LE(base_avg.max, e["base_E_avg"]["max"].get<double>() + kReferenceNoise);
  // the targets, on these points and as stated for the report's grid
  for (const ErrorStats* x : {&em, &base}) {
    EXPECT_LE(x->max, kTargetMax);
    EXPECT_LE(x->mean(), kTargetMean + kReferenceNoise);
  }
  EXPECT_LE(avg.max, kTargetMax);
  EXPECT_LE(base_avg.max, kTargetMax);
  for (const char* k : {"ggx_E", "ggx_E_avg", "base_E", "base_E_avg"}) {
    EXPECT_LE(e[k]["max"].get<double>(), kTargetMax) << k;
    EXPECT_LE(e[k]["mean"].get<double>(), kTargetMean) << k;
  }
}

// Both sheen albedos (the spec's Lambda fit; the alternative [NP13] visibility) on fresh points
// over the whole domain, against the (mu_l, phi) quadrature of the BRDFs themselves.
TEST(FitAlbedo, SheenWithinStatedBoundOnFreshGrid) {
  const json d = load_fit("albedo");
  const AlbedoFitParams p = albedo_params(d);
  ErrorStats main, ash;
  for (double a : {1.0 / 256, 0.0093, 0.02, 0.09, 0.3, 0.75, 1.0})
    for (double mu : {0.001, 0.0041, 0.04, 0.27, 0.55, 0.91}) {
      const double ref = lutref::sheen_albedo_quad(mu, [&](const Vec3& v, const Vec3& l) { return sheen_brdf(v, l, a); }, 64, 16);
      const double ref_ash =
          lutref::sheen_albedo_quad(mu, [&](const Vec3& v, const Vec3& l) { return sheen_brdf_ash(v, l, a); }, 64, 16);
      main.add(fit_sheen_E(mu, a, p) - ref);
      ash.add(fit_sheen_ash_E(mu, a, p) - ref_ash);
    }
  EXPECT_LE(main.max, d["error"]["sheen_E"]["max"].get<double>() + kReferenceNoise);
  EXPECT_LE(ash.max, d["error"]["sheen_ash_E"]["max"].get<double>() + kReferenceNoise);
  for (const char* k : {"sheen_E", "sheen_ash_E"}) {
    EXPECT_LE(d["error"][k]["max"].get<double>(), kTargetMax) << k;
    EXPECT_LE(d["error"][k]["mean"].get<double>(), kTargetMean) << k;
  }
}

// Consistent families: the generated E_avg functions are the cosine averages of the generated
// directional functions (float header, integrated here with the mu = t^4 rule).
TEST(FitAlbedo, AveragesAreCosineAveragesOfTheFits) {
  for (double r : {0.0, 0.004, 0.012, 0.031, 0.07, 0.18, 0.41, 0.77, 1.0}) {
    const double i_em = cosine_average_t4([&](double mu) { return dspbr_fit_ggx_E(float(mu), float(r)); });
    EXPECT_NEAR(dspbr_fit_ggx_E_avg(float(r)), i_em, 1e-4) << r;
    for (double f0 : {0.0, 0.04, 0.5, 1.0}) {
      const double i_b = cosine_average_t4([&](double mu) { return dspbr_fit_base_E(float(mu), float(r), float(f0)); });
      EXPECT_NEAR(dspbr_fit_base_E_avg(float(r), float(f0)), i_b, 1e-4) << r << " " << f0;
    }
  }
}

// White furnace of lobes built from the generated fits, integrated here: a white metal (F = 1)
// M_r + M_r,ms with M_r,ms = (1 - E^(mu_v)) (1 - E^(mu_l)) / (pi (1 - E^_avg)) (spec "Multiple-
// Scattering GGX BRDFs"), and a white opaque dielectric M_r F + F_ms M_r,ms + B_c with
// B_c = (1 - E^_B(mu_v)) (1 - E^_B(mu_l)) / (pi (1 - E^_B,avg)) (spec "Diffuse BRDF"). M_r's own
// albedo is the quadrature of the microfacet BRDF (lutref); the isotropic lobes' hemispherical
// integrals are the mu = t^4 rule. Exact albedos reflect 1.
TEST(FitAlbedo, WhiteFurnaceOfLobesBuiltFromTheFits) {
  double worst_metal = 0, worst_diel = 0;
  for (double r : {0.0, 0.01, 0.02, 0.035, 0.06, 0.1, 0.2, 0.35, 0.6, 0.85, 1.0}) {
    const float rf = float(r);
    const double e_avg = dspbr_fit_ggx_E_avg(rf);
    const double i_ms = cosine_average_t4([&](double mu) { return 1.0 - dspbr_fit_ggx_E(float(mu), rf); });
    const double ms_ratio = 1.0 - e_avg > 0 ? i_ms / (1.0 - e_avg) : 0.0;
    for (double mu : {0.001, 0.0031, 0.012, 0.07, 0.3, 0.62, 1.0}) {
      const double ms = (1.0 - dspbr_fit_ggx_E(float(mu), rf)) * ms_ratio;
      const double metal = lutref::ggx_albedo_quad(mu, r, 1.0, 32, 16) + ms;
      worst_metal = std::max(worst_metal, std::abs(metal - 1.0));
      EXPECT_NEAR(metal, 1.0, 3e-3) << "metal r " << r << " mu " << mu;
      for (double f0 : {0.04, 0.5}) {
        const float f = float(f0);
        const double b_avg = dspbr_fit_base_E_avg(rf, f);
        const double i_b = cosine_average_t4([&](double m) { return 1.0 - dspbr_fit_base_E(float(m), rf, f); });
        const double diffuse = (1.0 - dspbr_fit_base_E(float(mu), rf, f)) * i_b / (1.0 - b_avg);
        const double spec = lutref::ggx_albedo_quad(mu, r, f0, 32, 16) + fresnel_ms(f0, 1.0, e_avg) * ms;
        worst_diel = std::max(worst_diel, std::abs(spec + diffuse - 1.0));
        EXPECT_NEAR(spec + diffuse, 1.0, 3e-3) << "dielectric f0 " << f0 << " r " << r << " mu " << mu;
      }
    }
  }
  RecordProperty("worst_metal", std::to_string(worst_metal));
  RecordProperty("worst_dielectric", std::to_string(worst_diel));
}

// Limits the forms keep exactly or nearly: the mirror (r = 0) reflects everything, E_5 at r = 0
// is (1 - mu)^5, and the fitted albedos stay in their ranges over the whole domain.
TEST(FitAlbedo, LimitsAndRange) {
  const AlbedoFitParams p = albedo_params(load_fit("albedo"));
  for (double mu : {0.05, 0.3, 0.8}) {
    EXPECT_EQ(fit_ggx_E(mu, 0.0, p), 1.0) << mu;  // exact by the form
    EXPECT_NEAR(fit_ggx_E5(mu, 0.0, p), std::pow(1 - mu, 5), 5e-3) << mu;
  }
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      const double x = i / 20.0, mu = j / 20.0;
      for (double v : {fit_ggx_E(mu, x, p), fit_base_E(mu, x, 0.5, p), fit_base_E_avg(x, 1.0, p)}) {
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0);
      }
      // the sheen albedos exceed 1 at grazing (main: up to 1.08 at mu = 1e-3 with the spec's
      // Lambda; alternative: up to 6.1, validate/lut_reference.h) and are never negative
      // (their domain starts at mu = 1e-3)
      const double mb = std::max(mu, 1e-3);
      EXPECT_GE(fit_sheen_E(mb, x, p), 0.0);
      EXPECT_LE(fit_sheen_E(mb, x, p), 1.1);
      EXPECT_GE(fit_sheen_ash_E(mb, x, p), 0.0);
      EXPECT_LE(fit_sheen_ash_E(mb, x, p), 6.2);
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

// Aggregate of the flakes at one (v, l), brute force: the mean over the cone cap around l of the
// density of mirror directions, D(n) n.z / (4 v.n) with n = normalize(v + r), by the midpoint rule
// in the cap's polar coordinates (independent of flake_aggregate_brdf's Gauss-Legendre rule and
// of the model's rim integral).
double flake_cap_mean(const Vec3& v, const Vec3& l, double r_f, int n = 120) {
  const double a = flake_alpha_ggx(r_f), cc = flake_cos_cone(r_f), psi_max = std::acos(cc);
  const Frame f = Frame::from_normal(l);
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double psi = (i + 0.5) / n * psi_max, beta = (j + 0.5) / n * 2 * kPi;
      const Vec3 r = f.to_world({std::sin(psi) * std::cos(beta), std::sin(psi) * std::sin(beta), std::cos(psi)});
      const Vec3 m = normalize(v + r);
      const double vn = dot(v, m);
      if (vn <= 0 || m.z <= 0) continue;
      sum += std::sin(psi) * (psi_max / n) * (2 * kPi / n) * GgxDistribution(a, a).D(m) * m.z / (4 * vn);
    }
  return sum / (2 * kPi * (1 - cc));
}

// The far-field flake lobe of the header against the brute-force aggregate at fresh roughnesses
// and views (0-80 deg), at the mirror direction and around it: within the stated relative L2
// error (pointwise, relative to the peak) and never above it by more than 10 % of the peak.
TEST(FitFlakes, ConeLobeMatchesTheAggregate) {
  const json d = load_fit("flake_roughness");
  EXPECT_LE(d["lobe_error_max"].get<double>(), 0.10);
  EXPECT_LE(d["albedo_error_max"].get<double>(), 0.01);
  for (double rf : {0.06, 0.21, 0.42, 0.93})
    for (double deg : {0.0, 33.0, 61.0, 79.0}) {
      const double t = deg * kPi / 180;
      const Vec3 v{std::sin(t), 0, std::cos(t)};
      const Vec3 mirror{-v.x, 0, v.z};
      const double peak = flake_cap_mean(v, mirror, rf);
      const double w = 0.25 * (rf + 0.12);  // probe offsets of the order of the lobe width (rad)
      for (double dt : {-w, 0.0, 0.5 * w, w})
        for (double dp : {0.0, 0.6 * w}) {
          const double th = std::clamp(t + dt, 0.0, 1.5), ph = kPi + dp;
          const Vec3 l{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
          const double ref = flake_cap_mean(v, l, rf);
          const float m = dspbr_fit_flake_lobe(float(v.x), float(v.y), float(v.z), float(l.x), float(l.y), float(l.z), float(rf));
          EXPECT_NEAR(m, ref, 0.1 * peak) << "r_f " << rf << " view " << deg << " dt " << dt << " dp " << dp;
        }
    }
}

// The model's albedo (its integral over l, in a half-vector parametrisation around the mirror
// direction) against the aggregate albedo in closed form over the normals: a cap around r fully
// above the horizon has mean l.z = r.z (1 + cos theta_cone) / 2, so
// E(v) = (1 + cos theta_cone) / 2 Integral D(n) n.z max(0, r.z) [v.n > 0] dn (views up to 60 deg
// keep the caps of the relevant normals above the horizon).
TEST(FitFlakes, ConeLobeAlbedoMatchesClosedForm) {
  const json d = load_fit("flake_roughness");
  const double stated = d["albedo_error_max"].get<double>();
  static const QuadratureRule rule = gauss_legendre(8);
  for (double rf : {0.08, 0.33, 0.77})
    for (double deg : {0.0, 45.0, 60.0}) {
      const double t = deg * kPi / 180, a = flake_alpha_ggx(rf), cc = flake_cos_cone(rf);
      const Vec3 v{std::sin(t), 0, std::cos(t)};
      // Integrals over normals n(slope) = normalize(-x, -y, 1), slope = s (cos phi, sin phi),
      // s = c tan(pi q / 2), dn = d^2slope / (1 + s^2)^(3/2); c = the lobe's width.
      const double c = std::max(0.05, a + std::sqrt(1 - cc * cc));
      double closed = 0, model = 0;
      for (int pq = 0; pq < 24; ++pq)
        for (size_t iq = 0; iq < rule.x.size(); ++iq) {
          const double q = (pq + 0.5 + 0.5 * rule.x[iq]) / 24, wq = 0.5 / 24 * rule.w[iq];
          const double s = c * std::tan(0.5 * kPi * q);
          const double ds = c * 0.5 * kPi / std::pow(std::cos(0.5 * kPi * q), 2);
          for (int pp = 0; pp < 16; ++pp)
            for (size_t ip = 0; ip < rule.x.size(); ++ip) {
              const double ph = (pp + 0.5 + 0.5 * rule.x[ip]) / 16 * 2 * kPi, wp = 0.5 / 16 * 2 * kPi * rule.w[ip];
              const Vec3 n = normalize(Vec3{-s * std::cos(ph), -s * std::sin(ph), 1.0});
              const double dn = wq * ds * s * wp / std::pow(1 + s * s, 1.5);
              const double vn = dot(v, n);
              if (vn <= 0) continue;
              const Vec3 r = 2 * vn * n - v;
              closed += dn * flake_normal_pdf(n, a) * std::max(0.0, r.z) * 0.5 * (1 + cc);
              if (r.z > 0) {  // l = r: the model's integral over l, dl = 4 (v.n) dn
                const double f = dspbr_fit_flake_lobe(float(v.x), 0.0f, float(v.z), float(r.x), float(r.y), float(r.z), float(rf));
                model += dn * 4 * vn * f * r.z;
              }
            }
        }
      EXPECT_NEAR(model, closed, stated + 3e-3) << "r_f " << rf << " view " << deg;
    }
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
      EXPECT_NEAR(dspbr_fit_sheen_ash_E(float(mu), float(ab)), fit_sheen_ash_E(mu, ab, p), 2e-5);
    }
  for (int i = 0; i <= 16; ++i) {
    const double r = i / 16.0;
    EXPECT_NEAR(dspbr_fit_ggx_E_avg(float(r)), fit_ggx_E_avg(r, p), 2e-5);
    EXPECT_NEAR(dspbr_fit_base_E_avg(float(r), 0.7f), fit_base_E_avg(r, 0.7, p), 2e-5);
    if (r >= 0.05) EXPECT_NEAR(dspbr_fit_flake_roughness(float(r)), flake_roughness_formula(r, a), 2e-6);
    if (r >= 0.05)
      for (double deg : {0.0, 40.0, 75.0}) {
        const double t = deg * 3.14159265358979 / 180;
        const Vec3 v{std::sin(t), 0, std::cos(t)}, l = normalize(Vec3{-v.x + 0.03, 0.02, v.z});
        const double lib = flake_conv_lobe(v, l, flake_alpha_ggx(r), flake_cos_cone(r), kFlakeRimPoints);
        EXPECT_NEAR(dspbr_fit_flake_lobe(float(v.x), float(v.y), float(v.z), float(l.x), float(l.y), float(l.z), float(r)), lib,
                    1e-4 * (1 + lib)) << r << " " << deg;
      }
  }
}

TEST(FitHeader, CommittedHeaderIsGeneratedFromCommittedJson) {
  std::ifstream in(std::string(DSPBR_SOURCE_DIR) + "/fits/dspbr_fits.hpp");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, generate_fits_header(load_fit("sheen_lambda"), load_fit("albedo"), load_fit("flake_roughness")));
  for (auto [file, dialect] : {std::pair{"dspbr_fits.glsl", ShaderDialect::Glsl}, std::pair{"dspbr_fits.hlsl", ShaderDialect::Hlsl}}) {
    std::ifstream sh(std::string(DSPBR_SOURCE_DIR) + "/fits/" + file);
    const std::string st((std::istreambuf_iterator<char>(sh)), std::istreambuf_iterator<char>());
    EXPECT_EQ(st, generate_fits_shader(load_fit("sheen_lambda"), load_fit("albedo"), load_fit("flake_roughness"), dialect)) << file;
  }
}
