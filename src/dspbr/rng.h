// Deterministic random numbers. PCG32 (O'Neill 2014, "PCG: A Family of Simple Fast
// Space-Efficient Statistically Good Algorithms"), seeded through SplitMix64 so that any
// (seed, stream) pair, e.g. (user seed, cell index), gives an independent sequence.
// Results depend only on the seed and stream, never on threads.
#pragma once
#include <cstdint>

namespace dspbr {

inline uint64_t splitmix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

class Pcg32 {
 public:
  explicit Pcg32(uint64_t seed = 0, uint64_t stream = 0) {
    inc_ = (splitmix64(stream ^ 0x5851f42d4c957f2dULL) << 1u) | 1u;
    state_ = 0;
    next_u32();
    state_ += splitmix64(seed);
    next_u32();
  }
  uint32_t next_u32() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    const uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }
  // Uniform double in [0, 1) with 53 random bits.
  double next_double() {
    const uint64_t hi = next_u32(), lo = next_u32();
    return double(((hi << 32) | lo) >> 11) * 0x1.0p-53;
  }

 private:
  uint64_t state_ = 0, inc_ = 1;
};

}  // namespace dspbr
