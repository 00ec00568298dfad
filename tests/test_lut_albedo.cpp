// The LUT integrators (src/dspbr/lutgen/albedo.h, qmc.h) against independent Gauss-Legendre
// quadrature of the defining integrals (tests/test_lut_reference.h), limits and identities.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>

#include "dspbr/constants.h"
#include "dspbr/lutgen/albedo.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/lutgen/qmc.h"
#include "test_lut_reference.h"

using namespace dspbr;

namespace {

IntegratorSettings qmc_default() {
  IntegratorSettings s;
  s.samples = 8 << 16;
  s.target_error = 1e-5;
  return s;
}

// Reference E_m (or the Fresnel-weighted integral) with a self-convergence check: the rule with
// doubled panels must agree, so the reference is trustworthy where it is used.
double ggx_reference(double mu, double r, double f0) {
  // light domain for rough lobes (fewer panels suffice above r = 0.5), half-vector domain for
  // sharp ones
  const bool rough = r >= 0.3;
  const int n = r >= 0.5 ? 24 : 64;
  const double a = rough ? lutref::ggx_albedo_quad_l(mu, r, f0, n, n) : lutref::ggx_albedo_quad(mu, r, f0, 64, 32);
  const double b = rough ? lutref::ggx_albedo_quad_l(mu, r, f0, 2 * n, 2 * n) : lutref::ggx_albedo_quad(mu, r, f0, 128, 64);
  EXPECT_NEAR(a, b, 1e-6) << "reference quadrature not converged at mu " << mu << " r " << r;
  return b;
}

}  // namespace

// The unscrambled points form (0, m, 2)-nets in dimensions (0, 1): every elementary interval of
// area 2^-m holds exactly one of the first 2^m points. Nested scrambling keeps that property.
TEST(LutQmc, SobolAndScrambledSobolAreNets) {
  const int m = 8;
  const uint32_t n = 1u << m;
  const ScrambledSobol scrambled(42);
  for (int variant = 0; variant < 2; ++variant)
    for (int kx = 0; kx <= m; ++kx) {
      std::set<std::pair<uint32_t, uint32_t>> cells;
      for (uint32_t i = 0; i < n; ++i) {
        const double x = variant ? scrambled.sample(i, 0) : ScrambledSobol::sobol_bits(i, 0) * 0x1.0p-32;
        const double y = variant ? scrambled.sample(i, 1) : ScrambledSobol::sobol_bits(i, 1) * 0x1.0p-32;
        cells.insert({uint32_t(x * (1u << kx)), uint32_t(y * (1u << (m - kx)))});
      }
      EXPECT_EQ(cells.size(), n) << "variant " << variant << " kx " << kx;
    }
  // Each of the four dimensions is a (0,1)-sequence: stratified in 1D.
  for (int d = 0; d < ScrambledSobol::kMaxDims; ++d) {
    std::set<uint32_t> cells;
    for (uint32_t i = 0; i < n; ++i) cells.insert(uint32_t(scrambled.sample(i, d) * n));
    EXPECT_EQ(cells.size(), n) << "dim " << d;
  }
}

// Scrambled points are uniform: the mean of many independent scramblings of one point is 1/2.
TEST(LutQmc, ScrambledPointsAreUniform) {
  for (uint32_t index : {0u, 1u, 77u}) {
    double sum = 0, sum2 = 0;
    const int n = 20000;
    for (int s = 0; s < n; ++s) {
      const double u = ScrambledSobol(uint64_t(s) + 1).sample(index, 2);
      sum += u;
      sum2 += u * u;
    }
    EXPECT_NEAR(sum / n, 0.5, 5 * std::sqrt(1.0 / 12 / n));
    EXPECT_NEAR(sum2 / n, 1.0 / 3.0, 5 * std::sqrt(4.0 / 45 / n));
  }
}

