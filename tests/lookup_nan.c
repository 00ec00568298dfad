/* Hostile arguments into the generated C lookups (issue 45, finding 4): every public function of
 * luts/dspbr_lookup.h and luts/dspbr_glass_lookup.h called with NaN, +inf, -inf, +1e30 and -1e30 in
 * each argument (the others in range). Built with -fsanitize=undefined,address and no recovery, so an
 * out-of-range cell index or an undefined float-to-int conversion stops the run; each result must be
 * finite and in the range docs/luts.md states for it, and NaN must give the result at the argument's
 * low end (cosines, roughness, f0, f90, E_avg, alpha_b, rho_hat: 0; ior: 1). The albedos are also
 * scanned for values below 0 on a dense grid. Exit 0 when every call passes. */
#include "../luts/dspbr_lookup.h"
#include "../luts/dspbr_glass_lookup.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>

static int failures = 0, calls = 0;

/* NaN in an argument gives the result at that argument's low end (docs/luts.md): v_nan == v_low. */
static void check_nan_rule(const char* fn, int arg, float v_nan, float v_low) {
  ++calls;
  if (!(v_nan == v_low)) {
    printf("FAIL %s argument %d = NaN: %g, at the low end %g\n", fn, arg, (double)v_nan, (double)v_low);
    ++failures;
  }
}

/* lo/hi: the documented range of the function (albedos, averages, shares and scales >= 0 and at
 * most 1 up to the interpolation's overshoot; the lobes finite and >= 0). */
static void check(const char* fn, int arg, float bad, float v, float lo, float hi) {
  ++calls;
  if (!isfinite(v) || v < lo || v > hi) {
    printf("FAIL %s argument %d = %g: %g (expected finite in [%g, %g])\n", fn, arg, (double)bad, (double)v,
           (double)lo, (double)hi);
    ++failures;
  }
}

#define UNIT_LO 0.0f
#define UNIT_HI 1.01f
#define LOBE_HI 1e12f
/* sheen albedos exceed 1 toward grazing (mu = 0: main sheen 1.08, alternative 6.1 at alpha_b = 0) */
#define SHEEN_HI 1.1f
#define SHEEN_ASH_HI 6.2f

/* f(x...) with the hostile value, range-checked; for NaN also compared with f at the low end. */
#define CHECK(fn, arr, lowv, call, lo, hi)                              \
  do {                                                                  \
    float v_ = (call);                                                  \
    check(fn, a, z, v_, lo, hi);                                        \
    if (isnan(z)) {                                                     \
      float keep_ = arr[a];                                             \
      arr[a] = (lowv);                                                  \
      float w_ = (call);                                                \
      arr[a] = keep_;                                                   \
      check_nan_rule(fn, a, v_, w_);                                    \
    }                                                                   \
  } while (0)

/* The albedos near 0 on a dense grid: the cubic undershoots there unless clamped (before the clamp
 * dspbr_base_E at f0 = 0 reached -3.5e-4 near cos 0.87, r 0.11; the sheen albedos -1.3e-5). */
static void check_non_negative_on_a_grid(void) {
  const int n = 401;
  float worst = 0.0f;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const float mu = (float)i / (n - 1), r = (float)j / (n - 1);
      const float v[] = {dspbr_ggx_E(mu, r), dspbr_base_E(mu, r, 0.0f), dspbr_base_E(mu, r, 0.02f),
                         dspbr_ggx_beta(mu, r), dspbr_sheen_E(mu, r), dspbr_sheen_ash_E(mu, r),
                         dspbr_ggx_E_missing(mu, r)};
      for (int k = 0; k < 7; ++k) worst = v[k] < worst ? v[k] : worst;
    }
  }
  ++calls;
  if (worst < 0.0f) {
    printf("FAIL an albedo below 0 on the %d x %d grid: %g\n", n, n, (double)worst);
    ++failures;
  }
}

