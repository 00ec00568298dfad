// GgxDistribution (D, Lambda, G1, G2, visible normals, sampling) against closed forms and quadrature.
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
    const double I = hemisphere_integral([&](const Vec3& h) { return GgxDistribution(alpha, alpha).D(h) * h.z; }, 64, 64);
    EXPECT_NEAR(I, 1.0, 1e-6) << "alpha " << alpha;
  }
}

TEST(Ggx, DistributionIsNormalizedAnisotropic) {
  for (auto [au, av] : {std::pair{0.3, 0.1}, std::pair{0.8, 0.25}, std::pair{1.0, 0.5}}) {
    const double I = hemisphere_integral([&](const Vec3& h) { return GgxDistribution(au, av).D(h) * h.z; }, 64, 512);
    EXPECT_NEAR(I, 1.0, 1e-6) << au << " " << av;
  }
}

// Isotropic closed form of the spec: D = alpha^2 / (pi ((h.n)^2 (alpha^2 - 1) + 1)^2).
TEST(Ggx, IsotropicDistributionMatchesSimplifiedForm) {
  for (double alpha : {0.1, 0.5, 0.9})
    for (double c : {0.1, 0.5, 0.99}) {
      const double a2 = alpha * alpha, t = c * c * (a2 - 1) + 1;
      EXPECT_NEAR(GgxDistribution(alpha, alpha).D(spherical(c, 0.7)), a2 / (kPi * t * t), 1e-12);
    }
}

// Lambda by hand: alpha = 0.5, theta = 60 deg: 1/a^2 = 0.25 * 3 = 0.75,
// Lambda = (-1 + sqrt(1.75)) / 2 = 0.161437...
TEST(Ggx, LambdaHandComputed) {
  const Vec3 w = spherical(0.5, 1.1);
  const GgxDistribution ggx(0.5, 0.5);
  EXPECT_NEAR(ggx.Lambda(w), (-1 + std::sqrt(1.75)) / 2, 1e-14);
  EXPECT_NEAR(ggx.G1(w), 1.0 / (1 + (-1 + std::sqrt(1.75)) / 2), 1e-14);
  EXPECT_EQ(ggx.Lambda(Vec3{0, 0, 1}), 0.0);
}

// Smith's visible-area identity: Integral G1(w,h) max(0, w.h) D(h) dh = w.z (Heitz 2014, eq. 11).
TEST(Ggx, VisibleProjectedAreaEqualsCosine) {
  for (double alpha : {0.1, 0.6})
    for (double c : {0.2, 0.7}) {
      const GgxDistribution ggx(alpha, alpha);
      const Vec3 w = spherical(c, 0.3);
      const double I = hemisphere_integral(
          [&](const Vec3& h) { return ggx.G1(w) * std::max(0.0, dot(w, h)) * ggx.D(h); },
          64, 256);
      EXPECT_NEAR(I, c, 2e-5) << alpha << " " << c;
    }
}

// E_m(mu) -> 1 as r -> 0 away from grazing: single scattering loses no energy on a mirror.
TEST(Ggx, AlbedoTendsToOneForSmoothSurfaces) {
  Pcg32 rng(7);
  for (double mu : {0.3, 0.7, 1.0}) {
    const Vec3 v = spherical(mu, 0);
    const GgxDistribution ggx(1e-4, 1e-4);
    // weight of VNDF sampling: G2/G1(v); average over samples
    double sum = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const Vec3 h = ggx.Sample_wm(v, rng.next_double(), rng.next_double());
      const Vec3 l = reflect(v, h);
      if (l.z <= 0) continue;
      sum += ggx.G2(v, l) / ggx.G1(v);
    }
    EXPECT_NEAR(sum / n, 1.0, 1e-6) << mu;
  }
}

