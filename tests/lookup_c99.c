/* The generated C header compiles as strict C99 (built with -std=c99 -pedantic -Werror). */
#include "../luts/dspbr_lookup.h"

float dspbr_lookup_c99_check(float mu, float r, float f0, float ab) {
  return dspbr_ggx_E(mu, r) + dspbr_ggx_E_avg(r) + dspbr_base_E(mu, r, f0) + dspbr_base_E_avg(r, f0) +
         dspbr_sheen_E(mu, ab) + dspbr_sheen_ash_E(mu, ab) + dspbr_ms_lobe(mu, 0.5f, r) +
         dspbr_diffuse_bc(mu, 0.5f, r, f0) + dspbr_sheen_layer_scale(mu, 0.5f, ab, 1.0f) +
         dspbr_sheen_ash_layer_scale(mu, 0.5f, ab, 1.0f) + dspbr_fresnel_ms(f0, 1.0f, 0.5f) +
         (float)DSPBR_LOOKUP_FLOATS;
}

/* The rough-glass lookups (beyond DSPBR 2025x), included after the first file. */
#include "../luts/dspbr_glass_lookup.h"

float dspbr_glass_lookup_c99_check(float mu, float r, float ior) {
  return dspbr_glass_E(mu, r, ior, 0) + dspbr_glass_E(mu, r, ior, 1) + dspbr_glass_E_avg(r, ior, 1) +
         dspbr_glass_core_E(mu, r, ior, 0) + dspbr_glass_transmission_share(r, ior, 1) +
         dspbr_glass_compensation(mu, 0.5f, r, ior, 1, 1) + dspbr_thin_glass_compensation(mu, 0.5f, r, ior, 0) +
         (float)DSPBR_GLASS_LOOKUP_FLOATS;
}
