// The fit documents written to fits/<name>.json (docs/fits.md): coefficients, form, domain, error
// statistics, the command that rewrites them and its settings. Each runs its fit (Ceres, through
// the FitContext's thread count and seed: the same seed gives the same document whatever the
// thread count).
#pragma once
#include <nlohmann/json.hpp>

#include "dspbr/fit/fit_common.h"

namespace dspbr::fit {

// fits/sheen_lambda.json: the Smith Lambda of the Charlie sheen distribution (spec "Sheen").
nlohmann::json sheen_lambda_document(const FitContext& ctx);
// fits/albedo.json: the LUT-free albedo formulas (ggx_E, ggx_E_avg, base_E, base_E_avg, sheen_E,
// sheen_ash_E).
nlohmann::json albedo_document(const FitContext& ctx);
// fits/flake_roughness.json: the far-field flake roughness r_eq(r_f).
nlohmann::json flake_roughness_document(const FitContext& ctx);

}  // namespace dspbr::fit
