#include "dspbr/lutgen/renderer_generate.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>

#include "dspbr/lutgen/parallel_cells.h"
#include "dspbr/tables/table_registry.h"
#include "dspbr/quadrature.h"

namespace dspbr {

namespace {

// Roughness at which the r = 0 row of GGX_E is integrated: that row holds the limit of
// E_m(a alpha; r) as r -> 0 at fixed a = mu / alpha (the ggx_cos warp's coordinate), reached to
// ~1e-6 at r = 0.02 (the integrator's mu clamp of 1e-6 stays below every sample's mu there).
constexpr double kGgxLimitRoughness = 0.02;

WarpedTable make_table(const std::string& name, int scale) {
  WarpedTable t;
  t.name = name;
  t.axes = renderer_default_axes(name, scale);
  t.values.assign(t.size(), 0.0);
  t.errors.assign(t.size(), 0.0);
  return t;
}

double grid_x(const WarpedAxis& a, int i) { return double(i) / double(a.size - 1); }

// Rounds the stored values to float: the generated header, shaders and images hold floats, and
// the averages are integrated from exactly those.
void round_to_float(WarpedTable& t) {
  for (double& v : t.values) v = double(float(v));
}

// 2 Integral_0^1 g(mu) mu dmu for a g that is smooth inside each cell of the ggx_cos grid of
// `axis` at roughness alpha > 0 (a lookup is C1 across cells): Gauss-Legendre in mu, 4 panels of
// 8 nodes per cell [mu_k, mu_k+1], mu_k = from_grid(k / (N - 1)).
template <class G>
double cosine_average_ggx_cos(const WarpedAxis& axis, double alpha, G&& g) {
  static const QuadratureRule rule = gauss_legendre(8);
  const int cells = axis.size - 1;
  double sum = 0;
  for (int c = 0; c < cells; ++c) {
    const double m0 = axis.warp.from_grid(double(c) / cells, alpha);
    const double m1 = axis.warp.from_grid(double(c + 1) / cells, alpha);
    if (m1 > m0) sum += integrate_gl([&](double mu) { return 2.0 * mu * g(mu); }, m0, m1, 4, rule);
  }
  return sum;
}

// 2 Integral_0^1 g(mu) mu dmu for a lookup g along the ggx_cos axis at roughness r (the mirror
// row r = 0 in plain mu: there every mu > 0 maps to t = 1).
template <class G>
double cosine_average_of_lookup(const WarpedAxis& mu_axis, double r, G&& g) {
  if (r * r < 1e-12) {
    static const QuadratureRule rule = gauss_legendre(8);
    return integrate_gl([&](double mu) { return 2.0 * mu * g(mu); }, 0.0, 1.0, 64, rule);
  }
  return cosine_average_ggx_cos(mu_axis, r * r, g);
}

// Progress label "[renderer k/n] NAME cells": k-th of the n integrated renderer tables (those
// with a stream; the averages follow from them), in registry order, the order they are made;
// the glass ones counted only when made.
std::string progress_label(Lut id, bool glass) {
  size_t k = 0, n = 0;
  for (const LutInfo& t : lut_registry()) {
    if ((t.layouts & kRendererLayout) == 0 || t.renderer_stream == kNoStream || (t.glass && !glass)) continue;
    ++n;
    if (t.id <= id) ++k;
  }
  return "[renderer " + std::to_string(k) + "/" + std::to_string(n) + "] " + lut_name(id) + " cells";
}

bool wants_glass(const LutOptions& opt) {
  return std::find(opt.tables.begin(), opt.tables.end(), lut_name(Lut::GlassE)) != opt.tables.end();
}

}  // namespace

void fill_renderer_glass_averages(RendererLuts& luts) {
  for (const bool inside : {false, true}) {
    const WarpedTable& e = inside ? luts.glass_inv_E : luts.glass_E;
    WarpedTable& avg = inside ? luts.glass_inv_E_avg : luts.glass_E_avg;
    double max_error = 0;
    for (double x : e.errors) max_error = std::max(max_error, x);
    const int nr = avg.axes[1].size;
    for (size_t i = 0; i < avg.size(); ++i) {
      const double ior = glass_ior_of_x(avg.axes[0].warp.from_grid(grid_x(avg.axes[0], int(i) / nr)));
      const double r = avg.axes[1].warp.from_grid(grid_x(avg.axes[1], int(i) % nr));
      avg.values[i] = cosine_average_of_lookup(e.axes[2], r, [&](double mu) { return luts.E_glass(mu, r, ior, inside); });
      avg.errors[i] = max_error;
    }
    round_to_float(avg);
  }
}

void fill_renderer_averages(RendererLuts& luts) {
  // 1 - E^_m from a table of 1 - values (no cancellation where E_m is within float epsilon of 1).
  WarpedTable missing = luts.ggx_E;
  for (double& v : missing.values) v = 1.0 - v;
  const WarpedAxis& r_axis = luts.ggx_E.axes[0];
  const WarpedAxis& mu_axis = luts.ggx_E.axes[1];
  WarpedTable& e_avg = luts.ggx_E_avg;
  e_avg.encoding = Encoding::LogOneMinus;
  double max_error = 0;
  for (double e : luts.ggx_E.errors) max_error = std::max(max_error, e);
  for (int j = 0; j < e_avg.axes[0].size; ++j) {
    const double r = e_avg.axes[0].warp.from_grid(grid_x(e_avg.axes[0], j));
    const double alpha = r * r, x0 = r_axis.warp.to_grid(r);
    const double m = cosine_average_ggx_cos(mu_axis, alpha, [&](double mu) {
      return std::max(0.0, missing.interpolate(x0, mu_axis.warp.to_grid(mu, alpha)));
    });
    e_avg.values[size_t(j)] = std::log(std::max(m, 1e-300));
    e_avg.errors[size_t(j)] = max_error;
  }
  WarpedTable& b_avg = luts.ggx_B_avg;
  for (int j = 0; j < b_avg.axes[0].size; ++j) {
    const double r = b_avg.axes[0].warp.from_grid(grid_x(b_avg.axes[0], j));
    // (on the mirror row E_m = 1 and B = beta = (1 - mu)^5)
    b_avg.values[size_t(j)] = cosine_average_of_lookup(mu_axis, r, [&](double mu) { return luts.B(mu, r); });
    b_avg.errors[size_t(j)] = max_error;
  }
  round_to_float(e_avg);
  round_to_float(b_avg);
}

void add_renderer_glass_luts(RendererLuts& out, const LutOptions& opt, int scale) {
  validate_lut_options(opt);
  tbb::task_arena arena(opt.threads > 0 ? opt.threads : tbb::task_arena::automatic);
  for (const char* name : RendererLuts::glass_names()) *out.table(name) = make_table(name, scale);
  // Glass_E / Glass_inv_E over (glass_ior(mu), r, ggx_cos(mu; r^2)): the ior of a sample depends on
  // its mu (the warp follows the refraction's grazing scale).
  const IntegratorSettings sg = lut_settings(lut_name(Lut::GlassE), opt);
  for (const bool inside : {false, true}) {
    WarpedTable& t = inside ? out.glass_inv_E : out.glass_E;
    const WarpedAxis &ai = t.axes[0], &ar = t.axes[1], &am = t.axes[2];
    const size_t plane = size_t(ar.size) * size_t(am.size);
    parallel_cells(arena, t.size(), progress_label(inside ? Lut::GlassInvE : Lut::GlassE, true), opt.progress, opt.cancel, [&](size_t i) {
      const int ii = int(i / plane), ir = int((i % plane) / size_t(am.size)), im = int(i % size_t(am.size));
      const double r = std::max(ar.warp.from_grid(grid_x(ar, ir)), kGgxLimitRoughness);
      const double mu = am.warp.from_grid(grid_x(am, im), r * r);
      const double ior = ai.warp.from_grid(grid_x(ai, ii), mu);
      const Estimate e = glass_E(mu, r, ior, inside, sg, (lut_info(inside ? Lut::GlassInvE : Lut::GlassE).renderer_stream << 32) | i);
      t.values[i] = e.value;
      t.errors[i] = e.error;
    });
    round_to_float(t);
  }
  fill_renderer_glass_averages(out);
}

RendererLuts generate_renderer_luts(const LutOptions& opt, int scale) {
  validate_lut_options(opt);
  tbb::task_arena arena(opt.threads > 0 ? opt.threads : tbb::task_arena::automatic);
  RendererLuts out;
  for (const char* name : RendererLuts::names()) *out.table(name) = make_table(name, scale);
  const bool glass = wants_glass(opt);
  const IntegratorSettings s = lut_settings(lut_name(Lut::GgxE), opt);

  {  // GGX_E over (r, ggx_cos(mu; r^2))
    WarpedTable& t = out.ggx_E;
    const WarpedAxis &ar = t.axes[0], &am = t.axes[1];
    parallel_cells(arena, t.size(), progress_label(Lut::GgxE, glass), opt.progress, opt.cancel, [&](size_t i) {
      const int ir = int(i / size_t(am.size)), im = int(i % size_t(am.size));
      const double r = std::max(ar.warp.from_grid(grid_x(ar, ir)), kGgxLimitRoughness);
      const double mu = am.warp.from_grid(grid_x(am, im), r * r);
      const Estimate e = ggx_E(mu, r, s, (lut_info(Lut::GgxE).renderer_stream << 32) | i);
      t.values[i] = e.value;
      t.errors[i] = e.error;
    });
    round_to_float(t);
  }
  {  // GGX_beta - (1 - mu)^5 over (r^2, ggx_cos(mu; r^2)); zero on the r = 0 row (mirror)
    WarpedTable& t = out.ggx_beta;
    const WarpedAxis &ar = t.axes[0], &am = t.axes[1];
    parallel_cells(arena, t.size(), progress_label(Lut::GgxBeta, glass), opt.progress, opt.cancel, [&](size_t i) {
      const int ir = int(i / size_t(am.size)), im = int(i % size_t(am.size));
      const double r = ar.warp.from_grid(grid_x(ar, ir));
      if (r == 0) return;  // beta = (1 - mu)^5 exactly
      const double mu = am.warp.from_grid(grid_x(am, im), r * r);
      const Estimate e = ggx_beta(mu, r, s, (lut_info(Lut::GgxBeta).renderer_stream << 32) | i);
      t.values[i] = e.value - std::pow(1.0 - mu, 5);
      t.errors[i] = e.error;
    });
    round_to_float(t);
  }
  // The sheen tables reach alpha_b = 1/256 at grazing angles, where the estimator's variance is
  // largest: their default cap is 8x the other tables' (only those cells get near it).
  IntegratorSettings s_sheen = s;
  if (opt.samples == 0) s_sheen.samples = 8 * lut_default_samples(lut_name(Lut::SheenE));
  for (const bool ash : {false, true}) {
    WarpedTable& t = ash ? out.sheen_ash_E : out.sheen_E;
    const WarpedAxis &aa = t.axes[0], &am = t.axes[1];
    parallel_cells(arena, t.size(), progress_label(ash ? Lut::SheenAshE : Lut::SheenE, glass), opt.progress, opt.cancel, [&](size_t i) {
      const int ia = int(i / size_t(am.size)), im = int(i % size_t(am.size));
      const Estimate e = sheen_E(am.warp.from_grid(grid_x(am, im)), aa.warp.from_grid(grid_x(aa, ia)),
                                 ash ? SheenModel::Ash : SheenModel::Main, s_sheen,
                                 (lut_info(ash ? Lut::SheenAshE : Lut::SheenE).renderer_stream << 32) | i);
      t.values[i] = e.value;
      t.errors[i] = e.error;
    });
    round_to_float(t);
  }
  fill_renderer_averages(out);
  if (glass) add_renderer_glass_luts(out, opt, scale);
  return out;
}

}  // namespace dspbr