// Default QMC settings meet 1e-4 against quadrature, and the error estimate is honest.
TEST(LutAlbedo, GgxDirectionalAlbedoMatchesQuadrature) {
  const IntegratorSettings s = qmc_default();
  const double cells[][2] = {{1.0 / 64, 1.0 / 64}, {1.0 / 64, 0.5}, {0.11, 0.17}, {0.109, 0.984},
                             {0.39, 0.33},         {0.64, 1.0 / 64}, {0.98, 0.05}, {0.98, 0.98}};
  for (const auto& c : cells) {
    const double r = c[0], mu = c[1];
    const double ref = ggx_reference(mu, r, 1.0);
    const Estimate e = ggx_E(mu, r, s, 11);
    EXPECT_NEAR(e.value, ref, 1e-4) << "r " << r << " mu " << mu;
    // 1e-6 floor: the VNDF tail beyond the horizon has probability ~1e-7 at the smallest r, below
    // what any replicate resolves, so the spread cannot see it.
    EXPECT_NEAR(e.value, ref, 6 * e.error + 1e-6) << "error estimate too small at r " << r << " mu " << mu;
  }
}

TEST(LutAlbedo, PlainMonteCarloBaselineMatchesQuadrature) {
  IntegratorSettings s;
  s.integrator = Integrator::Mc;
  s.samples = 8 << 15;
  for (auto [r, mu] : {std::pair{0.7, 0.4}, std::pair{1.0, 0.9}}) {
    const Estimate e = ggx_E(mu, r, s, 3);
    EXPECT_NEAR(e.value, ggx_reference(mu, r, 1.0), 6 * e.error) << r << " " << mu;
  }
  const auto brdf = [](const Vec3& v, const Vec3& l) { return sheen_brdf(v, l, 0.5); };
  const Estimate e = sheen_E(0.3, 0.5, SheenModel::Main, s, 3);
  EXPECT_NEAR(e.value, lutref::sheen_albedo_quad(0.3, brdf), 6 * e.error);
}

TEST(LutAlbedo, SheenDirectionalAlbedosMatchQuadrature) {
  const IntegratorSettings s = qmc_default();
  for (double ab : {1.0 / 32, 0.2, 0.6, 0.97})
    for (double mu : {1.0 / 32, 0.3, 0.97}) {
      const auto main = [&](const Vec3& v, const Vec3& l) { return sheen_brdf(v, l, ab); };
      const auto ash = [&](const Vec3& v, const Vec3& l) { return sheen_brdf_ash(v, l, ab); };
      const double ref_main = lutref::sheen_albedo_quad(mu, main, 64, 32);
      const double ref_ash = lutref::sheen_albedo_quad(mu, ash, 64, 32);
      EXPECT_NEAR(ref_main, lutref::sheen_albedo_quad(mu, main, 32, 16), 1e-6);
      EXPECT_NEAR(ref_ash, lutref::sheen_albedo_quad(mu, ash, 32, 16), 1e-6);
      const Estimate em = sheen_E(mu, ab, SheenModel::Main, s, 5);
      const Estimate ea = sheen_E(mu, ab, SheenModel::Ash, s, 5);
      EXPECT_NEAR(em.value, ref_main, 1e-4) << "main ab " << ab << " mu " << mu;
      EXPECT_NEAR(ea.value, ref_ash, 1e-4) << "ash ab " << ab << " mu " << mu;
      EXPECT_NEAR(em.value, ref_main, 6 * em.error + 1e-6);
      EXPECT_NEAR(ea.value, ref_ash, 6 * ea.error + 1e-6);
    }
}

// E_m -> 1 as r -> 0 away from grazing (the mirror loses no energy); r = 0 is exact.
TEST(LutAlbedo, GgxAlbedoTendsToOneAsRoughnessVanishes) {
  for (Integrator integ : {Integrator::Qmc, Integrator::Mc}) {
    IntegratorSettings s;
    s.integrator = integ;
    s.samples = 8 << 10;
    for (double mu : {0.2, 0.5, 1.0}) {
      EXPECT_EQ(ggx_E(mu, 0.0, s).value, 1.0);
      if (integ == Integrator::Qmc) {
        EXPECT_NEAR(ggx_E(mu, 1e-3, s).value, 1.0, 1e-6) << mu;
        EXPECT_NEAR(ggx_E(mu, 1e-2, s).value, 1.0, 1e-5) << mu;
      }
    }
    EXPECT_EQ(ggx_E_avg(0.0, s).value, 1.0);
  }
}

