// The speed/accuracy study of the table integrators (`dspbr lut --bench`, docs/luts.md): for each
// table and integrator (QMC, MC at fixed sample budgets; the deterministic quadrature at a range
// of tolerances), the wall time per cell and the max |error| against the quadrature at tolerance
// 1e-10. Runs on a small grid per table (the options' sizes override it) to
// keep the reference affordable. Wall times are measurements, not reproducible bytes.
#pragma once
#include <functional>
#include <string>
#include <string_view>

#include "dspbr/lutgen/generate.h"

namespace dspbr::validate {

struct IntegratorStudyRow {
  std::string table, grid, integrator, samples;  // samples: the budget per cell (samples or tolerance)
  double wall_s = 0, ms_per_cell = 0, max_abs_error = 0, max_std_error = 0;
  bool reference = false;  // the reference itself: only samples and max_std_error are meaningful
};

// Runs the study for base.tables; calls on_row for each row as soon as it is measured.
void run_integrator_study(const LutOptions& base, const std::function<void(const IntegratorStudyRow&)>& on_row);

// The committed run of the study (luts/integrator_study.csv, written by `dspbr lut
// --bench-integrators --bench-csv luts/integrator_study.csv`), compiled in: the validation report
// plots it.
std::string_view committed_integrator_study_csv();

// The Markdown header of the study's table, and one row.
std::string integrator_study_markdown_header();
std::string integrator_study_markdown_row(const IntegratorStudyRow& r);
// The same as CSV (table,grid,integrator,budget,wall_s,ms_per_cell,max_abs_error,max_stated_error).
std::string integrator_study_csv_header();
std::string integrator_study_csv_row(const IntegratorStudyRow& r);

}  // namespace dspbr::validate
