// Volume coefficients and the Henyey-Greenstein phase function against closed forms, quadrature
// and radiative transfer (Chandrasekhar's H-function for a semi-infinite isotropic medium).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "dspbr/bsdf/volume.h"
#include "dspbr/constants.h"
#include "dspbr/quadrature.h"
#include "dspbr/rng.h"

using namespace dspbr;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// Chandrasekhar's H-function for isotropic scattering with single-scattering albedo w, from
// 1 / H(mu) = sqrt(1 - w) + (w / 2) Integral_0^1 mu' H(mu') / (mu + mu') dmu' (Chandrasekhar 1960,
// "Radiative Transfer", ch. V), by fixed-point iteration on graded Gauss-Legendre nodes.
struct HFunction {
  std::vector<double> x, wt, h;
  double w;
  explicit HFunction(double w_) : w(w_) {
    const QuadratureRule r = gauss_legendre(32);
    const double edges[] = {0.0, 1.0 / 64, 1.0 / 16, 0.25, 1.0};  // graded towards mu = 0
    for (int p = 0; p < 4; ++p)
      for (std::size_t i = 0; i < r.x.size(); ++i) {
        x.push_back(edges[p] + (edges[p + 1] - edges[p]) * (r.x[i] + 1) / 2);
        wt.push_back((edges[p + 1] - edges[p]) / 2 * r.w[i]);
      }
    h.assign(x.size(), 1.0);
    for (int it = 0; it < 5000; ++it) {
      double diff = 0;
      std::vector<double> nh(x.size());
      for (std::size_t i = 0; i < x.size(); ++i) {
        nh[i] = at(x[i]);
        diff = std::max(diff, std::abs(nh[i] - h[i]));
      }
      h = nh;
      if (diff < 1e-13) break;
    }
  }
  double at(double mu) const {
    double s = 0;
    for (std::size_t j = 0; j < x.size(); ++j) s += wt[j] * x[j] * h[j] / (mu + x[j]);
    return 1.0 / (std::sqrt(1 - w) + 0.5 * w * s);
  }
  double moment(int n) const {
    double s = 0;
    for (std::size_t j = 0; j < x.size(); ++j) s += wt[j] * std::pow(x[j], n) * h[j];
    return s;
  }
};

// Integral over the sphere of f(cos theta) by Gauss-Legendre in cos theta, panels graded
// geometrically towards cos = +1 and -1 where a strongly anisotropic phase function peaks.
template <class F>
double sphere_integral_cos(F&& f) {
  const QuadratureRule r = gauss_legendre(16);
  std::vector<double> e{0.0};
  for (double x = 1e-9; x < 1.0; x *= 2) e.push_back(x);
  e.push_back(1.0);
  double sum = 0;
  for (std::size_t p = 0; p + 1 < e.size(); ++p)
    for (std::size_t i = 0; i < r.x.size(); ++i) {
      const double x = e[p] + (e[p + 1] - e[p]) * (r.x[i] + 1) / 2, w = (e[p + 1] - e[p]) / 2 * r.w[i];
      sum += w * 2 * kPi * (f(1 - x) + f(-1 + x));  // the two halves [0, 1] and [-1, 0]
    }
  return sum;
}

// Closed-form CDF of the HG scattering cosine: P(cos <= c) = (1 - g^2) / (2 g) (1 / sqrt(1 + g^2 - 2 g c) - 1 / (1 + g)),
// with 1 + g^2 - 2 g c written as (1 - g)^2 + 2 g (1 - c) to keep precision near the forward peak.
double hg_cdf(double c, double g) {
  const double q = g > 0 ? (1 - g) * (1 - g) + 2 * g * (1 - c) : (1 + g) * (1 + g) - 2 * g * (1 + c);
  return (1 - g) * (1 + g) / (2 * g) * (1 / std::sqrt(q) - 1 / (1 + g));
}
}  // namespace

