#include "dspbr/validate/lut_reference.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <mutex>
#include <tuple>
#include <vector>

#include "dspbr/constants.h"
#include "dspbr/frame.h"
#include "dspbr/fresnel.h"
#include "dspbr/ggx.h"
#include "dspbr/lutgen/microfacet_quadrature.h"
#include "dspbr/quadrature.h"
#include "dspbr/sheen.h"

namespace dspbr::validate {

namespace {
constexpr int kOrder = 8;

const QuadratureRule& rule8() {
  static const QuadratureRule r = gauss_legendre(kOrder);
  return r;
}

// Composite GL over [a, b] with p panels of a function of one variable.
template <class F>
double gl(F&& f, double a, double b, int p) {
  return integrate_gl(f, a, b, p, rule8());
}

// Integral of f over [a, b] through the smoothstep substitution x = a + (b - a)(3t^2 - 2t^3):
// removes the square-root behaviour at both ends where the azimuth range opens or closes.
template <class F>
double gl_smooth(F&& f, double a, double b, int p) {
  return gl(
      [&](double t) {
        const double x = a + (b - a) * t * t * (3.0 - 2.0 * t);
        return f(x) * (b - a) * 6.0 * t * (1.0 - t);
      },
      0.0, 1.0, p);
}

// For a microfacet normal at polar angle theta_h (cos cz, sin sz) and v = (s_v, 0, mu), the reflected
// l = 2 (v.h) h - v is above the surface iff cos(phi_h) > c0 with
//   c0 = mu (1 - 2 cz^2) / (2 cz s_v sz)   (from l.z = 2 (v.h) cz - mu > 0; it implies v.h > 0).
// phi_max in [0, pi] is the end of that azimuth range (0: empty, pi: full circle). Integrating phi
// only over it removes the kink of the horizon from the integrand.
double phi_max(double mu, double cz, double sz) {
  const double sv = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  const double num = mu * (1.0 - 2.0 * cz * cz), den = 2.0 * cz * sv * sz;
  if (den <= 0) return num < 0 ? kPi : 0.0;
  const double c0 = num / den;
  if (c0 <= -1) return kPi;
  if (c0 >= 1) return 0.0;
  return std::acos(c0);
}

// theta_h where c0 crosses `target` (-1: the azimuth range starts shrinking, +1: it vanishes);
// c0 increases with theta_h. Bisection to double precision.
double theta_where(double mu, double target) {
  const double sv = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  if (sv <= 0) return kPi / 4;  // normal incidence: l above iff theta_h < 45 deg
  double lo = 0, hi = kPi / 2;
  for (int i = 0; i < 200; ++i) {
    const double t = 0.5 * (lo + hi), cz = std::cos(t), sz = std::sin(t);
    const double c0 = mu * (1.0 - 2.0 * cz * cz) / (2.0 * cz * sv * sz);
    (c0 < target ? lo : hi) = t;
  }
  return 0.5 * (lo + hi);
}

// Integral over the azimuth range of g(h, vh, l); v in the xz plane so [0, phi_max] counts twice.
template <class G>
double azimuth_integral(double mu, double cz, double sz, int panels, G&& g) {
  const double pm = phi_max(mu, cz, sz);
  if (pm <= 0) return 0.0;
  const Vec3 v = view_dir(mu);
  return 2.0 * gl(
                   [&](double phi) {
                     const Vec3 h{sz * std::cos(phi), sz * std::sin(phi), cz};
                     const double vh = dot(v, h);
                     const Vec3 l = 2.0 * vh * h - v;
                     if (l.z <= 0 || vh <= 0) return 0.0;  // round-off at the range ends
                     return g(v, h, vh, l);
                   },
                   0.0, pm, panels);
}

// Integral over h of D(h) G2 F (v.h) / mu, GGX isotropic alpha = r^2, in (u, phi) with
// D cos(theta_h) dh = du dphi / (2 pi). f0 < 0: no Fresnel.
double ggx_h_integral_uncached(double mu, double r, double f0, int panels) {
  const double alpha = roughness_to_alpha(r);
  if (alpha < 1e-9) {  // mirror limit: G2 = 1, single direction l = reflect(v, n)
    return f0 < 0 ? 1.0 : fresnel_schlick(mu, f0, 1.0);
  }
  const GgxDistribution ggx(alpha, alpha);
  auto u_of_theta = [&](double t) {
    const double t2 = std::tan(t) * std::tan(t);
    return t2 / (alpha * alpha + t2);
  };
  auto inner = [&](double u) {
    const double tan2 = alpha * alpha * u / (1.0 - u);
    const double cz = 1.0 / std::sqrt(1.0 + tan2), sz = std::sqrt(std::max(0.0, 1.0 - cz * cz));
    return azimuth_integral(mu, cz, sz, panels, [&](const Vec3& v, const Vec3& /*h*/, double vh, const Vec3& l) {
      const double g = ggx.G2(v, l);  // l = reflect(v, h), v.h > 0: l.h = v.h > 0
      const double fr = f0 < 0 ? 1.0 : fresnel_schlick(vh, f0, 1.0);
      return g * fr * vh / (mu * cz);
    });
  };
  const double ua = u_of_theta(theta_where(mu, -1.0)), ub = u_of_theta(theta_where(mu, 1.0));
  return (gl(inner, 0.0, ua, panels) + gl_smooth(inner, ua, ub, panels)) / (2.0 * kPi);
}

// ggx_h_integral_uncached, remembered per (mu, r, f0, panels): the table check asks for the same
// integrals many times (E_m(mu; r) for every f0 of Base_E, the average E_m,avg(r) for every mu and
// f0 of Base_E and Base_E_avg). A pure function of its arguments, so the values are the same
// bits whichever thread computes them first.
double ggx_h_integral(double mu, double r, double f0, int panels) {
  using Key = std::tuple<double, double, double, int>;
  static std::mutex mutex;
  static std::map<Key, double> memo;
  const Key key{mu, r, f0, panels};
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto it = memo.find(key);
    if (it != memo.end()) return it->second;
  }
  const double value = ggx_h_integral_uncached(mu, r, f0, panels);
  const std::lock_guard<std::mutex> lock(mutex);
  memo.emplace(key, value);
  return value;
}

// Integral over h of the sheen albedo integrand, in (x = cos theta_h, phi).
double sheen_h_integral(double mu, double alpha_b, bool alt, int panels) {
  const SheenLambdaFit& fit = sheen_lambda_fit_spec();
  auto inner = [&](double x) {
    const double s = std::sqrt(std::max(0.0, 1.0 - x * x));
    const double d = charlie_d(x, alpha_b);
    return azimuth_integral(mu, x, s, panels, [&](const Vec3& v, const Vec3& h, double vh, const Vec3& l) {
      if (alt) return d * l.z * vh / (mu + l.z - mu * l.z);
      return d * sheen_g2(v, l, h, alpha_b, fit) * vh / mu;
    });
  };
  // Breakpoints: where the azimuth range vanishes / starts shrinking, and the end of the
  // Charlie peak at the horizon (width ~ sqrt(alpha_b)).
  // The partial-azimuth segment [x_b, x_a] gets the smoothstep substitution.
  const double xb = std::cos(theta_where(mu, 1.0)), xa = std::cos(theta_where(mu, -1.0));
  std::vector<double> xs = {xa, 1.0};
  const double peak = 8.0 * std::sqrt(alpha_b);
  if (peak > xa && peak < 1.0) xs.insert(xs.begin() + 1, peak);
  double sum = gl_smooth(inner, xb, xa, panels);
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) sum += gl(inner, xs[i], xs[i + 1], panels);
  return sum;
}

