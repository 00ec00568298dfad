#include "dspbr/validate/integrator_study.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <vector>

namespace dspbr {
std::string_view integrator_study_csv();  // generated (cmake/generated_sources.cmake)
}  // namespace dspbr

namespace dspbr::validate {

namespace {
constexpr double kReferenceTolerance = 1e-10;

std::string dims_of(const Table& t) {
  std::string dims;
  for (const Axis& ax : t.axes) dims += (dims.empty() ? "" : "x") + std::to_string(ax.size);
  return dims;
}
}  // namespace

void run_integrator_study(const LutOptions& options, const std::function<void(const IntegratorStudyRow&)>& on_row) {
  LutOptions all = options;
  // Small grids: 4 samples on an f0 / ior axis, 8 on the others.
  for (const std::string& name : all.tables)
    if (!all.sizes.count(name)) {
      std::vector<int> size;
      for (const std::string& axis : lut_axis_names(name)) size.push_back(axis == "f0" || axis == "ior_x" ? 4 : 8);
      all.sizes[name] = size;
    }
  for (const std::string& name : options.tables) {
    const LutInfo& info = published_lut(name);
    // This table alone, with its size (a size for a table not generated is refused).
    LutOptions base = all;
    base.tables = {name};
    base.sizes = {{name, all.sizes.at(name)}};
    // Reference: the quadrature at a thousandth of its default tolerance (its accuracy against
    // independent rules is what tests/test_lut_quadrature.cpp checks).
    LutOptions ref = base;
    ref.tables = {name};
    ref.integrator = Integrator::Quad;
    ref.target_error = kReferenceTolerance;
    ref.progress = false;
    const Table reference = generate_luts(ref).front();
    double ref_err = 0;
    for (double e : reference.errors) ref_err = std::max(ref_err, e);
    const std::string dims = dims_of(reference);
    // Runs one setting: wall time, time per cell, max error against the reference.
    auto measure = [&](const LutOptions& o, const std::string& integrator, const std::string& budget) {
      const auto t0 = std::chrono::steady_clock::now();
      const Table t = generate_luts(o).front();
      IntegratorStudyRow row;
      row.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      for (size_t i = 0; i < t.size(); ++i) {
        row.max_abs_error = std::max(row.max_abs_error, std::abs(t.values[i] - reference.values[i]));
        row.max_std_error = std::max(row.max_std_error, t.errors[i]);
      }
      // Base_E / Base_E_avg: one integration serves every f0.
      const size_t cells = info.id == Lut::BaseE      ? t.size() / size_t(t.axes[0].size)
                           : info.id == Lut::BaseEAvg ? size_t(t.axes[1].size)
                                                      : t.size();
      row.table = name;
      row.grid = dims;
      row.integrator = integrator;
      row.samples = budget;
      row.ms_per_cell = 1e3 * row.wall_s / double(cells);
      on_row(row);
    };
    for (Integrator integ : {Integrator::Qmc, Integrator::Mc}) {  // fixed sample budgets per cell
      const int scale = info.average ? 4 : 1;                      // one more dimension
      for (int n : {8 << 8, 8 << 10, 8 << 12, 8 << 14}) {
        LutOptions o = base;
        o.tables = {name};
        o.integrator = integ;
        o.samples = n * scale;
        o.target_error = 0;
        o.progress = false;
        measure(o, integrator_name(integ), std::to_string(n * scale) + " samples");
      }
    }
    for (double tol : {1e-3, 1e-5, 1e-7, 1e-9}) {  // the quadrature's budget is its tolerance
      LutOptions o = base;
      o.tables = {name};
      o.integrator = Integrator::Quad;
      o.target_error = tol;
      o.progress = false;
      measure(o, integrator_name(Integrator::Quad), fmt::format("tolerance {:g}{}", tol,
                                                                 tol == kQuadDefaultTolerance ? " (default)" : ""));
    }
    IntegratorStudyRow r;
    r.table = name;
    r.grid = dims;
    r.integrator = "reference (quad)";
    r.samples = fmt::format("tolerance {:g}", kReferenceTolerance);
    r.max_std_error = ref_err;
    r.reference = true;
    on_row(r);
  }
}

std::string integrator_study_markdown_header() {
  return "| table | grid | integrator | budget per cell | wall time [s] | ms/cell | max abs error | max stated error |\n"
         "|---|---|---|---:|---:|---:|---:|---:|";
}

std::string integrator_study_markdown_row(const IntegratorStudyRow& r) {
  if (r.reference)
    return fmt::format("| {} | {} | {} | {} | | | | {:.2e} |", r.table, r.grid, r.integrator, r.samples, r.max_std_error);
  return fmt::format("| {} | {} | {} | {} | {:.3f} | {:.3f} | {:.2e} | {:.2e} |", r.table, r.grid, r.integrator,
                     r.samples, r.wall_s, r.ms_per_cell, r.max_abs_error, r.max_std_error);
}

std::string_view committed_integrator_study_csv() { return dspbr::integrator_study_csv(); }

std::string integrator_study_csv_header() {
  return "table,grid,integrator,budget,wall_s,ms_per_cell,max_abs_error,max_stated_error,reference";
}

std::string integrator_study_csv_row(const IntegratorStudyRow& r) {
  return fmt::format("{},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{}", r.table, r.grid, r.integrator, r.samples, r.wall_s,
                     r.ms_per_cell, r.max_abs_error, r.max_std_error, r.reference ? 1 : 0);
}

}  // namespace dspbr::validate