// VNDF samples follow D_v: the histogram of h.z matches the pdf integrated by quadrature.
TEST(Ggx, VndfSamplesMatchDensity) {
  const GgxDistribution ggx(0.4, 0.15);
  const Vec3 v = normalize(Vec3{0.5, -0.3, 0.6});
  Pcg32 rng(11);
  const int n = 400000, bins = 8;
  std::vector<double> hist(bins, 0);
  for (int i = 0; i < n; ++i) {
    const Vec3 h = ggx.Sample_wm(v, rng.next_double(), rng.next_double());
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
        mass += 0.5 / bins * r.w[i] * (2 * kPi / 512) * ggx.PDF(v, h);
      }
    }
    EXPECT_NEAR(hist[b], mass, 4 * std::sqrt(mass / n) + 1e-4) << "bin " << b;
  }
}

// Reciprocity of the microfacet BRDF.
TEST(Ggx, BrdfIsReciprocal) {
  const Vec3 v = normalize(Vec3{0.2, 0.4, 0.7}), l = normalize(Vec3{-0.5, 0.1, 0.3});
  const GgxDistribution ggx(0.3, 0.1);
  EXPECT_NEAR(ggx.M_r(v, l), ggx.M_r(l, v), 1e-14);
}

// G2 and G1 at known angles (alpha = 0.5): theta = 60 deg gives 1/a^2 = 0.25 * 3, theta = 45 deg
// gives 1/a^2 = 0.25, so Lambda = (-1 + sqrt(1.75)) / 2 and (-1 + sqrt(1.25)) / 2 (Heitz 2014, eq. 99).
TEST(Ggx, HeightCorrelatedG2HandComputed) {
  const GgxDistribution ggx(0.5, 0.5);
  const Vec3 wo = spherical(0.5, 1.1), wi = spherical(std::sqrt(0.5), -2.0);
  const double lo = (-1 + std::sqrt(1.75)) / 2, li = (-1 + std::sqrt(1.25)) / 2;
  EXPECT_NEAR(ggx.G2(wo, wi), 1.0 / (1 + lo + li), 1e-14);
  EXPECT_NEAR(ggx.G1(wi), 1.0 / (1 + li), 1e-14);
  EXPECT_EQ(ggx.G2(wo, Vec3{1, 0, 0}), 0.0);  // grazing: Lambda = +inf
}

// The correlated visibility form of Heitz 2014 eq. 99 for GGX, written without Lambda:
// G2 = 2 |o.n| |i.n| / (|i.n| sqrt(A(o)) + |o.n| sqrt(A(i))), A(w) = (w.n)^2 + (w.t a_u)^2 + (w.b a_v)^2;
// the same at every pair of directions, anisotropic and below the surface (transmission uses |cos|).
TEST(Ggx, G2MatchesTheVisibilityForm) {
  Pcg32 rng(3);
  for (auto [au, av] : {std::pair{0.3, 0.3}, std::pair{0.7, 0.05}, std::pair{0.02, 0.9}}) {
    const GgxDistribution ggx(au, av);
    auto A = [&](const Vec3& w) { return w.z * w.z + w.x * au * w.x * au + w.y * av * w.y * av; };
    for (int i = 0; i < 200; ++i) {
      const Vec3 wo = spherical(0.01 + 0.99 * rng.next_double(), 2 * kPi * rng.next_double());
      const Vec3 wi = spherical((i % 2 ? 1 : -1) * (0.01 + 0.99 * rng.next_double()), 2 * kPi * rng.next_double());
      const double co = std::abs(wo.z), ci = std::abs(wi.z);
      const double ref = 2 * co * ci / (ci * std::sqrt(A(wo)) + co * std::sqrt(A(wi)));
      EXPECT_NEAR(ggx.G2(wo, wi), ref, 1e-13 * ref) << au << " " << av;
    }
  }
}

