// Directional and average albedos of the DSPBR BRDF terms, by numerical integration: the exact
// integrals behind the energy-compensation tables (spec "Energy Preservation", "Multiple-
// Scattering GGX BRDFs", "Diffuse BRDF", "Sheen BRDF"). The table generator (lutgen/generate.h)
// calls these functions; fits and validation call them to get exact values at any point.
//
//   E_m(mu; r)         = Integral M_r(v, l) mu_l dl          M_r = D G2 / (4 mu_v mu_l), alpha = r^2
//   E_m,avg(r)         = 2 Integral_0^1 E_m(mu; r) mu dmu
//   E(mu; r, f0)       = Integral [M_r F(v.h; f0, 1) + M_r,ms F_ms(f0, 1)] mu_l dl
//                      = Integral M_r F(v.h; f0, 1) mu_l dl + F_ms(f0, 1; E_m,avg(r)) (1 - E_m(mu; r))
//   E_avg(r, f0)       = 2 Integral_0^1 E(mu; r, f0) mu dmu
//   E_b(mu; alpha_b)   = Integral M_b(v, l) mu_l dl           (main or alternative sheen)
//
// The second form of E uses the closed-form hemispherical integral of the multiple-scattering
// lobe: Integral (1 - E_m(mu_v))(1 - E_m(mu_l)) / (pi (1 - E_m,avg)) mu_l dl = 1 - E_m(mu_v),
// because 2 pi Integral_0^1 (1 - E_m(mu_l)) mu_l dmu_l = pi (1 - E_m,avg). E_m and E_m,avg in it
// are integrated at the same (mu, r), never interpolated from a table.
//
// Integrators (IntegratorSettings):
//  - Qmc: importance sampling that fits the lobe (GGX: visible normals, Heitz 2018; sheen: a
//    half/half mixture of uniform hemisphere sampling and Charlie half-vector sampling, one-sample
//    balance heuristic) driven by Owen-scrambled Sobol' points; `randomizations` independent
//    scramblings of samples/randomizations points each.
//  - Mc: the plain Monte Carlo baseline: uniform hemisphere sampling of l (and uniform mu for
//    averages) with Pcg32, in `randomizations` batches (the glass albedos: Qmc's visible-normal
//    estimator driven by Pcg32).
//  - Quad: deterministic adaptive Gauss-Kronrod quadrature over the microfacet normal in
//    coordinates that follow the lobe, the azimuth split where a term switches on or off
//    (lutgen/microfacet_quadrature.h); the error is its embedded estimate, at most target_error
//    (kQuadDefaultTolerance when 0). No replicates, no seed, no sample budget.
// Qmc and Mc return the mean of the replicates and its standard error (spread of the replicates /
// sqrt(R)). Streams: the random numbers of a call depend only on (settings.seed, stream), so a
// table cell with stream = cell id gives the same bits whatever the thread count.
//
// Domain and clamps: mu is clamped to [kMinCos, 1] (mu = 0 exactly has no directional albedo;
// the clamp gives the grazing limit to O(kMinCos)); r in [0, 1] with r = 0 the mirror limit
// (E_m = 1, handled exactly by the VNDF sampler and in closed form by the MC baseline);
// alpha_b is clamped to [kMinAlphaB, 1] (the Charlie distribution is undefined at 0).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "dspbr/sheen.h"  // SheenModel, kMinAlphaB