int main(void) {
  check_non_negative_on_a_grid();
  const float bad[] = {NAN, INFINITY, -INFINITY, 1e30f, -1e30f};
  for (int b = 0; b < 5; ++b) {
    for (int a = 0; a < 4; ++a) {
      /* nominal arguments; argument a replaced by the hostile value */
      float x[4] = {0.5f, 0.4f, 0.3f, 0.6f};
      if (a < 4) x[a] = bad[b];
      const float z = bad[b];
      if (a < 2) CHECK("dspbr_ggx_E", x, 0.0f, dspbr_ggx_E(x[0], x[1]), UNIT_LO, UNIT_HI);
      if (a < 2) CHECK("dspbr_ggx_E_missing", x, 0.0f, dspbr_ggx_E_missing(x[0], x[1]), 0.0f, 1.0f);
      if (a < 1) CHECK("dspbr_ggx_E_avg", x, 0.0f, dspbr_ggx_E_avg(x[0]), UNIT_LO, UNIT_HI);
      if (a < 1) CHECK("dspbr_ggx_E_avg_missing", x, 0.0f, dspbr_ggx_E_avg_missing(x[0]), 0.0f, UNIT_HI);
      if (a < 3) CHECK("dspbr_fresnel_ms", x, 0.0f, dspbr_fresnel_ms(x[0], x[1], x[2]), 0.0f, 1.0f);
      if (a < 3) CHECK("dspbr_base_E", x, 0.0f, dspbr_base_E(x[0], x[1], x[2]), UNIT_LO, UNIT_HI);
      if (a < 2) CHECK("dspbr_base_E_avg", x, 0.0f, dspbr_base_E_avg(x[0], x[1]), UNIT_LO, UNIT_HI);
      if (a < 2) CHECK("dspbr_sheen_E", x, 0.0f, dspbr_sheen_E(x[0], x[1]), UNIT_LO, SHEEN_HI);
      if (a < 2) CHECK("dspbr_sheen_ash_E", x, 0.0f, dspbr_sheen_ash_E(x[0], x[1]), UNIT_LO, SHEEN_ASH_HI);
      if (a < 3) CHECK("dspbr_ms_lobe", x, 0.0f, dspbr_ms_lobe(x[0], x[1], x[2]), 0.0f, LOBE_HI);
      if (a < 4) CHECK("dspbr_diffuse_bc", x, 0.0f, dspbr_diffuse_bc(x[0], x[1], x[2], x[3]), 0.0f, LOBE_HI);
      if (a < 4)
        CHECK("dspbr_sheen_layer_scale", x, 0.0f, dspbr_sheen_layer_scale(x[0], x[1], x[2], x[3]), 0.0f, 1.0f);
      if (a < 4)
        CHECK("dspbr_sheen_ash_layer_scale", x, 0.0f, dspbr_sheen_ash_layer_scale(x[0], x[1], x[2], x[3]), 0.0f,
              1.0f);
      /* glass (glass_f0 reads g[0] as its ior) */
      float g[3] = {0.5f, 0.4f, 1.5f};
      if (a < 3) g[a] = bad[b];
      if (a < 1) CHECK("dspbr_glass_f0", g, 1.0f, dspbr_glass_f0(g[0]), 0.0f, 1.0f);
      for (int side = 0; side < 2; ++side) {
        if (a < 3) CHECK("dspbr_glass_E", g, a == 2 ? 1.0f : 0.0f, dspbr_glass_E(g[0], g[1], g[2], side), UNIT_LO, UNIT_HI);
        if (a < 2) CHECK("dspbr_glass_E_avg", g, a == 1 ? 1.0f : 0.0f, dspbr_glass_E_avg(g[0], g[1], side), UNIT_LO, UNIT_HI);
        if (a < 3) CHECK("dspbr_glass_core_E", g, a == 2 ? 1.0f : 0.0f, dspbr_glass_core_E(g[0], g[1], g[2], side), UNIT_LO, UNIT_HI);
        if (a < 2)
          CHECK("dspbr_glass_core_E_avg", g, a == 1 ? 1.0f : 0.0f, dspbr_glass_core_E_avg(g[0], g[1], side), UNIT_LO, UNIT_HI);
        if (a < 2)
          CHECK("dspbr_glass_transmission_share", g, a == 1 ? 1.0f : 0.0f, dspbr_glass_transmission_share(g[0], g[1], side), 0.0f,
                1.0f);
      }
      for (int t = 0; t < 2; ++t) {
        float c[4] = {0.5f, 0.4f, 0.3f, 1.5f};
        if (a < 4) c[a] = bad[b];
        if (a < 4)
          CHECK("dspbr_glass_compensation", c, a == 3 ? 1.0f : 0.0f, dspbr_glass_compensation(c[0], c[1], c[2], c[3], 0, t), 0.0f,
                LOBE_HI);
        if (a < 4)
          CHECK("dspbr_thin_glass_compensation", c, a == 3 ? 1.0f : 0.0f, dspbr_thin_glass_compensation(c[0], c[1], c[2], c[3], t),
                0.0f, LOBE_HI);
      }
    }
  }
  /* An ior outside [1, 3] is the nearer end's (found by a fresh tester: +inf gave ior 1's value
   * and -3 ior 3's, through 2 (ior - 1) / (ior + 1) clamped after the division); NaN is ior 1's. */
  {
    const float iors[4] = {INFINITY, -3.0f, -INFINITY, NAN}, ends[4] = {3.0f, 1.0f, 1.0f, 1.0f};
    for (int k = 0; k < 4; ++k)
      for (int side = 0; side < 2; ++side) {
        const float got[4] = {dspbr_glass_E(0.5f, 0.3f, iors[k], side), dspbr_glass_E_avg(0.3f, iors[k], side),
                              dspbr_glass_core_E_avg(0.3f, iors[k], side), dspbr_glass_f0(iors[k])};
        const float want[4] = {dspbr_glass_E(0.5f, 0.3f, ends[k], side), dspbr_glass_E_avg(0.3f, ends[k], side),
                               dspbr_glass_core_E_avg(0.3f, ends[k], side), dspbr_glass_f0(ends[k])};
        for (int q = 0; q < 4; ++q) {
          ++calls;
          if (!(got[q] == want[q])) {
            ++failures;
            printf("glass function %d at ior %g (side %d): %.9g, the end %g gives %.9g\n", q, iors[k], side, got[q], ends[k],
                   want[q]);
          }
        }
      }
  }
  /* Any non-zero `inside` is inside, in the compensation too (found by a fresh tester: 2 and 3
   * took the light's side as inside as well, and INT_MIN overflowed 1 - inside). */
  for (int k = 0; k < 3; ++k) {
    const int insides[3] = {2, -1, INT_MIN};
    for (int t = 0; t < 2; ++t) {
      const float got = dspbr_glass_compensation(0.5f, 0.3f, 0.6f, 1.5f, insides[k], t);
      const float want = dspbr_glass_compensation(0.5f, 0.3f, 0.6f, 1.5f, 1, t);
      ++calls;
      if (!(got == want)) {
        ++failures;
        printf("dspbr_glass_compensation with inside %d (transmission %d): %.9g, inside 1 gives %.9g\n", insides[k], t, got, want);
      }
    }
  }
  printf("%d calls, %d failures\n", calls, failures);
  return failures == 0 ? 0 : 1;
}
