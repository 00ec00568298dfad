// The validation run behind `dspbr validate`: runs every check on a catalog of cases and writes
// the report data into a folder:
//   DIR/data/report.json   every number of every figure and table (schema: docs/validation.md)
//   DIR/images/*.exr|png   furnace spheres (EXR linear float, PNG sRGB)
// The HTML report and plots are made from report.json by scripts/report/make_report.py.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dspbr/lut/lut_set.h"
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
  int furnace_strata = 0;           // eval estimator: strata^2 directions per hemisphere
  std::size_t furnace_samples = 0;  // sampled estimator
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
  double lut_tol = 2e-3;  // |table - reference| allowed on top of 4 table standard errors
  // Pictures
  int image_res = 0;
  std::size_t image_spp = 0;
  // Convergence
  std::vector<std::size_t> convergence_samples;
  std::size_t convergence_cases = 3;

  // Defaults of the full run (minutes) or the quick run (seconds).
  static SuiteSettings defaults(bool quick);
};

struct SuiteResult {
  nlohmann::json report;  // also written to DIR/data/report.json
  int failed_checks = 0;  // number of failed verdicts over all checks
  std::vector<std::string> failures;  // one line per failed verdict
};

// Runs everything on `catalog` and the tables in `luts` (null: table checks skipped) and writes
// DIR/data/report.json and DIR/images/. Deterministic for a given seed, whatever the thread count.
SuiteResult run_suite(const Catalog& catalog, const LutSet* luts, const SuiteSettings& s, const std::string& dir);

}  // namespace dspbr::validate
