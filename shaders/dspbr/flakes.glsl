// Procedural flakes (spec "Flakes": Flake Texture, Flake BSDF, Flip-Flop Effect), as the reference
// computes them (src/dspbr/bsdf/flakes.cpp): the triplanar Voronoi grid with its per-cell PCG32
// (seeded through SplitMix64 by the cell's indices), the flake normal drawn from GGX, the cone BSDF
// of one flake and the flip-flop tint. The 64-bit arithmetic of the generator is written with two
// 32-bit words (the common subset has no 64-bit integers); the random numbers keep 24 bits.

// The 64-bit words and their arithmetic (the C++ interop has them natively: DSPBR_NATIVE_U64).
#ifndef DSPBR_NATIVE_U64
struct DspbrU64 {
  uint hi;
  uint lo;
};
DSPBR_FN DspbrU64 dspbr_u64(uint hi, uint lo) {
  DspbrU64 r;
  r.hi = hi;
  r.lo = lo;
  return r;
}
DSPBR_FN DspbrU64 dspbr_u64_add(DspbrU64 a, DspbrU64 b) {
  uint lo = a.lo + b.lo;
  return dspbr_u64(a.hi + b.hi + (lo < a.lo ? 1u : 0u), lo);
}
DSPBR_FN DspbrU64 dspbr_u64_xor(DspbrU64 a, DspbrU64 b) { return dspbr_u64(a.hi ^ b.hi, a.lo ^ b.lo); }
// a >> n for 0 < n < 64.
DSPBR_FN DspbrU64 dspbr_u64_shr(DspbrU64 a, uint n) {
  if (n >= 32u) return dspbr_u64(0u, n == 32u ? a.hi : a.hi >> (n - 32u));
  return dspbr_u64(a.hi >> n, (a.lo >> n) | (a.hi << (32u - n)));
}
// The full 64-bit product of two 32-bit words (the interop's dspbr_umul_extended: GLSL's
// umulExtended, 16-bit halves in HLSL).
DSPBR_FN DspbrU64 dspbr_mul32(uint a, uint b) {
  DspbrU64 r;
  dspbr_umul_extended(a, b, r.hi, r.lo);
  return r;
}
// The low 64 bits of a * b.
DSPBR_FN DspbrU64 dspbr_u64_mul(DspbrU64 a, DspbrU64 b) {
  DspbrU64 m = dspbr_mul32(a.lo, b.lo);
  m.hi += a.hi * b.lo + a.lo * b.hi;
  return m;
}
#endif

// SplitMix64 (Steele et al. 2014).
DSPBR_FN DspbrU64 dspbr_splitmix64(DspbrU64 x) {
  x = dspbr_u64_add(x, dspbr_u64(0x9e3779b9u, 0x7f4a7c15u));
  x = dspbr_u64_mul(dspbr_u64_xor(x, dspbr_u64_shr(x, 30u)), dspbr_u64(0xbf58476du, 0x1ce4e5b9u));
  x = dspbr_u64_mul(dspbr_u64_xor(x, dspbr_u64_shr(x, 27u)), dspbr_u64(0x94d049bbu, 0x133111ebu));
  return dspbr_u64_xor(x, dspbr_u64_shr(x, 31u));
}
// PCG32 (O'Neill 2014) with the reference's seeding (src/dspbr/rng.h).
struct DspbrPcg32 {
  DspbrU64 state;
  DspbrU64 inc;
};
// The output of the step from state old (PCG XSH RR).
DSPBR_FN uint dspbr_pcg32_output(DspbrU64 old) {
  uint x = dspbr_u64_shr(dspbr_u64_xor(dspbr_u64_shr(old, 18u), old), 27u).lo;
  uint rot = old.hi >> 27u;
  return (x >> rot) | (x << ((32u - rot) & 31u));
}
DSPBR_FN uint dspbr_pcg32_next(DSPBR_INOUT(DspbrPcg32) g) {
  DspbrU64 old = g.state;
  g.state = dspbr_u64_add(dspbr_u64_mul(old, dspbr_u64(0x5851f42du, 0x4c957f2du)), g.inc);
  return dspbr_pcg32_output(old);
}
DSPBR_FN DspbrPcg32 dspbr_pcg32(DspbrU64 seed, DspbrU64 stream) {
  DspbrPcg32 g;
  DspbrU64 s = dspbr_splitmix64(dspbr_u64_xor(stream, dspbr_u64(0x5851f42du, 0x4c957f2du)));
  g.inc = dspbr_u64((s.hi << 1u) | (s.lo >> 31u), (s.lo << 1u) | 1u);
  g.state = dspbr_u64(0u, 0u);
  dspbr_pcg32_next(g);
  g.state = dspbr_u64_add(g.state, dspbr_splitmix64(seed));
  dspbr_pcg32_next(g);
  return g;
}
// The reference's next_double (two words, 53 bits) to the 24 bits a float holds: [0, 1 - 2^-24].
// The number drawn at a state is its first word's (the second word only advances the state).
DSPBR_FN float dspbr_pcg32_float_at(DspbrU64 state) { return float(dspbr_pcg32_output(state) >> 8u) * (1.0f / 16777216.0f); }

