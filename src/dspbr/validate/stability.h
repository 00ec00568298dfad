// Numerical stability of a BSDF at extreme directions and random numbers: counts of NaN, Inf,
// negative and above-bound values of eval(), pdf() and sample() (target: all zero). Parameter
// corners (roughness 0, IOR 1, ...) are swept by the caller, which builds one Bsdf per corner.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dspbr/bsdf/bsdf.h"

namespace dspbr::validate {

struct StabilityCounts {
  std::size_t evaluations = 0;  // eval + pdf + sample calls made
  std::size_t nan = 0, inf = 0, negative = 0, above_bound = 0;
  std::size_t bad_direction = 0;  // valid sample with |l| not 1 (tolerance 1e-6)
  double max_weight = 0;          // largest sample-weight component seen
  Vec3 max_weight_v, max_weight_u;  // where (viewer direction, random numbers)
  // NaN, Inf, negative values and bad directions are errors; weights above the bound are fireflies
  // (unbiased, but a sampling density badly matched to f |cos|): reported separately.
  std::size_t total_failures() const { return nan + inf + negative + bad_direction; }
  StabilityCounts& operator+=(const StabilityCounts& o);
};

struct StabilitySettings {
  std::size_t random_directions = 2000;  // random (v, l) pairs and (v, u) draws on top of the corners
  // A sample weight above this is counted as "above bound": a firefly that signals a sampling
  // density badly matched to f |cos| (for a conserving BSDF the weight of a well-matched sampler
  // stays near its albedo).
  double weight_bound = 10.0;
  uint64_t seed = 1, stream = 0;
};

// Corner directions: cos(theta) in {1, 1 - 1e-12, 0.5, 1e-7, 0, -1e-7, -0.5, -1} at two azimuths.
std::vector<Vec3> corner_directions();

StabilityCounts stability_scan(const Bsdf& bsdf, const StabilitySettings& s);

}  // namespace dspbr::validate
