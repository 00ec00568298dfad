#include "dspbr/bsdf/volume.h"

#include <cmath>
#include <limits>

#include "dspbr/constants.h"
#include "dspbr/frame.h"

namespace dspbr {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// x * y with the convention inf * 0 = 0 (see VolumeCoefficients).
double mul_inf0(double x, double y) { return (x == 0 || y == 0) ? 0.0 : x * y; }
}  // namespace

double volume_sigma_t(double a, double d) {
  if (std::isinf(d)) return 0.0;  // infinite attenuation distance: no attenuation
  if (!(d > 0)) return kInf;      // d = 0: opaque (spec parameter table)
  if (!(a > 0)) return kInf;      // nothing survives any positive distance
  if (a >= 1) return 0.0;
  return -std::log(a) / d;        // spec "Volume": sigma_t = 1 / mfp = -log(a) / d
}

Rgb volume_sigma_t(const Rgb& a, double d) {
  return {volume_sigma_t(a.r, d), volume_sigma_t(a.g, d), volume_sigma_t(a.b, d)};
}

double volume_rho_ss(double rho_ms) {
  const double r = std::clamp(rho_ms, 0.0, 1.0);
  if (r == 0) return 0.0;  // subsurface scattering disabled (spec parameter table)
  if (r == 1) return 1.0;  // white: no absorption (the fit gives 1 - 2.7e-11)
  // [KC17] albedo inversion, as printed in the spec's "Volume" section.
  const double t = 4.09712 + 4.20863 * r - std::sqrt(9.59217 + 41.6808 * r + 17.7126 * r * r);
  return std::clamp(1.0 - t * t, 0.0, 1.0);
}

Rgb volume_rho_ss(const Rgb& rho_ms) {
  return {volume_rho_ss(rho_ms.r), volume_rho_ss(rho_ms.g), volume_rho_ss(rho_ms.b)};
}

VolumeCoefficients volume_coefficients(const Rgb& a, double d, const Rgb& rho_ms) {
  VolumeCoefficients c;
  c.sigma_t = volume_sigma_t(a, d);
  c.rho_ss = volume_rho_ss(rho_ms);
  const Rgb one_minus = 1.0 - c.rho_ss;
  // sigma_a = sigma_t (1 - rho_ss), sigma_s = sigma_t rho_ss (spec "Volume").
  c.sigma_a = {mul_inf0(c.sigma_t.r, one_minus.r), mul_inf0(c.sigma_t.g, one_minus.g), mul_inf0(c.sigma_t.b, one_minus.b)};
  c.sigma_s = {mul_inf0(c.sigma_t.r, c.rho_ss.r), mul_inf0(c.sigma_t.g, c.rho_ss.g), mul_inf0(c.sigma_t.b, c.rho_ss.b)};
  return c;
}

Rgb volume_transmittance(const Rgb& sigma_t, double distance) {
  auto tr = [&](double s) { return mul_inf0(s, distance) == 0 ? 1.0 : std::exp(-s * distance); };  // Beer-Lambert
  return {tr(sigma_t.r), tr(sigma_t.g), tr(sigma_t.b)};
}

double hg_phase_cos(double cos_theta, double g) {
  g = std::clamp(g, -1.0, 1.0);
  if (std::abs(g) == 1.0) return 0.0;  // Dirac: not evaluable
  // [HG41] with the scattering angle theta: (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^(3/2)).
  // 1 + g^2 - 2 g c written as (1 - g)^2 + 2 g (1 - c) (g >= 0) or (1 + g)^2 - 2 g (1 + c) (g < 0):
  // a sum of non-negative terms, >= (1 - |g|)^2 > 0, without cancellation at the peak.
  const double c = std::clamp(cos_theta, -1.0, 1.0);
  const double denom = g >= 0 ? (1.0 - g) * (1.0 - g) + 2.0 * g * (1.0 - c) : (1.0 + g) * (1.0 + g) - 2.0 * g * (1.0 + c);
  return (1.0 - g) * (1.0 + g) / (4.0 * kPi * denom * std::sqrt(denom));
}

double hg_phase(const Vec3& v, const Vec3& l, double g) {
  return hg_phase_cos(-dot(v, l), g);  // spec form: 1 + g^2 + 2 g (v.l)
}

double hg_sample_cos(double g, double u) {
  g = std::clamp(g, -1.0, 1.0);
  if (g == 1.0) return 1.0;
  if (g == -1.0) return -1.0;
  // Inverse CDF of HG in cos theta: cos = (1 + g^2 - ((1 - g^2) / s)^2) / (2 g), s = 1 + g (2u - 1).
  const double t = 2.0 * u - 1.0;
  double c;
  if (std::abs(g) <= 0.5) {
    // Same expression with g factored out of the numerator (no 1/g): exact at g = 0 (c = t).
    const double s = 1.0 + g * t;
    const double num = 2.0 * t + g * (t * t + 3.0) + 2.0 * g * g * t + g * g * g * (t * t - 1.0);
    c = num / (2.0 * s * s);
  } else {
    // s as a sum of non-negative terms: no cancellation as |g| -> 1.
    const double s = g > 0 ? (1.0 - g) + 2.0 * g * u : (1.0 + g) - 2.0 * g * (1.0 - u);
    const double q = (1.0 - g) * (1.0 + g) / s;
    c = (1.0 + g * g - q * q) / (2.0 * g);
  }
  return std::clamp(c, -1.0, 1.0);
}

PhaseSample hg_sample(const Vec3& v, double g, double u1, double u2) {
  PhaseSample ps;
  g = std::clamp(g, -1.0, 1.0);
  if (std::abs(g) == 1.0) {  // Dirac: forward (l = -v) or backward (l = v)
    ps.l = g > 0 ? -v : v;
    ps.pdf = 1.0;
    ps.delta = true;
    return ps;
  }
  const double c = hg_sample_cos(g, u1);
  const double s = std::sqrt(std::max(0.0, (1.0 - c) * (1.0 + c)));
  const double phi = 2.0 * kPi * u2;
  // The travel direction after scattering, v, makes angle theta with the incoming travel direction
  // -l: -l = c v + s (cos phi t + sin phi b).
  const Frame f = Frame::from_normal(v);
  ps.l = -f.to_world({s * std::cos(phi), s * std::sin(phi), c});
  ps.pdf = hg_phase_cos(c, g);
  return ps;
}

}  // namespace dspbr
