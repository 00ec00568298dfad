// The validation run behind `dspbr validate`: runs every check on a catalog of cases and writes
// the report data into a folder:
//   DIR/data/report.json   every number of every figure and table (schema: docs/validation.md)
//   DIR/images/*.exr|png   furnace spheres (EXR linear float, PNG sRGB)
// The HTML report and plots are made from report.json by scripts/report/make_report.py.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dspbr/tables/lut_set.h"
#include "dspbr/validate/catalog.h"
#include "dspbr/validate/chi2.h"
#include "dspbr/validate/furnace.h"
#include "dspbr/validate/lut_reference.h"
#include "dspbr/validate/reciprocity.h"
#include "dspbr/validate/stability.h"

namespace dspbr::validate {

struct SuiteSettings {
  bool quick = false;
  uint64_t seed = 1;
  bool progress = true;  // progress lines on stderr (only when it is a terminal)

  // White furnace
  std::vector<double> furnace_cos;  // view cosines (mirrored below for viewer_below cases)
  double furnace_quadrature_tolerance = 1e-4;  // absolute error aimed at by the quadrature
  std::size_t furnace_samples = 0;  // sampled estimator: first count
  std::size_t furnace_samples_max = 0;  // its cap (x4 per round while a verdict is NOT JUDGED)
  EnergyTolerances energy;
  // Reciprocity
  std::size_t reciprocity_pairs = 0;
  double reciprocity_tol = 1e-6;  // max relative deviation
  // Chi-square
  Chi2Settings chi2;
  std::vector<double> chi2_cos;        // incidences (viewer above)
  std::vector<double> chi2_cos_below;  // incidences for viewer_below cases (inside, incl. TIR)
  std::size_t chi2_histograms = 4;     // tests whose histograms go into the report
  // Stability
  StabilitySettings stability;
  // Tables
  int lut_cells_per_axis = 0;
  RefQuadrature lut_quadrature;
  // |table - reference| allowed on top of the reference's own error estimate. Fixed: the table's
  // own standard error is reported but never widens it (a noisy table must not validate itself).
  double lut_tol = 2e-3;           // published layout (absolute; relative where the value exceeds 1)
  double renderer_lut_tol = 1e-4;  // renderer layout, the value its lookups return at a sample
  double renderer_avg_lut_tol = 1e-3;  // renderer layout, averages (of the directional lookups)
  // Pictures
  int image_res = 0;
  std::size_t image_spp = 0;
  // Convergence
  std::vector<std::size_t> convergence_samples;
  std::vector<std::string> convergence_components;  // every case of these with a non-delta part
  // Provenance (copied into the report): the table file in use (table_text_settings(), null when
  // the tables did not come from a file) and the command line (goes into the "run" part).
  nlohmann::json table_file;
  std::string command_line;

  // Defaults of the full run (minutes) or the quick run (seconds).
  static SuiteSettings defaults(bool quick);
};

// Verdict words of the report: every verdict is one of these.
enum class Status { Pass, Fail, NotJudged, Waived };
const char* status_word(Status s);  // "PASS", "FAIL", "NOT JUDGED", "WAIVED"

struct SuiteResult {
  nlohmann::json report;  // also written to DIR/data/report.json
  int failed_checks = 0;  // number of failed verdicts without a waiver (exit status 1 when > 0)
  std::vector<std::string> failures;  // one line per unwaived failed verdict
  std::vector<std::string> waived;    // one line per waived failed verdict (with the waiver's id)
};

// The report's banner, one line (also report["banner"], shown by the HTML report and the CLI):
// the run's kind (a quick run says QUICK and what it cannot judge), its verdict and the number of
// verdicts NOT JUDGED, from report["mode"], ["summary"] and ["energy"].
std::string banner(const nlohmann::json& report);

// One line of the run's timing breakdown on stderr: "  energy  10.4s  (cpu  20.1s)". The suite
// prints one per phase; `dspbr validate` adds the report page's.
void print_phase_time(const char* name, double wall_s, double cpu_s);

// The tables of `luts` that are missing or empty (canonical names); a set used for validation must
// have none.
std::vector<std::string> missing_tables(const LutSet& luts);

// Another implementation of DSPBR checked in the same report (section "shader_library": the shader
// library's C++ compile, apps/dspbr/validate_shader_library.h): the same furnace, chi-square and
// stability checks on its own catalog, and its conformance over a vector set, one verdict per group.
// Its verdicts count under their check's name prefixed with "shader library: ".
struct ConformanceGroup {
  std::string group;
  std::size_t vectors = 0, failed = 0;
  double worst_ratio = 0;  // the largest error / tolerance of a vector
  std::string worst_id;    // that vector
};
struct OtherImplementation {
  std::string name;          // e.g. "shader library (C++ compile, float)"
  Catalog catalog;           // the cases and stability corners it is checked on
  std::vector<std::string> left_out;  // the reference's cases it is not checked on, and why
  // Pdf and sample weight against eval and pdf, relative (the chi-square's consistency check):
  // an implementation in float rounds where the reference does not.
  double consistency_tol = 1e-6;
  // At most this many samples per chi-square test (0: the reference's count).
  std::size_t chi2_samples_max = 0;
  std::string vector_set;  // what the conformance verdicts judge, e.g. "the default vectors (2384)"
  std::function<std::vector<ConformanceGroup>()> conformance;  // run and timed by the suite
};

// Runs everything on `catalog` and the tables in `luts` (null: table checks skipped; also used to
// place the table-layout waivers) and writes DIR/data/report.json and DIR/images/. Deterministic
// for a given seed whatever the thread count, except the report's "run" object (date, thread
// count, command line).
// With `other`, that implementation's checks as well (report["shader_library"]).
SuiteResult run_suite(const Catalog& catalog, const LutSet* luts, const SuiteSettings& s, const std::string& dir,
                      const OtherImplementation* other = nullptr);

}  // namespace dspbr::validate
