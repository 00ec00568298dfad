#include "dspbr/sheen.h"

#include <cmath>

#include "dspbr/constants.h"
#include "dspbr/quadrature.h"

namespace dspbr {

namespace {

// Integral over the azimuth of max(0, A cos(phi) + B), A >= 0 (closed form).
double azimuth_integral(double A, double B) {
  if (B >= A) return 2.0 * kPi * B;  // plane never clips
  if (B <= -A) return 0.0;           // fully clipped
  const double r = B / A;
  return 2.0 * (B * std::acos(-r) + std::sqrt(std::max(0.0, A * A - B * B)));
}
}  // namespace

double charlie_d(double cos_theta_h, double alpha_b) {
  if (cos_theta_h <= 0) return 0.0;
  const double inv_a = 1.0 / alpha_b;
  const double sin2 = std::max(0.0, 1.0 - cos_theta_h * cos_theta_h);
  return (2.0 + inv_a) * std::pow(sin2, 0.5 * inv_a) / (2.0 * kPi);
}

const SheenLambdaFit& sheen_lambda_fit_spec() {
  static const SheenLambdaFit fit{{11.9095, 4.68753, 0.33467, -2.22664, -1.76591},
                                  {13.7000, 2.92754, 0.28670, -0.81757, -1.22466},
                                  {-1.59612, 0.20375, -0.55825, 1.32805}};
  return fit;
}

const SheenLambdaFit& sheen_lambda_fit_ck17() {
  static const SheenLambdaFit fit{{25.3245, 3.32435, 0.16801, -1.27393, -4.85967},
                                  {21.5473, 3.82987, 0.19823, -1.97760, -4.32054},
                                  {0, 0, 0, 0},
                                  true};
  return fit;
}

SheenLambda::SheenLambda(double alpha_b, const SheenLambdaFit& f) {
  const double w = f.ck17_blend ? 1.0 - (1.0 - alpha_b) * (1.0 - alpha_b)
                                : f.c[0] / (1.0 + f.c[1] * std::pow(alpha_b, f.c[2])) + f.c[3];
  for (size_t i = 0; i < p_.size(); ++i) p_[i] = (1.0 - w) * f.p0[i] + w * f.p1[i];
  l_half_ = L(0.5);
}

double SheenLambda::L(double x) const { return p_[0] / (1.0 + p_[1] * std::pow(x, p_[2])) + p_[3] * x + p_[4]; }

double SheenLambda::operator()(double cos_theta) const {
  const double c = std::min(1.0, std::abs(cos_theta));
  if (c < 0.5) return std::exp(L(c));
  return std::exp(2.0 * l_half_ - L(1.0 - c));
}

double sheen_lambda_exact(double cos_theta, double alpha_b) {
  static const QuadratureRule rule = gauss_legendre(24);
  const double mu = std::min(1.0, std::abs(cos_theta));
  const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  const double k = 1.0 / alpha_b;
  // Projected area of visible microfacets: Integral D(h) max(0, w.h) dh over theta_h in [0, pi/2].
  // The integrand is (2+k)/(2pi) sin^k(th) * az(th) * sin(th); sin^k concentrates the mass near
  // th = pi/2 (width ~ 1/sqrt(k)), so the grid is graded towards pi/2 in the variable
  // v = pi/2 - th (v in [0, pi/2]). (Integrating in u = cos th instead puts a square-root
  // singularity of sin th = sqrt(1 - u^2) at u = 1, which cost up to 4e-2 relative error for
  // alpha_b = 1 near normal incidence.)
  auto integrand = [&](double v) {
    const double u = std::sin(v), sh = std::cos(v);  // u = cos th_h, sh = sin th_h
    return (2.0 + k) / (2.0 * kPi) * std::pow(sh, k) * azimuth_integral(s * sh, mu * u) * sh;
  };
  // Kink of max(0, .) at B = A, i.e. cos th_h = sin th, v = asin(s): split there.
  // Graded panels in v: boundaries geometric towards v = 0 (th = pi/2).
  double total = 0;
  auto integrate = [&](double a, double b) {
    if (b <= a) return 0.0;
    double sum = 0;
    // geometric grading towards a when a == 0, since sin^k(th) = cos^k(v) decays over v ~ 1/sqrt(k)
    const int panels = 48;
    double lo = a;
    const double scale = std::max(1e-6, std::min(b - a, 4.0 / std::sqrt(k + 1.0)));
    for (int p = 1; p <= panels; ++p) {
      // first 3/4 of the panels cover [a, a + scale] geometrically, the rest uniformly to b
      double hi;
      const int g = panels * 3 / 4;
      if (p <= g) hi = a + scale * std::pow(1e-4, 1.0 - double(p) / g);
      else hi = a + scale + (b - a - scale) * double(p - g) / (panels - g);
      if (p == 1) lo = a;
      hi = std::min(hi, b);
      if (hi > lo) sum += integrate_gl(integrand, lo, hi, 1, rule);
      lo = hi;
    }
    return sum;
  };
  const double v_kink = std::asin(std::min(s, 1.0));
  total = integrate(0.0, v_kink) + integrate(v_kink, kPi / 2);
  return total / mu - 1.0;
}

double sheen_g2(const Vec3& v, const Vec3& l, const Vec3& h, double lambda_v, double lambda_l) {
  if (dot(v, h) <= 0 || dot(l, h) <= 0) return 0.0;
  return 1.0 / (1.0 + lambda_v + lambda_l);
}

double sheen_g2(const Vec3& v, const Vec3& l, const Vec3& h, double alpha_b, const SheenLambdaFit& fit) {
  const SheenLambda lambda(alpha_b, fit);
  return sheen_g2(v, l, h, lambda(v.z), lambda(l.z));
}

double sheen_brdf(const Vec3& v, const Vec3& l, double alpha_b, const SheenLambdaFit& fit) {
  if (v.z <= 0 || l.z <= 0) return 0.0;
  const SheenLambda lambda(alpha_b, fit);
  return sheen_brdf(v, l, alpha_b, lambda, lambda(v.z));
}

double sheen_brdf(const Vec3& v, const Vec3& l, double alpha_b, const SheenLambda& lambda, double lambda_v) {
  if (v.z <= 0 || l.z <= 0) return 0.0;
  const Vec3 h = normalize(v + l);
  return charlie_d(h.z, alpha_b) * sheen_g2(v, l, h, lambda_v, lambda(l.z)) / (4.0 * v.z * l.z);
}

double sheen_brdf_ash(const Vec3& v, const Vec3& l, double alpha_b) {
  if (v.z <= 0 || l.z <= 0) return 0.0;
  const Vec3 h = normalize(v + l);
  return charlie_d(h.z, alpha_b) / (4.0 * (v.z + l.z - v.z * l.z));
}

}  // namespace dspbr
