#include "dspbr/lut/albedo_slice.h"

#include <algorithm>
#include <cmath>

namespace dspbr {

namespace {

// The published table at fixed leading coordinates, as a 1-D table over its last axis: the
// multilinear lookup at each sample of that axis (clamp-to-edge like Table::lookup).
Table published_slice(const Table& t, std::vector<double> leading) {
  Table s;
  s.name = t.name;
  s.axes = {t.axes.back()};
  leading.push_back(0.0);
  for (int k = 0; k < s.axes[0].size; ++k) {
    leading.back() = s.axes[0].coord(k);
    s.values.push_back(t.lookup(leading));
  }
  return s;
}

}  // namespace

AlbedoSlice::Padded AlbedoSlice::Padded::of(const WarpedTable& t) {
  Padded s;
  const std::vector<double>& v = t.values;
  s.n = int(v.size());
  s.warp = t.axes[0].warp;
  s.encoding = t.encoding;
  // Samples padded with the extrapolated ones: p[0] = 2 v_0 - v_1, p[k + 1] = v_k,
  // p[n + 1] = 2 v_n-1 - v_n-2.
  std::vector<double> p;
  p.reserve(v.size() + 2);
  p.push_back(2.0 * v[0] - v[1]);
  p.insert(p.end(), v.begin(), v.end());
  p.push_back(2.0 * v[size_t(s.n) - 1] - v[size_t(s.n) - 2]);
  // Catmull-Rom of cell i from samples i - 1 .. i + 2 (catmull_rom_weights expanded in powers of f).
  s.c.reserve(4 * (v.size() - 1));
  for (int i = 0; i + 1 < s.n; ++i) {
    const double p0 = p[size_t(i)], p1 = p[size_t(i) + 1], p2 = p[size_t(i) + 2], p3 = p[size_t(i) + 3];
    s.c.push_back(0.5 * (-p0 + 3.0 * p1 - 3.0 * p2 + p3));
    s.c.push_back(0.5 * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3));
    s.c.push_back(0.5 * (p2 - p0));
    s.c.push_back(p1);
  }
  return s;
}

double AlbedoSlice::Padded::at_grid(double x) const {
  // The cell and fraction of WarpedTable::interpolate.
  const double g = std::clamp(x, 0.0, 1.0) * (n - 1);
  const int i = std::min(int(g), n - 2);
  const double f = g - i;
  const double* k = c.data() + 4 * size_t(i);
  const double s = ((k[0] * f + k[1]) * f + k[2]) * f + k[3];
  return encoding == Encoding::LogOneMinus ? 1.0 - std::exp(s) : s;
}

AlbedoSlice AlbedoSlice::E_m(const LutSet& luts, double roughness) {
  AlbedoSlice s;
  const double r = std::clamp(roughness, 0.0, 1.0);
  if (luts.layout == LutLayout::Published) {
    s.published_ = published_slice(luts.ggx_e, {r});
    return s;
  }
  s.kind_ = Kind::Renderer;
  const WarpedTable& t = luts.renderer.ggx_E;
  s.table_ = Padded::of(t.slice(t.axes[0].warp.to_grid(r)));
  s.alpha_ = r * r;
  s.em_key_ = {&t, r};
  return s;
}

AlbedoSlice AlbedoSlice::E_base(const LutSet& luts, double roughness, double f0) {
  AlbedoSlice s;
  const double r = std::clamp(roughness, 0.0, 1.0);
  if (luts.layout == LutLayout::Published) {
    s.published_ = published_slice(luts.base_e, {f0, r});
    return s;
  }
  s = E_m(luts, r);
  s.kind_ = Kind::RendererBase;
  const WarpedTable& beta = luts.renderer.ggx_beta;
  s.beta_ = Padded::of(beta.slice(beta.axes[0].warp.to_grid(r)));
  const Warp &we = s.table_.warp, &wb = s.beta_.warp;
  s.shared_warp_ = we.kind == wb.kind && we.p == wb.p && we.lo == wb.lo;
  s.f0_ = f0;
  s.f_ms_ = RendererLuts::base_fresnel_ms(f0, luts.renderer.E_m_avg(r));
  return s;
}

AlbedoSlice AlbedoSlice::E_sheen(const LutSet& luts, double alpha_b, bool alternative) {
  AlbedoSlice s;
  if (luts.layout == LutLayout::Published) {
    s.published_ = published_slice(alternative ? luts.sheen_ash_e : luts.sheen_e, {alpha_b});
    return s;
  }
  s.kind_ = Kind::Renderer;
  const WarpedTable& t = alternative ? luts.renderer.sheen_ash_E : luts.renderer.sheen_E;
  s.table_ = Padded::of(t.slice(t.axes[0].warp.to_grid(alpha_b)));
  return s;
}

AlbedoSlice::EmPart AlbedoSlice::e_m_part(double cos_theta) const {
  if (!em_key_.table) return {0, (*this)(cos_theta)};
  const double x = table_.warp.to_grid_fast(std::clamp(cos_theta, 0.0, 1.0), alpha_);
  return {x, table_.at_grid(x)};
}

double AlbedoSlice::from_e_m_part(double cos_theta, const EmPart& part) const {
  if (!em_key_.table) return part.e_m;
  if (kind_ == Kind::Renderer) return part.e_m;
  const double mu = std::clamp(cos_theta, 0.0, 1.0);
  const double xb = shared_warp_ ? part.x : beta_.warp.to_grid_fast(mu, alpha_);
  const double beta = RendererLuts::decode_beta_fast(mu, beta_.at_grid(xb));
  return RendererLuts::compose_E_base(f0_, part.e_m, beta, f_ms_);
}

double AlbedoSlice::operator()(double cos_theta) const {
  switch (kind_) {
    case Kind::Published:
      return published_.lookup({cos_theta});
    case Kind::Renderer:
      return table_.at_grid(table_.warp.to_grid_fast(cos_theta, alpha_));
    case Kind::RendererBase:
      return from_e_m_part(cos_theta, e_m_part(cos_theta));
  }
  return 0;
}

}  // namespace dspbr
