#include "dspbr/tables/warped_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dspbr {

double glass_ior_of_x(double x) {
  const double c = std::clamp(x, 0.0, 1.0);
  return (2.0 + c) / (2.0 - c);
}
double glass_x_of_ior(double ior) {
  const double n = std::clamp(ior, 1.0, kGlassMaxIor);  // first: +-inf and -3 go to the nearer end
  return 2.0 * (n - 1.0) / (n + 1.0);
}

namespace {

// GlassIor (see the header): the half-linear, half-logarithmic coordinate of x_F = 2 sqrt(F_0) at
// scale k mu^2; mu clamped to 1e-6 (the integrators' grazing clamp), so k mu^2 > 0.
constexpr double kGlassMinMu = 1e-6;
double glass_warp(double xf, double k_mu2) { return 0.5 * xf + 0.5 * std::log1p(xf / k_mu2) / std::log1p(1.0 / k_mu2); }
double glass_k_mu2(double k, double mu) {
  const double m = std::clamp(mu, kGlassMinMu, 1.0);
  return k * m * m;
}

}  // namespace

double Warp::to_grid_log_or_glass(double v, double alpha) const {
  if (kind == WarpKind::LogRoughness) return std::log(std::clamp(v, lo, 1.0) / lo) / std::log(1.0 / lo);
  return glass_warp(glass_x_of_ior(v), glass_k_mu2(p, alpha));
}

double Warp::from_grid(double x, double alpha) const {
  x = std::clamp(x, 0.0, 1.0);
  switch (kind) {
    case WarpKind::Power:
      return lo + (1.0 - lo) * (p == 1 ? x : std::pow(x, 1.0 / p));
    case WarpKind::GgxCos: {
      // mu (1 - t) = t alpha sqrt(1 - mu^2)  =>  mu = t alpha / sqrt((1 - t)^2 + t^2 alpha^2)
      const double t = std::pow(x, 1.0 / p);
      const double d = std::sqrt((1.0 - t) * (1.0 - t) + t * t * alpha * alpha);
      return d > 0 ? std::min(1.0, t * alpha / d) : 1.0;
    }
    case WarpKind::LogRoughness:
      return lo * std::pow(1.0 / lo, x);
    case WarpKind::GlassIor: {  // monotone in x_F: bisection to double precision
      const double k_mu2 = glass_k_mu2(p, alpha);
      double a = 0, b = 1;
      for (int it = 0; it < 64; ++it) (glass_warp(0.5 * (a + b), k_mu2) < x ? a : b) = 0.5 * (a + b);
      return glass_ior_of_x(0.5 * (a + b));
    }
  }
  return 0;
}

std::string Warp::describe() const {
  switch (kind) {
    case WarpKind::Power: return fmt::format("power(p={:g}, lo={:g})", p, lo);
    case WarpKind::GgxCos: return fmt::format("ggx_cos(p={:g})", p);
    case WarpKind::LogRoughness: return fmt::format("log(lo={:g})", lo);
    case WarpKind::GlassIor: return fmt::format("glass_ior(k={:g})", p);
  }
  return "";
}

size_t WarpedTable::size() const {
  size_t n = 1;
  for (const WarpedAxis& a : axes) n *= size_t(a.size);
  return n;
}

double WarpedTable::interpolate(double x0, double x1, double x2) const {
  if (axes.empty() || axes.size() > 3) throw std::invalid_argument("WarpedTable: rank must be 1, 2 or 3 (" + name + ")");
  const double* v = values.data();
  const int n0 = axes[0].size;
  const CatmullRomTaps t0 = catmull_rom_taps(x0, n0);
  if (axes.size() == 1) return catmull_rom_sum(t0, [&](int k) { return v[k]; });
  if (axes.size() == 2) return interpolate_2d(x0, x1);
  // Rank 3: interpolate along the fastest axis first, then across rows and planes.
  const int n1 = axes[1].size;
  const CatmullRomTaps t1 = catmull_rom_taps(x1, n1);
  const int n2 = axes[2].size;
  const CatmullRomTaps t2 = catmull_rom_taps(x2, n2);
  auto plane = [&](int q) {
    auto row = [&](int r) {
      const double* p = v + (size_t(q) * size_t(n1) + size_t(r)) * size_t(n2);
      return catmull_rom_sum(t2, [&](int k) { return p[k]; });
    };
    return catmull_rom_sum(t1, row);
  };
  return catmull_rom_sum(t0, plane);
}

WarpedTable WarpedTable::slice(double x0) const {
  if (axes.size() != 2) throw std::invalid_argument("WarpedTable::slice: needs a 2-D table (" + name + ")");
  WarpedTable s;
  s.name = name;
  s.axes = {axes[1]};
  s.encoding = encoding;
  const int n1 = axes[1].size;
  // At the fast axis' samples x1 = k / (n1 - 1) the Catmull-Rom weights are (0, 1, 0, 0) exactly,
  // so each value is the slow-axis interpolation of one column.
  for (int k = 0; k < n1; ++k) s.values.push_back(interpolate(x0, double(k) / (n1 - 1)));
  return s;
}

WarpedTable WarpedTable::slice_middle(double x1) const {
  if (axes.size() != 3) throw std::invalid_argument("WarpedTable::slice_middle: needs a 3-D table (" + name + ")");
  WarpedTable s;
  s.name = name;
  s.axes = {axes[0], axes[2]};
  s.encoding = encoding;
  const int n0 = axes[0].size, n1 = axes[1].size, n2 = axes[2].size;
  const CatmullRomTaps t1 = catmull_rom_taps(x1, n1);
  // The interpolant is linear in the samples, so the middle axis can be interpolated first: at
  // each (slow, fast) sample, the Catmull-Rom sum over the middle axis (as in interpolate).
  s.values.reserve(size_t(n0) * size_t(n2));
  for (int p = 0; p < n0; ++p)
    for (int k = 0; k < n2; ++k)
      s.values.push_back(catmull_rom_sum(
          t1, [&](int r) { return values[(size_t(p) * size_t(n1) + size_t(r)) * size_t(n2) + size_t(k)]; }));
  return s;
}

double WarpedTable::lookup_grid(double x0, double x1, double x2) const {
  return decode(encoding, interpolate(x0, x1, x2));
}

}  // namespace dspbr
