// White-furnace directional albedo E(v) = Integral over the sphere of f(v, l) |l.n| dl, by two
// independent Monte Carlo estimators:
//  - albedo_eval: stratified cosine-weighted directions on BOTH hemispheres, using only eval()
//    (never sample() or pdf()); misses delta lobes by construction;
//  - albedo_sampled: the BSDF's own sample() weights (includes delta lobes); the non-delta part
//    is reported separately so the two estimators can be compared on the same integral.
// Under a uniform white environment of radiance 1 the reflected radiance equals E(v), so E <= 1
// is energy conservation and E >= 1 energy preservation (white furnace test).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "dspbr/bsdf/bsdf.h"
#include "dspbr/validate/albedo_quadrature.h"

namespace dspbr::validate {

struct AlbedoEstimate {
  Rgb value;      // estimate of the integral
  Rgb std_error;  // standard error (independent-sample formula: conservative for stratification)
  std::size_t samples = 0;
};

// Eval-only estimator with strata x strata jittered cells per hemisphere (2 strata^2 evals).
// Deterministic for a given (seed, stream).
AlbedoEstimate albedo_eval(const Bsdf& bsdf, const Vec3& v, int strata, uint64_t seed, uint64_t stream);

struct SampledAlbedo {
  AlbedoEstimate total;      // all valid samples (delta included)
  AlbedoEstimate non_delta;  // samples without kLobeDelta only (estimates the same integral as albedo_eval)
  AlbedoEstimate delta;      // samples with kLobeDelta only (total = non_delta + delta)
  std::size_t invalid = 0;   // samples with valid = false
};

// BSDF-sampled estimator: mean of sample weights over n draws with u stratified on a
// sqrt(n) x sqrt(n) grid in (u.y, u.z) and u.x (lobe choice) independent uniform.
SampledAlbedo albedo_sampled(const Bsdf& bsdf, const Vec3& v, std::size_t n, uint64_t seed, uint64_t stream);

// Verdicts of the white-furnace check at one direction. Two estimates of the whole integral:
// the sampled one (sampled.total) and the combined one (the quadrature of the non-delta part,
// albedo_quadrature.h, plus sampled.delta; exact to its stated error where the BSDF has no delta
// lobe). A bound (conservation E <= 1 + tol, preservation E >= 1 - tol)
//  - fails where either estimate lies beyond it by more than its band (sigmas standard errors,
//    plus the quadrature's stated error), so that noise alone does not fail it;
//  - passes only where the band of the narrower estimate lies within the tolerance (band <= tol):
//    a violation of the tolerance by its own size would then have failed it;
//  - is not judged otherwise (the band is wider than the tolerance: the check has no power).
// The agreement of the quadrature and the sampled estimator on the non-delta integral is judged
// the same way, with the tolerance agreement_abs + agreement_band_max: fails beyond its band +
// agreement_abs, not judged where the band exceeds agreement_band_max (times the albedo where it exceeds 1).
struct EnergyTolerances {
  double conservation = 0.01;   // E <= 1 + conservation
  // E >= 1 - preservation (only where the spec claims preservation). Measured with the quadrature
  // (full run, 2026-12-06): the lowest preserving albedo is 0.99903 (opaque dielectric r = 0.2 at
  // cos 0.8, table interpolation), the widest band 1.8e-3: 0.005 leaves room for both and fails a
  // lobe that loses 1.5% (test ValidateSuite.PlantedGrazingLossFailsTheFullRun).
  double preservation = 0.005;
  double sigmas = 4.0;
  double agreement_abs = 2e-3;  // |E_quad - E_sampled,non-delta| allowed on top of the band
  // Widest band with which the agreement is judged, relative where the albedo exceeds 1 (the
  // alternative sheen's gain reaches E = 3.9 at grazing view).
  double agreement_band_max = 0.02;
};

enum class Decision { Pass, Fail, NotJudged };

// One judged bound (or the agreement) at one direction: the estimate and band the decision used
// (worst channel), the tolerance, and the estimator's name.
struct BoundVerdict {
  Decision decision = Decision::Pass;
  double value = 0;      // estimate (agreement: |difference|)
  double band = 0;       // sigmas standard errors of it
  double tolerance = 0;  // the bound's tolerance (the band must not exceed it)
  const char* estimator = "";  // "sampled" or "quadrature + sampled delta" (agreement: "quadrature vs sampled non-delta")
  // The estimate lies beyond the bound, its band left aside (what a NOT JUDGED view would suggest).
  bool beyond = false;
  // "band +-0.43 wider than the tolerance 0.01" for Decision::NotJudged, else empty.
  std::string reason() const;
};

struct EnergyVerdict {
  BoundVerdict conservation, preservation, agreement;
  double albedo_max = 0, albedo_min = 0;  // over channels, sampled estimator (delta included)
  double disagreement = 0;                // max over channels |E_quad - E_sampled,non-delta| / noise-aware bound
  // Convenience: the bound did not fail (PASS or NOT JUDGED).
  bool conserving() const { return conservation.decision != Decision::Fail; }
  bool preserving() const { return preservation.decision != Decision::Fail; }
  bool estimators_agree() const { return agreement.decision != Decision::Fail; }
};

EnergyVerdict judge_energy(const QuadratureAlbedo& quad, const SampledAlbedo& sampled, const EnergyTolerances& tol);

}  // namespace dspbr::validate