template <class F>
RefValue with_error(F&& f, int panels) {
  RefValue r;
  r.value = f(panels);
  r.error = std::abs(r.value - f(std::max(1, panels / 2)));
  return r;
}

// 2 Integral_0^1 g(mu) mu dmu, with g evaluated by a rule of `panels` panels.
template <class G>
double average(G&& g, int panels) {
  return 2.0 * gl([&](double mu) { return g(mu, panels) * mu; }, 0.0, 1.0, std::max(2, panels / 8));
}

double base_value(double mu, double r, double f0, int panels) {
  const double em = ggx_h_integral(mu, r, -1, panels);
  const double em_avg = average([&](double m, int p) { return ggx_h_integral(m, r, -1, p); }, panels);
  return ggx_h_integral(mu, r, f0, panels) + fresnel_ms(f0, 1.0, em_avg) * (1.0 - em);
}
}  // namespace

RefValue ggx_albedo_ref(double mu, double roughness, const RefQuadrature& q) {
  return with_error([&](int p) { return ggx_h_integral(mu, roughness, -1, p); }, q.panels);
}

RefValue ggx_fresnel_albedo_ref(double mu, double roughness, double f0, const RefQuadrature& q) {
  return with_error([&](int p) { return ggx_h_integral(mu, roughness, f0, p); }, q.panels);
}

