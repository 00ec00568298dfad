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

AlbedoSlice AlbedoSlice::E_m(const LutSet& luts, double roughness) {
  AlbedoSlice s;
  const double r = std::clamp(roughness, 0.0, 1.0);
  if (luts.layout == LutLayout::Published) {
    s.published_ = published_slice(luts.ggx_e, {r});
    return s;
  }
  s.kind_ = Kind::Renderer;
  const WarpedTable& t = luts.renderer.ggx_E;
  s.table_ = t.slice(t.axes[0].warp.to_grid(r));
  s.alpha_ = r * r;
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
  s.beta_ = beta.slice(beta.axes[0].warp.to_grid(r));
  const Warp &we = s.table_.axes[0].warp, &wb = s.beta_.axes[0].warp;
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
  s.table_ = t.slice(t.axes[0].warp.to_grid(alpha_b));
  return s;
}

double AlbedoSlice::operator()(double cos_theta) const {
  switch (kind_) {
    case Kind::Published:
      return published_.lookup({cos_theta});
    case Kind::Renderer:
      return table_.lookup_grid(table_.axes[0].warp.to_grid(cos_theta, alpha_));
    case Kind::RendererBase: {
      const double mu = std::clamp(cos_theta, 0.0, 1.0);
      const double x = table_.axes[0].warp.to_grid(mu, alpha_);
      const double xb = shared_warp_ ? x : beta_.axes[0].warp.to_grid(mu, alpha_);
      const double beta = RendererLuts::decode_beta(mu, beta_.lookup_grid(xb));
      return RendererLuts::compose_E_base(f0_, table_.lookup_grid(x), beta, f_ms_);
    }
  }
  return 0;
}

}  // namespace dspbr
