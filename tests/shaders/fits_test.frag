#version 450
// Compiles the generated GLSL fits (tests/fit_shaders.cmake, glslangValidator -V).
#extension GL_GOOGLE_include_directive : require
#include "dspbr_fits.glsl"
layout(location = 0) in vec4 v_in;
layout(location = 1) in vec4 w_in;
layout(location = 0) out vec4 color;
void main() {
  float a = dspbr_fit_ggx_E(v_in.x, v_in.y) + dspbr_fit_ggx_E_avg(v_in.y) + dspbr_fit_ggx_E_loss(v_in.x, v_in.y) +
            dspbr_fit_ggx_E_avg_loss(v_in.y) + dspbr_fit_base_E(v_in.x, v_in.y, v_in.z) +
            dspbr_fit_base_E_avg(v_in.y, v_in.z) + dspbr_fit_sheen_E(v_in.x, v_in.w) + dspbr_fit_sheen_ash_E(v_in.x, v_in.w);
  float b = dspbr_fit_sheen_lambda(v_in.x, v_in.w) + dspbr_fit_flake_roughness(v_in.z) +
            dspbr_fit_flake_lobe(v_in.x, v_in.y, v_in.z, w_in.x, w_in.y, w_in.z, w_in.w);
  color = vec4(a, b, 0.0, 1.0);
}