RefValue ggx_albedo_avg_ref(double roughness, const RefQuadrature& q) {
  return with_error(
      [&](int p) { return average([&](double m, int pp) { return ggx_h_integral(m, roughness, -1, pp); }, p); },
      q.panels);
}

RefValue base_albedo_ref(double mu, double roughness, double f0, const RefQuadrature& q) {
  return with_error([&](int p) { return base_value(mu, roughness, f0, p); }, q.panels);
}

RefValue base_albedo_avg_ref(double roughness, double f0, const RefQuadrature& q) {
  return with_error(
      [&](int p) {
        const double em_avg = average([&](double m, int pp) { return ggx_h_integral(m, roughness, -1, pp); }, p);
        const double fms = fresnel_ms(f0, 1.0, em_avg);
        // E_avg = 2 Int E mu dmu with E = E_F + F_ms (1 - E_m): the second part averages to F_ms (1 - E_m,avg).
        const double ef_avg = average([&](double m, int pp) { return ggx_h_integral(m, roughness, f0, pp); }, p);
        return ef_avg + fms * (1.0 - em_avg);
      },
      q.panels);
}

RefValue sheen_albedo_ref(double mu, double alpha_b, bool alternative, const RefQuadrature& q) {
  return with_error([&](int p) { return sheen_h_integral(mu, alpha_b, alternative, p); }, q.panels);
}

RefValue ggx_fresnel_albedo_avg_ref(double roughness, double f0, const RefQuadrature& q) {
  return with_error(
      [&](int p) { return average([&](double m, int pp) { return ggx_h_integral(m, roughness, f0, pp); }, p); },
      q.panels);
}

namespace {
constexpr double kGlassTolerance = 1e-6;
}  // namespace

RefValue glass_albedo_ref(double mu, double roughness, double ior, bool inside) {
  const QuadResult<1> r =
      dielectric_albedo_quadrature(std::max(mu, 1e-6), std::max(roughness * roughness, 1e-12), f0_from_ior(1.0, ior),
                                   inside ? ior : 1.0, inside ? 1.0 : ior, kGlassTolerance);
  return {r.value[0], r.error};
}

RefValue glass_albedo_avg_ref(double roughness, double ior, bool inside) {
  const double alpha = std::max(roughness * roughness, 1e-12), f0 = f0_from_ior(1.0, ior);
  // Inside, total internal reflection begins at the critical cosine: a kink of E_g.
  std::vector<double> breaks;
  if (inside && ior > 1) breaks.push_back(std::sqrt(1.0 - 1.0 / (ior * ior)));
  const QuadResult<1> r = cosine_average_quadrature<1>(
      [&](double mu, double tol) {
        return dielectric_albedo_quadrature(std::max(mu, 1e-6), alpha, f0, inside ? ior : 1.0, inside ? 1.0 : ior, tol);
      },
      breaks, kGlassTolerance);
  return {r.value[0], r.error};
}

RefValue table_quantity_ref(Lut id, const TablePoint& p, const RefQuadrature& q) {
  const double mu = std::max(p.mu, 1e-6), ab = std::max(p.alpha_b, 1e-3), r = p.roughness;
  switch (id) {
    case Lut::GgxE: return ggx_albedo_ref(mu, r, q);
    case Lut::GgxBeta: return ggx_fresnel_albedo_ref(mu, r, 0.0, q);
    case Lut::GgxEAvg: return ggx_albedo_avg_ref(r, q);
    case Lut::GgxBAvg: return ggx_fresnel_albedo_avg_ref(r, 0.0, q);
    case Lut::BaseE: return base_albedo_ref(mu, r, p.f0, q);
    case Lut::BaseEAvg: return base_albedo_avg_ref(r, p.f0, q);
    case Lut::SheenE: return sheen_albedo_ref(mu, ab, false, q);
    case Lut::SheenAshE: return sheen_albedo_ref(mu, ab, true, q);
    case Lut::GlassE: return glass_albedo_ref(mu, r, p.ior, false);
    case Lut::GlassInvE: return glass_albedo_ref(mu, r, p.ior, true);
    case Lut::GlassEAvg: return glass_albedo_avg_ref(r, p.ior, false);
    case Lut::GlassInvEAvg: return glass_albedo_avg_ref(r, p.ior, true);
  }
  throw std::invalid_argument(std::string("no reference for table '") + lut_name(id) + "'");
}

}  // namespace dspbr::validate
