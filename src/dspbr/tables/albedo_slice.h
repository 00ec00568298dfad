// A table's dependence on cos theta at one fixed roughness (and f0, or alpha_b): what a lobe reads
// per evaluation, cut out of a LutSet once when the lobe is built, so that an evaluation does a
// 1-D lookup instead of a 2-D or 3-D one. Equal to the LutSet lookup to rounding (the same
// interpolant: multilinear for the published layout, Catmull-Rom per axis for the renderer
// layout; interpolation across the fixed axes is done first). Owns its samples. The renderer
// slices keep the Catmull-Rom spline of each cell as its cubic's coefficients (the outside
// samples extrapolated linearly as in warped_table.h), so that a lookup is one Horner evaluation
// (equal to the weighted sum of WarpedTable::interpolate to rounding), and evaluate the warp with
// Warp::to_grid_fast. The renderer glass slices keep, instead of one row, the rows of the ior
// samples their lookups reach (the ior axis' grid coordinate depends on mu), and interpolate
// across them per lookup as WarpedTable::interpolate does; these rows are shared, immutable, by
// the copies of a slice.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "dspbr/cubic_spline.h"
#include "dspbr/tables/lut_set.h"

namespace dspbr {

class AlbedoSlice {
 public:
  AlbedoSlice() = default;
  // E_m(mu; r) (GGX_E).
  static AlbedoSlice E_m(const LutSet& luts, double roughness);
  // E(mu; r, f0) of the opaque dielectric base (Base_E; renderer layout: from GGX_E and GGX_beta).
  static AlbedoSlice E_base(const LutSet& luts, double roughness, double f0);
  // E_b(mu; alpha_b) of the main (Sheen_E) or the alternative (Sheen_ash_E) sheen.
  static AlbedoSlice E_sheen(const LutSet& luts, double alpha_b, bool alternative);
  // E_g(mu; r, ior) of the rough dielectric interface with v outside (Glass_E) or inside
  // (Glass_inv_E); throws std::runtime_error when the set has no glass tables (has_glass()).
  static AlbedoSlice E_glass(const LutSet& luts, double roughness, double ior, bool inside);

  double operator()(double cos_theta) const;

  // The E_m part of an E_m or E_base slice of the renderer layout: the grid coordinate x of mu
  // and E_m(x). The E_m and E_base slices of one set at one roughness have the same part
  // (same e_m_key(); null for the other slices), so lobes reading both at one cosine can share it.
  struct EmPart {
    double x = 0, e_m = 0;
  };
  struct EmKey {
    // Fingerprint of what the E_m part is computed from (the slice's GGX_E cubics, warp and
    // alpha; 0: no E_m part), a value of the slice's own, so that the slice holds nothing of the
    // set it was cut from.
    uint64_t fingerprint = 0;
    double roughness = 0;
    bool operator==(const EmKey& o) const { return fingerprint == o.fingerprint && roughness == o.roughness; }
  };
  EmKey e_m_key() const { return em_key_; }
  EmPart e_m_part(double cos_theta) const;
  // The E_m parts at two cosines (v.n and l.n of one evaluation): equal to two e_m_part calls.
  void e_m_parts(double cos_a, double cos_b, EmPart out[2]) const;
  // The slice's value from its E_m part at the same cos theta: equal to operator().
  double from_e_m_part(double cos_theta, const EmPart& part) const;

