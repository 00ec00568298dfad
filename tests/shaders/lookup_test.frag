#version 450
// Compiles the generated GLSL lookups (tests/lookup_code.cmake, glslangValidator -V).
#extension GL_GOOGLE_include_directive : require
#include "dspbr_lookup.glsl"
#include "dspbr_glass_lookup.glsl"
layout(location = 0) in vec4 v_in;
layout(location = 0) out vec4 color;
void main() {
  float a = dspbr_ggx_E(v_in.x, v_in.y) + dspbr_ggx_E_avg(v_in.y) + dspbr_base_E(v_in.x, v_in.y, v_in.z) +
            dspbr_base_E_avg(v_in.y, v_in.z) + dspbr_base_E_avg_given(v_in.y, v_in.z, v_in.x) + dspbr_sheen_E(v_in.x, v_in.w) + dspbr_sheen_ash_E(v_in.x, v_in.w);
  float b = dspbr_ms_lobe(v_in.x, v_in.z, v_in.y) + dspbr_diffuse_bc(v_in.x, v_in.z, v_in.y, v_in.w) +
            dspbr_sheen_layer_scale(v_in.x, v_in.z, v_in.w, v_in.y) +
            dspbr_sheen_ash_layer_scale(v_in.x, v_in.z, v_in.w, v_in.y) + dspbr_fresnel_ms(v_in.x, 1.0, v_in.y);
  float g = dspbr_glass_E(v_in.x, v_in.y, 1.0 + 2.0 * v_in.z, 1) + dspbr_glass_E_avg(v_in.y, 1.5, 0) +
            dspbr_glass_compensation(v_in.x, v_in.w, v_in.y, 1.5, 1, 1) +
            dspbr_thin_glass_compensation(v_in.x, v_in.w, v_in.y, 1.5, 0);
  color = vec4(a, b, g, float(DSPBR_LOOKUP_FLOATS + DSPBR_GLASS_LOOKUP_FLOATS));
}
