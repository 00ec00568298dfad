#include "dspbr/validate/integrator_study.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <vector>

namespace dspbr::validate {

namespace {
std::string dims_of(const Table& t) {
  std::string dims;
  for (const Axis& ax : t.axes) dims += (dims.empty() ? "" : "x") + std::to_string(ax.size);
  return dims;
}
}  // namespace

void run_integrator_study(const LutOptions& options, const std::function<void(const IntegratorStudyRow&)>& on_row) {
  LutOptions base = options;
  const std::map<std::string, std::vector<int>> bench_sizes{{"GGX_E", {8, 8}},      {"GGX_E_avg", {8}},
                                                            {"Base_E", {4, 8, 8}},  {"Base_E_avg", {4, 8}},
                                                            {"Sheen_E", {8, 8}},    {"Sheen_ash_E", {8, 8}},
                                                            {"Glass_E", {4, 8, 8}}, {"Glass_inv_E", {4, 8, 8}},
                                                            {"Glass_E_avg", {4, 8}}, {"Glass_inv_E_avg", {4, 8}}};
  for (const auto& [name, size] : bench_sizes)
    if (!base.sizes.count(name)) base.sizes[name] = size;
  for (const std::string& name : base.tables) {
    LutOptions ref = base;
    ref.tables = {name};
    ref.integrator = Integrator::Qmc;
    const bool avg = name.size() > 4 && name.compare(name.size() - 4, 4, "_avg") == 0;
    ref.samples = avg ? (8 << 18) : (8 << 16);
    ref.seed = base.seed + 1000003;  // independent of the runs it checks
    ref.target_error = 0;
    ref.progress = false;
    const Table reference = generate_luts(ref).front();
    double ref_err = 0;
    for (double e : reference.errors) ref_err = std::max(ref_err, e);
    const std::string dims = dims_of(reference);
    // Runs one setting: wall time, time per cell, max error against the reference.
    auto measure = [&](const LutOptions& o, const std::string& integrator, const std::string& samples) {
      const auto t0 = std::chrono::steady_clock::now();
      const Table t = generate_luts(o).front();
      IntegratorStudyRow row;
      row.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      for (size_t i = 0; i < t.size(); ++i) {
        row.max_abs_error = std::max(row.max_abs_error, std::abs(t.values[i] - reference.values[i]));
        row.max_std_error = std::max(row.max_std_error, t.errors[i]);
      }
      const size_t cells = name == "Base_E" ? t.size() / size_t(t.axes[0].size)
                           : name == "Base_E_avg" ? size_t(t.axes[1].size) : t.size();
      row.table = name;
      row.grid = dims;
      row.integrator = integrator;
      row.samples = samples;
      row.ms_per_cell = 1e3 * row.wall_s / double(cells);
      on_row(row);
    };
    for (Integrator integ : {Integrator::Qmc, Integrator::Mc, Integrator::Quad}) {
      // Quad: (4P)^dims points for P panels per dimension; these budgets give P = 8 .. 64 (2D) and 8 .. 32 (3D).
      const std::vector<int> budgets = integ == Integrator::Quad
                                           ? (avg ? std::vector<int>{8 << 14, 8 << 17, 8 << 20}
                                                  : std::vector<int>{8 << 8, 8 << 10, 8 << 12, 8 << 14})
                                       : avg ? std::vector<int>{8 << 10, 8 << 12, 8 << 14, 8 << 16}
                                             : std::vector<int>{8 << 8, 8 << 10, 8 << 12, 8 << 14};
      for (int n : budgets) {
        LutOptions o = base;
        o.tables = {name};
        o.integrator = integ;
        o.samples = n;
        o.target_error = 0;  // fixed budget
        o.progress = false;
        measure(o, integrator_name(integ), std::to_string(n));
      }
    }
    for (Integrator integ : {Integrator::Qmc, Integrator::Quad}) {  // the adaptive settings
      LutOptions o = base;
      o.tables = {name};
      o.integrator = integ;
      o.progress = false;
      const bool is_default = integ == lut_default_integrator(name);
      measure(o, std::string(integrator_name(integ)) + " adaptive" + (is_default ? " (default)" : ""),
              "<= " + std::to_string(lut_settings(name, o).samples));
    }
    IntegratorStudyRow r;
    r.table = name;
    r.grid = dims;
    r.integrator = "reference (qmc)";
    r.samples = std::to_string(ref.samples);
    r.max_std_error = ref_err;
    r.reference = true;
    on_row(r);
  }
}

std::string integrator_study_markdown_header() {
  return "| table | grid | integrator | samples/cell | wall time [s] | ms/cell | max abs error | max est. std error |\n"
         "|---|---|---|---:|---:|---:|---:|---:|";
}

std::string integrator_study_markdown_row(const IntegratorStudyRow& r) {
  if (r.reference)
    return fmt::format("| {} | {} | {} | {} | | | | {:.2e} |", r.table, r.grid, r.integrator, r.samples, r.max_std_error);
  return fmt::format("| {} | {} | {} | {} | {:.3f} | {:.3f} | {:.2e} | {:.2e} |", r.table, r.grid, r.integrator,
                     r.samples, r.wall_s, r.ms_per_cell, r.max_abs_error, r.max_std_error);
}

}  // namespace dspbr::validate
