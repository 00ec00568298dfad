/* The generated lookups (luts/dspbr_lookup.h, dspbr_glass_lookup.h) with NaN, +-inf and +-1e30 in
 * every argument, built with AddressSanitizer and UndefinedBehaviorSanitizer (CTest lookup_nan):
 * no sanitizer report (no out-of-bounds table read, no invalid float-to-int conversion), and a
 * finite result in the function's range whenever the bad value is only a table coordinate (cos
 * theta, roughness, alpha_b, ior of the glass tables). A bad value that also enters arithmetic (f0,
 * rho_hat, the ior of the compensation lobes' Fresnel) follows IEEE arithmetic. Exit 0 when every
 * check holds; the failing calls are printed. */
#include <math.h>
#include <stdio.h>

#include "../luts/dspbr_lookup.h"
#include "../luts/dspbr_glass_lookup.h"

static int failures = 0;
static void check(const char* call, float bad, float value, float lo, float hi) {
  if (!(value >= lo && value <= hi)) {
    printf("%s with %g: %g outside [%g, %g]\n", call, (double)bad, (double)value, (double)lo, (double)hi);
    ++failures;
  }
}

int main(void) {
  const float bad[5] = {NAN, INFINITY, -INFINITY, 1e30f, -1e30f};
  int k;
  for (k = 0; k < 5; ++k) {
    const float x = bad[k];
    /* Albedos E in [0, 1.01] (table noise above 1; the sheen's up to 1.05 at grazing, where the
       spec's Lambda fit gains energy), compensation lobes >= 0 and bounded. */
    check("ggx_E(x, r)", x, dspbr_ggx_E(x, 0.3f), 0.0f, 1.01f);
    check("ggx_E(mu, x)", x, dspbr_ggx_E(0.5f, x), 0.0f, 1.01f);
    check("ggx_E_avg(x)", x, dspbr_ggx_E_avg(x), 0.0f, 1.0f);
    check("ggx_E_avg_missing(x)", x, dspbr_ggx_E_avg_missing(x), 0.0f, 1.0f);
    check("base_E(x, r, f0)", x, dspbr_base_E(x, 0.3f, 0.04f), 0.0f, 1.01f);
    check("base_E(mu, x, f0)", x, dspbr_base_E(0.5f, x, 0.04f), 0.0f, 1.01f);
    check("base_E_avg(x, f0)", x, dspbr_base_E_avg(x, 0.04f), 0.0f, 1.01f);
    check("sheen_E(x, a)", x, dspbr_sheen_E(x, 0.3f), 0.0f, 1.1f);
    check("sheen_E(mu, x)", x, dspbr_sheen_E(0.5f, x), 0.0f, 1.1f);
    check("sheen_ash_E(x, a)", x, dspbr_sheen_ash_E(x, 0.3f), 0.0f, 1.01f);
    check("sheen_ash_E(mu, x)", x, dspbr_sheen_ash_E(0.5f, x), 0.0f, 1.01f);
    check("ms_lobe(x, l, r)", x, dspbr_ms_lobe(x, 0.5f, 0.3f), 0.0f, 1e3f);
    check("ms_lobe(v, x, r)", x, dspbr_ms_lobe(0.5f, x, 0.3f), 0.0f, 1e3f);
    check("ms_lobe(v, l, x)", x, dspbr_ms_lobe(0.5f, 0.5f, x), 0.0f, 1e3f);
    check("diffuse_bc(x, l, r, f0)", x, dspbr_diffuse_bc(x, 0.5f, 0.3f, 0.04f), 0.0f, 1e3f);
    check("diffuse_bc(v, l, x, f0)", x, dspbr_diffuse_bc(0.5f, 0.5f, x, 0.04f), 0.0f, 1e3f);
    check("sheen_layer_scale(x, l, a, 1)", x, dspbr_sheen_layer_scale(x, 0.5f, 0.3f, 1.0f), 0.0f, 1.0f);
    check("sheen_layer_scale(v, l, x, 1)", x, dspbr_sheen_layer_scale(0.5f, 0.5f, x, 1.0f), 0.0f, 1.0f);
    check("sheen_ash_layer_scale(v, x, a, 1)", x, dspbr_sheen_ash_layer_scale(0.5f, x, 0.3f, 1.0f), 0.0f, 1.0f);
    check("glass_E(x, r, ior, 0)", x, dspbr_glass_E(x, 0.3f, 1.5f, 0), 0.0f, 1.01f);
    check("glass_E(mu, x, ior, 1)", x, dspbr_glass_E(0.5f, x, 1.5f, 1), 0.0f, 1.01f);
    check("glass_E(mu, r, x, 0)", x, dspbr_glass_E(0.5f, 0.3f, x, 0), 0.0f, 1.01f);
    check("glass_E_avg(r, x, 1)", x, dspbr_glass_E_avg(0.3f, x, 1), 0.0f, 1.01f);
    check("glass_core_E(x, r, ior, 0)", x, dspbr_glass_core_E(x, 0.3f, 1.5f, 0), 0.0f, 1.01f);
    check("glass_transmission_share(x, ior, 1)", x, dspbr_glass_transmission_share(x, 1.5f, 1), 0.0f, 1.0f);
    check("glass_compensation(x, l, r, ior, 1, 1)", x, dspbr_glass_compensation(x, 0.5f, 0.3f, 1.5f, 1, 1), 0.0f, 1e3f);
    check("thin_glass_compensation(v, x, r, ior, 0)", x, dspbr_thin_glass_compensation(0.5f, x, 0.3f, 1.5f, 0), 0.0f, 1e3f);
    /* Arithmetic-only arguments: any result, but no sanitizer report. */
    (void)dspbr_fresnel_ms(x, 1.0f, 0.5f);
    (void)dspbr_base_E(0.5f, 0.3f, x);
    (void)dspbr_sheen_layer_scale(0.5f, 0.5f, 0.3f, x);
    (void)dspbr_glass_compensation(0.5f, 0.5f, 0.3f, x, 0, 1);
  }
  printf("%d passed, %d failed\n", 5 * 27 - failures, failures);
  return failures ? 1 : 0;
}
