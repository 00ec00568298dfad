// Randomized quasi-Monte Carlo points for the LUT integrators: the first dimensions of the
// Sobol' sequence (Sobol' 1967; direction numbers of Joe & Kuo 2008, "Constructing Sobol
// sequences with better two-dimensional projections"), randomized per dimension by
//  1. hash-based nested scrambling (Burley 2020, "Practical Hash-based Owen Scrambling", after
//     Laine & Karras 2011): a seeded permutation of the bit-reversed value in which every digit
//     depends only on the digits above it, so the (t,m,s)-net structure is kept;
//  2. a random digital shift (XOR with a uniform 32-bit value), which makes every point exactly
//     uniform on the 2^-32 grid, and uniform random low bits below it (2^-53 grid).
// So the mean over the points is an unbiased estimate, and independent seeds give independent
// replicates for an error estimate. Deterministic for a given seed.
#pragma once
#include <array>
#include <cstdint>

namespace dspbr {

class ScrambledSobol {
 public:
  static constexpr int kMaxDims = 4;
  // Largest supported number of points per scrambling.
  static constexpr uint32_t kMaxPoints = 1u << 24;

  // One randomization; `seed` selects the scramble (use independent seeds for independent ones).
  explicit ScrambledSobol(uint64_t seed);

  // Coordinate `dim` (0 <= dim < kMaxDims) of point `index` (< kMaxPoints), in [0, 1).
  double sample(uint32_t index, int dim) const;

  // The unscrambled Sobol' coordinate as a 32-bit fraction (exposed for tests).
  static uint32_t sobol_bits(uint32_t index, int dim);

 private:
  std::array<uint32_t, kMaxDims> scramble_{}, shift_{};
  uint64_t low_seed_ = 0;
};

}  // namespace dspbr
