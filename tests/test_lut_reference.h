// Independent reference values for the LUT, glass and fit tests: deterministic composite
// Gauss-Legendre quadrature of the defining integrals (no sampling, no code shared with
// src/dspbr/lutgen/ or src/dspbr/validate/): over the GGX half vector in its slope parametrisation
// (sharp lobes), and over the light direction by the tests' one light-space rule
// (light_space_albedo.h) for rough GGX lobes and the sheen.
#pragma once
#include <cmath>

#include "dspbr/constants.h"
#include "dspbr/frame.h"
#include "dspbr/fresnel.h"
#include "dspbr/ggx.h"
#include "dspbr/quadrature.h"
#include "dspbr/sheen.h"
#include "light_space_albedo.h"

namespace dspbr::lutref {


// 2D composite Gauss-Legendre of f(x, y) over [0,1] x [0,1].
template <class F>
double integrate_unit_square(F&& f, int panels_x, int panels_y, int order = 8) {
  const QuadratureRule rule = gauss_legendre(order);
  return integrate_gl([&](double x) { return integrate_gl([&](double y) { return f(x, y); }, 0.0, 1.0, panels_y, rule); },
                      0.0, 1.0, panels_x, rule);
}

// Integral over the GGX half-vector domain of g(h) D(h) (h.n) dh, in the slope
// parametrisation: slope = alpha rho (cos phi, sin phi), u = rho^2 / (1 + rho^2) in [0,1], for
// which D(h) (h.n) dh = du dphi / (2 pi); then u = 1 - w^2 (du = 2 w dw) removes the
// 1/sqrt(1 - u) growth of integrands carrying 1/(h.n). This follows the lobe at any alpha (also
// r -> 0), unlike (mu_l, phi). Only phi in [0, pi] is integrated (the integrands are even in phi).
template <class G>
double ggx_half_vector_integral(double alpha, G&& g, int panels_u, int panels_phi) {
  // w = s^3 grades the nodes towards w = 0 (strongly tilted normals), where the reflected
  // direction crosses the horizon and the integrand has a kink.
  return integrate_unit_square(
      [&](double s, double t) {
        const double w = s * s * s;
        const double phi = kPi * t;
        if (w == 0) return 0.0;
        const double rho = std::sqrt(std::max(0.0, 1.0 - w * w)) / w;  // u / (1 - u) = (1 - w^2) / w^2
        const Vec3 h = normalize(Vec3{-alpha * rho * std::cos(phi), -alpha * rho * std::sin(phi), 1.0});
        // du = 2w dw, dw = 3 s^2 ds; dphi = pi dt; both halves of phi; measure du dphi / (2 pi)
        return 3.0 * s * s * 2.0 * w * g(h) * kPi / (2.0 * kPi) * 2.0;
      },
      panels_u, panels_phi);
}

// Same integral as ggx_albedo_quad in the light domain (mu_l, phi) (light_space_albedo.h: phi
// over [0, 2 pi] with twice the panels, the nodes of [0, pi] mirrored): the integrand M_r F mu_l
// has no kink inside the hemisphere (v.h > 0 for any l above it), but the lobe is a spike of
// width ~alpha around the mirror direction, so this form is for rough cells only.
inline double ggx_albedo_quad_l(double mu, double r, double f0, int panels_mu = 64, int panels_phi = 64) {
  const double alpha = r * r;
  return test::light_space_albedo(
      [&](const Vec3& v, const Vec3& l) {
        const Vec3 h = normalize(v + l);
        const double F = f0 + (1 - f0) * std::pow(1 - dot(v, h), 5);
        return GgxDistribution(alpha, alpha).M_r(v, l, h) * F;
      },
      mu, panels_mu, 2 * panels_phi, test::MuGrading::Linear);
}

// Integral M_r F(v.h) mu_l dl with F = f0 + (1 - f0) (1 - v.h)^5, using
// dl = 4 (v.h) dh:  Integral D G2 F (v.h) / mu_v dh.
inline double ggx_albedo_quad(double mu, double r, double f0, int panels_u = 64, int panels_phi = 32) {
  const double alpha = r * r;
  const Vec3 v = view_dir(mu);
  return ggx_half_vector_integral(
      alpha,
      [&](const Vec3& h) {
        const double vh = dot(v, h);
        if (vh <= 0) return 0.0;
        const Vec3 l = 2 * vh * h - v;
        if (l.z <= 0) return 0.0;
        const GgxDistribution ggx(alpha, alpha);
        const double G2 = 1.0 / (1.0 + ggx.Lambda(v) + ggx.Lambda(l));
        const double F = f0 + (1 - f0) * std::pow(1 - vh, 5);
        return G2 * F * vh / (mu * h.z);
      },
      panels_u, panels_phi);
}

// Integral M_b mu_l dl for the sheen models in (mu_l, phi) (light_space_albedo.h: phi over
// [0, 2 pi] with twice the panels, the nodes of [0, pi] mirrored).
template <class Brdf>
double sheen_albedo_quad(double mu, Brdf&& brdf, int panels_mu = 64, int panels_phi = 32) {
  return test::light_space_albedo(brdf, mu, panels_mu, 2 * panels_phi, test::MuGrading::Linear);
}

}  // namespace dspbr::lutref

namespace dspbr::lutref {

// 2 Integral_0^1 E(mu) mu dmu by composite Gauss-Legendre in mu.
template <class E>
double cosine_average(E&& e, int panels = 24) {
  static const QuadratureRule rule = gauss_legendre(8);
  return integrate_gl([&](double mu) { return 2.0 * e(mu) * mu; }, 0.0, 1.0, panels, rule);
}

}  // namespace dspbr::lutref
