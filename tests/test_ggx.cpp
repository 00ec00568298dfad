// GGX distribution, Smith masking and VNDF sampling against closed forms and quadrature.
#include <gtest/gtest.h>

#include <cmath>

#include "dspbr/constants.h"
#include "dspbr/ggx.h"
#include "dspbr/quadrature.h"
#include "dspbr/rng.h"

using namespace dspbr;

namespace {

Vec3 spherical(double cos_t, double phi) {
  const double s = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
  return {s * std::cos(phi), s * std::sin(phi), cos_t};
}

// Integral over the upper hemisphere of f(w) dw by Gauss-Legendre in (cos theta, phi).
template <class F>
double hemisphere_integral(F&& f, int n_mu, int n_phi) {
  const QuadratureRule r = gauss_legendre(64);
  double sum = 0;
  for (int a = 0; a < n_mu; ++a) {
    const double lo = std::pow(double(a) / n_mu, 2), hi = std::pow(double(a + 1) / n_mu, 2);
    for (size_t i = 0; i < r.x.size(); ++i) {
      // graded in cos theta towards 0 (grazing) is not needed; graded towards 1 where D peaks
      const double mu = 1.0 - (lo + 0.5 * (hi - lo) * (1 + r.x[i]));
      const double wmu = 0.5 * (hi - lo) * r.w[i];
      for (int p = 0; p < n_phi; ++p) {
        const double phi = 2 * kPi * (p + 0.5) / n_phi;
        sum += wmu * (2 * kPi / n_phi) * f(spherical(mu, phi));
      }
    }
  }
  return sum;
}
}  // namespace

// Projected-area normalization: Integral D(h) (h.n) dh = 1 (Heitz 2014, eq. 4).
TEST(Ggx, DistributionIsNormalizedIsotropic) {
  for (double alpha : {0.05, 0.2, 0.5, 1.0}) {
    const double I = hemisphere_integral([&](const Vec3& h) { return ggx_d(h, alpha, alpha) * h.z; }, 64, 64);
    EXPECT_NEAR(I, 1.0, 1e-6) << "alpha " << alpha;
  }
}

TEST(Ggx, DistributionIsNormalizedAnisotropic) {
  for (auto [au, av] : {std::pair{0.3, 0.1}, std::pair{0.8, 0.25}, std::pair{1.0, 0.5}}) {
    const double I = hemisphere_integral([&](const Vec3& h) { return ggx_d(h, au, av) * h.z; }, 64, 512);
    EXPECT_NEAR(I, 1.0, 1e-6) << au << " " << av;
  }
}

// Isotropic closed form of the spec: D = alpha^2 / (pi ((h.n)^2 (alpha^2 - 1) + 1)^2).
TEST(Ggx, IsotropicDistributionMatchesSimplifiedForm) {
  for (double alpha : {0.1, 0.5, 0.9})
    for (double c : {0.1, 0.5, 0.99}) {
      const double a2 = alpha * alpha, t = c * c * (a2 - 1) + 1;
      EXPECT_NEAR(ggx_d(spherical(c, 0.7), alpha, alpha), a2 / (kPi * t * t), 1e-12);
    }
}

// Lambda by hand: alpha = 0.5, theta = 60 deg: 1/a^2 = 0.25 * 3 = 0.75,
// Lambda = (-1 + sqrt(1.75)) / 2 = 0.161437...
TEST(Ggx, LambdaHandComputed) {
  const Vec3 w = spherical(0.5, 1.1);
  EXPECT_NEAR(smith_lambda(w, 0.5, 0.5), (-1 + std::sqrt(1.75)) / 2, 1e-14);
  EXPECT_NEAR(ggx_g1(w, Vec3{0, 0, 1}, 0.5, 0.5), 1.0 / (1 + (-1 + std::sqrt(1.75)) / 2), 1e-14);
  EXPECT_EQ(smith_lambda(Vec3{0, 0, 1}, 0.5, 0.5), 0.0);
}

// Smith's visible-area identity: Integral G1(w,h) max(0, w.h) D(h) dh = w.z (Heitz 2014, eq. 11).
TEST(Ggx, VisibleProjectedAreaEqualsCosine) {
  for (double alpha : {0.1, 0.6})
    for (double c : {0.2, 0.7}) {
      const Vec3 w = spherical(c, 0.3);
      const double I = hemisphere_integral(
          [&](const Vec3& h) { return ggx_g1(w, h, alpha, alpha) * std::max(0.0, dot(w, h)) * ggx_d(h, alpha, alpha); },
          64, 256);
      EXPECT_NEAR(I, c, 2e-5) << alpha << " " << c;
    }
}

// E_m(mu) -> 1 as r -> 0 away from grazing: single scattering loses no energy on a mirror.
TEST(Ggx, AlbedoTendsToOneForSmoothSurfaces) {
  Pcg32 rng(7);
  for (double mu : {0.3, 0.7, 1.0}) {
    const Vec3 v = spherical(mu, 0);
    const double alpha = 1e-4;
    // weight of VNDF sampling: G2/G1(v); average over samples
    double sum = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const Vec3 h = ggx_sample_vndf(v, alpha, alpha, rng.next_double(), rng.next_double());
      const Vec3 l = reflect(v, h);
      if (l.z <= 0) continue;
      sum += ggx_g2(v, l, h, alpha, alpha) / ggx_g1(v, h, alpha, alpha);
    }
    EXPECT_NEAR(sum / n, 1.0, 1e-6) << mu;
  }
}

// VNDF samples follow D_v: the histogram of h.z matches the pdf integrated by quadrature.
TEST(Ggx, VndfSamplesMatchDensity) {
  const double au = 0.4, av = 0.15;
  const Vec3 v = normalize(Vec3{0.5, -0.3, 0.6});
  Pcg32 rng(11);
  const int n = 400000, bins = 8;
  std::vector<double> hist(bins, 0);
  for (int i = 0; i < n; ++i) {
    const Vec3 h = ggx_sample_vndf(v, au, av, rng.next_double(), rng.next_double());
    hist[std::min(bins - 1, int(h.z * bins))] += 1.0 / n;
  }
  // Expected mass per bin of h.z by quadrature of the VNDF.
  const QuadratureRule r = gauss_legendre(48);
  for (int b = 0; b < bins; ++b) {
    double mass = 0;
    for (size_t i = 0; i < r.x.size(); ++i) {
      const double mu = (b + 0.5 + 0.5 * r.x[i]) / bins;
      for (int p = 0; p < 512; ++p) {
        const Vec3 h = spherical(mu, 2 * kPi * (p + 0.5) / 512);
        mass += 0.5 / bins * r.w[i] * (2 * kPi / 512) * ggx_vndf_pdf(v, h, au, av);
      }
    }
    EXPECT_NEAR(hist[b], mass, 4 * std::sqrt(mass / n) + 1e-4) << "bin " << b;
  }
}

// Reciprocity of the microfacet BRDF.
TEST(Ggx, BrdfIsReciprocal) {
  const Vec3 v = normalize(Vec3{0.2, 0.4, 0.7}), l = normalize(Vec3{-0.5, 0.1, 0.3});
  EXPECT_NEAR(ggx_microfacet_brdf(v, l, 0.3, 0.1), ggx_microfacet_brdf(l, v, 0.3, 0.1), 1e-14);
}