// E_m,avg = 2 Integral E_m(mu) mu dmu with E_m itself from quadrature.
TEST(LutAlbedo, GgxAverageAlbedoMatchesItsQuadrature) {
  IntegratorSettings s = qmc_default();
  s.samples = 8 << 18;
  for (double r : {0.45, 0.7, 0.99}) {
    const double ref = lutref::cosine_average([&](double mu) { return lutref::ggx_albedo_quad_l(mu, r, 1.0, 16, 16); });
    const double ref2 =
        lutref::cosine_average([&](double mu) { return lutref::ggx_albedo_quad_l(mu, r, 1.0, 24, 24); }, 32);
    EXPECT_NEAR(ref, ref2, 2e-6) << "reference not converged at r " << r;
    const Estimate e = ggx_E_avg(r, s, 9);
    EXPECT_NEAR(e.value, ref2, 1e-4) << r;
    EXPECT_NEAR(e.value, ref2, 6 * e.error + 2e-6) << r;
  }
}

// E(mu; r, f0) = Integral M_r F mu_l + F_ms (1 - E_m) and its average, against quadrature of
// both terms (E_m,avg of F_ms also from quadrature).
TEST(LutAlbedo, BaseAlbedosMatchQuadrature) {
  const IntegratorSettings s = qmc_default();
  for (auto [r, f0] : {std::pair{0.53, 0.03}, std::pair{0.97, 0.97}, std::pair{0.78, 0.34}}) {
    const double e_avg = lutref::cosine_average([&](double m) { return lutref::ggx_albedo_quad_l(m, r, 1.0, 16, 16); }, 16);
    const double fms = fresnel_ms(f0, 1.0, e_avg);
    for (double mu : {0.1, 0.5, 0.97}) {
      const double ref = ggx_reference(mu, r, f0) + fms * (1.0 - ggx_reference(mu, r, 1.0));
      const Estimate e = base_E(mu, r, f0, s, 21);
      EXPECT_NEAR(e.value, ref, 1e-4) << "r " << r << " f0 " << f0 << " mu " << mu;
      EXPECT_NEAR(e.value, ref, 6 * e.error + 2e-6);
    }
    const double ref_avg = lutref::cosine_average(
        [&](double m) { return lutref::ggx_albedo_quad_l(m, r, f0, 16, 16) + fms * (1.0 - lutref::ggx_albedo_quad_l(m, r, 1.0, 16, 16)); },
        16);
    IntegratorSettings sa = s;
    sa.samples = 8 << 18;
    const Estimate ea = base_E_avg(r, f0, sa, 4);
    EXPECT_NEAR(ea.value, ref_avg, 1e-4) << "avg r " << r << " f0 " << f0;
  }
}

// The closed form used for the multiple-scattering term of Base_E: brute-force quadrature of
// Integral (1 - E_m(mu_v))(1 - E_m(mu_l)) / (pi (1 - E_m,avg)) mu_l dl over the hemisphere, with
// E_m(mu_l) and E_m,avg from the library integrators, equals 1 - E_m(mu_v).
TEST(LutAlbedo, MultipleScatteringLobeIntegratesToOneMinusEm) {
  IntegratorSettings s = qmc_default();
  const double r = 0.8;
  IntegratorSettings sa = s;
  sa.samples = 8 << 18;
  const double e_avg = ggx_E_avg(r, sa, 1).value;
  const double mu_v = 0.4;
  const double e_v = ggx_E(mu_v, r, s, 2).value;
  // The lobe does not depend on phi: 2 pi Integral_0^1 M_ms(mu_l) mu_l dmu_l, 16-point GL panels.
  const QuadratureRule rule = gauss_legendre(16);
  uint64_t stream = 100;
  const double integral = integrate_gl(
      [&](double mu_l) {
        const double e_l = ggx_E(mu_l, r, s, stream++).value;
        const double m_ms = (1 - e_v) * (1 - e_l) / (kPi * (1 - e_avg));
        return 2 * kPi * m_ms * mu_l;
      },
      0.0, 1.0, 4, rule);
  EXPECT_NEAR(integral, 1.0 - e_v, 2e-5 * (1.0 - e_v) / (1.0 - e_avg) + 1e-6);
}

