#include "dspbr/lut/generate.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "dspbr/limits.h"
#include "dspbr/lut/parallel_cells.h"

namespace dspbr {

namespace {

// Stream ids: table id in the high 32 bits, cell index in the low ones.
enum TableId : uint64_t { kGgxE = 0, kGgxEAvg = 1, kBaseE = 2, kBaseEAvg = 3, kSheenE = 4, kSheenAshE = 5,
                          kBaseEMAvg = 6 /* E_m,avg on Base_E's roughness axis */,
                          kGlassE = 7, kGlassInvE = 8, kGlassEAvg = 9, kGlassInvEAvg = 10 };
uint64_t stream_of(uint64_t table, uint64_t cell) { return (table << 32) | cell; }

// Largest size per axis and total cells accepted (keeps memory and run time sane).
constexpr int kMaxAxisSize = limits::kTableAxisSize;
constexpr size_t kMaxCells = limits::kTableCells;

std::vector<double> coords(const Axis& a) {
  std::vector<double> x(size_t(a.size));
  for (int i = 0; i < a.size; ++i) x[size_t(i)] = a.coord(i);
  return x;
}

Table make_table(const std::string& name, const LutOptions& opt) {
  Table t;
  t.name = name;
  t.axes = lut_axes(name, opt);
  t.values.assign(t.size(), 0.0);
  t.errors.assign(t.size(), 0.0);
  return t;
}

}  // namespace

const std::vector<std::string>& lut_table_names() {
  static const std::vector<std::string> names{"GGX_E",   "GGX_E_avg",   "Base_E",          "Base_E_avg",
                                              "Sheen_E", "Sheen_ash_E", "Glass_E",         "Glass_inv_E",
                                              "Glass_E_avg", "Glass_inv_E_avg"};
  return names;
}

bool is_lut_table_name(const std::string& name) {
  const auto& n = lut_table_names();
  return std::find(n.begin(), n.end(), name) != n.end();
}

std::vector<std::string> lut_axis_names(const std::string& t) {
  if (t == "GGX_E") return {"roughness", "cos_theta"};
  if (t == "GGX_E_avg") return {"roughness"};
  if (t == "Base_E") return {"f0", "roughness", "cos_theta"};
  if (t == "Base_E_avg") return {"f0", "roughness"};
  if (t == "Sheen_E" || t == "Sheen_ash_E") return {"alpha_b", "cos_theta"};
  if (t == "Glass_E" || t == "Glass_inv_E") return {"ior_x", "roughness", "cos_theta"};
  if (t == "Glass_E_avg" || t == "Glass_inv_E_avg") return {"ior_x", "roughness"};
  throw std::invalid_argument("unknown table '" + t + "'");
}

bool is_glass_table(const std::string& t) { return t.rfind("Glass_", 0) == 0 && is_lut_table_name(t); }


Integrator lut_default_integrator(const std::string& t) {
  (void)lut_axis_names(t);  // refuses an unknown name
  return Integrator::Quad;
}

std::vector<int> lut_default_size(const std::string& t) {
  if (t == "GGX_E") return {32, 32};
  if (t == "GGX_E_avg") return {32};
  if (t == "Base_E") return {16, 16, 16};
  if (t == "Base_E_avg") return {16, 16};
  if (t == "Sheen_E" || t == "Sheen_ash_E") return {16, 16};
  if (t == "Glass_E" || t == "Glass_inv_E") return {16, 16, 32};
  if (t == "Glass_E_avg" || t == "Glass_inv_E_avg") return {16, 16};
  throw std::invalid_argument("unknown table '" + t + "'");
}

int lut_default_samples(const std::string& t) {
  // Caps for the adaptive budget (docs/luts.md): only the hardest cells (grazing, smallest
  // roughness) come near them.
  if (t == "GGX_E_avg" || t == "Base_E_avg" || t == "Glass_E_avg" || t == "Glass_inv_E_avg") return 8 << 18;
  return 8 << 16;
}

IntegratorSettings lut_settings(const std::string& table, const LutOptions& opt) {
  IntegratorSettings s;
  s.integrator = opt.integrator ? *opt.integrator : lut_default_integrator(table);
  s.samples = opt.samples > 0 ? opt.samples : lut_default_samples(table);
  s.randomizations = opt.randomizations;
  s.seed = opt.seed;
  s.target_error = !std::isnan(opt.target_error) ? opt.target_error
                   : s.integrator == Integrator::Quad ? kQuadDefaultTolerance
                                                      : kLutDefaultTargetError;
  return s;
}

std::vector<Axis> lut_axes(const std::string& table, const LutOptions& opt) {
  const std::vector<std::string> names = lut_axis_names(table);
  auto it = opt.sizes.find(table);
  const std::vector<int> size = it != opt.sizes.end() ? it->second : lut_default_size(table);
  if (size.size() != names.size())
    throw std::invalid_argument("size of " + table + " needs " + std::to_string(names.size()) + " dimensions");
  std::vector<Axis> axes;
  for (size_t d = 0; d < names.size(); ++d) {
    Axis a;
    a.name = names[d];
    a.size = size[d];
    a.lo = 0;
    a.hi = 1;
    a.kind = is_glass_table(table) ? GridKind::Endpoint : opt.grid;
    axes.push_back(a);
  }
  return axes;
}

void validate_lut_options(const LutOptions& opt) {
  if (opt.tables.empty()) throw std::invalid_argument("no tables selected");
  for (const auto& t : opt.tables)
    if (!is_lut_table_name(t))
      throw std::invalid_argument("unknown table '" + t +
                                  "' (known: GGX_E, GGX_E_avg, Base_E, Base_E_avg, Sheen_E, Sheen_ash_E, Glass_E, "
                                  "Glass_inv_E, Glass_E_avg, Glass_inv_E_avg)");
  for (const auto& [t, size] : opt.sizes) {
    if (!is_lut_table_name(t)) throw std::invalid_argument("unknown table '" + t + "' in a size option");
    const size_t rank = lut_axis_names(t).size();
    if (size.size() != rank)
      throw std::invalid_argument("size of " + t + " needs " + std::to_string(rank) + " dimensions, e.g. " +
                                  (rank == 1 ? "32" : rank == 2 ? "16x16" : "16x16x16"));
    size_t cells = 1;
    for (int n : size) {
      const int min = opt.grid == GridKind::Endpoint || is_glass_table(t) ? 2 : 1;
      if (n < min || n > kMaxAxisSize)
        throw std::invalid_argument("size of " + t + ": each dimension must be in [" + std::to_string(min) + ", " +
                                    std::to_string(kMaxAxisSize) + "]");
      cells *= size_t(n);
    }
    if (cells > kMaxCells) throw std::invalid_argument("size of " + t + ": too many cells (max 2^24)");
  }
  if (opt.randomizations < 2 || opt.randomizations > 1024)
    throw std::invalid_argument("randomizations must be in [2, 1024]");
  if (opt.samples < 0) throw std::invalid_argument("samples must be positive");
  if (opt.samples > 0 && opt.samples < opt.randomizations)
    throw std::invalid_argument("samples must be at least the number of randomizations (" +
                                std::to_string(opt.randomizations) + ")");
  if (opt.samples > 0 && opt.samples / opt.randomizations > (1 << 24))
    throw std::invalid_argument("samples / randomizations must be at most 2^24");
  if (!std::isnan(opt.target_error) && !(opt.target_error >= 0 && opt.target_error <= 1))
    throw std::invalid_argument("target error must be in [0, 1]");
  if (opt.threads < 0 || opt.threads > limits::kThreads)
    throw std::invalid_argument("threads must be from 0 (all cores) to " + std::to_string(limits::kThreads));
  // Endpoint grids need two samples per axis for the default sizes too (all defaults are >= 16).
}

std::vector<Table> generate_luts(const LutOptions& opt) {
  validate_lut_options(opt);
  tbb::task_arena arena(opt.threads > 0 ? opt.threads : tbb::task_arena::automatic);
  std::vector<Table> out;
  for (const std::string& name : lut_table_names()) {
    if (std::find(opt.tables.begin(), opt.tables.end(), name) == opt.tables.end()) continue;
    Table t = make_table(name, opt);
    const IntegratorSettings s = lut_settings(name, opt);
    const size_t n = t.size();
    if (name == "GGX_E") {
      const auto r = coords(t.axes[0]), mu = coords(t.axes[1]);
      parallel_cells(arena, n, name, opt.progress, [&](size_t i) {
        const Estimate e = ggx_E(mu[i % mu.size()], r[i / mu.size()], s, stream_of(kGgxE, i));
        t.values[i] = e.value;
        t.errors[i] = e.error;
      });
    } else if (name == "GGX_E_avg") {
      const auto r = coords(t.axes[0]);
      parallel_cells(arena, n, name, opt.progress, [&](size_t i) {
        const Estimate e = ggx_E_avg(r[i], s, stream_of(kGgxEAvg, i));
        t.values[i] = e.value;
        t.errors[i] = e.error;
      });
    } else if (name == "Base_E") {
      const auto f0 = coords(t.axes[0]), r = coords(t.axes[1]), mu = coords(t.axes[2]);
      // E_m,avg at Base_E's own roughness points (not interpolated from GGX_E_avg), with the
      // averages' sample budget.
      IntegratorSettings s_avg = s;
      s_avg.samples = opt.samples > 0 ? opt.samples : lut_default_samples("Base_E_avg");
      std::vector<Estimate> e_m_avg(r.size());
      parallel_cells(arena, r.size(), name + " (E_m,avg)", opt.progress, [&](size_t i) {
        e_m_avg[i] = ggx_E_avg(r[i], s_avg, stream_of(kBaseEMAvg, i));
      });
      // One integration per (roughness, cos) serves every f0.
      const size_t nrm = r.size() * mu.size();
      parallel_cells(arena, nrm, name, opt.progress, [&](size_t i) {
        const size_t ir = i / mu.size(), im = i % mu.size();
        const std::vector<Estimate> e = base_E_f0s(mu[im], r[ir], f0, e_m_avg[ir], s, stream_of(kBaseE, i));
        for (size_t k = 0; k < f0.size(); ++k) {
          t.values[k * nrm + i] = e[k].value;
          t.errors[k * nrm + i] = e[k].error;
        }
      });
    } else if (name == "Base_E_avg") {
      const auto f0 = coords(t.axes[0]), r = coords(t.axes[1]);
      parallel_cells(arena, r.size(), name, opt.progress, [&](size_t i) {
        const std::vector<Estimate> e = base_E_avg_f0s(r[i], f0, s, stream_of(kBaseEAvg, i));
        for (size_t k = 0; k < f0.size(); ++k) {
          t.values[k * r.size() + i] = e[k].value;
          t.errors[k * r.size() + i] = e[k].error;
        }
      });
    } else if (name == "Glass_E" || name == "Glass_inv_E") {
      const bool inside = name == "Glass_inv_E";
      const auto x = coords(t.axes[0]), r = coords(t.axes[1]), mu = coords(t.axes[2]);
      parallel_cells(arena, n, name, opt.progress, [&](size_t i) {
        const size_t ix = i / (r.size() * mu.size()), ir = (i / mu.size()) % r.size(), im = i % mu.size();
        const Estimate e = glass_E(mu[im], r[ir], glass_ior_of_x(x[ix]), inside, s,
                                   stream_of(inside ? kGlassInvE : kGlassE, i));
        t.values[i] = e.value;
        t.errors[i] = e.error;
      });
    } else if (name == "Glass_E_avg" || name == "Glass_inv_E_avg") {
      const bool inside = name == "Glass_inv_E_avg";
      const auto x = coords(t.axes[0]), r = coords(t.axes[1]);
      parallel_cells(arena, n, name, opt.progress, [&](size_t i) {
        const Estimate e = glass_E_avg(r[i % r.size()], glass_ior_of_x(x[i / r.size()]), inside, s,
                                       stream_of(inside ? kGlassInvEAvg : kGlassEAvg, i));
        t.values[i] = e.value;
        t.errors[i] = e.error;
      });
    } else {  // Sheen_E, Sheen_ash_E: rows hold alpha_b directly
      const bool ash = name == "Sheen_ash_E";
      const auto ab = coords(t.axes[0]), mu = coords(t.axes[1]);
      parallel_cells(arena, n, name, opt.progress, [&](size_t i) {
        const Estimate e = sheen_E(mu[i % mu.size()], ab[i / mu.size()], ash ? SheenModel::Ash : SheenModel::Main, s,
                                   stream_of(ash ? kSheenAshE : kSheenE, i));
        t.values[i] = e.value;
        t.errors[i] = e.error;
      });
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace dspbr
