#version 450
// The generated GLSL lookups and fits as a compute shader (tests/vulkan/vulkan_lookup.cpp runs
// it on a Vulkan device): one invocation per point of the input buffer, kOutputs values each.
// Built with DSPBR_LOOKUP_TEXTURES (the tables bound as combined image samplers at bindings
// 2..11, the two buffers at 0 and 1), and without it (constant arrays) with VULKAN_LOOKUP_1D:
// only the outputs that read no table or the 1-D tables (lavapipe compiles a shader indexing a
// 2-D constant table of 2048 floats in over a minute; tests/vulkan.cmake), the others 0.
#extension GL_GOOGLE_include_directive : require
#ifdef DSPBR_LOOKUP_TEXTURES
#define DSPBR_LOOKUP_BINDING_BASE 2
#endif
#include "dspbr_lookup.glsl"
#include "dspbr_glass_lookup.glsl"
#include "dspbr_fits.glsl"

layout(local_size_x = 64) in;
// Per point: cos_v, cos_l, roughness, s (s in [0, 1]: f0 = s, alpha_b = s, ior = 1 + 2 s,
// rho_hat = s, flake roughness = s). The order of the outputs is the harness's (kOutputs).
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; };
layout(std430, binding = 1) writeonly buffer Values { float values[]; };
layout(push_constant) uniform Count { uint n; } count;

const uint kOutputs = 26;
#ifdef VULKAN_LOOKUP_1D
#define TABLES_2D(value) 0.0
#else
#define TABLES_2D(value) (value)
#endif

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count.n) return;
  vec4 q = points[i];
  float cv = q.x, cl = q.y, r = q.z, s = q.w, ior = 1.0 + 2.0 * s;
  float o[kOutputs];
  o[0] = TABLES_2D(dspbr_ggx_E(cv, r));
  o[1] = dspbr_ggx_E_avg(r);
  o[2] = dspbr_ggx_E_avg_missing(r);
  o[3] = dspbr_fresnel_ms(s, 1.0, cv);
  o[4] = TABLES_2D(dspbr_base_E(cv, r, s));
  o[5] = dspbr_base_E_avg(r, s);
  o[6] = TABLES_2D(dspbr_sheen_E(cv, s));
  o[7] = TABLES_2D(dspbr_sheen_ash_E(cv, s));
  o[8] = TABLES_2D(dspbr_ms_lobe(cv, cl, r));
  o[9] = TABLES_2D(dspbr_diffuse_bc(cv, cl, r, s));
  o[10] = TABLES_2D(dspbr_sheen_layer_scale(cv, cl, r, s));
  o[11] = TABLES_2D(dspbr_sheen_ash_layer_scale(cv, cl, r, s));
  o[12] = TABLES_2D(dspbr_glass_E(cv, r, ior, 0));
  o[13] = TABLES_2D(dspbr_glass_E(cv, r, ior, 1));
  o[14] = TABLES_2D(dspbr_glass_E_avg(r, ior, 0));
  o[15] = TABLES_2D(dspbr_glass_E_avg(r, ior, 1));
  o[16] = TABLES_2D(dspbr_glass_compensation(cv, cl, r, ior, 1, 1));
  o[17] = TABLES_2D(dspbr_thin_glass_compensation(cv, cl, r, ior, 0));
  o[18] = dspbr_fit_ggx_E(cv, r);
  o[19] = dspbr_fit_ggx_E_avg(r);
  o[20] = dspbr_fit_base_E(cv, r, s);
  o[21] = dspbr_fit_base_E_avg(r, s);
  o[22] = dspbr_fit_sheen_E(cv, s);
  o[23] = dspbr_fit_sheen_ash_E(cv, s);
  o[24] = dspbr_fit_sheen_lambda(cv, s);
  o[25] = dspbr_fit_flake_lobe(sqrt(1.0 - cv * cv), 0.0, cv, -sqrt(1.0 - cl * cl), 0.0, cl, 0.05 + 0.9 * s);
  for (uint k = 0; k < kOutputs; ++k) values[i * kOutputs + k] = o[k];
}