// No NaN, Inf or negative values at the ends of the domain (mu = 0 and 1, r = 0 and 1,
// alpha_b = 0 and 1, f0 = 0 and 1), for both integrators.
TEST(LutAlbedo, FiniteAndNonNegativeAtDomainEnds) {
  for (Integrator integ : {Integrator::Qmc, Integrator::Mc}) {
    IntegratorSettings s;
    s.integrator = integ;
    s.samples = 8 << 8;
    for (double mu : {0.0, 1e-9, 1.0})
      for (double r : {0.0, 1e-6, 1.0}) {
        for (double f0 : {0.0, 1.0}) {
          const Estimate e = base_E(mu, r, f0, s);
          EXPECT_TRUE(std::isfinite(e.value) && e.value >= 0 && std::isfinite(e.error)) << mu << " " << r << " " << f0;
        }
        const Estimate e = ggx_E(mu, r, s);
        EXPECT_TRUE(std::isfinite(e.value) && e.value >= 0 && e.value <= 1 + 1e-12) << mu << " " << r;
        const double ab = r;
        for (SheenModel m : {SheenModel::Main, SheenModel::Ash}) {
          const Estimate b = sheen_E(mu, ab, m, s);
          EXPECT_TRUE(std::isfinite(b.value) && b.value >= 0 && std::isfinite(b.error)) << mu << " " << ab;
        }
      }
  }
}

// The committed default tables (luts/dspbr_luts.json, read through LutSet::published) against
// quadrature at sample cells of every table, including the smallest roughness at grazing angle
// where the published tables are badly wrong. Goal: max abs error <= 1e-4 per cell.
TEST(LutTables, CommittedCellsMatchQuadrature) {
  const LutSet& s = LutSet::published();
  auto c32 = [](int i) { return (i + 0.5) / 32; };
  auto c16 = [](int i) { return (i + 0.5) / 16; };
  for (auto [i, j] : {std::pair{0, 0}, {0, 20}, {3, 5}, {3, 31}, {12, 10}, {20, 0}, {31, 31}})
    EXPECT_NEAR(s.ggx_e.at({i, j}), ggx_reference(c32(j), c32(i), 1.0), 1e-4) << "GGX_E " << i << " " << j;
  for (auto [i, j] : {std::pair{0, 0}, {5, 8}, {15, 15}, {10, 1}}) {
    const double ab = c16(i), mu = c16(j);
    const auto main = [&](const Vec3& v, const Vec3& l) { return sheen_brdf(v, l, ab); };
    const auto ash = [&](const Vec3& v, const Vec3& l) { return sheen_brdf_ash(v, l, ab); };
    EXPECT_NEAR(s.sheen_e.at({i, j}), lutref::sheen_albedo_quad(mu, main), 1e-4) << "Sheen_E " << i << " " << j;
    EXPECT_NEAR(s.sheen_ash_e.at({i, j}), lutref::sheen_albedo_quad(mu, ash), 1e-4) << "Sheen_ash_E " << i << " " << j;
  }
  auto e_avg_ref = [](double r, double f0, double fms) {
    return lutref::cosine_average(
        [&](double m) {
          return lutref::ggx_albedo_quad_l(m, r, f0, 16, 16) + fms * (1.0 - lutref::ggx_albedo_quad_l(m, r, 1.0, 16, 16));
        },
        16);
  };
  for (int i : {15, 25, 31})
    EXPECT_NEAR(s.ggx_e_avg.at({i}), e_avg_ref(c32(i), 1.0, 0.0), 1e-4) << "GGX_E_avg " << i;
  for (auto [k, i, j] : {std::tuple{0, 8, 3}, {15, 15, 15}, {5, 12, 8}}) {
    const double f0 = c16(k), r = c16(i), mu = c16(j);
    const double fms = fresnel_ms(f0, 1.0, e_avg_ref(r, 1.0, 0.0));
    EXPECT_NEAR(s.base_e.at({k, i, j}), ggx_reference(mu, r, f0) + fms * (1 - ggx_reference(mu, r, 1.0)), 1e-4)
        << "Base_E " << k << " " << i << " " << j;
  }
  for (auto [k, i] : {std::pair{3, 10}, {15, 15}}) {
    const double f0 = c16(k), r = c16(i);
    const double fms = fresnel_ms(f0, 1.0, e_avg_ref(r, 1.0, 0.0));
    EXPECT_NEAR(s.base_e_avg.at({k, i}), e_avg_ref(r, f0, fms), 1e-4) << "Base_E_avg " << k << " " << i;
  }
}