// sigma_t: after distance d, exactly the attenuation colour a remains; documented limits.
TEST(Volume, AttenuationCoefficient) {
  for (double a : {0.01, 0.3, 0.5, 0.99})
    for (double d : {1e-3, 0.5, 2.0, 100.0}) {
      const Rgb tr = volume_transmittance(volume_sigma_t(Rgb(a), d), d);
      EXPECT_NEAR(tr.g, a, 1e-14 * std::max(1.0, a));
    }
  EXPECT_NEAR(volume_sigma_t(0.5, 2.0), std::log(2.0) / 2, 1e-16);
  EXPECT_EQ(volume_sigma_t(0.5, kInf), 0.0);   // d = inf: no attenuation
  EXPECT_EQ(volume_sigma_t(0.0, kInf), 0.0);
  EXPECT_EQ(volume_sigma_t(0.5, 0.0), kInf);   // d = 0: opaque
  EXPECT_EQ(volume_sigma_t(1.0, 0.0), kInf);
  EXPECT_EQ(volume_sigma_t(0.0, 1.0), kInf);   // a = 0: opaque
  EXPECT_EQ(volume_sigma_t(1.0, 1.0), 0.0);    // a = 1: clear
  const Rgb opaque = volume_transmittance(Rgb(kInf), 1e-9), at0 = volume_transmittance(Rgb(kInf), 0.0);
  EXPECT_EQ(opaque.r, 0.0);
  EXPECT_EQ(at0.r, 1.0);
  // Coefficients: sigma_a + sigma_s = sigma_t; opaque channels stay free of NaN.
  const VolumeCoefficients c = volume_coefficients(Rgb(0.2, 1.0, 0.0), 0.5, Rgb(0.5, 0.0, 1.0));
  EXPECT_NEAR(c.sigma_a.r + c.sigma_s.r, c.sigma_t.r, 1e-15);
  EXPECT_NEAR(c.sigma_s.r, c.sigma_t.r * volume_rho_ss(0.5), 1e-15);
  EXPECT_EQ(c.sigma_t.g, 0.0);
  EXPECT_EQ(c.sigma_s.g, 0.0);
  EXPECT_EQ(c.sigma_t.b, kInf);
  EXPECT_EQ(c.sigma_a.b, 0.0);  // rho_ss = 1: inf * 0 = 0
  EXPECT_EQ(c.sigma_s.b, kInf);
}

// rho_ss(rho_ms): limits, monotonicity, and its physical meaning: it inverts the bihemispherical
// albedo A = 1 - 2 sqrt(1 - rho_ss) Integral H(mu) mu dmu of a semi-infinite, index-matched,
// isotropically scattering medium (max deviation 0.002, see docs/components.md).
TEST(Volume, SingleScatteringAlbedo) {
  EXPECT_EQ(volume_rho_ss(0.0), 0.0);
  EXPECT_NEAR(volume_rho_ss(1.0), 1.0, 1e-9);
  double prev = 0;
  for (int i = 1; i <= 1000; ++i) {
    const double r = volume_rho_ss(i / 1000.0);
    EXPECT_GT(r, prev);
    EXPECT_LE(r, 1.0);
    prev = r;
  }
  for (double ms : {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.99}) {
    const double ss = volume_rho_ss(ms);
    const HFunction hf(ss);
    // The H solver itself: Integral_0^1 H = (2 / w) (1 - sqrt(1 - w)) (Chandrasekhar eq. V.35).
    EXPECT_NEAR(hf.moment(0), 2 / ss * (1 - std::sqrt(1 - ss)), 1e-9);
    const double albedo = 1 - 2 * std::sqrt(1 - ss) * hf.moment(1);
    EXPECT_NEAR(albedo, ms, 3e-3) << ms;
  }
}

// The spec's form of p (with +2g(v.l)) is our phase function of the scattering cosine -(v.l);
// p is reciprocal.
TEST(Volume, HgMatchesSpecFormAndIsReciprocal) {
  const Vec3 v = normalize(Vec3{0.3, -0.4, 0.8});
  for (double g : {-0.9, -0.3, 0.0, 0.5, 0.95})
    for (const Vec3& l : {normalize(Vec3{0.1, 0.2, -0.9}), normalize(Vec3{-0.5, 0.5, 0.3}), -v, v}) {
      const double spec = (1 - g * g) / (4 * kPi * std::pow(1 + g * g + 2 * g * dot(v, l), 1.5));
      EXPECT_NEAR(hg_phase(v, l, g), spec, 1e-13 * spec);
      EXPECT_EQ(hg_phase(v, l, g), hg_phase(l, v, g));
    }
  // g > 0 is forward scattering: the light continues straight on, l = -v.
  EXPECT_GT(hg_phase(v, -v, 0.5), hg_phase(v, v, 0.5));
}

