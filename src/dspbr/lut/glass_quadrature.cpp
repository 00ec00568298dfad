#include "dspbr/lut/glass_quadrature.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dspbr/constants.h"
#include "dspbr/fresnel.h"
#include "dspbr/ggx.h"
#include "dspbr/quadrature.h"

namespace dspbr {

namespace {

constexpr int kMaxDepth = 6;  // at most 2^6 panels per segment between kinks

struct Glass {
  Vec3 v;
  double mu, sv, alpha, f0, eta_i, eta_o, eta;  // eta = eta_i / eta_o
  GgxDistribution ggx;  // isotropic alpha
  double lambda_v;
};

// Transmitted direction's z (unnormalised) for v.h = vh at cos(theta_h) = cz; +1 under TIR.
double refracted_z(const Glass& g, double vh, double cz) {
  const double s2 = g.eta * g.eta * std::max(0.0, 1.0 - vh * vh);
  if (s2 >= 1.0) return 1.0;
  return -g.eta * g.mu + (g.eta * vh - std::sqrt(1.0 - s2)) * cz;
}

// The integrand over phi at fixed theta_h (cz, sz), without the 1 / (2 pi) and the 2 for phi < 0.
double integrand(const Glass& g, double cz, double sz, double phi) {
  const Vec3 h{sz * std::cos(phi), sz * std::sin(phi), cz};
  const double vh = dot(g.v, h);
  if (vh <= 0) return 0.0;
  const double F = fresnel_schlick_d(vh, g.f0, 1.0, g.eta_i, g.eta_o);
  double w = 0;
  const Vec3 lr = reflect(g.v, h);
  if (lr.z > 0) w += F / (1.0 + g.lambda_v + g.ggx.Lambda(lr));
  if (F < 1) {
    Vec3 lt;
    if (refract_dir(g.v, h, g.eta, lt) && lt.z < 0)
      w += (1.0 - F) / (1.0 + g.lambda_v + g.ggx.Lambda(lt));
  }
  return w * vh / (g.mu * cz);
}

// The v.h thresholds at cos(theta_h) = cz where a term switches on or off: 0, the reflection
// horizon mu / (2 cz), total internal reflection sqrt(1 - 1/eta^2) (eta > 1) and the refraction
// horizon (refracted_z = 0; refracted_z is monotone in v.h on the non-TIR range: bisection, the
// range end when it has no root there, so that the threshold is continuous in theta_h).
std::vector<double> thresholds(const Glass& g, double cz) {
  std::vector<double> t = {0.0, g.mu / (2.0 * cz)};
  const double lo = g.eta > 1 ? std::sqrt(1.0 - 1.0 / (g.eta * g.eta)) : 0.0, hi = 1.0;
  if (g.eta > 1) t.push_back(lo);
  const double zlo = refracted_z(g, lo + 1e-15, cz), zhi = refracted_z(g, hi, cz);
  if ((zlo < 0) != (zhi < 0)) {
    double a = lo, b = hi;
    for (int i = 0; i < 60; ++i) {
      const double m = 0.5 * (a + b);
      ((refracted_z(g, m, cz) < 0) == (zlo < 0) ? a : b) = m;
    }
    t.push_back(0.5 * (a + b));
  } else {
    t.push_back(zlo < 0 ? hi : lo);
  }
  return t;
}

// cos(theta_h), sin(theta_h) of w (u = 1 - w^2, tan^2 theta_h = alpha^2 u / (1 - u)).
// tan(theta_h) = alpha sqrt(1 - w^2) / w, written without cancellation at w -> 0.
void half_angle(const Glass& g, double w, double& cz, double& sz) {
  const double s = std::sqrt(std::max(0.0, 1.0 - w * w)) * g.alpha, d = std::sqrt(w * w + s * s);
  cz = w / d;
  sz = s / d;
}

// Integral over phi in [0, pi] (doubled: the integrand is even in phi), one `rule` per piece
// between the azimuths where v.h = A cos(phi) + B crosses a threshold.
double azimuth(const Glass& g, double cz, double sz, const QuadratureRule& rule) {
  const double A = g.sv * sz, B = g.mu * cz;
  std::vector<double> phis = {0.0, kPi};
  for (double t : thresholds(g, cz))
    if (A > 0 && t > B - A && t < B + A) phis.push_back(std::acos((t - B) / A));
  std::sort(phis.begin(), phis.end());
  double sum = 0;
  for (size_t k = 0; k + 1 < phis.size(); ++k) {
    const double a = phis[k], b = phis[k + 1];
    if (b - a < 1e-15) continue;
    // Smoothstep substitution phi = a + (b - a)(3t^2 - 2t^3): square-root behaviour at both ends.
    sum += integrate_gl(
        [&](double t) {
          const double phi = a + (b - a) * t * t * (3.0 - 2.0 * t);
          return integrand(g, cz, sz, phi) * (b - a) * 6.0 * t * (1.0 - t);
        },
        0.0, 1.0, 1, rule);
  }
  return 2.0 * sum;
}

// Integral over w in [a, b] (du = 2 w dw) with `rule` in both directions.
double panel(const Glass& g, double a, double b, const QuadratureRule& rule) {
  return integrate_gl(
      [&](double w) {
        double cz, sz;
        half_angle(g, w, cz, sz);
        if (!(cz > 0)) return 0.0;
        return 2.0 * w * azimuth(g, cz, sz, rule);
      },
      a, b, 1, rule);
}

// The w where a threshold's azimuth appears or vanishes (t = B - A = cos(theta_v + theta_h) or
// t = B + A = cos(theta_v - theta_h)): the azimuthal integral has a kink there. Scan and bisect.
std::vector<double> kinks(const Glass& g) {
  constexpr int kScan = 48;
  auto signs = [&](double w) {
    double cz, sz;
    half_angle(g, w, cz, sz);
    const double A = g.sv * sz, B = g.mu * cz;
    std::vector<double> d;
    for (double t : thresholds(g, cz)) {
      d.push_back(t - (B - A));
      d.push_back(t - (B + A));
    }
    return d;
  };
  std::vector<double> out;
  const double w_lo = 1e-9;
  std::vector<double> prev = signs(w_lo);
  double w_prev = w_lo;
  for (int i = 1; i <= kScan; ++i) {
    const double w = double(i) / kScan;
    const std::vector<double> cur = signs(w);
    for (size_t k = 0; k < std::min(cur.size(), prev.size()); ++k) {
      if ((prev[k] < 0) == (cur[k] < 0)) continue;
      double a = w_prev, b = w;
      for (int it = 0; it < 40; ++it) {
        const double m = 0.5 * (a + b);
        const std::vector<double> dm = signs(m);
        if (k >= dm.size()) break;
        ((dm[k] < 0) == (prev[k] < 0) ? a : b) = m;
      }
      out.push_back(0.5 * (a + b));
    }
    prev = cur;
    w_prev = w;
  }
  std::sort(out.begin(), out.end());
  return out;
}

void adaptive(const Glass& g, double a, double b, double tol, int depth, double& value, double& error) {
  static const QuadratureRule r8 = gauss_legendre(8), r16 = gauss_legendre(16);
  const double fine = panel(g, a, b, r16), coarse = panel(g, a, b, r8);
  const double e = std::abs(fine - coarse);
  if (e <= tol * (b - a) || depth >= kMaxDepth) {
    value += fine;
    error += e;
    return;
  }
  const double m = 0.5 * (a + b);
  adaptive(g, a, m, tol, depth + 1, value, error);
  adaptive(g, m, b, tol, depth + 1, value, error);
}

}  // namespace

Estimate glass_albedo_quadrature(double mu, double alpha, double f0, double eta_i, double eta_o, double target) {
  Glass g;
  g.mu = mu;
  g.sv = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  g.v = {g.sv, 0.0, mu};
  g.alpha = alpha;
  g.f0 = f0;
  g.eta_i = eta_i;
  g.eta_o = eta_o;
  g.eta = eta_i / eta_o;
  g.ggx = GgxDistribution(alpha, alpha);
  g.lambda_v = g.ggx.Lambda(g.v);
  double value = 0, error = 0;
  // Panels in w between the kinks (w -> 0 is the grazing-normal end), refined where needed.
  std::vector<double> ws = {0.0};
  for (double k : kinks(g))
    if (k > ws.back() + 1e-12 && k < 1.0 - 1e-12) ws.push_back(k);
  ws.push_back(1.0);
  for (size_t k = 0; k + 1 < ws.size(); ++k) adaptive(g, ws[k], ws[k + 1], target, 0, value, error);
  value /= 2.0 * kPi;
  error /= 2.0 * kPi;
  return {value, error};
}

}  // namespace dspbr