// The LCG's state n steps on is A_n state + C_n inc, A_n = a^n, C_n = 1 + a + ... + a^(n-1) (mod
// 2^64; Brown 1994, "Random Number Generation with Arbitrary Strides"): a flake's five numbers are
// the states 0, 2, 4, 6, 8 steps after its first, the next flake's first 10 steps on. A probe needs
// only the first two numbers of each flake (its position) and the best flake's other three, and the
// jumps are independent of each other (the sequential generator is a chain of 40 dependent 64-bit
// products per cell; 2 us of a car paint's prepare).
struct DspbrLcgStride {
  DspbrU64 a;  // A_n
  DspbrU64 c;  // C_n
};
DSPBR_FN DspbrLcgStride dspbr_lcg_stride_of(uint a_hi, uint a_lo, uint c_hi, uint c_lo) {
  DspbrLcgStride t;
  t.a = dspbr_u64(a_hi, a_lo);
  t.c = dspbr_u64(c_hi, c_lo);
  return t;
}
// (A_n, C_n) of the PCG32 multiplier for the strides n = 2, 4, 6, 8, 10.
DSPBR_FN DspbrLcgStride dspbr_lcg_stride(int n) {
  if (n == 2) return dspbr_lcg_stride_of(0x685f98a2u, 0x018fade9u, 0x5851f42du, 0x4c957f2eu);
  if (n == 4) return dspbr_lcg_stride_of(0xfb4d3ae3u, 0x9272be11u, 0xcbb5f646u, 0x404a560cu);
  if (n == 6) return dspbr_lcg_stride_of(0xf08d02b0u, 0x115f7a79u, 0x30705b04u, 0x2917ec1au);
  if (n == 8) return dspbr_lcg_stride_of(0xb59dda5fu, 0x38413d21u, 0x9a8b7f78u, 0xda6ef4d8u);
  return dspbr_lcg_stride_of(0xc07a0e3eu, 0x901ef009u, 0xab894868u, 0xb3b04fc6u);  // n = 10
}
// The state n steps on, from the stride's C_n inc (a cell's probe forms it once per stride).
DSPBR_FN DspbrU64 dspbr_lcg_jump(DspbrU64 state, int n, DspbrU64 c_inc) {
  return dspbr_u64_add(dspbr_u64_mul(state, dspbr_lcg_stride(n).a), c_inc);
}
DSPBR_FN DspbrU64 dspbr_lcg_c_inc(DspbrU64 inc, int n) { return dspbr_u64_mul(inc, dspbr_lcg_stride(n).c); }

