// `dspbr fit`: Ceres refits: the sheen shadowing Lambda, LUT-free albedo
// formulas and the far-field flake roughness. Writes fits/<name>.json (coefficients, form,
// domain, error statistics, command and settings; built by fit/fit_documents.h) and
// fits/dspbr_fits.hpp generated from them.
// Deterministic: the same command and seed give the same bytes whatever --threads.
#include <algorithm>
#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "commands.h"
#include "interrupt_cleanup.h"
#include "dspbr/limits.h"
#include "dspbr/io/json_write.h"
#include "dspbr/fit/fit_documents.h"
#include "dspbr/fit/fits_header.h"
#include "dspbr/fit/fits_shader.h"
#include "dspbr/io/atomic_file.h"
#include "dspbr/io/read_file.h"
#include "dspbr/progress.h"

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

// A fit document of an earlier run in the output folder that --only keeps, or null when there is
// none; one that is there (a link included, even a dangling one) must be that fit's document.
json read_kept_document(const fs::path& dir, const std::string& name) {
  const fs::path p = dir / (name + ".json");
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(p, ec))) return nullptr;
  try {
    const json doc = read_json_file(p.string(), "fit document", limits::kDocumentBytes);
    fit::check_fit_document(name, doc);
    return doc;
  } catch (const std::exception& e) {
    const std::string what = e.what();
    // read_json_file names the file; check_fit_document does not.
    throw UsageError((what.rfind(p.string(), 0) == 0 ? what : p.string() + ": " + what) +
                     "; delete it or rerun without --only");
  }
}

// One summary line (or a few) per document on stdout.
void print_summary(const std::string& name, const json& d) {
  if (name == "sheen_lambda") {
    const auto& m = d["error"]["models"];
    std::printf("sheen_lambda: max relative error of Lambda over alpha_b in [%g, 1], cos in [%g, %g]:\n",
                d["domain"]["alpha_b"][0].get<double>(), d["domain"]["cos_theta"][0].get<double>(),
                d["domain"]["cos_theta"][1].get<double>());
    for (const char* k : {"ck17", "spec", "ours_spec_form", "ours_rich"})
      std::printf("  %-15s max %.4f  rms %.4f\n", k, m[k]["lambda_rel_error"]["max"].get<double>(),
                  m[k]["lambda_rel_error"]["rms"].get<double>());
  } else if (name == "albedo") {
    std::printf("albedo fits: abs error on a fresh whole-domain grid (max / mean):\n");
    for (const char* k : {"ggx_E", "ggx_E_avg", "base_E", "base_E_avg", "sheen_E", "sheen_ash_E", "white_furnace_metal",
                          "white_furnace_dielectric"})
      std::printf("  %-26s %.2e / %.2e\n", k, d["error"][k]["max"].get<double>(), d["error"][k]["mean"].get<double>());
  } else {
    std::printf("flake_roughness: r_eq(r_f) formula max |r_eq - fitted r_eq| %.2e; worst lobe rel. L2 error %.3f\n",
                d["formula_error"]["max"].get<double>(), d["lobe_error_max"].get<double>());
  }
}

void run(const FitArgs& a, const std::string& command_line) {
  const auto names = parse_only(a.only);
  // Written into a private staging folder inside --out, moved into place once complete.
  InterruptCleanup cleanup(a.out);  // the handlers first, then the folder
  OutputFolder& out = cleanup.out();
  // The earlier run's documents that --only keeps are read before any fit runs: a malformed one is
  // bad input (exit 2) found in a moment, not after minutes of fitting (the tenth fresh tester's pass).
  std::map<std::string, json> kept;
  for (const char* name : {"sheen_lambda", "albedo", "flake_roughness"})
    if (std::find(names.begin(), names.end(), name) == names.end())
      kept[name] = read_kept_document(fs::path(a.out), name);
  fit::FitContext ctx;
  ctx.threads = a.threads;
  ctx.seed = a.seed;
  ctx.quick = a.quick;
  ctx.command = command_line;
  Progress progress("dspbr fit", names.size());
  std::map<std::string, json> docs;  // this run's documents
  for (const auto& name : names) {
    const auto t0 = std::chrono::steady_clock::now();
    const json doc = name == "sheen_lambda" ? fit::sheen_lambda_document(ctx)
                     : name == "albedo"     ? fit::albedo_document(ctx)
                                            : fit::flake_roughness_document(ctx);
    print_summary(name, doc);
    write_text_atomically((fs::path(out.staging()) / (name + ".json")).string(), json_text(doc, 1, name + " fit document") + "\n");
    docs[name] = doc;
    progress.add();
    std::printf("  (%s: %.1f s)\n", name.c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  progress.finish();
  // The header always reflects every document: this run's, else the one already in --out.
  auto document = [&](const std::string& name) {
    return docs.count(name) ? docs[name] : kept[name];
  };
  const json sl = document("sheen_lambda"), al = document("albedo"), fl = document("flake_roughness");
  const fs::path dir(out.staging());
  write_text_atomically((dir / "dspbr_fits.hpp").string(), fit::generate_fits_header(sl, al, fl));
  write_text_atomically((dir / "dspbr_fits.glsl").string(), fit::generate_fits_shader(sl, al, fl, fit::ShaderDialect::Glsl));
  write_text_atomically((dir / "dspbr_fits.hlsl").string(), fit::generate_fits_shader(sl, al, fl, fit::ShaderDialect::Hlsl));
  out.commit();
  std::printf("wrote %s/{%s}.json and dspbr_fits.{hpp,glsl,hlsl}\n", a.out.c_str(), fmt::format("{}", fmt::join(names, ",")).c_str());
}

}  // namespace

void add_fit_command(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  auto* cmd = app.add_subcommand("fit", "Ceres fits: sheen Lambda, LUT-free albedo formulas, far-field flake roughness");
  cmd->add_option("--out", args->out, "Output folder for <fit>.json and dspbr_fits.hpp")->capture_default_str();
  cmd->add_option("--only", args->only,
                  "Comma-separated fits: sheen_lambda, albedo (= ggx_E, ggx_E_avg, base_E, base_E_avg, sheen_E), "
                  "flake_roughness (default: all)")
      ->check(non_empty_list());
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores); results do not depend on it")
      ->capture_default_str()
      ->transform(thread_count());
  cmd->add_option("--seed", args->seed, "Seed of the QMC reference integrals")->capture_default_str()->transform(non_negative_integer());
  cmd->add_flag("--quick", args->quick, "Small grids and sample counts (smoke tests; coarser error figures)");
  cmd->callback([args] { run(*args, "dspbr fit"); });
}

}  // namespace dspbr::cli
