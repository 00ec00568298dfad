// `dspbr validate`: the validation suite (white furnace, reciprocity, chi-square sampling tests,
// stability sweeps, table accuracy, furnace spheres) and its HTML report.
//   dspbr validate --out DIR           full run (minutes)
//   dspbr validate --quick --out DIR   reduced sample counts and cases (seconds; run by CTest)
// Writes DIR/data/report.json and DIR/images/ (C++), then DIR/index.html and DIR/plots/ through
// scripts/report/make_report.py (matplotlib + jinja2), found relative to the running binary
// (installed in <prefix>/share/dspbr/report; the build copies it next to build/dspbr).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <memory>
#include <optional>
#include <string>
#include <sys/resource.h>
#include <tbb/global_control.h>

#include "commands.h"
#include "interrupt_cleanup.h"
#include "report_script.h"
#include "validate_shader_library.h"
#include "dspbr/limits.h"
#include "dspbr/io/read_file.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/validate/catalog.h"
#include "dspbr/validate/provenance.h"
#include "dspbr/validate/suite.h"
#include "dspbr/validate/waivers.h"

namespace dspbr::cli {

namespace {

struct ValidateArgs {
  std::string out = "report";
  bool quick = false;
  uint64_t seed = 1;
  std::string luts;  // empty: the built-in tables
  std::string tables = "renderer";  // table layout of the BSDF cases
  bool transmission_compensation = false;  // every case with the compensated transparent core
  std::string python = "/usr/bin/python3";
  bool html = true;
  bool allow_failures = false;
  bool shader_library = true;  // the shader library's section (validate_shader_library.h)
  int threads = 0;  // 0: all cores
};

void run_validate(const ValidateArgs& a) {
  const std::string script = a.html ? report_script("make_report.py", a.python) : std::string();
  std::unique_ptr<tbb::global_control> threads;
  if (a.threads > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::size_t(a.threads));

  validate::SuiteSettings s = validate::SuiteSettings::defaults(a.quick);
  s.seed = a.seed;
  s.command_line = validate::process_command_line();

  // The tables: the BSDF cases read --luts FILE (either layout) or the built-in set of --tables
  // (default: the renderer layout); the table check compares every table of that set with the
  // reference quadrature.
  const LutSet* checked = nullptr;
  const LutSet* bsdf_tables = nullptr;
  LutSet loaded;
  if (!a.luts.empty()) {
    try {
      const std::string bytes = read_file(a.luts, limits::kTableFileBytes);  // read once: the tables and their provenance
      loaded = LutSet::from_text(bytes, a.luts);
      s.table_file = validate::table_text_settings(bytes, a.luts);
    } catch (const std::exception& e) {
      throw UsageError(std::string("--luts: ") + e.what());
    }
    if (loaded.layout == LutLayout::Published) {
      const std::vector<std::string> missing = validate::missing_tables(loaded);
      if (!missing.empty())
        throw UsageError(fmt::format("--luts: {}: incomplete table file: missing or empty {}", a.luts,
                                     fmt::join(missing, ", ")));
    }
    bsdf_tables = checked = &loaded;
  } else {
    LutLayout layout;
    try {
      layout = parse_lut_layout(a.tables);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--tables: ") + e.what());
    }
    try {
      bsdf_tables = checked = &LutSet::of_layout(layout);
      s.table_file = validate::table_text_settings(LutSet::builtin_text(layout), LutSet::builtin_name(layout));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "dspbr validate: tables skipped: %s\n", e.what());
    }
  }
  // The report is written into a private staging folder inside --out and moved into place once
  // complete (io/output_folder.h); a refused or interrupted run leaves --out as it was.
  InterruptCleanup cleanup(a.out);  // the handlers first, then the folder
  OutputFolder& out = cleanup.out();
  validate::CatalogOptions co;
  co.quick = a.quick;
  co.seed = a.seed;
  co.random_materials = a.quick ? 20 : 2000;
  co.luts = bsdf_tables;
  co.transmission_compensation = a.transmission_compensation;
  validate::Catalog cat = validate::dspbr_catalog(co);

  std::fprintf(stderr, "dspbr validate (%s): %zu cases, %zu stability corners, %zu furnace rows -> %s\n",
               a.quick ? "quick" : "full", cat.cases.size(), cat.stability.size(), cat.furnace_rows.size(),
               a.out.c_str());
  std::optional<validate::OtherImplementation> library;
  if (a.shader_library) library = shader_library_checks(cat, a.quick);
  const validate::SuiteResult r = validate::run_suite(cat, checked, s, out.staging(), library ? &*library : nullptr);