// Omega_cone = 2 pi (1 - cos theta_cone) (spec "Flake BSDF"); alpha_cone^2 = min(Omega(cos 7 deg) /
// (4 pi - Omega(cos 7 deg)), r_f^2 / 2) (spec eq. alpha-cone; tan^2(3.5 deg) when unclamped).
DSPBR_FN float dspbr_flake_alpha_cone2(float r_f) { return min(0.0037408661f, 0.5f * r_f * r_f); }
// 1 - cos theta_cone = 2 alpha_cone^2 / (1 + alpha_cone^2), kept as such (no cancellation).
DSPBR_FN float dspbr_flake_one_minus_cos_cone(float r_f) {
  float a2 = dspbr_flake_alpha_cone2(r_f);
  return 2.0f * a2 / (1.0f + a2);
}
// The cone is a Dirac (a mirror flake) below this 1 - cos theta_cone (the reference's kFlakeDeltaConeEps).
DSPBR_CONST float dspbr_flake_delta_cone = 1e-10f;

// The flake under a shading point (spec Listing "flakes", the Voronoi-nearest of the flakes of the
// cells around it): opacity o_f in {0, 1} and the normal n_f in the core's local frame.
struct DspbrFlake {
  float opacity;
  vec3 normal;
};
DSPBR_FN float dspbr_frac(float x) {
  float f = x - floor(x);
  return f < 1.0f ? f : 0.0f;
}
DSPBR_FN float dspbr_sgn(float x) { return x < 0.0f ? -1.0f : 1.0f; }

// The flakes of grid cell (ii, jj) (unwrapped; hashed modulo res) against the best found so far:
// its squared distance, its rank in the spec's scan (cells row by row, the 3x3 block before the
// 5x5 ring, 4 flakes each: the first of equally near flakes wins, as in the scan), and the state
// and increment of its cell's generator at its first number.
struct DspbrFlakeBest {
  float d2;
  int rank;
  DspbrU64 state;
  DspbrU64 inc;
};
// A cell that cannot hold a flake nearer than the best is not drawn: its flakes lie in the cell
// (xi in [0, 1)), so the squared distance from (gx, gy) to the cell's square, computed as the
// flakes' is (float rounding is monotonic), bounds theirs from below. The factor 1.000001 leaves
// room for a compiler that fuses the flakes' sum into a multiply-add and not the bound's.
// No flake found yet: any flake is nearer.
DSPBR_FN DspbrFlakeBest dspbr_flake_none() {
  DspbrFlakeBest best;
  best.d2 = 3.402823466e38f;
  best.rank = 0;
  best.state = dspbr_u64(0u, 0u);
  best.inc = dspbr_u64(0u, 0u);
  return best;
}
DSPBR_FN bool dspbr_flake_cell_beyond(int ii, int jj, int i, int j, float gx, float gy, DspbrFlakeBest best) {
  float bx = ii > i ? gx - float(ii) : (ii < i ? gx - float(ii + 1) : 0.0f);
  float by = jj > j ? gy - float(jj) : (jj < j ? gy - float(jj + 1) : 0.0f);
  return bx * bx + by * by > best.d2 * 1.000001f;
}
DSPBR_FN void dspbr_flake_probe(int ii, int jj, int res, float gx, float gy, int rank, DSPBR_INOUT(DspbrFlakeBest) best) {
  // The cell modulo res (|offset| <= 2 < res: one wrap; no % of a negative number).
  int wi = ii < 0 ? ii + res : (ii >= res ? ii - res : ii);
  int wj = jj < 0 ? jj + res : (jj >= res ? jj - res : jj);
  DspbrPcg32 g = dspbr_pcg32(dspbr_u64(0u, uint(wi)), dspbr_u64(0u, uint(wj)));
  DspbrU64 s = g.state;
  DspbrU64 c2 = dspbr_lcg_c_inc(g.inc, 2), c10 = dspbr_lcg_c_inc(g.inc, 10);
  for (int k = 0; k < 4; ++k) {  // k = 4 flakes per cell, 5 numbers each (spec generate_flake)
    float xi1 = dspbr_pcg32_float_at(s);
    float xi2 = dspbr_pcg32_float_at(dspbr_lcg_jump(s, 2, c2));
    float dx = gx - (float(ii) + xi1), dy = gy - (float(jj) + xi2);
    float d2 = dx * dx + dy * dy;
    if (d2 < best.d2 || (d2 == best.d2 && rank + k < best.rank)) {
      best.d2 = d2;
      best.rank = rank + k;
      best.state = s;
      best.inc = g.inc;
    }
    s = dspbr_lcg_jump(s, 10, c10);
  }
}

