// Compiles the generated HLSL lookups (tests/lookup_code.cmake, glslangValidator -D -V).
#include "dspbr_lookup.hlsl"
float4 main(float4 v : TEXCOORD0) : SV_Target {
  float a = dspbr_ggx_E(v.x, v.y) + dspbr_ggx_E_avg(v.y) + dspbr_base_E(v.x, v.y, v.z) + dspbr_base_E_avg(v.y, v.z) +
            dspbr_sheen_E(v.x, v.w) + dspbr_sheen_ash_E(v.x, v.w);
  float b = dspbr_ms_lobe(v.x, v.z, v.y) + dspbr_diffuse_bc(v.x, v.z, v.y, v.w) +
            dspbr_sheen_layer_scale(v.x, v.z, v.w, v.y) + dspbr_sheen_ash_layer_scale(v.x, v.z, v.w, v.y) +
            dspbr_fresnel_ms(v.x, 1.0, v.y);
  return float4(a, b, float(DSPBR_LOOKUP_FLOATS), 1.0);
}
