#include "dspbr/conformance/demo_tables.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "../../../fits/dspbr_fits.hpp"  // the LUT-free fits a renderer includes

namespace dspbr::conformance {

namespace {

// Stores quantity(a0, a1) at every sample of a 1-D or 2-D renderer table: a_k the physical
// coordinate of sample i_k (a ggx_cos axis warps with alpha = r^2 of the roughness coordinate).
void fill(WarpedTable& t, const std::function<double(double, double)>& quantity) {
  const int n0 = t.axes[0].size, n1 = t.axes.size() > 1 ? t.axes[1].size : 1;
  for (int i0 = 0; i0 < n0; ++i0) {
    const double a0 = t.axes[0].warp.from_grid(double(i0) / (n0 - 1));
    for (int i1 = 0; i1 < n1; ++i1) {
      double a1 = 0;
      if (t.axes.size() > 1) {
        const Warp& w = t.axes[1].warp;
        a1 = w.from_grid(double(i1) / (n1 - 1), w.kind == WarpKind::GgxCos ? a0 * a0 : 0.0);
      }
      const double q = quantity(a0, a1);
      double& stored = t.values[std::size_t(i0) * std::size_t(n1) + std::size_t(i1)];
      // ln(1 - q), kept finite (1 - q >= 1e-300: a mirror's average).
      stored = t.encoding == Encoding::LogOneMinus ? std::log(std::max(1.0 - q, 1e-300)) : q;
    }
  }
}

LutSet fit_set() {
  LutSet s = LutSet::builtin();
  RendererLuts& r = s.renderer;
  fill(r.ggx_E, [](double rough, double mu) { return double(dspbr_fit_ggx_E(float(mu), float(rough))); });
  fill(r.ggx_beta, [](double rough, double mu) {
    const double e = dspbr_fit_ggx_E(float(mu), float(rough)), e5 = dspbr_fit_detail_ggx_E5(float(mu), float(rough));
    return (e > 0 ? e5 / e : 0.0) - std::pow(1.0 - mu, 5);
  });
  fill(r.ggx_E_avg, [](double rough, double) { return 1.0 - double(dspbr_fit_ggx_E_avg_loss(float(rough))); });
  fill(r.ggx_B_avg, [](double rough, double) { return double(dspbr_fit_detail_ggx_E5_avg(float(rough))); });
  fill(r.sheen_E, [](double ab, double mu) { return double(dspbr_fit_sheen_E(float(mu), float(ab))); });
  fill(r.sheen_ash_E, [](double ab, double mu) { return double(dspbr_fit_sheen_ash_E(float(mu), float(ab))); });
  return s;
}

// Karis 2014 ("Physically Based Shading on Mobile"), the analytic environment BRDF A + B at
// F_0 = 1 for roughness r: E_m(mu; r) = 1 - 0.55 r whatever mu (its mu terms cancel in A + B).
double analytic_E(double rough, double mu) {
  const double c0[4] = {-1, -0.0275, -0.572, 0.022}, c1[4] = {1, 0.0425, 1.04, -0.04};
  double r[4];
  for (int k = 0; k < 4; ++k) r[k] = rough * c0[k] + c1[k];
  const double a004 = std::min(r[0] * r[0], std::exp2(-9.28 * mu)) * r[0] + r[1];
  return std::clamp((-1.04 * a004 + r[2]) + (1.04 * a004 + r[3]), 0.0, 1.0);
}

LutSet analytic_set() {
  LutSet s = LutSet::builtin();
  RendererLuts& r = s.renderer;
  fill(r.ggx_E, [](double rough, double mu) { return analytic_E(rough, mu); });
  // Its cosine-weighted average 2 Int E mu dmu: the same value (E does not depend on mu).
  fill(r.ggx_E_avg, [](double rough, double) { return analytic_E(rough, 1.0); });
  return s;
}

LutSet uncompensated_set() {
  LutSet s = LutSet::builtin();
  RendererLuts& r = s.renderer;
  fill(r.ggx_E, [](double, double) { return 1.0; });
  fill(r.ggx_E_avg, [](double, double) { return 1.0; });
  fill(r.sheen_E, [](double, double) { return 0.0; });
  fill(r.sheen_ash_E, [](double, double) { return 0.0; });
  return s;
}

}  // namespace

const char* demo_tables_name(DemoTables t) {
  switch (t) {
    case DemoTables::Renderer: return "renderer";
    case DemoTables::Published: return "published";
    case DemoTables::Fits: return "fits";
    case DemoTables::Uncompensated: return "uncompensated";
    case DemoTables::Analytic: return "analytic";
  }
  return "?";
}

DemoTables parse_demo_tables(const std::string& name) {
  for (DemoTables t :
       {DemoTables::Renderer, DemoTables::Published, DemoTables::Fits, DemoTables::Uncompensated, DemoTables::Analytic})
    if (name == demo_tables_name(t)) return t;
  throw std::invalid_argument("unknown table set '" + name + "' (known: renderer, published, fits, uncompensated, analytic)");
}

const LutSet& demo_table_set(DemoTables t) {
  switch (t) {
    case DemoTables::Renderer: return LutSet::builtin();
    case DemoTables::Published: return LutSet::published();
    case DemoTables::Fits: {
      static const LutSet s = fit_set();
      return s;
    }
    case DemoTables::Uncompensated: {
      static const LutSet s = uncompensated_set();
      return s;
    }
    case DemoTables::Analytic: {
      static const LutSet s = analytic_set();
      return s;
    }
  }
  return LutSet::builtin();
}

}  // namespace dspbr::conformance