 private:
  // A 1-D renderer table over cos theta as the cubic of each of its n - 1 cells:
  // c[4 i .. 4 i + 3] = (a, b, c, d), value = ((a f + b) f + c) f + d at fraction f of cell i.
  struct Padded {
    std::vector<double> c;
    int n = 0;
    Warp warp;
    Encoding encoding = Encoding::Value;
    // The decoded value's range, as RendererLuts clamps the same lookup (kEmRange, kSheenERange).
    AlbedoRange range{-HUGE_VAL, HUGE_VAL};
    static Padded of(const WarpedTable& t);
    // The cubic of cell i at fraction f, not decoded.
    double cubic(int i, double f) const { return cubic_at(c.data() + 4 * size_t(i), f); }
    // Catmull-Rom at grid coordinate x, decoded (equal to WarpedTable::lookup_grid).
    double at_grid(double x) const {
      int i;
      double f;
      grid_cell(x, n, &i, &f);
      return range.clamp(decode(encoding, cubic(i, f)));
    }
  };
  // RendererGlass: the table cut at the roughness (WarpedTable::slice_middle), its rows
  // first .. first + rows.size() - 1 of the n ior samples, each over cos theta (not decoded).
  struct GlassRows {
    std::vector<Padded> rows;
    int first = 0, n = 0;
    Warp warp;  // the ior axis' (GlassIor: depends on mu)
    double ior = 1;
    Encoding encoding = Encoding::Value;
  };
  double glass_at(double cos_theta) const;
  double slow_at(double cos_theta) const;  // Published and RendererGlass
  enum class Kind { Published, Renderer, RendererBase, RendererGlass };
  Kind kind_ = Kind::Published;
  Table published_;  // 1-D over cos theta
  Padded table_;     // 1-D over cos theta: E_m, E_b
  std::shared_ptr<const GlassRows> glass_;  // RendererGlass
  Padded beta_;      // 1-D over cos theta: GGX_beta (RendererBase)
  double alpha_ = 0;   // GgxCos warp parameter r^2
  EmKey em_key_;      // E_m and E_base of the renderer layout
  bool shared_warp_ = false;  // RendererBase: GGX_E and GGX_beta have the same cos theta warp
  double f0_ = 0, f_ms_ = 0;  // RendererBase: f0 and F_ms(f0, 1; E_m,avg)
};

// The lookups every evaluation makes (inline: one call per lobe, not one per step).
inline AlbedoSlice::EmPart AlbedoSlice::e_m_part(double cos_theta) const {
  if (!em_key_.fingerprint) return {0, (*this)(cos_theta)};
  const double x = table_.warp.to_grid_fast(std::clamp(cos_theta, 0.0, 1.0), alpha_);
  return {x, table_.at_grid(x)};
}

inline void AlbedoSlice::e_m_parts(double cos_a, double cos_b, EmPart out[2]) const {
  if (!em_key_.fingerprint || table_.warp.kind != WarpKind::GgxCos || table_.warp.p != 0.5) {
    out[0] = e_m_part(cos_a);
    out[1] = e_m_part(cos_b);
    return;
  }
  double x[2];
  ggx_cos_sqrt_warp2(cos_a, cos_b, alpha_, x);  // the ggx_cos warp of e_m_part, both at once
  out[0] = {x[0], table_.at_grid(x[0])};
  out[1] = {x[1], table_.at_grid(x[1])};
}

inline double AlbedoSlice::from_e_m_part(double cos_theta, const EmPart& part) const {
  if (!em_key_.fingerprint || kind_ == Kind::Renderer) return part.e_m;
  const double mu = std::clamp(cos_theta, 0.0, 1.0);
  const double xb = shared_warp_ ? part.x : beta_.warp.to_grid_fast(mu, alpha_);
  const double beta = RendererLuts::decode_beta_fast(mu, beta_.at_grid(xb));
  return RendererLuts::compose_E_base(f0_, part.e_m, beta, f_ms_);
}

inline double AlbedoSlice::operator()(double cos_theta) const {
  switch (kind_) {
    case Kind::Renderer: return table_.at_grid(table_.warp.to_grid_fast(cos_theta, alpha_));
    case Kind::RendererBase: return from_e_m_part(cos_theta, e_m_part(cos_theta));
    case Kind::Published:
    case Kind::RendererGlass: break;
  }
  return slow_at(cos_theta);
}

}  // namespace dspbr
