#include "dspbr/tables/albedo_slice.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "dspbr/cubic_spline.h"

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

namespace {

// The E_m part's fingerprint (AlbedoSlice::EmKey): splitmix64 steps over the bits of the values
// it is computed from; never 0.
uint64_t mix(uint64_t h, uint64_t v) {
  h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebULL;
  return h ^ (h >> 31);
}
uint64_t bits(double x) {
  uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

}  // namespace

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
  s.table_.range = kEmRange;
  s.alpha_ = r * r;
  uint64_t h = mix(uint64_t(s.table_.n), uint64_t(s.table_.warp.kind));
  for (double v : {s.table_.warp.p, s.table_.warp.lo, s.alpha_}) h = mix(h, bits(v));
  for (double v : s.table_.c) h = mix(h, bits(v));
  s.em_key_ = {h == 0 ? 1 : h, r};
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
  s.table_.range = kSheenERange;
  return s;
}

AlbedoSlice AlbedoSlice::E_glass(const LutSet& luts, double roughness, double ior, bool inside) {
  if (!luts.has_glass()) throw std::runtime_error("albedo slice: the table set has no Glass tables (dspbr lut)");
  AlbedoSlice s;
  if (luts.layout == LutLayout::Published) {
    s.published_ = published_slice(inside ? luts.glass_inv_e : luts.glass_e, {glass_x_of_ior(ior), roughness});
    return s;
  }
  // RendererLuts::E_glass: grid coordinates (ior at mu, r, mu at alpha = r^2).
  s.kind_ = Kind::RendererGlass;
  const WarpedTable& t = inside ? luts.renderer.glass_inv_E : luts.renderer.glass_E;
  const double r = std::clamp(roughness, 0.0, 1.0);
  const WarpedTable cut = t.slice_middle(t.axes[1].warp.to_grid(r));
  auto g = std::make_shared<GlassRows>();
  g->n = cut.axes[0].size;
  g->warp = cut.axes[0].warp;
  g->ior = ior;
  g->encoding = cut.encoding;
  // The ior grid coordinate at this ior grows monotonically as mu falls (GlassIor warp:
  // ln(1 + x_F / s) / ln(1 + 1 / s) decreases with s = k mu^2 for x_F in [0, 1]), so the lookups
  // reach the cells between those at mu = 1 and mu = 0 and their Catmull-Rom neighbours (one
  // more cell each way for rounding at a cell boundary).
  int i_lo, i_hi;
  double f;
  grid_cell(g->warp.to_grid(ior, 1.0), g->n, &i_lo, &f);
  grid_cell(g->warp.to_grid(ior, 0.0), g->n, &i_hi, &f);
  g->first = std::clamp(std::min(i_lo, i_hi) - 2, 0, g->n - 2);
  const int last = std::clamp(std::max(i_lo, i_hi) + 3, 1, g->n - 1);
  const int n2 = cut.axes[1].size;
  for (int p = g->first; p <= last; ++p) {
    WarpedTable row{cut.name, {cut.axes[1]}, {}, {}, Encoding::Value};
    row.values.assign(cut.values.begin() + ptrdiff_t(p) * n2, cut.values.begin() + ptrdiff_t(p + 1) * n2);
    g->rows.push_back(Padded::of(row));
  }
  s.alpha_ = r * r;
  s.glass_ = std::move(g);
  return s;
}

double AlbedoSlice::glass_at(double cos_theta) const {
  const GlassRows& g = *glass_;
  const double mu = std::clamp(cos_theta, 0.0, 1.0);
  const Padded& row0 = g.rows.front();
  int i2;
  double f2;
  grid_cell(row0.warp.to_grid_fast(mu, alpha_), row0.n, &i2, &f2);
  // Across the ior samples as WarpedTable::interpolate: cell, weights, linear extension.
  const CatmullRomTaps t0 = catmull_rom_taps(g.warp.to_grid(g.ior, mu), g.n);
  const double v = catmull_rom_sum(t0, [&](int p) { return g.rows[size_t(p - g.first)].cubic(i2, f2); });
  return decode(g.encoding, v);
}

double AlbedoSlice::slow_at(double cos_theta) const {
  return kind_ == Kind::Published ? published_.lookup({cos_theta}) : glass_at(cos_theta);
}

}  // namespace dspbr
