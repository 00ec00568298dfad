// Tables on warped endpoint grids with Catmull-Rom interpolation: the layout family of the
// renderer tables (docs/luts.md, "Renderer layout"). Each axis maps its physical coordinate v to a
// grid coordinate x in [0, 1] by a warp; samples sit at x_i = i / (N - 1) (the grid reaches both
// ends of the domain); a lookup interpolates the samples with a Catmull-Rom spline per axis,
// outside samples extrapolated linearly (p_-1 = 2 p_0 - p_1, p_N = 2 p_N-1 - p_N-2), so the
// interpolant is C1, exact on quadratics inside and on lines at the ends.
//
// Warps (v clamped to the axis domain first):
//   Power(p, lo):   x = ((v - lo) / (1 - lo))^p                     v in [lo, 1]
//   GgxCos(p):      x = t^p, t = mu / (mu + alpha sqrt(1 - mu^2))   mu in [0, 1]; alpha = r^2 of the
//                   table's roughness axis. t depends on mu / alpha only (Smith's a = cot(theta) / alpha),
//                   so the grazing drop of E_m keeps its shape at every roughness (t = 1 when alpha = 0).
//   LogRoughness(lo): x = ln(r / lo) / ln(1 / lo)                   r in [lo, 1]
//   GlassIor(k):    x = (x_F + ln(1 + x_F / (k mu^2)) / ln(1 + 1 / (k mu^2))) / 2, x_F = 2 sqrt(F_0)
//                   = 2 (ior - 1) / (ior + 1), ior in [1, kGlassMaxIor], mu = the lookup's view cosine
//                   (clamped to 1e-6). Near ior 1 at grazing the rough-glass albedo changes on the
//                   scale x_F ~ mu^2 (the critical cosine sqrt(1 - 1/ior^2) ~ sqrt(x_F) meets mu):
//                   the logarithmic half resolves that scale at every mu, the linear half the rest.
#pragma once
#include <algorithm>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <string>
#include <vector>

namespace dspbr {

enum class WarpKind { Power, GgxCos, LogRoughness, GlassIor };

// The rough-glass tables' index of refraction range (lookups above evaluate at the maximum), and
// the published layout's IOR axis x = 2 (ior - 1) / (ior + 1) = 2 sqrt(F_0) in [0, 1] and back.
constexpr double kGlassMaxIor = 3.0;
double glass_ior_of_x(double x);
double glass_x_of_ior(double ior);

struct Warp {
  WarpKind kind = WarpKind::Power;
  double p = 1;   // exponent (Power, GgxCos); scale k (GlassIor)
  double lo = 0;  // lower end of the domain (Power, LogRoughness)