  if (a.html) {
    // Timed like the suite's phases (the report's own time is part of the run's).
    const auto t0 = std::chrono::steady_clock::now();
    rusage before{}, after{};
    getrusage(RUSAGE_CHILDREN, &before);
    run_report_script(a.python, script, out.staging(), a.out);
    getrusage(RUSAGE_CHILDREN, &after);
    auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    const double cpu = seconds(after.ru_utime) + seconds(after.ru_stime) - seconds(before.ru_utime) -
                       seconds(before.ru_stime);
    validate::print_phase_time("report (html)",
                               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), cpu);
  } else {
    replace_earlier_pages(out, {"index.html", "report.html"}, "data/report.json",
                          r.failed_checks > 0 ? "FAIL" : "PASS");
  }
  out.commit();

  // Summary on stdout.
  std::printf("validation (%s run, seed %llu): report in %s/%s\n", a.quick ? "quick" : "full",
              static_cast<unsigned long long>(a.seed), a.out.c_str(), a.html ? "index.html" : "data/report.json");
  int width = 58;  // the longest check name
  for (const auto& c : r.report["summary"]) width = std::max(width, int(c["check"].get<std::string>().size()));
  std::printf("  %-*s %5s %5s %7s %11s\n", width, "check", "PASS", "FAIL", "WAIVED", "NOT JUDGED");
  int not_judged = 0, total = 0;
  for (const auto& c : r.report["summary"]) {
    std::printf("  %-*s %5d %5d %7d %11d\n", width, c["check"].get<std::string>().c_str(), c["passed"].get<int>(),
                c["failed"].get<int>(), c["waived"].get<int>(), c["not_judged"].get<int>());
    not_judged += c["not_judged"].get<int>();
    total += c["total"].get<int>();
  }
  std::printf("  %s\n", validate::banner(r.report).c_str());
  if (not_judged > 0)
    std::printf("  NOT JUDGED %d of %d verdicts: measured, but the check could not have failed there (reasons in the "
                "report)\n", not_judged, total);
  const auto& skipped = r.report["skipped"];
  std::size_t shown = 0;
  for (const auto& sk : skipped) {
    const std::string line = sk.get<std::string>();
    if (line.rfind("stability random", 0) == 0) continue;  // counted below
    std::printf("  skipped: %s\n", line.c_str());
    ++shown;
  }
  if (skipped.size() > shown) std::printf("  skipped: %zu rejected random materials\n", skipped.size() - shown);
  for (const auto& w : r.report["waivers"])
    if (w["used"].get<int>() > 0)
      std::printf("  WAIVED %d x %s (%s): %s\n", w["used"].get<int>(), w["id"].get<std::string>().c_str(),
                  w["spec"].get<std::string>().c_str(), w["reason"].get<std::string>().c_str());
  for (const std::string& f : r.failures) std::printf("  FAILED %s\n", f.c_str());
  if (r.failed_checks > 0 && !a.allow_failures)
    throw std::runtime_error(fmt::format("{} validation check(s) failed (listed above; details in {}/{})", r.failed_checks,
                                         a.out, a.html ? "index.html" : "data/report.json"));
}

}  // namespace

void add_validate_command(CLI::App& app) {
  auto args = std::make_shared<ValidateArgs>();
  auto* cmd = app.add_subcommand(
      "validate",
      "Validation suite: white furnace, reciprocity, chi-square sampling tests, stability sweeps, table accuracy, "
      "furnace spheres; writes an HTML report");
  cmd->add_option("--out", args->out, "Output folder (index.html, images/, plots/, data/)")->capture_default_str();
  cmd->add_flag("--transmission-compensation", args->transmission_compensation,
                "Check every case with the rough-transmission energy compensation (beyond DSPBR 2025x; "
                "docs/bsdf.md); the transparent cases then claim energy preservation");
  cmd->add_flag("--quick", args->quick, "Reduced run (seconds): fewer cases, directions and samples");
  cmd->add_option("--seed", args->seed, "Seed of every random stream (same seed -> same report)")
      ->capture_default_str()
      ->transform(non_negative_integer());
  cmd->add_option("--luts", args->luts, "Table file (dspbr_luts.json or dspbr_renderer_luts.json) the BSDF cases read instead of the built-in set of --tables; every table the cases read is checked against the reference quadrature");
  cmd->add_option("--tables", args->tables,
                  "Energy tables of the BSDF cases: renderer (default) or published (shows the published layout's "
                  "artefacts, e.g. energy gains at grazing angles)")
      ->capture_default_str();
  cmd->add_option("--python", args->python, "Python interpreter with numpy, matplotlib and jinja2")->capture_default_str();
  cmd->add_flag("--no-html", [args](int64_t) { args->html = false; }, "Write only the data (data/report.json, images/)");
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores); the report does not depend on it")
      ->capture_default_str()
      ->transform(thread_count());
  cmd->add_flag("--no-shader-library", [args](int64_t) { args->shader_library = false; },
                "Leave out the section that checks the shader library's C++ compile (shaders/dspbr.h) with the same "
                "furnace, chi-square and stability checks and the default conformance vectors");
  cmd->add_flag("--allow-failures", args->allow_failures,
                "Exit with status 0 even when checks fail (waived failures never fail the run)");
  cmd->callback([args] { run_validate(*args); });
}

}  // namespace dspbr::cli
