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

#include "dspbr/bsdf/bsdf.h"

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
  std::size_t invalid = 0;   // samples with valid = false
};

// BSDF-sampled estimator: mean of sample weights over n draws with u stratified on a
// sqrt(n) x sqrt(n) grid in (u.y, u.z) and u.x (lobe choice) independent uniform.
SampledAlbedo albedo_sampled(const Bsdf& bsdf, const Vec3& v, std::size_t n, uint64_t seed, uint64_t stream);

// Verdicts of the white-furnace check at one direction. A verdict fails only when the deviation
// is beyond the tolerance by more than `sigmas` standard errors (so noise alone does not fail it).
struct EnergyTolerances {
  double conservation = 0.01;   // E <= 1 + conservation
  double preservation = 0.02;   // E >= 1 - preservation (only where the spec claims preservation)
  double sigmas = 4.0;
  double agreement_abs = 2e-3;  // |E_eval - E_sampled,non-delta| allowed on top of the noise
};

struct EnergyVerdict {
  bool conserving = true, preserving = true, estimators_agree = true;
  double albedo_max = 0, albedo_min = 0;  // over channels, sampled estimator (delta included)
  double disagreement = 0;                // max over channels |E_eval - E_sampled,non-delta| / noise-aware bound
};

EnergyVerdict judge_energy(const AlbedoEstimate& eval, const SampledAlbedo& sampled, const EnergyTolerances& tol);

}  // namespace dspbr::validate