  // Grid coordinate x in [0, 1] of physical coordinate v; aux: alpha for GgxCos, mu for GlassIor.
  // Inline for the power warps (every 2-D lookup's axes), out of line for the others.
  double to_grid(double v, double aux = 0) const;
  // The same within a few ulp, for the lobes' per-evaluation lookups (inline, below): the power
  // x^p as sqrt for p = 1/2 (exactly to_grid) and 1/4, else exp2(p log2 x) (about half the cost of
  // std::pow). The generator and the LutSet lookups keep to_grid, so the committed tables do not
  // depend on this form.
  double to_grid_fast(double v, double aux = 0) const;
  // to_grid of the LogRoughness and GlassIor warps.
  double to_grid_log_or_glass(double v, double aux) const;
  // Inverse: the physical coordinate of grid coordinate x.
  double from_grid(double x, double aux = 0) const;
  // Short description, e.g. "power(p=0.25, lo=0.001)".
  std::string describe() const;
};

// The argument u of the power of the Power and GgxCos warps (v clamped to the domain).
inline double warp_power_base(const Warp& w, double v, double alpha) {
  // lo = 0 (every roughness axis): (v - 0) / 1 == v exactly, without the division.
  if (w.kind == WarpKind::Power)
    return w.lo == 0 ? std::clamp(v, 0.0, 1.0) : (std::clamp(v, w.lo, 1.0) - w.lo) / (1.0 - w.lo);
  const double mu = std::clamp(v, 0.0, 1.0);
  const double d = mu + alpha * std::sqrt(std::max(0.0, 1.0 - mu * mu));
  return d > 0 ? mu / d : 1.0;  // alpha = 0 (mirror): t = 1 for every mu
}

// u^p of a warp: u itself for p = 1, the correctly rounded square root for p = 1/2 (the
// ggx_cos and average axes: a square root costs a fraction of std::pow), else std::pow.
inline double warp_power(double u, double p) { return p == 1 ? u : p == 0.5 ? std::sqrt(u) : std::pow(u, p); }

inline double Warp::to_grid(double v, double aux) const {
  if (kind == WarpKind::LogRoughness || kind == WarpKind::GlassIor) return to_grid_log_or_glass(v, aux);
  return warp_power(warp_power_base(*this, v, aux), p);
}

inline double Warp::to_grid_fast(double v, double alpha) const {
  // to_grid itself where it has no cheaper form: the log and glass warps, and p = 1 and 1/2.
  if (kind == WarpKind::LogRoughness || kind == WarpKind::GlassIor || p == 1 || p == 0.5) return to_grid(v, alpha);
  const double u = warp_power_base(*this, v, alpha);
  if (p == 0.25) return std::sqrt(std::sqrt(u));
  return u > 0 ? std::exp2(p * std::log2(u)) : std::pow(u, p);
}

// The ggx_cos warp of power 1/2 (Warp::to_grid_fast, same values) at two cosines side by side: one
// packed square root and division per step instead of two scalar ones.
inline void ggx_cos_sqrt_warp2(double mu_a, double mu_b, double alpha, double x[2]) {
#if defined(__SSE2__)
  const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
  // clamp(v, 0, 1) as std::clamp (NaN passes: maxpd / minpd return their second operand on NaN).
  const __m128d mu = _mm_min_pd(one, _mm_max_pd(zero, _mm_set_pd(mu_b, mu_a)));
  const __m128d s = _mm_sqrt_pd(_mm_max_pd(_mm_sub_pd(one, _mm_mul_pd(mu, mu)), zero));
  const __m128d d = _mm_add_pd(mu, _mm_mul_pd(_mm_set1_pd(alpha), s));
  const __m128d pos = _mm_cmpgt_pd(d, zero);
  const __m128d t = _mm_or_pd(_mm_and_pd(pos, _mm_div_pd(mu, d)), _mm_andnot_pd(pos, one));
  _mm_storeu_pd(x, _mm_sqrt_pd(t));
#else
  const Warp w{WarpKind::GgxCos, 0.5, 0.0};
  x[0] = w.to_grid_fast(mu_a, alpha);
  x[1] = w.to_grid_fast(mu_b, alpha);
#endif
}

struct WarpedAxis {
  std::string name;  // physical coordinate: "roughness", "cos_theta", "alpha_b"
  int size = 0;      // samples, >= 2, at x_i = i / (size - 1)
  Warp warp;
};

// Value encodings: what a table stores, and how a lookup decodes it.
//   Value:        the quantity itself
//   LogOneMinus:  ln(1 - quantity); decode 1 - exp(stored) (keeps relative precision of 1 - E_m,avg
//                 as it vanishes like r^4 at r -> 0)
enum class Encoding { Value, LogOneMinus };

// The quantity of a stored (interpolated) value.
inline double decode(Encoding e, double stored) { return e == Encoding::LogOneMinus ? 1.0 - std::exp(stored) : stored; }

struct WarpedTable {
  std::string name;
  std::vector<WarpedAxis> axes;  // 1, 2 or 3, slowest first
  std::vector<double> values;    // stored (encoded) values, row-major, fastest axis contiguous
  std::vector<double> errors;    // standard error of the decoded quantity per sample (may be empty)
  Encoding encoding = Encoding::Value;

