#include "dspbr/fit/sheen_lambda_fit.h"

#include <algorithm>
#include <cmath>

#include "dspbr/constants.h"
#include "dspbr/frame.h"
#include "dspbr/quadrature.h"
#include "dspbr/sheen.h"

namespace dspbr::fit {

namespace {

struct RichResidual {
  double mu, alpha, ln_exact;
  template <class T>
  bool operator()(const T* q, T* r) const {
    r[0] = sheen_ln_lambda_rich_form<T>(q, mu, alpha) - T(ln_exact);
    return true;
  }
};
struct SpecResidual {
  double mu, alpha, ln_exact;
  template <class T>
  bool operator()(const T* q, T* r) const {
    // error of ln(1 + Lambda), i.e. the relative error of G1 = 1/(1 + Lambda): near normal
    // incidence Lambda -> 0 and its relative error does not matter to G_b
    using std::exp;
    using std::log;
    r[0] = log(T(1.0) + exp(sheen_ln_lambda_spec_form<T>(q, mu, alpha))) - T(std::log1p(std::exp(ln_exact)));
    return true;
  }
};

struct GridPoint {
  double mu, alpha, ln_exact;
};

std::vector<GridPoint> exact_grid(const std::vector<double>& alphas, const std::vector<double>& mus,
                                  const FitContext& ctx) {
  const size_t n = alphas.size() * mus.size();
  return parallel_map<GridPoint>(ctx, n, [&](size_t i) {
    const double a = alphas[i / mus.size()], mu = mus[i % mus.size()];
    return GridPoint{mu, a, std::log(sheen_lambda_exact(mu, a))};
  });
}
}  // namespace

std::array<double, kSheenRichFormParams> sheen_rich_start() {
  return {0.75, 0, 0, 0, 1.0, 0, 0, 0, 1.0 / 3.0, 0, 0, 0, 0.2, 0, 0, 0};
}

SheenLambdaFitResult fit_sheen_lambda(const SheenLambdaFitSettings& s, const FitContext& ctx) {
  const auto alphas = geometric_grid(s.alpha_min, 1.0, s.n_alpha);
  const auto mus = cosine_grid(s.mu_min, s.mu_max, s.n_mu);
  const auto grid = exact_grid(alphas, mus, ctx);
  SheenLambdaFitResult out;
  std::vector<RichResidual> rich;
  std::vector<SpecResidual> spec;
  for (const auto& g : grid) {
    rich.push_back({g.mu, g.alpha, g.ln_exact});
    spec.push_back({g.mu, g.alpha, g.ln_exact});
  }
  out.rich = sheen_rich_start();
  out.rich_summary = fit_minimax<kSheenRichFormParams>(rich, out.rich, s.minimax);
  out.spec_form = to_params(sheen_lambda_fit_spec());
  out.spec_form_summary = fit_minimax<kSheenSpecFormParams>(spec, out.spec_form, s.minimax);
  return out;
}

double sheen_albedo_quadrature(double mu_v, double alpha_b, const LambdaModel& lambda) {
  // mu_l: 24 panels graded geometrically towards 0 (the Charlie peak sits at grazing half vectors),
  // phi in [0, pi] (symmetric), 32 uniform panels; 8-point Gauss-Legendre on each.
  static const QuadratureRule rule = gauss_legendre(8);
  const double mu = std::clamp(mu_v, 1e-6, 1.0);  // mu = 0: albedo limit, as lutgen/albedo.h (kMinCos)
  const Vec3 v = view_dir(mu);
  const double lam_v = lambda(mu, alpha_b);
  std::vector<double> mu_nodes, mu_weights;
  // Panel edges: geometric from 1e-4 to 1, plus 0.5 where the spec-form fits switch branch (kink).
  std::vector<double> edges{0.0, 0.5};
  const int panels = 24;
  for (int p = 1; p <= panels; ++p) edges.push_back(p == panels ? 1.0 : std::pow(1e-4, 1.0 - double(p) / panels));
  std::sort(edges.begin(), edges.end());
  for (size_t e = 1; e < edges.size(); ++e) {
    const double lo = edges[e - 1], hi = edges[e];
    const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
    for (size_t i = 0; i < rule.x.size(); ++i) {
      mu_nodes.push_back(mid + half * rule.x[i]);
      mu_weights.push_back(half * rule.w[i]);
    }
  }
  double total = 0;
  for (size_t j = 0; j < mu_nodes.size(); ++j) {
    const double ml = mu_nodes[j], sl = std::sqrt(std::max(0.0, 1.0 - ml * ml));
    const double lam_l = lambda(ml, alpha_b);
    const double g = 1.0 / (1.0 + lam_v + lam_l);  // chi+(v.h) chi+(l.h) = 1 for both above
    const double inner = integrate_gl(
        [&](double phi) {
          const Vec3 h = normalize(v + Vec3{sl * std::cos(phi), sl * std::sin(phi), ml});
          return charlie_d(h.z, alpha_b);
        },
        0.0, kPi, 32, rule);
    // M_b mu_l = D G / (4 mu_v); factor 2 for phi in [pi, 2 pi]
    total += mu_weights[j] * 2.0 * inner * g / (4.0 * mu);
  }
  return total;
}

nlohmann::json sheen_lambda_report(const SheenLambdaFitSettings& s, const SheenLambdaFitResult& r,
                                   const FitContext& ctx) {
  const SheenLambdaFit spec_form = from_params(r.spec_form);
  const auto rich = r.rich;
  struct Model {
    std::string name, source;
    LambdaModel f;
  };
  const std::vector<Model> models = {
      {"ck17", "Conty Estevez & Kulla 2017, Table 1 (rows at alpha_b = 0, 1, blend (1 - alpha_b)^2)",
       [](double mu, double a) { return sheen_lambda_ck17(mu, a); }},
      {"spec", "DSPBR 2025x Table sheen-lambda-fit, reading (1 - w) p0 + w p1 (docs/sheen_lambda.md)",
       [](double mu, double a) { return sheen_lambda(mu, a); }},
      {"ours_spec_form", "this fit: the spec's functional form refitted with Ceres",
       [spec_form](double mu, double a) { return sheen_lambda(mu, a, spec_form); }},
      {"ours_rich", "this fit: the richer form (dspbr_fit_sheen_lambda)",
       [rich](double mu, double a) { return sheen_lambda_rich(mu, a, rich.data()); }},
  };
  // Fresh grid: alpha_b geometric with points between the fit rows, mu on an offset cosine grid.
  const int na = ctx.quick ? 9 : 41, nm = ctx.quick ? 40 : 160;
  const auto alphas = geometric_grid(s.alpha_min, 1.0, na);
  const auto mus = cosine_grid(s.mu_min, s.mu_max, nm, 0.31);
  const auto grid = exact_grid(alphas, mus, ctx);
  // Bands of alpha_b (a factor 4 each).
  std::vector<std::pair<double, double>> bands;
  for (double lo = s.alpha_min; lo < 1.0 - 1e-12; lo *= 4) bands.push_back({lo, std::min(1.0, lo * 4)});
  auto band_of = [&](double a) {
    for (size_t b = 0; b < bands.size(); ++b)
      if (a < bands[b].second * (1 + 1e-12)) return b;
    return bands.size() - 1;
  };
  nlohmann::json out;
  out["grid"] = {{"alpha_b", {{"kind", "geometric"}, {"lo", s.alpha_min}, {"hi", 1.0}, {"n", na}}},
                 {"cos_theta", {{"kind", "geometric below 0.1, uniform above, offset 0.31"}, {"lo", s.mu_min},
                                {"hi", s.mu_max}, {"n", nm}}}};
  for (const auto& m : models) {
    std::vector<ErrorStats> rel(bands.size()), g1(bands.size());
    ErrorStats rel_all, g1_all;
    for (const auto& p : grid) {
      const double exact = std::exp(p.ln_exact), fit = m.f(p.mu, p.alpha);
      const double e_rel = fit / exact - 1.0, e_g1 = 1.0 / (1.0 + fit) - 1.0 / (1.0 + exact);
      const size_t b = band_of(p.alpha);
      rel[b].add(e_rel);
      g1[b].add(e_g1);
      rel_all.add(e_rel);
      g1_all.add(e_g1);
    }
    nlohmann::json jm;
    jm["source"] = m.source;
    jm["lambda_rel_error"] = rel_all.to_json();
    jm["g1_abs_error"] = g1_all.to_json();
    for (size_t b = 0; b < bands.size(); ++b)
      jm["bands"].push_back({{"alpha_b", {bands[b].first, bands[b].second}},
                             {"lambda_rel_error", rel[b].to_json()},
                             {"g1_abs_error", g1[b].to_json()}});
    out["models"][m.name] = jm;
  }
  // Curves for the plots (docs/fits.md): Lambda of every model and the exact one along mu.
  {
    const std::vector<double> c_alphas = {s.alpha_min, 1.0 / 64, 1.0 / 16, 0.25, 1.0};
    const auto c_mus = cosine_grid(s.mu_min, s.mu_max, ctx.quick ? 16 : 48, 0.5);
    const auto exact = parallel_map<double>(ctx, c_alphas.size() * c_mus.size(), [&](size_t i) {
      return sheen_lambda_exact(c_mus[i % c_mus.size()], c_alphas[i / c_mus.size()]);
    });
    for (size_t ia = 0; ia < c_alphas.size(); ++ia) {
      nlohmann::json c;
      c["alpha_b"] = c_alphas[ia];
      c["cos_theta"] = c_mus;
      std::vector<double> ex(exact.begin() + long(ia * c_mus.size()), exact.begin() + long((ia + 1) * c_mus.size()));
      c["lambda"]["exact"] = ex;
      for (const auto& m : models) {
        std::vector<double> v;
        for (double mu : c_mus) v.push_back(m.f(mu, c_alphas[ia]));
        c["lambda"][m.name] = v;
      }
      out["curves"].push_back(c);
    }
  }
  // Downstream: sheen albedo E_b with each Lambda vs with the exact Lambda (white furnace of M_b:
  // E_b > 1 is an energy gain; E_b(model) - E_b(exact) the error the Lambda fit causes).
  const std::vector<double> e_alphas = ctx.quick ? std::vector<double>{1.0 / 64, 0.25}
                                                 : std::vector<double>{1.0 / 256, 1.0 / 64, 1.0 / 16, 0.25, 1.0};
  const std::vector<double> e_mus = ctx.quick ? std::vector<double>{0.05, 0.5} : cosine_grid(0.01, 1.0, 12, 0.5);
  const size_t per_alpha = e_mus.size() * (models.size() + 1);
  const auto eb = parallel_map<double>(ctx, e_alphas.size() * per_alpha, [&](size_t i) {
    const double a = e_alphas[i / per_alpha], mu = e_mus[(i % per_alpha) / (models.size() + 1)];
    const size_t m = i % (models.size() + 1);
    if (m == models.size()) {
      // exact Lambda: cache along the quadrature's mu nodes is not needed at this size
      return sheen_albedo_quadrature(mu, a, [](double x, double al) { return sheen_lambda_exact(x, al); });
    }
    return sheen_albedo_quadrature(mu, a, models[m].f);
  });
  for (size_t ia = 0; ia < e_alphas.size(); ++ia) {
    nlohmann::json row;
    row["alpha_b"] = e_alphas[ia];
    row["cos_theta"] = e_mus;
    for (size_t m = 0; m <= models.size(); ++m) {
      std::vector<double> vals;
      double max_e = 0, max_diff = 0;
      for (size_t j = 0; j < e_mus.size(); ++j) {
        const double v = eb[ia * per_alpha + j * (models.size() + 1) + m];
        const double ex = eb[ia * per_alpha + j * (models.size() + 1) + models.size()];
        vals.push_back(v);
        max_e = std::max(max_e, v);
        max_diff = std::max(max_diff, std::abs(v - ex));
      }
      const std::string name = m == models.size() ? "exact" : models[m].name;
      row["E_b"][name] = vals;
      row["max_E_b"][name] = max_e;                         // > 1: white-furnace energy gain
      row["max_abs_E_b_error"][name] = max_diff;            // vs the exact-Lambda albedo
    }
    out["albedo"].push_back(row);
  }
  return out;
}

}  // namespace dspbr::fit
