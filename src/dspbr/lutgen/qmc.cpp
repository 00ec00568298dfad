#include "dspbr/lutgen/qmc.h"

#include "dspbr/rng.h"

namespace dspbr {

namespace {

// Direction numbers v_k = m_k 2^(32-k), k = 1..32, for the first four Sobol' dimensions.
// Dimension 0 is van der Corput (m_k = 1); the others follow Joe & Kuo's table
// (new-joe-kuo-6.21201, d = 2..4): (s, a, m_1..m_s) = (1, 0, 1), (2, 1, 1 3), (3, 1, 1 3 1),
// extended by the Bratley-Fox recurrence
//   m_k = 2 a_1 m_(k-1) ^ 4 a_2 m_(k-2) ^ ... ^ 2^(s-1) a_(s-1) m_(k-s+1) ^ 2^s m_(k-s) ^ m_(k-s).
struct DirectionNumbers {
  uint32_t v[ScrambledSobol::kMaxDims][32];
  DirectionNumbers() {
    for (int k = 0; k < 32; ++k) v[0][k] = 1u << (31 - k);
    struct Poly { int s; uint32_t a; uint32_t m[3]; };
    const Poly polys[3] = {{1, 0, {1, 0, 0}}, {2, 1, {1, 3, 0}}, {3, 1, {1, 3, 1}}};
    for (int d = 1; d < ScrambledSobol::kMaxDims; ++d) {
      const Poly& p = polys[d - 1];
      uint64_t m[33] = {};
      for (int k = 1; k <= p.s; ++k) m[k] = p.m[k - 1];
      for (int k = p.s + 1; k <= 32; ++k) {
        uint64_t x = m[k - p.s] ^ (m[k - p.s] << p.s);
        for (int j = 1; j < p.s; ++j)
          if ((p.a >> (p.s - 1 - j)) & 1u) x ^= m[k - j] << j;
        m[k] = x;
      }
      for (int k = 1; k <= 32; ++k) v[d][k - 1] = uint32_t(m[k] << (32 - k));
    }
  }
};

const DirectionNumbers& directions() {
  static const DirectionNumbers dn;
  return dn;
}

uint32_t reverse_bits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

}  // namespace

ScrambledSobol::ScrambledSobol(uint64_t seed) {
  Pcg32 rng(seed, 0x5c4a3b2d1e0f9a8bULL);
  for (int d = 0; d < kMaxDims; ++d) {
    scramble_[d] = rng.next_u32();
    shift_[d] = rng.next_u32();
  }
  low_seed_ = (uint64_t(rng.next_u32()) << 32) | rng.next_u32();
}

uint32_t ScrambledSobol::sobol_bits(uint32_t index, int dim) {
  const uint32_t* v = directions().v[dim];
  uint32_t x = 0;
  for (; index != 0; index &= index - 1) x ^= v[__builtin_ctz(index)];  // one XOR per set bit
  return x;
}

double ScrambledSobol::sample(uint32_t index, int dim) const {
  // Nested scramble (Burley 2020, sec. 3): in bit-reversed order, x += seed and x ^= x * even
  // only carry information from lower to higher bits, i.e. from leading to trailing digits.
  uint32_t x = reverse_bits(sobol_bits(index, dim));
  x += scramble_[dim];
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  x = reverse_bits(x) ^ shift_[dim];
  // 21 uniform bits below the 32 scrambled ones, per (point, dimension).
  const uint64_t low = splitmix64(low_seed_ ^ ((uint64_t(index) << 3) | uint64_t(dim))) >> 43;
  return double((uint64_t(x) << 21) | low) * 0x1.0p-53;
}

}  // namespace dspbr
