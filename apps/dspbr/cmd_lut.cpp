// `dspbr lut`: generates the DSPBR energy-compensation tables (GGX_E, GGX_E_avg, Base_E,
// Base_E_avg, Sheen_E, Sheen_ash_E) as EXR, C++ header and JSON; `--bench` measures the
// speed/accuracy trade of the integrators. Definitions and conventions: docs/luts.md.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.h"
#include "interrupt_cleanup.h"
#include "provenance.h"
#include "dspbr/io/atomic_file.h"
#include "dspbr/io/output_folder.h"
#include "dspbr/lutgen/generate.h"
#include "dspbr/lutgen/lookup_codegen.h"
#include "dspbr/lutgen/lut_io.h"
#include "dspbr/lutgen/renderer_generate.h"
#include "dspbr/lutgen/renderer_io.h"
#include "dspbr/scene/scene_analysis.h"
#include "dspbr/validate/integrator_study.h"
#include "dspbr/validate/lookup_study.h"
#include "dspbr/nearest_name.h"

namespace dspbr::cli {

namespace {

namespace fs = std::filesystem;

struct LutArgs {
  std::string out;
  std::string tables;  // comma-separated; empty: all
  bool tables_given = false;
  std::vector<std::string> sizes;
  std::string grid = "cell";
  bool grid_given = false;
  std::string formats = "exr,png,hpp,json";
  std::string integrator;  // empty: each table's default (lut_default_integrator)
  int samples = 0;
  double target_error = kLutIntegratorDefault;
  int randomizations = 8;
  uint64_t seed = 1;
  int threads = 0;
  bool half = false;
  bool quiet = false;  // no progress on stderr
  bool bench = false;
  bool bench_lookups = false;
  bool bench_integrators = false;  // --bench without the point-of-use study
  std::string bench_csv;           // --bench: also the integrator rows as CSV (for the plot)
  int bench_points = 400;
  std::string scene;
  bool transmission_compensation = false;  // --scene: also the tables of the compensation
  std::string layouts = "published,renderer";
  bool layouts_given = false;
  int renderer_scale = 1;
  bool renderer_scale_given = false;
};


// "64x32" -> {64, 32}.
std::vector<int> parse_dims(const std::string& s, const std::string& what) {
  std::vector<int> dims;
  for (const std::string& p : split_list(s, 'x')) {
    if (p.empty() || p.find_first_not_of("0123456789") != std::string::npos || p.size() > 6)
      throw UsageError(what + ": '" + s + "' is not a size like 32 or 16x16 or 16x16x16");
    dims.push_back(std::stoi(p));
  }
  return dims;
}

LutOptions to_options(const LutArgs& a) {
  LutOptions opt;
  if (!a.scene.empty() && a.tables_given) throw UsageError("use either --tables or --scene, not both");
  if (!a.scene.empty()) {
    try {
      opt.tables = tables_for_scene(a.scene, a.transmission_compensation);
    } catch (const std::exception& e) {
      throw UsageError(std::string("--scene: ") + e.what());
    }
  } else if (a.tables_given) {
    opt.tables.clear();
    for (const std::string& t : split_list(a.tables)) {
      if (!is_lut_table_name(t))
        throw UsageError("--tables: unknown table '" + t + "'" + did_you_mean(t, lut_names(kPublishedLayout)) +
                         " (choose from " + lut_names_list(kPublishedLayout) + ")");
      if (std::find(opt.tables.begin(), opt.tables.end(), t) == opt.tables.end()) opt.tables.push_back(t);
    }
  }
  for (const std::string& s : a.sizes) {
    // One policy for spaces: none (they were trimmed around the numbers but not around the name;
    // the tenth fresh tester's pass).
    if (s.find_first_of(" \t\n\r\f\v") != std::string::npos)
      throw UsageError("--size: '" + s + "' holds a space: give NAME=SIZE without spaces, e.g. GGX_E=64x64");
    const auto eq = s.find('=');
    if (eq == std::string::npos) throw UsageError("--size: '" + s + "' is not NAME=SIZE, e.g. GGX_E=64x64");
    const std::string name = s.substr(0, eq);
    if (!is_lut_table_name(name))
      throw UsageError("--size: unknown table '" + name + "'" + did_you_mean(name, lut_names(kPublishedLayout)) +
                       " (choose from " + lut_names_list(kPublishedLayout) + ")");
    opt.sizes[name] = parse_dims(s.substr(eq + 1), "--size " + name);
  }
  try {
    opt.grid = parse_grid_kind(a.grid);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--grid: ") + e.what());
  }
  try {
    if (!a.integrator.empty()) opt.integrator = parse_integrator(a.integrator);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--integrator: ") + e.what());
  }
  opt.samples = a.samples;
  opt.target_error = a.target_error;
  opt.randomizations = a.randomizations;
  opt.seed = a.seed;
  opt.threads = a.threads;
  opt.progress = !a.quiet;
  opt.command = reproducible_command();
  // A scene whose materials need no table is not an error: run_generate says so (as `shader
  // --scene` does; the tenth fresh tester's pass: "no tables selected", naming no file).
  if (!a.scene.empty() && opt.tables.empty() && opt.sizes.empty()) return opt;
  try {
    validate_lut_options(opt);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return opt;
}

LutFormats to_formats(const LutArgs& a) {
  LutFormats f;
  f.exr = f.hpp = f.json = f.png = false;
  for (const std::string& s : split_list(a.formats)) {
    if (s == "exr") f.exr = true;
    else if (s == "hpp") f.hpp = true;
    else if (s == "json") f.json = true;
    else if (s == "png") f.png = true;
    else throw UsageError("--formats: unknown format '" + s + "' (choose from exr, png, hpp, json)");
  }
  f.half = a.half;
  return f;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The renderer layout (tables/renderer_luts.h): JSON, images, and the generated lookup code.
void run_renderer(const LutArgs& a, const LutOptions& opt, const LutFormats& formats, const std::string& dir) {
  const auto t0 = std::chrono::steady_clock::now();
  const RendererLuts luts = generate_renderer_luts(opt, a.renderer_scale);
  const double t_gen = seconds_since(t0);
  const std::string provenance =
      fmt::format("Settings: integrator {}, target error {:g}, seed {}, scale {}.",
                  integrator_name(lut_settings(lut_name(Lut::GgxE), opt).integrator),
                  lut_settings(lut_name(Lut::GgxE), opt).target_error, opt.seed,
                  a.renderer_scale);
  if (formats.json)
    write_text_atomically((fs::path(dir) / "dspbr_renderer_luts.json").string(),
                          renderer_json_text(luts, opt, a.renderer_scale));
  if (formats.exr || formats.png) write_renderer_images(luts, (fs::path(dir) / "renderer").string(), formats.half, kSplitSumSize,
                                                        opt.command);
  if (formats.hpp) write_text_atomically((fs::path(dir) / thin_film_lookup_file_name()).string(), thin_film_lookup_code());
  if (formats.hpp)
    for (LookupDialect d : {LookupDialect::C, LookupDialect::Glsl, LookupDialect::Hlsl}) {
      write_text_atomically((fs::path(dir) / lookup_file_name(d)).string(), lookup_code(luts, d, provenance));
      if (luts.has_glass())
        write_text_atomically((fs::path(dir) / glass_lookup_file_name(d)).string(),
                              glass_lookup_code(luts, d, provenance));
    }
  for (const char* name : luts.held_names()) {
    const WarpedTable& t = *luts.table(name);
    double max_err = 0;
    for (double e : t.errors) max_err = std::max(max_err, e);
    std::string dims;
    for (const WarpedAxis& ax : t.axes) dims += (dims.empty() ? "" : "x") + std::to_string(ax.size);
    std::printf("renderer %-12s %-9s max std error %.2e\n", name, dims.c_str(), max_err);
  }
  std::printf("renderer layout: %zu stored values (+ %zu glass), generated in %.2f s\n", luts.stored_values(),
              luts.glass_stored_values(), t_gen);
}

// A file `dspbr lut` writes (either layout, any format): an earlier run's file of these kinds
// that this run does not replace would be left beside the new set.
bool table_output(const std::string& name) {
  const auto ends = [&](const char* suffix) {
    const std::string x(suffix);
    return name.size() >= x.size() && name.compare(name.size() - x.size(), x.size(), x) == 0;
  };
  return ends(".exr") || ends(".png") || name == "pbrlut.hpp" || name == "dspbr_luts.json" ||
         name == "dspbr_renderer_luts.json" || name.rfind("dspbr_lookup.", 0) == 0 ||
         name.rfind("dspbr_glass_lookup.", 0) == 0 || name == thin_film_lookup_file_name();
}

// Before the commit: the folder must not keep files of an earlier table set that this set does not
// replace (different --tables, --formats or --layout), or it would mix two sets (the fourth fresh
// tester's pass: GGX_E.exr and pbrlut.hpp of 16x16 beside a dspbr_luts.json of 4x4). Nothing of
// the earlier set is deleted; the run is refused and commits nothing.
void refuse_mixed_set(const OutputFolder& out) {
  std::vector<std::string> stale;
  for (const char* sub : {"", "renderer"}) {
    std::error_code ec;
    const fs::path dir = fs::path(out.dir()) / sub;
    if (!fs::is_directory(fs::symlink_status(dir, ec))) continue;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
      const std::string rel = (std::string(sub).empty() ? "" : std::string(sub) + "/") + e.path().filename().string();
      std::error_code ec2;
      if (!fs::is_regular_file(e.symlink_status(ec2)) || !table_output(e.path().filename().string())) continue;
      if (!fs::exists(fs::path(out.staging()) / rel, ec2)) stale.push_back(rel);
    }
  }
  if (stale.empty()) return;
  std::sort(stale.begin(), stale.end());
  std::string list;
  for (std::size_t i = 0; i < stale.size() && i < 3; ++i) list += (i ? ", " : "") + quote_input(stale[i]);
  if (stale.size() > 3) list += ", ... (" + std::to_string(stale.size()) + " in all)";
  throw UsageError("--out: '" + quote_input(out.dir()) + "' holds files of an earlier table set that this run does not "
                   "replace (" + list + "): the folder would mix two sets. Give an empty folder, or the earlier run's "
                   "--tables, --formats and --layout");
}

void run_generate(const LutArgs& a) {
  if (a.out.empty()) throw UsageError("--out DIR is required (the folder the tables are written to)");
  const LutOptions opt = to_options(a);
  const LutFormats formats = to_formats(a);
  if (opt.tables.empty()) {
    std::printf("%s: its materials need no tables; nothing written\n", a.scene.c_str());
    return;
  }
  bool published = false, renderer = false;
  // The renderer layout is one set (Base_E and the averages derive from GGX_E and GGX_beta):
  // selecting published tables (--tables, --scene, --size) or their sampling (--grid) means the
  // published layout only, unless --layout says otherwise.
  const bool selection = a.tables_given || !a.scene.empty() || !a.sizes.empty() || a.grid_given;
  for (const std::string& l : split_list(a.layouts_given || !selection ? a.layouts : "published")) {
    if (l == "published") published = true;
    else if (l == "renderer") renderer = true;
    else throw UsageError("--layout: unknown layout '" + l + "' (choose from published, renderer)");
  }
  // Options that would be ignored are refused: the renderer layout is one fixed set (its
  // resolution is --renderer-scale), and --half changes only EXRs.
  if (renderer && (a.tables_given || !a.scene.empty() || !a.sizes.empty() || a.grid_given))
    throw UsageError(std::string(a.tables_given ? "--tables" : !a.scene.empty() ? "--scene" : !a.sizes.empty() ? "--size" : "--grid") +
                     " applies to the published tables only; the renderer layout is one fixed set (its "
                     "resolution: --renderer-scale). Give --layout published, or leave the option out");
  if (a.renderer_scale_given && !renderer)
    throw UsageError("--renderer-scale sets the renderer layout's resolution: give --layout renderer (or leave it out)");
  if (a.half && !formats.exr) throw UsageError("--half writes EXRs as 16-bit floats: give exr in --formats (or leave --half out)");
  // Every file is written into a private staging folder inside --out and moved into place once
  // the whole set is complete (io/output_folder.h); SIGINT/SIGTERM discard the staging folder.
  InterruptCleanup cleanup(a.out);  // the handlers first, then the folder
  OutputFolder& out = cleanup.out();
  if (renderer) run_renderer(a, opt, formats, out.staging());
  if (!published) {
    refuse_mixed_set(out);
    out.commit();
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Table> tables = generate_luts(opt);
  const double t_gen = seconds_since(t0);
  const std::vector<double> rounding = write_luts(tables, opt, out.staging(), formats);
  refuse_mixed_set(out);
  out.commit();
  for (size_t i = 0; i < tables.size(); ++i) {
    const Table& t = tables[i];
    double max_err = 0, max_v = -1e300;
    for (double e : t.errors) max_err = std::max(max_err, e);
    for (double v : t.values) max_v = std::max(max_v, v);
    std::string dims;
    for (const Axis& ax : t.axes) dims += (dims.empty() ? "" : "x") + std::to_string(ax.size);
    std::printf("%-12s %-9s max std error %.2e  max value %.6f", t.name.c_str(), dims.c_str(), max_err, max_v);
    if (formats.exr && formats.half) std::printf("  half rounding %.2e", rounding[i]);
    std::printf("\n");
  }
  std::printf("generated in %.2f s, written to %s\n", t_gen, a.out.c_str());
}

// Point-of-use study: lookup errors of the committed published and renderer layouts and of the
// fits against independent quadrature, furnaces built from the lookups (validate/lookup_study.h).
void run_lookup_bench(const LutArgs& a) {
  const validate::LookupStudy s =
      validate::run_lookup_study(LutSet::published(), LutSet::builtin(), a.bench_points, a.seed);
  std::printf("%s\n", validate::lookup_study_markdown(s).c_str());
  std::fflush(stdout);
}

// Speed/accuracy study: the point-of-use study, then the integrators' study
// (validate/integrator_study.h), printed row by row as it runs.
void run_bench(const LutArgs& a) {
  if (!a.bench_integrators) run_lookup_bench(a);
  std::printf("%s\n", validate::integrator_study_markdown_header().c_str());
  std::string csv = validate::integrator_study_csv_header() + "\n";
  validate::run_integrator_study(to_options(a), [&](const validate::IntegratorStudyRow& r) {
    std::printf("%s\n", validate::integrator_study_markdown_row(r).c_str());
    std::fflush(stdout);
    csv += validate::integrator_study_csv_row(r) + "\n";
  });
  if (!a.bench_csv.empty()) write_text_atomically(a.bench_csv, csv);
}

}  // namespace

void add_lut_command(CLI::App& app) {
  auto args = std::make_shared<LutArgs>();
  auto* cmd = app.add_subcommand(
      "lut",
      "Generate the DSPBR energy-compensation tables (EXR, pbrlut.hpp, dspbr_luts.json); see docs/luts.md");
  cmd->add_option("--out", args->out, "Output folder (created when missing)");
  auto* tables_opt = cmd->add_option(
      "--tables", args->tables, "Comma-separated tables: " + lut_names_list(kPublishedLayout) + " (default: all)");
  auto* scene_opt =
      cmd->add_option("--scene", args->scene, "Generate only the tables the materials of this scene (.gltf/.glb/.json) need");
  cmd->add_flag("--transmission-compensation", args->transmission_compensation,
                "With --scene: also the tables of the rough-transmission compensation (beyond DSPBR 2025x)")
      ->needs(scene_opt);
  cmd->add_option("--size", args->sizes,
                  "Per-table resolution NAME=SIZE, slowest axis first, e.g. GGX_E=64x64, Base_E=16x32x32 (repeatable)");
  auto* grid_opt = cmd->add_option("--grid", args->grid, "Axis sampling: cell (x_i = (i+0.5)/N, default) or endpoint (x_i = i/(N-1))");
  cmd->add_option("--formats", args->formats, "Comma-separated output formats: exr, png (16-bit), hpp (headers, lookup code), json (default: all)");
  cmd->add_option("--integrator", args->integrator,
                  "quad (adaptive Gauss-Kronrod over the microfacet normal, deterministic; the default), qmc "
                  "(importance-sampled, Owen-scrambled Sobol') or mc (plain Monte Carlo baseline)");
  cmd->add_option("--samples", args->samples,
                  "Maximum samples per cell, all randomizations together (default: 524288; 2097152 for the "
                  "averages); exactly this many with --target-error 0")
      ->transform(decimal_integer(1, INT_MAX, "a sample count"));
  cmd->add_option("--target-error", args->target_error,
                  "Error target per cell: quad's error estimate (default 1e-7), qmc/mc's standard error "
                  "(default 1e-5; 0: the fixed budget of --samples)")
      ->check(decimal_number());
  cmd->add_option("--randomizations", args->randomizations,
                  "Independent randomizations per cell for the error estimate (default: 8)")
      ->transform(decimal_integer(2, 1024, "a randomization count"));
  cmd->add_option("--seed", args->seed, "Random seed (default: 1)")->transform(non_negative_integer());
  cmd->add_option("--threads", args->threads, "Worker threads (default: 0 = all cores)")->transform(thread_count());
  auto* layout_opt = cmd->add_option("--layout", args->layouts,
                  "Comma-separated layouts: published (the published grids: EXR, pbrlut.hpp, dspbr_luts.json) and "
                  "renderer (warped grids, Catmull-Rom lookups: dspbr_renderer_luts.json, renderer/*.exr|png, "
                  "dspbr_lookup.h|glsl|hlsl, the thin film's dspbr_thin_film_lookup.h); default: both, or published alone with --tables/--scene/--size/--grid");
  auto* scale_opt = cmd->add_option("--renderer-scale", args->renderer_scale,
                  "Renderer layout: (N - 1) * scale + 1 samples per axis of the default N (default: 1)")
      ->transform(decimal_integer(1, 16, "a scale"));
  cmd->add_flag("--half", args->half, "Write EXRs as 16-bit half floats (default: 32-bit float)");
  cmd->add_flag("--quiet", args->quiet,
                "No progress on stderr (default: a live line per table on a terminal, one plain line per table "
                "elsewhere)");
  cmd->add_flag("--bench", args->bench,
                "Measure wall time vs max error for a range of sample budgets per table and integrator "
                "(prints a Markdown table; writes no files)");
  cmd->add_flag("--bench-lookups", args->bench_lookups,
                "Only the point-of-use part of --bench: lookup error of each layout and fit against quadrature, "
                "white furnaces from the lookups (Markdown)");
  cmd->add_option("--bench-points", args->bench_points, "Random points of the lookup study (default: 400)")
      ->transform(decimal_integer(10, 100000, "a point count"));
  cmd->add_flag("--bench-integrators", args->bench_integrators,
                "Only the integrators' part of --bench: error against time per cell of qmc, mc and quad for each "
                "table (Markdown)");
  cmd->add_option("--bench-csv", args->bench_csv,
                  "With --bench/--bench-integrators: also write the integrators' rows to this CSV file (the input "
                  "of scripts/plot_integrator_study.py)");
  cmd->callback([args, tables_opt, layout_opt, grid_opt, scale_opt] {
    args->tables_given = tables_opt->count() > 0;
    args->grid_given = grid_opt->count() > 0;
    args->renderer_scale_given = scale_opt->count() > 0;
    args->layouts_given = layout_opt->count() > 0;
    if (!args->bench_csv.empty() && !args->bench && !args->bench_integrators)
      throw UsageError("--bench-csv writes the rows of --bench or --bench-integrators: give one of them");
    if (args->bench_lookups) run_lookup_bench(*args);
    else if (args->bench || args->bench_integrators) run_bench(*args);
    else run_generate(*args);
  });
}

}  // namespace dspbr::cli
