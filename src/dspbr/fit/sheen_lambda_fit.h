// The sheen shadowing fit: exact Smith Lambda of the Charlie
// distribution (sheen_lambda_exact) on a grid over alpha_b in [alpha_min, 1] x cos in [mu_min, mu_max],
// Ceres fits of the spec's functional form and of our richer form (sheen_lambda_forms.h), and the
// comparison of (a) Conty Estevez & Kulla 2017, (b) the spec's coefficients, (c) our fits, in
// Lambda and downstream in the sheen albedo E_b (white furnace of the sheen BRDF).
#pragma once
#include <array>
#include <functional>
#include <nlohmann/json.hpp>

#include "dspbr/fit/fit_common.h"
#include "dspbr/fit/minimax_fit.h"
#include "dspbr/fit/sheen_lambda_forms.h"

namespace dspbr::fit {

struct SheenLambdaFitSettings {
  double alpha_min = 1.0 / 256;  // r_b = 1/16; below it Lambda ~ 1/sqrt(alpha) grows without bound
  double mu_min = 1e-3, mu_max = 0.999;
  int n_alpha = 26, n_mu = 40;   // fit grid (geometric in alpha_b, cosine_grid in mu)
  MinimaxOptions minimax{16, 2000, 1e-3};  // docs/design/fits.md: the rich form converges slowly
};

// Documented starting points of the Ceres fits.
// Rich form: b, A, c, d constant = (3/4, 1, 1/3, 1/5): Lambda = 3/4 (1/mu - 1) e^(mu/3/(1 + mu/5)),
// close to the exact row at alpha_b = 1/2.
std::array<double, kSheenRichFormParams> sheen_rich_start();
// Spec form: the spec's own coefficients.

struct SheenLambdaFitResult {
  std::array<double, kSheenRichFormParams> rich{};
  std::array<double, kSheenSpecFormParams> spec_form{};
  MinimaxSummary rich_summary, spec_form_summary;
};

// Runs both fits on the exact grid (computed in parallel).
SheenLambdaFitResult fit_sheen_lambda(const SheenLambdaFitSettings& s, const FitContext& ctx);

// A Lambda model: Lambda(mu, alpha_b).
using LambdaModel = std::function<double(double mu, double alpha_b)>;

// Sheen albedo E_b(mu_v; alpha_b) = Integral D_b G_b / (4 mu_v mu_l) mu_l dl (spec "Sheen BRDF")
// with G_b built from the given Lambda, by deterministic composite Gauss-Legendre quadrature in
// (mu_l, phi) (lutgen/albedo.h integrates only the spec's Lambda; this one takes any Lambda).
// Accuracy ~1e-5 for alpha_b >= 1/256 (checked against lutgen/albedo.h in the tests).
double sheen_albedo_quadrature(double mu_v, double alpha_b, const LambdaModel& lambda);

// Error report (JSON) of the models on a fresh grid, per alpha_b band: relative error of Lambda,
// error of G1 = 1/(1 + Lambda), and the downstream sheen albedo and white furnace.
nlohmann::json sheen_lambda_report(const SheenLambdaFitSettings& s, const SheenLambdaFitResult& r,
                                   const FitContext& ctx);

}  // namespace dspbr::fit