namespace dspbr {

enum class Integrator { Qmc, Mc, Quad };
const char* integrator_name(Integrator i);  // "qmc" / "mc" / "quad"
// "qmc" / "mc" / "quad" -> Integrator; throws std::invalid_argument "'<name>' is not qmc, mc or quad".
Integrator parse_integrator(const std::string& name);

struct IntegratorSettings {
  Integrator integrator = Integrator::Qmc;
  int samples = 65536;      // samples per cell in total (all replicates together), the maximum
                            // when target_error > 0
  int randomizations = 8;   // independent replicates (QMC scramblings / MC batches), >= 2
  uint64_t seed = 1;
  // Adaptive budget: > 0 stops doubling the points per replicate (from min_samples in total)
  // once the standard error is at most this; 0 always uses `samples`.
  double target_error = 0;
  // First stage of the adaptive budget. It bounds the bias of stopping early: a part of the
  // domain of probability p that no replicate has sampled yet is invisible to the error
  // estimate, and with weights <= 1 (GGX: G2/G1) it can bias the result by at most p. GGX tails
  // beyond the horizon have p = alpha^2 / (1 + alpha^2) at normal incidence (1.4e-4 at
  // r = 0.11), so the first stage must sample them: 65536 points make p < ~2e-5 invisible only.
  int min_samples = 8 << 13;
};

// The Quad integrator's target error per value when the settings give none (target_error 0).
constexpr double kQuadDefaultTolerance = 1e-7;
// The smallest tolerance the quad integrator accepts. Below it the double rounding of the
// integrand keeps the error estimate from converging, and every cell refines to the panel limits
// (kQuadMaxPanels at each level): GGX_E_avg, one cell, took 0.4 s at 1e-11, 10 s at 5e-12 and
// more than 60 s at 2e-12 (2026-12-06).
constexpr double kQuadMinTolerance = 1e-10;
double quad_tolerance(const IntegratorSettings& s);

struct Estimate {
  double value = 0;
  double error = 0;  // standard error (1 sigma) of value; Quad: the quadrature's error estimate
};

// Grazing clamp of the view cosine (see above).
constexpr double kMinCos = 1e-6;
// Grazing clamp of the view cosine for the sheen albedos. The spec's Lambda fit tends to a
// finite value at mu -> 0 (the exact Charlie Lambda grows like 1/mu), so G_b does not vanish
// there and the main sheen's albedo grows like ~4e-5 / mu below mu ~ 1e-3 and diverges at 0
// (40 at mu = 1e-6, alpha_b = 1/2). Only endpoint grids (mu = 0 column) reach the clamp.
constexpr double kMinCosSheen = 1e-3;

// E_m(mu; r).
Estimate ggx_E(double mu, double r, const IntegratorSettings& s, uint64_t stream = 0);
// E_m,avg(r).
Estimate ggx_E_avg(double r, const IntegratorSettings& s, uint64_t stream = 0);
// E(mu; r, f0), computing E_m,avg(r) itself (stream + 1 is used for it).
Estimate base_E(double mu, double r, double f0, const IntegratorSettings& s, uint64_t stream = 0);
// beta(mu; r) = B / E_m, B = Integral M_r (1 - v.h)^5 mu_l dl: the Schlick moment relative to E_m,
// from one integration of both (the renderer layout stores it; docs/luts.md).
Estimate ggx_beta(double mu, double r, const IntegratorSettings& s, uint64_t stream = 0);
// E_avg(r, f0).
Estimate base_E_avg(double r, double f0, const IntegratorSettings& s, uint64_t stream = 0);
// E_b(mu; alpha_b) for the main or alternative sheen.
Estimate sheen_E(double mu, double alpha_b, SheenModel model, const IntegratorSettings& s, uint64_t stream = 0);

// The rough dielectric interface of the transparent core as the BSDF evaluates it (spec
// "Dielectric BSDF for Transparent Surfaces", volumetric, white, specular 1, rho_s = 1, no film):
//   E_g(mu; r, ior) = Integral [M_r F_d(v.h; F_0, 1) + M_t (1 - F_d(v.h; F_0, 1))] |mu_l| dl
// over both hemispheres, F_0 = ((ior - 1) / (ior + 1))^2; inside = false: v outside
// (eta_i = 1, eta_o = ior); inside = true: v inside (eta_i = ior, eta_o = 1; F_d = 1 under total
// internal reflection, which goes to the reflection lobe). At ior = 1 the value is the limit
// ior -> 1+ of the rough M_t (l_t = -v), continuous with ior > 1; the BSDF itself switches to a
// Dirac there (kIndexMatched), which the compensation leaves alone. Without the M_r,ms term (its
// albedo F_ms (1 - E_m) is closed-form).
Estimate glass_E(double mu, double r, double ior, bool inside, const IntegratorSettings& s, uint64_t stream = 0);
// 2 Integral_0^1 E_g(mu; r, ior) mu dmu.
Estimate glass_E_avg(double r, double ior, bool inside, const IntegratorSettings& s, uint64_t stream = 0);

// Batched forms used by the table generator (one integration serves every f0).
// E(mu; r, f0_i) for all f0s, with E_m,avg(r) given (its error is propagated).
std::vector<Estimate> base_E_f0s(double mu, double r, const std::vector<double>& f0s, const Estimate& e_m_avg,
                                 const IntegratorSettings& s, uint64_t stream);
// E_avg(r, f0_i) for all f0s; also returns E_m,avg(r) from the same samples in *e_m_avg.
std::vector<Estimate> base_E_avg_f0s(double r, const std::vector<double>& f0s, const IntegratorSettings& s,
                                     uint64_t stream, Estimate* e_m_avg = nullptr);

}  // namespace dspbr
