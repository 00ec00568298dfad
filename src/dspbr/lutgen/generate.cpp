#include "dspbr/lutgen/generate.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "dspbr/limits.h"
#include "dspbr/lutgen/parallel_cells.h"

namespace dspbr {

namespace {

// Stream ids: the table's (registry) in the high 32 bits, cell index in the low ones.
constexpr uint64_t kBaseEMAvgStream = 6;  // E_m,avg on Base_E's roughness axis
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

Integrator lut_default_integrator(const std::string& t) {
  (void)published_lut(t);  // refuses an unknown name
  return Integrator::Quad;
}


int lut_default_samples(const std::string& t) {
  // Caps for the adaptive budget (docs/luts.md): only the hardest cells (grazing, smallest
  // roughness) come near them.
  return published_lut(t).average ? 8 << 18 : 8 << 16;
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
  for (const auto& t : opt.tables) (void)published_lut(t);
  for (const auto& [t, size] : opt.sizes) {
    (void)published_lut(t);
    if (std::find(opt.tables.begin(), opt.tables.end(), t) == opt.tables.end())
      throw std::invalid_argument("a size is given for " + t + ", which is not being generated (tables: " +
                                  fmt::format("{}", fmt::join(opt.tables, ", ")) + ")");
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
  if ((!opt.integrator || *opt.integrator == Integrator::Quad) && opt.target_error > 0 &&
      opt.target_error < kQuadMinTolerance)
    throw std::invalid_argument("target error of the quad integrator must be 0 (its default) or at least " +
                                fmt::format("{:g}", kQuadMinTolerance) + ", got " + fmt::format("{:g}", opt.target_error) +
                                " (below it rounding keeps the error estimate from converging)");
  if (opt.threads < 0 || opt.threads > limits::kThreads)
    throw std::invalid_argument("threads must be from 0 (all cores) to " + std::to_string(limits::kThreads));
  // Endpoint grids need two samples per axis for the default sizes too (all defaults are >= 16).
}

std::vector<Table> generate_luts(const LutOptions& opt) {
  validate_lut_options(opt);
  tbb::task_arena arena(opt.threads > 0 ? opt.threads : tbb::task_arena::automatic);
  std::vector<Table> out;
  size_t done = 0;
  for (const std::string& name : lut_table_names()) {
    if (std::find(opt.tables.begin(), opt.tables.end(), name) == opt.tables.end()) continue;
    const LutInfo& info = published_lut(name);
    // Progress label: "[k/n] NAME cells" (k of the n tables of this run).
    const std::string label = "[" + std::to_string(++done) + "/" + std::to_string(opt.tables.size()) + "] " + name + " cells";
    Table t = make_table(name, opt);
    const IntegratorSettings s = lut_settings(name, opt);
    const size_t n = t.size();
    const Lut id = info.id;
    if (id == Lut::GgxE) {
      const auto r = coords(t.axes[0]), mu = coords(t.axes[1]);
      parallel_cells(arena, n, label, opt.progress, opt.cancel, [&](size_t i) {
        const Estimate e = ggx_E(mu[i % mu.size()], r[i / mu.size()], s, stream_of(info.stream, i));
        t.values[i] = e.value;
        t.errors[i] = e.error;
      });
    } else if (id == Lut::GgxEAvg) {
      const auto r = coords(t.axes[0]);
      parallel_cells(arena, n, label, opt.progress, opt.cancel, [&](size_t i) {
        const Estimate e = ggx_E_avg(r[i], s, stream_of(info.stream, i));
        t.values[i] = e.value;
        t.errors[i] = e.error;
      });
    } else if (id == Lut::BaseE) {
      const auto f0 = coords(t.axes[0]), r = coords(t.axes[1]), mu = coords(t.axes[2]);
      // E_m,avg at Base_E's own roughness points (not interpolated from GGX_E_avg), with the
      // averages' sample budget.
      IntegratorSettings s_avg = s;
      s_avg.samples = opt.samples > 0 ? opt.samples : lut_default_samples(lut_name(Lut::BaseEAvg));
      std::vector<Estimate> e_m_avg(r.size());
      parallel_cells(arena, r.size(), label + " (E_m,avg)", opt.progress, opt.cancel, [&](size_t i) {
        e_m_avg[i] = ggx_E_avg(r[i], s_avg, stream_of(kBaseEMAvgStream, i));
      });
      // One integration per (roughness, cos) serves every f0.
      const size_t nrm = r.size() * mu.size();
      parallel_cells(arena, nrm, label, opt.progress, opt.cancel, [&](size_t i) {
        const size_t ir = i / mu.size(), im = i % mu.size();
        const std::vector<Estimate> e = base_E_f0s(mu[im], r[ir], f0, e_m_avg[ir], s, stream_of(info.stream, i));
        for (size_t k = 0; k < f0.size(); ++k) {
          t.values[k * nrm + i] = e[k].value;
          t.errors[k * nrm + i] = e[k].error;
        }
      });
    } else if (id == Lut::BaseEAvg) {
      const auto f0 = coords(t.axes[0]), r = coords(t.axes[1]);
      parallel_cells(arena, r.size(), label, opt.progress, opt.cancel, [&](size_t i) {
        const std::vector<Estimate> e = base_E_avg_f0s(r[i], f0, s, stream_of(info.stream, i));
        for (size_t k = 0; k < f0.size(); ++k) {
          t.values[k * r.size() + i] = e[k].value;
          t.errors[k * r.size() + i] = e[k].error;
        }
      });
    } else if (info.glass && !info.average) {
      const bool inside = info.inside;
      const auto x = coords(t.axes[0]), r = coords(t.axes[1]), mu = coords(t.axes[2]);
      parallel_cells(arena, n, label, opt.progress, opt.cancel, [&](size_t i) {
        const size_t ix = i / (r.size() * mu.size()), ir = (i / mu.size()) % r.size(), im = i % mu.size();
        const Estimate e = glass_E(mu[im], r[ir], glass_ior_of_x(x[ix]), inside, s,
                                   stream_of(info.stream, i));
        t.values[i] = e.value;
        t.errors[i] = e.error;
      });
    } else if (info.glass) {
      const bool inside = info.inside;
      const auto x = coords(t.axes[0]), r = coords(t.axes[1]);
      parallel_cells(arena, n, label, opt.progress, opt.cancel, [&](size_t i) {
        const Estimate e = glass_E_avg(r[i % r.size()], glass_ior_of_x(x[i / r.size()]), inside, s,
                                       stream_of(info.stream, i));
        t.values[i] = e.value;
        t.errors[i] = e.error;
      });
    } else {  // Sheen_E, Sheen_ash_E: rows hold alpha_b directly
      const bool ash = id == Lut::SheenAshE;
      const auto ab = coords(t.axes[0]), mu = coords(t.axes[1]);
      parallel_cells(arena, n, label, opt.progress, opt.cancel, [&](size_t i) {
        const Estimate e = sheen_E(mu[i % mu.size()], ab[i / mu.size()], ash ? SheenModel::Ash : SheenModel::Main, s,
                                   stream_of(info.stream, i));
        t.values[i] = e.value;
        t.errors[i] = e.error;
      });
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace dspbr
