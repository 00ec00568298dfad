// The tests' one light-space rule: composite Gauss-Legendre quadrature over the light direction
// l = (sqrt(1 - mu^2) cos phi, sqrt(1 - mu^2) sin phi, sign mu), phi over [0, 2 pi], mu over
// [0, 1] through one of three substitutions. Independent of the library's reference quadrature
// (validate/lut_reference.h integrates over the half vector), so the tests check that reference,
// and the BSDF's albedos, against it.
#pragma once
#include <algorithm>
#include <cmath>

#include "dspbr/constants.h"
#include "dspbr/frame.h"
#include "dspbr/quadrature.h"

namespace dspbr::test {

// How the mu axis is parametrised (t in [0, 1], panels uniform in t):
//   Linear:  mu = t
//   Horizon: mu = t^2            (nodes graded towards the horizon, dmu = 2 t dt)
//   Polar:   mu = cos(t pi / 2)  (uniform in theta_l, dmu = sin(theta) pi / 2 dt)
enum class MuGrading { Linear, Horizon, Polar };

// Integral over the hemisphere of `sign` (+1 upper, -1 lower) of g(l) dl.
template <class G>
double hemisphere_integral(G&& g, double sign, int panels_mu, int panels_phi, MuGrading grading = MuGrading::Linear,
                           int order = 8) {
  const QuadratureRule rule = gauss_legendre(order);
  return integrate_gl(
      [&](double t) {
        double mu = t, jac = 1.0;
        if (grading == MuGrading::Horizon) mu = t * t, jac = 2.0 * t;
        if (grading == MuGrading::Polar) {
          const double th = t * (kPi / 2);
          mu = std::cos(th), jac = std::sin(th) * (kPi / 2);
        }
        const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
        return jac * integrate_gl([&](double phi) { return g(Vec3{s * std::cos(phi), s * std::sin(phi), sign * mu}); },
                                  0.0, 2.0 * kPi, panels_phi, rule);
      },
      0.0, 1.0, panels_mu, rule);
}

// Directional albedo Integral brdf(v, l) l.z dl over the upper hemisphere, v = view_dir(mu_v).
template <class Brdf>
double light_space_albedo(Brdf&& brdf, double mu_v, int panels_mu, int panels_phi, MuGrading grading) {
  const Vec3 v = view_dir(mu_v);
  return hemisphere_integral([&](const Vec3& l) { return brdf(v, l) * l.z; }, 1.0, panels_mu, panels_phi, grading);
}

}  // namespace dspbr::test
