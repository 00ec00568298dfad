// Compiles the generated HLSL fits (tests/fit_shaders.cmake, glslangValidator -D -V).
#include "dspbr_fits.hlsl"
float4 main(float4 v : TEXCOORD0, float4 w : TEXCOORD1) : SV_Target {
  float a = dspbr_fit_ggx_E(v.x, v.y) + dspbr_fit_ggx_E_avg(v.y) + dspbr_fit_ggx_E_loss(v.x, v.y) +
            dspbr_fit_ggx_E_avg_loss(v.y) + dspbr_fit_base_E(v.x, v.y, v.z) + dspbr_fit_base_E_avg(v.y, v.z) +
            dspbr_fit_sheen_E(v.x, v.w) + dspbr_fit_sheen_ash_E(v.x, v.w);
  float b = dspbr_fit_sheen_lambda(v.x, v.w) + dspbr_fit_flake_roughness(v.z) +
            dspbr_fit_flake_lobe(v.x, v.y, v.z, w.x, w.y, w.z, w.w);
  return float4(a, b, 0.0, 1.0);
}
