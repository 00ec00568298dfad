// The deterministic table integrator (lutgen/microfacet_quadrature.h, Integrator::Quad, the
// default of every table) against independent numbers: a light-domain / half-vector Gauss-Legendre
// reference with a convergence check (tests/test_lut_reference.h), the same quadrature at a
// 10^4 times tighter target (its stated error must bound the true one), and QMC at 2^20 samples x 16 randomizations.
// Also: the committed published tables agree with the reference within 1e-6.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dspbr/fresnel.h"
#include "dspbr/lutgen/albedo.h"
#include "dspbr/lutgen/lut_io.h"
#include "dspbr/lutgen/microfacet_quadrature.h"
#include "test_lut_reference.h"

using namespace dspbr;

namespace {

IntegratorSettings quad() {
  IntegratorSettings s;
  s.integrator = Integrator::Quad;
  return s;  // target_error 0: kQuadDefaultTolerance
}

IntegratorSettings qmc_fine() {
  IntegratorSettings s;
  s.samples = 1 << 20;
  s.randomizations = 16;
  s.target_error = 0;
  return s;
}

}  // namespace

// Stated error <= 1e-7 at the default target and the true error (against the quadrature at
// 1e-11) within the stated one, over the whole domain: grazing, roughness -> 0, both glass sides.
TEST(LutQuadrature, StatedErrorBoundsTheTrueErrorOverTheDomain) {
  for (double mu : {1e-6, 1e-3, 0.05, 0.3, 0.7, 1.0})
    for (double r : {0.001, 0.02, 0.1, 0.3, 0.6, 1.0}) {
      const QuadResult<2> q = ggx_moments_quadrature(mu, r * r, 1e-7), x = ggx_moments_quadrature(mu, r * r, 1e-11);
      EXPECT_LE(q.error, 1e-7);
      for (int k = 0; k < 2; ++k) EXPECT_LE(std::abs(q.value[size_t(k)] - x.value[size_t(k)]), 2e-7) << mu << " " << r;
    }
  for (bool inside : {false, true})
    for (double ior : {1.0, 1.05, 1.5, 3.0})
      for (double r : {0.02, 0.3, 1.0})
        for (double mu : {1e-6, 0.01, 0.3, 0.8, 1.0}) {
          const double ei = inside ? ior : 1.0, eo = inside ? 1.0 : ior, f0 = f0_from_ior(1.0, ior);
          const QuadResult<1> q = dielectric_albedo_quadrature(mu, r * r, f0, ei, eo, 1e-7);
          const QuadResult<1> x = dielectric_albedo_quadrature(mu, r * r, f0, ei, eo, 1e-11);
          EXPECT_LE(q.error, 1e-7);
          EXPECT_LE(std::abs(q.value[0] - x.value[0]), 1e-6) << inside << " " << ior << " " << r << " " << mu;
        }
  for (bool ash : {false, true})
    for (double ab : {1e-3, 0.05, 1.0})
      for (double mu : {1e-3, 0.2, 1.0}) {
        const QuadResult<1> q = sheen_albedo_quadrature(mu, ab, ash, 1e-7), x = sheen_albedo_quadrature(mu, ab, ash, 1e-11);
        EXPECT_LE(q.error, 1e-7);
        EXPECT_LE(std::abs(q.value[0] - x.value[0]), 2e-7) << ash << " " << ab << " " << mu;
      }
}

// Every integrand of both layouts: quad within 4 sigma (+1e-7) of QMC at 2^20 samples x 16.
TEST(LutQuadrature, AgreesWithQmcOnEveryIntegrand) {
  const IntegratorSettings q = quad(), m = qmc_fine();
  auto near = [](const Estimate& a, const Estimate& b, const char* what) {
    EXPECT_NEAR(a.value, b.value, 4 * b.error + 1e-7) << what;
    EXPECT_LE(a.error, 3e-7) << what;
  };
  for (double mu : {0.02, 0.5, 0.95})
    for (double r : {0.05, 0.4, 1.0}) {
      near(ggx_E(mu, r, q), ggx_E(mu, r, m, 1), "GGX_E");
      near(ggx_beta(mu, r, q), ggx_beta(mu, r, m, 2), "GGX_beta");
      near(base_E(mu, r, 0.3, q), base_E(mu, r, 0.3, m, 3), "Base_E");
      near(sheen_E(mu, r * r, SheenModel::Main, q), sheen_E(mu, r * r, SheenModel::Main, m, 4), "Sheen_E");
      near(sheen_E(mu, r * r, SheenModel::Ash, q), sheen_E(mu, r * r, SheenModel::Ash, m, 5), "Sheen_ash_E");
      for (bool inside : {false, true})
        near(glass_E(mu, r, 1.5, inside, q), glass_E(mu, r, 1.5, inside, m, 6), inside ? "Glass_inv_E" : "Glass_E");
    }
  for (double r : {0.05, 0.5, 1.0}) {
    near(ggx_E_avg(r, q), ggx_E_avg(r, m, 7), "GGX_E_avg");
    near(base_E_avg(r, 0.5, q), base_E_avg(r, 0.5, m, 8), "Base_E_avg");
    for (bool inside : {false, true})
      near(glass_E_avg(r, 1.5, inside, q), glass_E_avg(r, 1.5, inside, m, 9), "Glass_E_avg");
  }
}

// The committed published GGX_E and Base_E cells within 1e-6 of the independent reference
// (light-domain Gauss-Legendre, checked converged by doubling its panels).
TEST(LutQuadrature, CommittedPublishedTablesWithin1e6OfTheReference) {
  const std::vector<Table> tables = read_lut_json(DSPBR_SOURCE_DIR "/luts/dspbr_luts.json");
  int judged = 0;
  for (const Table& t : tables) {
    if (t.name != "GGX_E") continue;
    const int nm = t.axes[1].size;
    for (int ir : {3, 12, 20, 31})
      for (int im : {0, 9, 31}) {
        const double r = t.axes[0].coord(ir), mu = t.axes[1].coord(im);
        const bool rough = r >= 0.3;
        const int n = r >= 0.5 ? 48 : 96;
        const double a = rough ? lutref::ggx_albedo_quad_l(mu, r, 1.0, n, n) : lutref::ggx_albedo_quad(mu, r, 1.0, 96, 48);
        const double b = rough ? lutref::ggx_albedo_quad_l(mu, r, 1.0, 2 * n, 2 * n) : lutref::ggx_albedo_quad(mu, r, 1.0, 192, 96);
        // Judged only where the reference has converged to well within the 1e-6 claimed.
        if (std::abs(a - b) > 2e-7) continue;
        ++judged;
        EXPECT_NEAR(t.values[size_t(ir * nm + im)], b, 1e-6) << "GGX_E r " << r << " mu " << mu;
      }
  }
  EXPECT_GE(judged, 8) << "too few cells where the reference converged";
}
