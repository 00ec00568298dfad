#include "dspbr/fit/fit_documents.h"

#include <fmt/format.h>

#include "dspbr/fit/albedo_fit.h"
#include "dspbr/fit/flake_fit.h"
#include "dspbr/fit/sheen_lambda_fit.h"
#include "dspbr/version.h"

namespace dspbr::fit {

using nlohmann::json;

namespace {

// Provenance of a fit document: the project version alone (version.h, so that regenerating at
// another commit gives the same bytes) and the command that rewrites it.
void record_provenance(json& d, const FitContext& ctx, const std::string& name) {
  d["dspbr_version"] = project_version();
  d["command"] = fmt::format("dspbr fit --out DIR --only {} --seed {}{}", name, ctx.seed, ctx.quick ? " --quick" : "");
}

}  // namespace

json sheen_lambda_document(const FitContext& ctx) {
  SheenLambdaFitSettings s;
  if (ctx.quick) {
    s.n_alpha = 10;
    s.n_mu = 24;
  }
  const auto r = fit_sheen_lambda(s, ctx);
  json d;
  d["name"] = "sheen_lambda";
  d["function"] = "dspbr_fit_sheen_lambda(float cos_theta, float alpha_b)";
  d["quantity"] = "Smith Lambda of the Charlie sheen distribution (spec \"Sheen\"), exact by quadrature (sheen_lambda_exact)";
  d["form"] = "Lambda = b (sqrt(1 + A^2 t^2) - 1) exp(c mu / (1 + d mu)), t^2 = (1 - mu^2)/mu^2; "
              "f(s) = (u0 + u1 s + u2 s^2)/(1 + u3 s), s = sqrt(alpha_b), coefficients [b u0..u3, A u0..u3, c u0..u3, d u0..u3]";
  d["coefficients"] = r.rich;
  d["start"] = sheen_rich_start();
  d["spec_form_refit"] = {{"form", "spec: L(x) = a0/(1 + a1 x^a2) + a3 x + a4 at rows p0, p1, w = c0/(1 + c1 a^c2) + c3, "
                                   "p = (1 - w) p0 + w p1; fitted on ln(1 + Lambda)"},
                          {"coefficients", {{"p0", from_params(r.spec_form).p0}, {"p1", from_params(r.spec_form).p1},
                                            {"c", from_params(r.spec_form).c}}},
                          {"start", "the spec's coefficients"},
                          {"converged", r.spec_form_summary.converged}};
  d["domain"] = {{"alpha_b", {s.alpha_min, 1.0}}, {"cos_theta", {s.mu_min, s.mu_max}}};
  d["cost"] = "2 sqrt, 1 exp, 6 div, ~30 mul/add per call (measured ns: docs/fits.md, bench/bench_fits.cpp)";
  d["fit"] = {{"metric", "ln Lambda (relative error), minimax by Lawson reweighting"},
              {"grid", {{"alpha_b", {{"kind", "geometric"}, {"n", s.n_alpha}}},
                        {"cos_theta", {{"kind", "geometric below 0.1, uniform above"}, {"n", s.n_mu}}}}},
              {"lawson_rounds", s.minimax.lawson_rounds},
              {"converged", r.rich_summary.converged},
              {"max_abs_residual", r.rich_summary.max_abs_residual}};
  d["error"] = sheen_lambda_report(s, r, ctx);
  record_provenance(d, ctx, "sheen_lambda");
  d["settings"] = {{"seed", ctx.seed}, {"quick", ctx.quick}};
  return d;
}

json albedo_document(const FitContext& ctx) {
  AlbedoFitSettings s;
  if (ctx.quick) {
    s.n_r = 8;
    s.n_mu = 12;
    s.panels = 6;
  }
  const auto r = fit_albedos(s, ctx);
  json d;
  d["name"] = "albedo";
  d["functions"] = {"dspbr_fit_ggx_E(float cos_theta, float roughness)", "dspbr_fit_ggx_E_avg(float roughness)",
                    "dspbr_fit_base_E(float cos_theta, float roughness, float f0)",
                    "dspbr_fit_base_E_avg(float roughness, float f0)", "dspbr_fit_sheen_E(float cos_theta, float alpha_b)",
                    "dspbr_fit_sheen_ash_E(float cos_theta, float alpha_b)"};
  d["form"] = {{"ggx_E", "1 - (1 - u) S(r; u, mu), u = mu/(mu + r^2); S(x; y1, y2) = sum_{i,j<=5} q[6i+j] X^i Y1^j + sum_{i<=5, 1<=j<=5} q[36+5i+j-1] X^i Y2^j with X = 2x - 1, Y = 2y - 1"},
               {"ggx_E_avg", "1 - r^2 sum_k q[k] R^k, k = 0..7, R = 2r - 1; fitted to 2 Integral E^_m mu dmu of the fitted ggx_E (relative error of 1 - E_avg)"},
               {"ggx_E5", "S(r; mu, u): E_5 = Integral M_r (1 - v.h)^5 mu_l dl"},
               {"ggx_E5_avg", "sum_k q[k] R^k, k = 0..7, R = 2r - 1; fitted to 2 Integral E^_5 mu dmu of the fitted E_5"},
               {"base_E", "f0 E_m + (1 - f0) E_5 + F_ms(f0, 1; E_m,avg) (1 - E_m) (exact decomposition)"},
               {"base_E_avg", "f0 E_m,avg + (1 - f0) E_5,avg + F_ms (1 - E_m,avg)"},
               {"sheen_E", "S(l; sqrt(mu), mu/(mu + sqrt(alpha_b)/2)), l = -log2(alpha_b)/8, alpha_b clamped to [1/256, 1]; main sheen model (spec's Lambda fit)"},
               {"sheen_ash_E", "as sheen_E, for the alternative sheen (Ashikhmin-style visibility, [NP13])"}};
  d["coefficients"] = {{"ggx_E", r.params.ggx_E},   {"ggx_E_avg", r.params.ggx_E_avg}, {"ggx_E5", r.params.ggx_E5},
                       {"ggx_E5_avg", r.params.ggx_E5_avg}, {"sheen_E", r.params.sheen_E}, {"sheen_ash_E", r.params.sheen_ash_E}};
  d["start"] = "constants: S_Em = 0.5, Q_avg = 0.5, S_E5 = 0.1, Q_5,avg = 0.1, S_b = 0.5 (all other coefficients 0)";
  d["domain"] = {{"cos_theta", {s.mu_min, 1.0}}, {"roughness", {0.0, 1.0}}, {"f0", {0.0, 1.0}}, {"alpha_b", {s.alpha_b_min, 1.0}}};
  // Operation counts per call of the generated float code (the measured ns are in docs/fits.md,
  // bench/bench_fits.cpp: timings are not reproducible bytes).
  d["cost"] = {{"ggx_E", "66 FMA (Horner), 1 div"},
               {"ggx_E_avg", "8 FMA"},
               {"base_E", "2 x 66 FMA + 8 FMA, 2 div"},
               {"base_E_avg", "2 x 8 FMA, 1 div"},
               {"sheen_E", "66 FMA, 2 sqrt, 1 log2, 1 div"},
               {"sheen_ash_E", "66 FMA, 2 sqrt, 1 log2, 1 div"}};
  d["fit"] = {{"metric", "absolute error (ggx_E_avg: relative error of 1 - E_avg), minimax by Lawson reweighting"},
              {"reference", "validate/lut_reference.h: deterministic Gauss-Legendre quadrature over the half vector"},
              {"panels", s.panels},
              {"reference_error_max", r.reference_error_max},
              {"ggx_E_avg_tolerance_units_max", r.ggx_E_avg.max_abs_residual},
              {"grid", {{"roughness", fmt::format("0, 1, 8 geometric on [0.004, 0.1), {} cell-centred", s.n_r)},
                        {"cos_theta", fmt::format("{} (geometric from {} below 0.1, uniform above) + both ends", s.n_mu, 0.5 * s.mu_min)},
                        {"alpha_b", fmt::format("{} geometric", s.n_r)}}},
              {"lawson_rounds", {{"default", s.minimax.lawson_rounds}, {"averages", 8}}},
              {"converged",
               {{"ggx_E", r.ggx_E.converged}, {"ggx_E_avg", r.ggx_E_avg.converged}, {"ggx_E5", r.ggx_E5.converged},
                {"ggx_E5_avg", r.ggx_E5_avg.converged}, {"sheen_E", r.sheen_E.converged},
                {"sheen_ash_E", r.sheen_ash_E.converged}}}};
  d["error"] = albedo_report(s, r.params, ctx);
  record_provenance(d, ctx, "albedo");
  d["settings"] = {{"seed", ctx.seed}, {"quick", ctx.quick}};
  return d;
}

json flake_roughness_document(const FitContext& ctx) {
  json d = flake_roughness_fit(ctx);
  record_provenance(d, ctx, "flake_roughness");
  d["settings"] = {{"seed", ctx.seed}, {"quick", ctx.quick}};
  return d;
}

}  // namespace dspbr::fit
