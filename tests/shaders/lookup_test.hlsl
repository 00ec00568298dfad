// Compiles the generated HLSL lookups (tests/lookup_code.cmake, glslangValidator -D -V).
#include "dspbr_lookup.hlsl"
#include "dspbr_glass_lookup.hlsl"
float4 main(float4 v : TEXCOORD0) : SV_Target {
  float a = dspbr_ggx_E(v.x, v.y) + dspbr_ggx_E_avg(v.y) + dspbr_base_E(v.x, v.y, v.z) + dspbr_base_E_avg(v.y, v.z) + dspbr_base_E_avg_given(v.y, v.z, v.x) +
            dspbr_sheen_E(v.x, v.w) + dspbr_sheen_ash_E(v.x, v.w);
  float b = dspbr_ms_lobe(v.x, v.z, v.y) + dspbr_diffuse_bc(v.x, v.z, v.y, v.w) +
            dspbr_sheen_layer_scale(v.x, v.z, v.w, v.y) + dspbr_sheen_ash_layer_scale(v.x, v.z, v.w, v.y) +
            dspbr_fresnel_ms(v.x, 1.0, v.y);
  float g = dspbr_glass_E(v.x, v.y, 1.0 + 2.0 * v.z, 1) + dspbr_glass_E_avg(v.y, 1.5, 0) +
            dspbr_glass_compensation(v.x, v.w, v.y, 1.5, 1, 1) + dspbr_thin_glass_compensation(v.x, v.w, v.y, 1.5, 0);
  return float4(a, b, g, float(DSPBR_LOOKUP_FLOATS + DSPBR_GLASS_LOOKUP_FLOATS));
}
