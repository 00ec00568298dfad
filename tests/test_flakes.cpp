// Flakes against independent numbers: closed forms of the cone, quadrature of the GGX density
// (GgxDistribution::D), a brute-force Voronoi search, binomial bounds on the coverage, hand-computed mappings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dspbr/bsdf/flakes.h"
#include "dspbr/constants.h"
#include "dspbr/ggx.h"
#include "dspbr/quadrature.h"
#include "dspbr/rng.h"

using namespace dspbr;

namespace {

// Fraction of the projected area of flakes with h.z > mu: Integral over {cos > mu} of D(h) h.z dh,
// by Gauss-Legendre in cos theta (isotropic: the phi integral is 2 pi).
double ggx_projected_cdf_above(double mu, double alpha) {
  const QuadratureRule r = gauss_legendre(32);
  // Substitution c = 1 - t^2 concentrates nodes near c = 1 where D peaks for small alpha.
  const double tmax = std::sqrt(1.0 - mu);
  return integrate_gl([&](double t) {
    const double c = 1.0 - t * t;
    const Vec3 h{std::sqrt(std::max(0.0, 1 - c * c)), 0, c};
    return 2 * kPi * GgxDistribution(alpha, alpha).D(h) * c * 2 * t;
  }, 0.0, tmax, 16, r);
}

// Kolmogorov-Smirnov statistic of samples of cos theta against the exact CDF above.
double ks_statistic(std::vector<double> cosines, double alpha) {
  std::sort(cosines.begin(), cosines.end());
  const double n = double(cosines.size());
  double ks = 0;
  for (std::size_t i = 0; i < cosines.size(); i += 20) {  // every 20th point is plenty
    const double cdf = 1.0 - ggx_projected_cdf_above(cosines[i], alpha);  // P(cos <= c)
    ks = std::max({ks, std::abs(cdf - i / n), std::abs(cdf - (i + 1) / n)});
  }
  return ks;
}

// Deterministic quasi-uniform directions on the sphere (Fibonacci lattice).
Vec3 fibonacci_sphere(int i, int n) {
  const double golden = (1 + std::sqrt(5.0)) / 2;
  const double z = 1 - (2 * i + 1.0) / n;
  const double phi = 2 * kPi * i / golden;
  const double s = std::sqrt(std::max(0.0, 1 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}
}  // namespace

// Omega(cos 7deg) / (4 pi - Omega(cos 7deg)) = tan^2(3.5 deg): above r_f = sqrt(2) tan(3.5 deg) the cone
// half-angle is exactly the 7 deg target; below, alpha_cone = alpha_ggx = r_f / sqrt(2).
TEST(Flakes, ConeAndOrientationRoughness) {
  const double t = std::tan(3.5 * kPi / 180);
  for (double r : {0.1, 0.25, 0.5, 1.0}) {
    EXPECT_NEAR(flake_alpha_cone(r), t, 1e-15);
    EXPECT_NEAR(flake_cos_cone(r), std::cos(7 * kPi / 180), 1e-15);
    EXPECT_NEAR(flake_alpha_ggx(r), std::sqrt(r * r - t * t), 1e-15);
  }
  for (double r : {1e-6, 0.01, 0.05, 0.08}) {
    EXPECT_NEAR(flake_alpha_cone(r), r / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(flake_alpha_ggx(r), r / std::sqrt(2.0), 1e-15);
    // half-angle of the cone = 2 atan(alpha_cone)
    EXPECT_NEAR(std::acos(flake_cos_cone(r)), 2 * std::atan(r / std::sqrt(2.0)), 1e-7 * r + 1e-9);
  }
  EXPECT_EQ(flake_alpha_cone(0.0), 0.0);
  EXPECT_EQ(flake_alpha_ggx(0.0), 0.0);
  EXPECT_EQ(flake_cos_cone(0.0), 1.0);
  EXPECT_TRUE(flake_cone_is_delta(flake_cos_cone(0.0)));
  EXPECT_FALSE(flake_cone_is_delta(flake_cos_cone(1e-4)));
}

// N = 1 / (3 sqrt(3) / 2 r^2) ~ 1.5396e6 / s_f^2 and res = max(4, ceil(sqrt(N / 4))).
TEST(Flakes, CountAndGridResolution) {
  for (double s : {0.01, 0.05, 0.3, 2.0}) EXPECT_NEAR(flake_count_per_m2(s) * s * s / 1.5396e6, 1.0, 5e-5);
  EXPECT_EQ(flake_grid_res(0.05), 12409);  // N = 6.15840e8, sqrt(N / 4) = 12408.1
  EXPECT_EQ(flake_grid_res(1.0), 621);     // N = 1.53960e6, sqrt(N / 4) = 620.4
  EXPECT_EQ(flake_grid_res(1000.0), 4);    // N = 1.54 per m^2: the floor of 4 cells
  EXPECT_EQ(flake_grid_res(std::numeric_limits<double>::infinity()), 4);
  EXPECT_EQ(flake_count_per_m2(0.0), 0.0);
  const Flake none = flake_at({0.1, 0.2, 0.3}, {0, 0, 1}, 1.0, 0.0, 0.5);
  EXPECT_EQ(none.opacity, 0.0);
  EXPECT_EQ(none.index, -1);
  EXPECT_EQ(flake_at({std::nan(""), 0.2, 0.3}, {0, 0, 1}, 1.0, 0.05, 0.5).index, -1);
}

TEST(Flakes, TriplanarMapping) {
  // z dominant: (frac(sgn(p_z) p_x + 1/2), frac(p_y + 1/2)).
  FlakeUv a = flake_triplanar_uv({0.25, 0.125, -2.0}, {0.1, 0.2, -0.9});
  EXPECT_DOUBLE_EQ(a.u, 0.25);   // frac(-0.25 + 0.5)
  EXPECT_DOUBLE_EQ(a.v, 0.625);
  // x dominant: (frac(sgn(p_x) p_y + 1/2), frac(p_z + 1/2)).
  FlakeUv b = flake_triplanar_uv({-1.0, 0.125, 0.75}, {-0.9, 0.1, 0.2});
  EXPECT_DOUBLE_EQ(b.u, 0.375);  // frac(-0.125 + 0.5)
  EXPECT_DOUBLE_EQ(b.v, 0.25);   // frac(1.25)
  // y dominant: (frac(-sgn(p_y) p_x + 1/2), frac(p_z + 1/2)).
  FlakeUv c = flake_triplanar_uv({0.125, 3.0, -0.75}, {0.1, 0.9, 0.2});
  EXPECT_DOUBLE_EQ(c.u, 0.375);  // frac(-0.125 + 0.5)
  EXPECT_DOUBLE_EQ(c.v, 0.75);   // frac(-0.25)
  FlakeUv d = flake_triplanar_uv({-1e-18, 0.0, 0.0}, {0, 0, 1});
  EXPECT_LT(d.u, 1.0);  // frac never returns 1
}

// The flake found is the Voronoi-nearest of all flakes: brute force over a 9x9 block of cells
// (periodic images included), using the documented per-cell PRNG Pcg32(i mod res, j mod res).
TEST(Flakes, NearestFlakeMatchesBruteForce) {
  Pcg32 rng(7, 1);
  for (double s_f : {1000.0, 0.3}) {  // res = 4 (wrapping, periodic images) and res = 2073
    const int64_t res = flake_grid_res(s_f);
    for (int trial = 0; trial < 400; ++trial) {
      const Vec3 p{rng.next_double() * 3 - 1.5, rng.next_double() * 3 - 1.5, 0.2};
      const Flake fl = flake_at(p, {0, 0, 1}, 0.5, s_f, 0.3);
      const FlakeUv uv = flake_triplanar_uv(p, {0, 0, 1});
      const double gx = uv.u * res, gy = uv.v * res;
      const int64_t i = int64_t(gx), j = int64_t(gy);
      double best = 1e300;
      int64_t bi = -1, bj = -1;
      int bk = -1;
      for (int64_t ii = i - 4; ii <= i + 4; ++ii)
        for (int64_t jj = j - 4; jj <= j + 4; ++jj) {
          const int64_t wi = ((ii % res) + res) % res, wj = ((jj % res) + res) % res;
          Pcg32 cell{uint64_t(wi), uint64_t(wj)};
          for (int k = 0; k < kFlakesPerCell; ++k) {
            double xi[5];
            for (double& x : xi) x = cell.next_double();
            const double d = std::hypot(gx - (ii + xi[0]), gy - (jj + xi[1]));
            if (d < best) best = d, bi = wi, bj = wj, bk = k;
          }
        }
      EXPECT_EQ(fl.cell_i, bi);
      EXPECT_EQ(fl.cell_j, bj);
      EXPECT_EQ(fl.index, bk);
    }
  }
}

// Determinism and seamless tiling: the same point gives the same flake bit for bit; points on
// either side of the texture seam u = 0 = 1 see the same flake.
TEST(Flakes, DeterministicAndSeamless) {
  const Vec3 p{0.123456, -0.654321, 0.0};
  const Flake a = flake_at(p, {0, 0, 1}, 0.7, 0.05, 0.4), b = flake_at(p, {0, 0, 1}, 0.7, 0.05, 0.4);
  EXPECT_EQ(a.opacity, b.opacity);
  EXPECT_EQ(a.normal.x, b.normal.x);
  EXPECT_EQ(a.normal.z, b.normal.z);
  EXPECT_EQ(a.cell_i, b.cell_i);
  for (double s_f : {1000.0, 0.05}) {
    // p_x = 0.5 maps to u = frac(1) = 0: the seam.
    const Flake l = flake_at({0.5 - 1e-12, 0.3, 1.0}, {0, 0, 1}, 0.5, s_f, 0.2);
    const Flake r = flake_at({0.5 + 1e-12, 0.3, 1.0}, {0, 0, 1}, 0.5, s_f, 0.2);
    EXPECT_EQ(l.cell_i, r.cell_i);
    EXPECT_EQ(l.cell_j, r.cell_j);
    EXPECT_EQ(l.index, r.index);
  }
}

// Coverage: the fraction of the surface covered by opaque flakes is f (binomial, 4.5 sigma).
TEST(Flakes, CoverageFraction) {
  Pcg32 rng(11, 2);
  const int n = 20000;
  for (double f : {0.0, 0.1, 0.5, 0.9, 1.0}) {
    int opaque = 0;
    for (int s = 0; s < n; ++s) {
      const Vec3 p{rng.next_double(), rng.next_double(), 0.0};
      opaque += flake_at(p, {0, 0, 1}, f, 0.05, 0.3).opacity > 0;
    }
    const double frac = double(opaque) / n, sigma = std::sqrt(f * (1 - f) / n);
    EXPECT_NEAR(frac, f, 4.5 * sigma + 1e-12) << f;
  }
}

// Flake normals follow D(h) (h.n) of GGX with alpha_ggx: directly from K and through the texture.
TEST(Flakes, NormalsFollowGgx) {
  Pcg32 rng(3, 4);
  for (double r_f : {0.1, 0.4, 1.0}) {
    const double alpha = flake_alpha_ggx(r_f);
    std::vector<double> direct, texture;
    for (int s = 0; s < 20000; ++s) {
      const Vec3 h = flake_normal_sample(alpha, rng.next_double(), rng.next_double());
      EXPECT_NEAR(length(h), 1.0, 1e-12);
      direct.push_back(h.z);
      const Vec3 p{rng.next_double(), rng.next_double(), 0.0};
      texture.push_back(flake_at(p, {0, 0, 1}, 1.0, 0.05, r_f).normal.z);
    }
    // KS critical value at the 0.1% level: 1.95 / sqrt(n).
    EXPECT_LT(ks_statistic(direct, alpha), 1.95 / std::sqrt(20000.0)) << r_f;
    EXPECT_LT(ks_statistic(texture, alpha), 1.95 / std::sqrt(20000.0)) << r_f;
  }
  // The density is normalized: Integral of flake_normal_pdf over the hemisphere = 1.
  EXPECT_NEAR(ggx_projected_cdf_above(0.0, 0.3), 1.0, 1e-9);
  // alpha = 0: every flake is parallel to the surface.
  const Vec3 flat = flake_normal_sample(0.0, 0.7, 0.2);
  EXPECT_EQ(flat.z, 1.0);
}

// Cone BSDF: 1 / Omega inside the cone around the mirror direction, 0 outside; its integral over
// the sphere is 1 (Fibonacci-lattice quadrature of the whole sphere); sampling matches it.
TEST(Flakes, ConeBsdfIntegratesToOneAndSamplingMatches) {
  const Vec3 v = normalize(Vec3{0.3, -0.2, 0.9});
  const Vec3 n_f = normalize(Vec3{0.1, 0.05, 1.0});
  for (double r_f : {0.05, 0.3}) {
    const double c = flake_cos_cone(r_f);
    const int n = 2000000;
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += flake_cone_bsdf(v, fibonacci_sphere(i, n), n_f, c);
    EXPECT_NEAR(sum * 4 * kPi / n, 1.0, 3e-3) << r_f;  // >= 2400 lattice points in the cone
    // Inside / outside the cone boundary, mirror direction computed independently.
    const Vec3 r = n_f * (2 * dot(v, n_f)) - v;
    const Vec3 perp = normalize(cross(r, Vec3{0, 0, 1}));
    const double th = std::acos(c);
    auto at = [&](double a) { return r * std::cos(a) + cross(perp, r) * std::sin(a); };
    EXPECT_NEAR(flake_cone_bsdf(v, at(0.999 * th), n_f, c) * 2 * kPi * (1 - c), 1.0, 1e-12);
    EXPECT_EQ(flake_cone_bsdf(v, at(1.001 * th), n_f, c), 0.0);
    // Samples: all inside, pdf = B_f, mean cosine to r = (1 + cos theta_cone) / 2 (uniform cap).
    Pcg32 rng(5, 6);
    double mean = 0;
    const int m = 20000;
    for (int s = 0; s < m; ++s) {
      const FlakeConeSample fs = flake_cone_sample(v, n_f, c, rng.next_double(), rng.next_double());
      ASSERT_TRUE(fs.valid && !fs.delta);
      EXPECT_NEAR(length(fs.l), 1.0, 1e-12);
      EXPECT_NEAR(fs.pdf, 1.0 / (2 * kPi * (1 - c)), 1e-9 / (1 - c));
      mean += dot(fs.l, r);
    }
    // Variance of cos over the cap is (1 - c)^2 / 12; 5 sigma.
    EXPECT_NEAR(mean / m, 0.5 * (1 + c), 5 * (1 - c) / std::sqrt(12.0 * m));
  }
  // Flake facing away from the viewer: invisible.
  EXPECT_EQ(flake_cone_bsdf(v, v, Vec3{0, 0, -1}, 0.99), 0.0);
  EXPECT_FALSE(flake_cone_sample(v, Vec3{0, 0, -1}, 0.99, 0.5, 0.5).valid);
  // Mirror flake (r_f = 0): a delta lobe along the reflection.
  const FlakeConeSample d = flake_cone_sample(v, n_f, flake_cos_cone(0.0), 0.3, 0.6);
  EXPECT_TRUE(d.valid && d.delta);
  const Vec3 r = n_f * (2 * dot(v, n_f)) - v;
  EXPECT_NEAR(d.l.x, r.x, 1e-15);
  EXPECT_NEAR(d.l.z, r.z, 1e-15);
  EXPECT_EQ(flake_cone_bsdf(v, r, n_f, 1.0), 0.0);
}

TEST(Flakes, FlipFlopTint) {
  const Rgb rho_f(0.8, 0.2, 0.1), rho_ff(0.1, 0.3, 0.9);
  const Vec3 v = normalize(Vec3{0.5, 0.0, 0.8}), l = normalize(Vec3{-0.6, 0.3, 0.7});
  const Vec3 h = normalize(v + l);
  // f_f = 0: no flip-flop; f_f = 1: linear in v.h; f_f = 0.5: (v.h)^4.
  const Rgb a = flake_flip_flop_tint(v, l, rho_f, 0.0, rho_ff);
  EXPECT_EQ(a.r, rho_f.r);
  EXPECT_EQ(a.b, rho_f.b);
  const double vh = dot(v, h);
  const Rgb b = flake_flip_flop_tint(v, l, rho_f, 1.0, rho_ff);
  EXPECT_NEAR(b.g, 0.2 + 0.1 * vh, 1e-15);
  const Rgb c = flake_flip_flop_tint(v, l, rho_f, 0.5, rho_ff);
  EXPECT_NEAR(c.b, 0.1 + 0.8 * std::pow(vh, 4), 1e-15);
  // Reciprocal (v.h_r = l.h_r); at v = l (retro-reflection) the flip-flop colour is reached.
  const Rgb cs = flake_flip_flop_tint(l, v, rho_f, 0.5, rho_ff);
  EXPECT_NEAR(cs.b, c.b, 1e-15);
  const Rgb full = flake_flip_flop_tint(v, v, rho_f, 0.3, rho_ff);
  EXPECT_NEAR(full.r, rho_ff.r, 1e-15);
  // Opposite directions (h undefined): flake colour, finite.
  const Rgb opp = flake_flip_flop_tint(v, -v, rho_f, 0.3, rho_ff);
  EXPECT_EQ(opp.r, rho_f.r);
}