  size_t size() const;
  // Catmull-Rom interpolation of the stored values at grid coordinates (slowest first).
  double interpolate(double x0, double x1 = 0, double x2 = 0) const;
  // The same for a 2-D table, inline: the lookup a caller makes per shading point (RendererLuts::E_m).
  double interpolate_2d(double x0, double x1) const;
  // Decoded value at grid coordinates.
  double lookup_grid(double x0, double x1 = 0, double x2 = 0) const;
  // A 2-D table at fixed slow-axis grid coordinate x0, as the 1-D table over its fast axis whose
  // lookups equal lookup_grid(x0, x1) to rounding (the slow axis is interpolated first). Errors
  // are not carried over.
  WarpedTable slice(double x0) const;
  // A 3-D table at fixed middle-axis grid coordinate x1, as the 2-D table over its slow and fast
  // axes whose lookups equal lookup_grid(x0, x1, x2) to rounding (the middle axis is interpolated
  // first, at each (slow, fast) sample). Errors are not carried over.
  WarpedTable slice_middle(double x1) const;
};

// Catmull-Rom weights of the four samples around fractional position f in [0, 1].
inline void catmull_rom_weights(double f, double w[4]) {
  const double f2 = f * f, f3 = f2 * f;
  w[0] = 0.5 * (-f3 + 2.0 * f2 - f);
  w[1] = 0.5 * (3.0 * f3 - 5.0 * f2 + 2.0);
  w[2] = 0.5 * (-3.0 * f3 + 4.0 * f2 + f);
  w[3] = 0.5 * (f3 - f2);
}

// Cell index i in [0, n - 2] and fraction f of grid coordinate x (clamped to [0, 1]) on n >= 2
// samples at i / (n - 1).
inline void grid_cell(double x, int n, int* i, double* f) {
  const double c = (x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0) * (n - 1);
  *i = int(c) < n - 2 ? int(c) : n - 2;
  *f = c - *i;
}

// One Catmull-Rom axis of a lookup at grid coordinate x on n samples: the weights of the samples
// first .. first + count - 1 (count = min(n, 4)). The spline of cell i weighs the samples
// i - 1 .. i + 2; beyond an end (i - 1 = -1, i + 2 = n) the outside sample is the linear extension
// of the two end samples (p_-1 = 2 p_0 - p_1, p_n = 2 p_n-1 - p_n-2; see the top of this file), so
// its weight goes to those two, and the taps are the (up to) four samples at that end: the same
// interpolant, with the extension folded into the axis' weights once instead of into every row.
struct CatmullRomTaps {
  int first, count;
  double w[4];
};
inline CatmullRomTaps catmull_rom_taps(double x, int n) {
  int i;
  double f, w[4];
  grid_cell(x, n, &i, &f);
  catmull_rom_weights(f, w);
  // The weights of the samples i - 1 .. i + 2 with the outside ones' (e0 below the first sample,
  // e3 beyond the last) moved to the two end samples, padded with a zero weight on each side.
  const double e0 = i == 0 ? w[0] : 0.0, e3 = i + 2 == n ? w[3] : 0.0;
  const double u[6] = {0.0, w[0] - e0, w[1] + 2.0 * e0 - e3, w[2] - e0 + 2.0 * e3, w[3] - e3, 0.0};
  CatmullRomTaps t;
  t.count = n < 4 ? n : 4;
  t.first = std::clamp(i - 1, 0, n - t.count);
  // t.first - (i - 1): +1 at the first cell, -1 at the last when n >= 4, else 0.
  const double* from = u + 1 + (t.first - (i - 1));
  for (int k = 0; k < 4; ++k) t.w[k] = from[k];
  return t;
}

// sum_k w[k] at(first + k) over the taps of one axis.
template <class At>
double catmull_rom_sum(const CatmullRomTaps& t, At&& at) {
  double s = t.w[0] * at(t.first);
  for (int k = 1; k < t.count; ++k) s += t.w[k] * at(t.first + k);
  return s;
}

inline double WarpedTable::interpolate_2d(double x0, double x1) const {
  const int n1 = axes[1].size;
  const CatmullRomTaps t0 = catmull_rom_taps(x0, axes[0].size), t1 = catmull_rom_taps(x1, n1);
  const double* v = values.data() + size_t(t0.first) * size_t(n1) + size_t(t1.first);
#if defined(__SSE2__)
  if (t0.count == 4 && t1.count == 4) {
    // The 4 x 4 taps as pairs: each row's sum over its two pairs of samples, weighted by the row's
    // weight, summed over the rows per pair lane; then the two lanes.
    const __m128d w01 = _mm_loadu_pd(t1.w), w23 = _mm_loadu_pd(t1.w + 2);
    __m128d acc = _mm_setzero_pd();
    for (int j = 0; j < 4; ++j, v += n1) {
      const __m128d row = _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(v), w01), _mm_mul_pd(_mm_loadu_pd(v + 2), w23));
      acc = _mm_add_pd(acc, _mm_mul_pd(_mm_set1_pd(t0.w[j]), row));
    }
    return _mm_cvtsd_f64(_mm_add_sd(acc, _mm_unpackhi_pd(acc, acc)));
  }
#endif
  // Along the fast axis first (the rows' sums), then across the rows.
  return catmull_rom_sum(t0, [&](int j) {
    const double* row = v + size_t(j - t0.first) * size_t(n1) - t1.first;
    return catmull_rom_sum(t1, [&](int k) { return row[k]; });
  });
}

}  // namespace dspbr