// p integrates to 1 over the sphere and its mean scattering cosine is g.
TEST(Volume, HgNormalizationAndMeanCosine) {
  for (double g : {-0.999, -0.9, -0.5, -1e-9, 0.0, 1e-9, 0.3, 0.9, 0.999}) {
    EXPECT_NEAR(sphere_integral_cos([&](double c) { return hg_phase_cos(c, g); }), 1.0, 1e-9) << g;
    EXPECT_NEAR(sphere_integral_cos([&](double c) { return c * hg_phase_cos(c, g); }), g, 1e-9) << g;
  }
}

// Sampling: exact inversion of the closed-form CDF; stable at g -> 0 and |g| -> 1; directions
// consistent with the returned pdf; sample mean cosine = g.
TEST(Volume, HgSampling) {
  for (double g : {-0.999, -0.9, -0.5000001, -0.5, -0.2, -1e-6, 1e-6, 0.1, 0.5, 0.5000001, 0.8, 0.999})
    for (int i = 0; i < 200; ++i) {
      const double u = (i + 0.5) / 200;
      const double c = hg_sample_cos(g, u);
      EXPECT_NEAR(hg_cdf(c, g), u, 1e-9) << g << " " << u;
    }
  // At |g| = 1 - 1e-6 the lobe is ~1e-12 wide in cos theta, close to the resolution of a double
  // near 1: the CDF slope is ~1e12, so only ~1e-4 can be asked of any sampler of cos theta.
  for (double g : {-0.999999, 0.999999})
    for (int i = 0; i < 200; ++i) {
      const double u = (i + 0.5) / 200;
      EXPECT_NEAR(hg_cdf(hg_sample_cos(g, u), g), u, 1e-3) << g << " " << u;
    }
  for (int i = 0; i < 100; ++i) {
    const double u = i / 100.0;
    EXPECT_EQ(hg_sample_cos(0.0, u), 2 * u - 1);
    EXPECT_NEAR(hg_sample_cos(1e-12, u), 2 * u - 1, 1e-11);
  }
  const Vec3 v = normalize(Vec3{-0.2, 0.6, 0.7});
  Pcg32 rng(9, 3);
  for (double g : {-0.7, 0.0, 0.4, 0.9}) {
    double mean = 0;
    const int n = 40000;
    for (int s = 0; s < n; ++s) {
      const PhaseSample ps = hg_sample(v, g, rng.next_double(), rng.next_double());
      ASSERT_FALSE(ps.delta);
      EXPECT_NEAR(length(ps.l), 1.0, 1e-12);
      EXPECT_NEAR(ps.pdf, hg_phase(v, ps.l, g), 1e-9 * ps.pdf);
      mean += -dot(v, ps.l);
    }
    // Var(cos) <= 1: 5 sigma.
    EXPECT_NEAR(mean / n, g, 5 / std::sqrt(double(n))) << g;
  }
  // |g| = 1: Dirac in the forward (l = -v) or backward (l = v) direction; eval is 0.
  const PhaseSample fwd = hg_sample(v, 1.0, 0.3, 0.3), back = hg_sample(v, -1.0, 0.3, 0.3);
  EXPECT_TRUE(fwd.delta && back.delta);
  EXPECT_EQ(fwd.l.x, -v.x);
  EXPECT_EQ(back.l.z, v.z);
  EXPECT_EQ(hg_phase(v, -v, 1.0), 0.0);
  // Near-Dirac g stays finite.
  EXPECT_TRUE(std::isfinite(hg_phase(v, -v, 1 - 1e-12)));
  EXPECT_TRUE(std::isfinite(hg_sample(v, 1 - 1e-12, 0.0, 0.1).pdf));
}
