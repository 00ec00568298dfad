// Fits of the LUT-free albedo forms (albedo_forms.h) to independent deterministic quadrature of
// the albedo integrals (validate/lut_reference.h, Gauss-Legendre over the half vector; not the
// table integrators of lutgen/albedo.h), minimax by Lawson reweighting, over the whole domain
// (cos theta down to mu_min, roughness from 0, alpha_b from 1/256). The averages are fitted to the
// cosine averages of the fitted directional albedos (consistent families), and the report gives
// the errors on fresh grids (not the fit points) and the white furnaces of a white metal
// (M_r + M_r,ms) and of the white opaque dielectric (M_r + M_r,ms + B_c) built from the fits.
#pragma once
#include <nlohmann/json.hpp>

#include "dspbr/fit/albedo_forms.h"
#include "dspbr/fit/fit_common.h"
#include "dspbr/fit/minimax_fit.h"

namespace dspbr::fit {

struct AlbedoFitSettings {
  double alpha_b_min = kSheenEAlphaMin;  // sheen domain alpha_b in [alpha_b_min, 1] (as the Lambda fit)
  double mu_min = 1e-3;                  // judged domain: cos theta in [mu_min, 1]
  int n_r = 28, n_mu = 40;               // fit grid (plus small roughnesses and the edges)
  int panels = 16;                       // panels per dimension of the reference quadrature
  MinimaxOptions minimax{1, 300, 1e-3};  // one Lawson round: balances max and mean error
};

// Documented starting points (constants): S_Em = 0.5, A = 1 (B = 0), S_E5 = 0.1, Q_5,avg = 0.1, S_b = 0.5.
AlbedoFitParams albedo_fit_start();

struct AlbedoFitResult {
  AlbedoFitParams params;
  MinimaxSummary ggx_E, ggx_E_avg, ggx_E5, ggx_E5_avg, sheen_E, sheen_ash_E;
  double reference_error_max = 0;  // largest quadrature error estimate of the fit references
};

AlbedoFitResult fit_albedos(const AlbedoFitSettings& s, const FitContext& ctx);

// 2 Integral_0^1 E(mu) mu dmu of the fitted E_m and E_5 (graded Gauss-Legendre, quadrature.h):
// what the fitted averages approximate.
double fitted_ggx_E_cosine_average(double r, const AlbedoFitParams& p);
double fitted_ggx_E5_cosine_average(double r, const AlbedoFitParams& p);

// Errors of every public function on fresh grids, the consistency of the averages, and the
// white furnaces (JSON, one entry per function name of the header).
nlohmann::json albedo_report(const AlbedoFitSettings& s, const AlbedoFitParams& p, const FitContext& ctx);

}  // namespace dspbr::fit