// The shading point on the flake grid: res cells per side, the point's grid coordinates (gx, gy)
// and its cell (i, j); valid false without flakes (size 0) or for a point that is not finite.
struct DspbrFlakeGrid {
  bool valid;
  int res;
  float gx;
  float gy;
  int i;
  int j;
};
// p: the shading point in object space (m); n: the bumped normal in object space.
DSPBR_FN DspbrFlakeGrid dspbr_flake_grid(vec3 p, vec3 n, float size_mm) {
  DspbrFlakeGrid g;
  g.valid = size_mm > 0.0f && !isnan(p.x + p.y + p.z) && !isinf(p.x + p.y + p.z);
  // res = max(4, ceil(sqrt(N / 4))), N = 1 / (3 sqrt(3) / 2 (s_f / 2000)^2) flakes per m^2, capped
  // at 2^23 cells per side (float resolves no finer grid at p in [-1, 1] m). sqrt(N / 4) =
  // (2000 / sqrt(6 sqrt 3)) / s_f: one division, which rounds once where the product, quotient and
  // square root rounded three times. Of 200000 sizes from 1e-3 mm to 150 mm it gives another res
  // than the reference's double at 135 (one cell off, at a boundary of ceil), the three-step form
  // at 360 (test ShaderLibrary.FlakeGridAsTheReference).
  g.res = g.valid ? int(min(max(4.0f, ceil(620.40324f / size_mm)), 8388608.0f)) : 4;
  // Triplanar mapping T_map(p, n) (spec eq. tr-mapping).
  float ax = abs(n.x), ay = abs(n.y), az = abs(n.z), u, v;
  if (ax > ay && ax > az) {
    u = dspbr_frac(dspbr_sgn(p.x) * p.y + 0.5f);
    v = dspbr_frac(p.z + 0.5f);
  } else if (ay > ax && ay > az) {
    u = dspbr_frac(-dspbr_sgn(p.y) * p.x + 0.5f);
    v = dspbr_frac(p.z + 0.5f);
  } else {
    u = dspbr_frac(dspbr_sgn(p.z) * p.x + 0.5f);
    v = dspbr_frac(p.y + 0.5f);
  }
  g.gx = g.valid ? u * float(g.res) : 0.5f;
  g.gy = g.valid ? v * float(g.res) : 0.5f;
  // gx, gy >= 0 (u, v in [0, 1)): the conversion's truncation is their floor.
  g.i = min(int(g.gx), g.res - 1);
  g.j = min(int(g.gy), g.res - 1);
  return g;
}
// The Voronoi-nearest flake of the cells around the point (spec Listing "flakes"): the first of
// the nearest in the spec's scan of the 3x3 block (and of the 5x5 ring where the block cannot be
// sure), found without drawing the cells that cannot hold it.
DSPBR_FN DspbrFlakeBest dspbr_flake_nearest(DspbrFlakeGrid g) {
  int i = g.i, j = g.j, res = g.res;
  float gx = g.gx, gy = g.gy;
  DspbrFlakeBest best = dspbr_flake_none();
  // The point's own cell first (rank 16: the centre of the 3x3 scan), then its neighbours that
  // can still hold a nearer flake.
  dspbr_flake_probe(i, j, res, gx, gy, 16, best);
  for (int di = -1; di <= 1; ++di)
    for (int dj = -1; dj <= 1; ++dj)
      if ((di != 0 || dj != 0) && !dspbr_flake_cell_beyond(i + di, j + dj, i, j, gx, gy, best))
        dspbr_flake_probe(i + di, j + dj, res, gx, gy, 4 * (3 * (di + 1) + dj + 1), best);
  // The 3x3 block is exact unless the nearest flake is farther than its border; 5x5 always is.
  float fx = gx - float(i), fy = gy - float(j);
  float margin = 1.0f + min(min(fx, 1.0f - fx), min(fy, 1.0f - fy));
  if (best.d2 > margin * margin) {
    int ring = 36;
    for (int di = -2; di <= 2; ++di)
      for (int dj = -2; dj <= 2; ++dj)
        if (max(abs(di), abs(dj)) == 2) {
          if (!dspbr_flake_cell_beyond(i + di, j + dj, i, j, gx, gy, best)) dspbr_flake_probe(i + di, j + dj, res, gx, gy, ring, best);
          ring += 4;
        }
  }
  return best;
}

