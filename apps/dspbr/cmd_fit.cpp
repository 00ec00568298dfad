// `dspbr fit`: Ceres refits (issue "Ceres refits"): the sheen shadowing Lambda, LUT-free albedo
// formulas and the far-field flake roughness. Writes fits/<name>.json (coefficients, form,
// domain, error statistics, command and settings) and fits/dspbr_fits.hpp generated from them.
// Deterministic: the same command and seed give the same bytes whatever --threads.
#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "commands.h"
#include "dspbr/fit/albedo_fit.h"
#include "dspbr/fit/fits_header.h"
#include "dspbr/fit/fits_shader.h"
#include "dspbr/fit/flake_fit.h"
#include "dspbr/fit/sheen_lambda_fit.h"
#include "dspbr/io/atomic_file.h"
#include "dspbr/progress.h"
#include "dspbr/version.h"

namespace dspbr::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::vector<std::string> kFitNames = {"sheen_lambda", "albedo", "flake_roughness"};

struct FitArgs {
  std::string out = "fits";
  std::string only;
  int threads = 0;
  uint64_t seed = 1;
  bool quick = false;
};

std::vector<std::string> parse_only(const std::string& s) {
  if (s.empty()) return kFitNames;
  std::vector<std::string> out;
  std::string cur;
  auto flush = [&] {
    if (cur.empty()) return;
    // the albedo fits form one group (Base_E is built from the GGX fits): accept their names
    static const std::set<std::string> albedo = {"ggx_E", "ggx_E_avg", "base_E", "base_E_avg", "sheen_E", "sheen_ash_E"};
    const std::string name = albedo.count(cur) ? "albedo" : cur;
    if (std::find(kFitNames.begin(), kFitNames.end(), name) == kFitNames.end())
      throw UsageError("--only: unknown fit '" + cur +
                       "' (use sheen_lambda, albedo (or ggx_E, ggx_E_avg, base_E, base_E_avg, sheen_E, sheen_ash_E), flake_roughness)");
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
    cur.clear();
  };
  for (char c : s) {
    if (c == ',') flush();
    else if (c != ' ') cur += c;
  }
  flush();
  if (out.empty()) throw UsageError("--only: give at least one fit name");
  return out;
}

json read_json_if_exists(const fs::path& p) {
  if (!fs::exists(p)) return nullptr;
  std::ifstream in(p);
  try {
    return json::parse(in);
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("{}: not valid JSON ({}); delete it or rerun without --only", p.string(), e.what()));
  }
}

// Provenance of a fit document: the project version alone (version.h, so that regenerating at
// another commit gives the same bytes) and the command that rewrites it.
void record_provenance(json& d, const FitArgs& a, const std::string& name) {
  d["dspbr_version"] = project_version();
  d["command"] = fmt::format("dspbr fit --out DIR --only {} --seed {}{}", name, a.seed, a.quick ? " --quick" : "");
}