// Isotropic vs anisotropic: Lambda at azimuth phi is the isotropic Lambda of the projected
// roughness alpha_phi = sqrt(cos^2 phi a_u^2 + sin^2 phi a_v^2) (Heitz 2014, section 5.4), and along
// the axes D equals the isotropic D of that axis' alpha times the ratio of the normalisations
// (D(h) pi a_u a_v depends on h.t / a_u only in the t-n plane).
TEST(Ggx, AnisotropicReducesToIsotropicAlongAzimuths) {
  const double au = 0.6, av = 0.15;
  const GgxDistribution aniso(au, av);
  for (double c : {0.2, 0.5, 0.9})
    for (double phi : {0.0, 0.4, kPi / 2, 2.5}) {
      const double a_phi = std::sqrt(std::cos(phi) * std::cos(phi) * au * au + std::sin(phi) * std::sin(phi) * av * av);
      const Vec3 w = spherical(c, phi);
      EXPECT_NEAR(aniso.Lambda(w), GgxDistribution(a_phi, a_phi).Lambda(w), 1e-14) << c << " " << phi;
    }
  for (double c : {0.3, 0.8, 0.99}) {
    const Vec3 ht = spherical(c, 0.0), hb = spherical(c, kPi / 2);
    EXPECT_NEAR(aniso.D(ht) * au * av, GgxDistribution(au, au).D(ht) * au * au, 1e-12 * aniso.D(ht) * au * av);
    EXPECT_NEAR(aniso.D(hb) * au * av, GgxDistribution(av, av).D(hb) * av * av, 1e-12 * aniso.D(hb) * au * av);
  }
}

// The visible-normal density is a density: Integral D(w, w_m) dw_m = 1 for any w above the
// surface (Heitz 2018, eq. 1 with Heitz 2014 eq. 11), anisotropic, by quadrature.
TEST(Ggx, VisibleNormalDensityIntegratesToOne) {
  for (auto [au, av] : {std::pair{0.4, 0.15}, std::pair{0.9, 0.5}})
    for (double c : {0.15, 0.6, 1.0}) {
      const GgxDistribution ggx(au, av);
      const Vec3 w = spherical(c, 0.8);
      const double I = hemisphere_integral([&](const Vec3& wm) { return ggx.D(w, wm); }, 64, 512);
      EXPECT_NEAR(I, 1.0, 2e-5) << au << " " << av << " " << c;
      EXPECT_EQ(ggx.PDF(w, w), ggx.D(w, w));
    }
}

// The one clamp: below kDeltaAlpha (both axes) the distribution is a mirror and keeps its alphas
// (alpha = 0: no masking, every sampled normal is n); a rough one raises a vanishing axis to
// kMinAlpha, so D stays finite (D(n) = 1 / (pi a_u a_v)).
TEST(Ggx, SmoothLimitAndTheMinimumAlpha) {
  const GgxDistribution mirror(0, 0);
  EXPECT_TRUE(mirror.effectively_smooth());
  EXPECT_EQ(mirror.alpha_u(), 0.0);
  const Vec3 w = spherical(0.3, 1.0);
  EXPECT_EQ(mirror.G1(w), 1.0);
  EXPECT_EQ(mirror.G2(w, spherical(0.6, -2.0)), 1.0);
  const Vec3 h = mirror.Sample_wm(w, 0.37, 0.81);
  EXPECT_EQ(h.x, 0.0);
  EXPECT_EQ(h.y, 0.0);
  EXPECT_EQ(h.z, 1.0);
  EXPECT_TRUE(GgxDistribution(0.5 * kDeltaAlpha, 0.9 * kDeltaAlpha).effectively_smooth());
  const GgxDistribution line(0.3, 0.0);
  EXPECT_FALSE(line.effectively_smooth());
  EXPECT_EQ(line.alpha_u(), 0.3);
  EXPECT_EQ(line.alpha_v(), kMinAlpha);
  EXPECT_NEAR(line.D(Vec3{0, 0, 1}), 1.0 / (kPi * 0.3 * kMinAlpha), 1e-6 / (kPi * 0.3 * kMinAlpha));
}