// The flake under a shading point: p the point in object space (m), n the bumped normal in object space.
DSPBR_FN DspbrFlake dspbr_flake_at(vec3 p, vec3 n, float coverage, float size_mm, float r_f) {
  DspbrFlake out_f;
  out_f.opacity = 0.0f;
  out_f.normal = vec3(0.0f, 0.0f, 1.0f);
  DspbrFlakeGrid grid = dspbr_flake_grid(p, n, size_mm);
  if (!grid.valid) return out_f;
  DspbrFlakeBest best = dspbr_flake_nearest(grid);
  // The nearest flake's other numbers: orientation xi_3, xi_4 and opacity O_f(f, xi_5).
  float xi3 = dspbr_pcg32_float_at(dspbr_lcg_jump(best.state, 4, dspbr_lcg_c_inc(best.inc, 4)));
  float xi4 = dspbr_pcg32_float_at(dspbr_lcg_jump(best.state, 6, dspbr_lcg_c_inc(best.inc, 6)));
  float xi5 = dspbr_pcg32_float_at(dspbr_lcg_jump(best.state, 8, dspbr_lcg_c_inc(best.inc, 8)));
  float opacity = xi5 < coverage ? 1.0f : 0.0f;
  // K(r_f, xi_3, xi_4): cos^2 theta = (1 - xi) / (1 - (1 - alpha^2) xi), alpha = alpha_ggx =
  // sqrt(r_f^2 - alpha_cone^2) (spec eq. roughness-distribution).
  float a2 = max(0.0f, r_f * r_f - dspbr_flake_alpha_cone2(r_f));
  float w = (1.0f - xi3) / (1.0f - (1.0f - a2) * xi3);
  float s = sqrt(max(0.0f, 1.0f - w)), phi = 2.0f * dspbr_pi * xi4;
  out_f.normal = vec3(s * cos(phi), s * sin(phi), sqrt(max(0.0f, w)));
  out_f.opacity = opacity;
  return out_f;
}

// Flip-flop tint c_f = rho_f + (rho_ff - rho_f) (v.h_r)^(1 / f_f^2) (spec "Flip-Flop Effect").
DSPBR_FN vec3 dspbr_flake_tint(vec3 v, vec3 l, vec3 rho_f, float f_f, vec3 rho_ff) {
  if (!(f_f > 0.0f)) return rho_f;
  vec3 hs = v + l;
  float len = length(hs);
  float vh = len > 0.0f ? clamp(dot(v, hs) / len, 0.0f, 1.0f) : 0.0f;
  return rho_f + (rho_ff - rho_f) * pow(vh, 1.0f / (f_f * f_f));
}