json sheen_lambda_doc(const FitArgs& a, const fit::FitContext& ctx) {
  fit::SheenLambdaFitSettings s;
  if (ctx.quick) {
    s.n_alpha = 10;
    s.n_mu = 24;
  }
  const auto r = fit::fit_sheen_lambda(s, ctx);
  json d;
  d["name"] = "sheen_lambda";
  d["function"] = "dspbr_fit_sheen_lambda(float cos_theta, float alpha_b)";
  d["quantity"] = "Smith Lambda of the Charlie sheen distribution (spec \"Sheen\"), exact by quadrature (sheen_lambda_exact)";
  d["form"] = "Lambda = b (sqrt(1 + A^2 t^2) - 1) exp(c mu / (1 + d mu)), t^2 = (1 - mu^2)/mu^2; "
              "f(s) = (u0 + u1 s + u2 s^2)/(1 + u3 s), s = sqrt(alpha_b), coefficients [b u0..u3, A u0..u3, c u0..u3, d u0..u3]";
  d["coefficients"] = r.rich;
  d["start"] = fit::sheen_rich_start();
  d["spec_form_refit"] = {{"form", "spec: L(x) = a0/(1 + a1 x^a2) + a3 x + a4 at rows p0, p1, w = c0/(1 + c1 a^c2) + c3, "
                                   "p = (1 - w) p0 + w p1; fitted on ln(1 + Lambda)"},
                          {"coefficients", {{"p0", fit::from_params(r.spec_form).p0}, {"p1", fit::from_params(r.spec_form).p1},
                                            {"c", fit::from_params(r.spec_form).c}}},
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
  d["error"] = fit::sheen_lambda_report(s, r, ctx);
  record_provenance(d, a, "sheen_lambda");
  d["settings"] = {{"seed", a.seed}, {"quick", a.quick}};
  const auto& m = d["error"]["models"];
  std::printf("sheen_lambda: max relative error of Lambda over alpha_b in [%g, 1], cos in [%g, %g]:\n", s.alpha_min,
              s.mu_min, s.mu_max);
  for (const char* k : {"ck17", "spec", "ours_spec_form", "ours_rich"})
    std::printf("  %-15s max %.4f  rms %.4f\n", k, m[k]["lambda_rel_error"]["max"].get<double>(),
                m[k]["lambda_rel_error"]["rms"].get<double>());
  return d;
}

json albedo_doc(const FitArgs& a, const fit::FitContext& ctx) {
  fit::AlbedoFitSettings s;
  if (ctx.quick) {
    s.n_r = 8;
    s.n_mu = 12;
    s.panels = 6;
  }
  const auto r = fit::fit_albedos(s, ctx);
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
  d["error"] = fit::albedo_report(s, r.params, ctx);
  record_provenance(d, a, "albedo");
  d["settings"] = {{"seed", a.seed}, {"quick", a.quick}};
  std::printf("albedo fits: abs error on a fresh whole-domain grid (max / mean):\n");
  for (const char* k : {"ggx_E", "ggx_E_avg", "base_E", "base_E_avg", "sheen_E", "sheen_ash_E", "white_furnace_metal",
                        "white_furnace_dielectric"})
    std::printf("  %-26s %.2e / %.2e\n", k, d["error"][k]["max"].get<double>(), d["error"][k]["mean"].get<double>());
  return d;
}

json flake_doc(const FitArgs& a, const fit::FitContext& ctx) {
  json d = fit::flake_roughness_fit(ctx);
  record_provenance(d, a, "flake_roughness");
  d["settings"] = {{"seed", a.seed}, {"quick", a.quick}};
  std::printf("flake_roughness: r_eq(r_f) formula max |r_eq - fitted r_eq| %.2e; worst lobe rel. L2 error %.3f\n",
              d["formula_error"]["max"].get<double>(), d["lobe_error_max"].get<double>());
  return d;
}

void run(const FitArgs& a, const std::string& command_line) {
  const auto names = parse_only(a.only);
  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (ec || !fs::is_directory(a.out)) throw UsageError("--out: cannot create folder '" + a.out + "'");
  fit::FitContext ctx;
  ctx.threads = a.threads;
  ctx.seed = a.seed;
  ctx.quick = a.quick;
  ctx.command = command_line;
  Progress progress("dspbr fit", names.size());
  for (const auto& name : names) {
    const auto t0 = std::chrono::steady_clock::now();
    json doc;
    if (name == "sheen_lambda") doc = sheen_lambda_doc(a, ctx);
    else if (name == "albedo") doc = albedo_doc(a, ctx);
    else doc = flake_doc(a, ctx);
    write_text_atomically((fs::path(a.out) / (name + ".json")).string(), doc.dump(1) + "\n");
    progress.add();
    std::printf("  (%s: %.1f s)\n", name.c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  progress.finish();
  // The header always reflects every JSON present in the folder.
  const fs::path dir(a.out);
  const json sl = read_json_if_exists(dir / "sheen_lambda.json"), al = read_json_if_exists(dir / "albedo.json"),
             fl = read_json_if_exists(dir / "flake_roughness.json");
  write_text_atomically((dir / "dspbr_fits.hpp").string(), fit::generate_fits_header(sl, al, fl));
  write_text_atomically((dir / "dspbr_fits.glsl").string(), fit::generate_fits_shader(sl, al, fl, fit::ShaderDialect::Glsl));
  write_text_atomically((dir / "dspbr_fits.hlsl").string(), fit::generate_fits_shader(sl, al, fl, fit::ShaderDialect::Hlsl));
  std::printf("wrote %s/{%s}.json and dspbr_fits.{hpp,glsl,hlsl}\n", a.out.c_str(), fmt::format("{}", fmt::join(names, ",")).c_str());
}

}  // namespace

void add_fit_command(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  auto* cmd = app.add_subcommand("fit", "Ceres fits: sheen Lambda, LUT-free albedo formulas, far-field flake roughness");
  cmd->add_option("--out", args->out, "Output folder for <fit>.json and dspbr_fits.hpp")->capture_default_str();
  cmd->add_option("--only", args->only,
                  "Comma-separated fits: sheen_lambda, albedo (= ggx_E, ggx_E_avg, base_E, base_E_avg, sheen_E), "
                  "flake_roughness (default: all)");
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores); results do not depend on it")
      ->capture_default_str()
      ->check(thread_count());
  cmd->add_option("--seed", args->seed, "Seed of the QMC reference integrals")->capture_default_str()->check(non_negative_integer());
  cmd->add_flag("--quick", args->quick, "Small grids and sample counts (smoke tests; coarser error figures)");
  cmd->callback([args] { run(*args, "dspbr fit"); });
}

}  // namespace dspbr::cli
