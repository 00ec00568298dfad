// Fits of the LUT-free albedo forms (albedo_forms.h) to the exact albedos of lut/albedo.h
// (QMC integrals, the same functions the tables come from), minimax by Lawson reweighting, and
// their error on fresh grids (not the fit points), plus the white-furnace deviation of a white
// metal (M_r + M_r,ms, F = 1) whose energy compensation uses the fits instead of exact tables.
#pragma once
#include <nlohmann/json.hpp>

#include "dspbr/fit/albedo_forms.h"
#include "dspbr/fit/fit_common.h"
#include "dspbr/fit/minimax_fit.h"

namespace dspbr::fit {

struct AlbedoFitSettings {
  double alpha_b_min = kSheenEAlphaMin;  // sheen domain alpha_b in [alpha_b_min, 1] (as the Lambda fit)
  int n_r = 28, n_mu = 36;         // fit grid
  int samples = 16384;             // QMC samples per reference value (lut/albedo.h)
  MinimaxOptions minimax{2, 300, 1e-3};  // few Lawson rounds: balances max and mean error
};

// Documented starting points (constants): P_Em = 1, Q_avg = 0.5 (E_m,avg = 1 - r^3/2), P_E5 = 0.1, Q_5,avg = 0.1, P_b = 0.5.
AlbedoFitParams albedo_fit_start();

struct AlbedoFitResult {
  AlbedoFitParams params;
  MinimaxSummary ggx_E, ggx_E_avg, ggx_E5, ggx_E5_avg, sheen_E;
};

AlbedoFitResult fit_albedos(const AlbedoFitSettings& s, const FitContext& ctx);

// Errors of every public function on fresh grids, and the white-furnace deviation (JSON, one
// entry per function name of the header).
nlohmann::json albedo_report(const AlbedoFitSettings& s, const AlbedoFitParams& p, const FitContext& ctx);

}  // namespace dspbr::fit
