// A compute kernel that prepares one DSPBR material with its parameters read from a buffer and
// evaluates it (or samples it, -DSAMPLE; every component's parameters with -DFULL): the SPIR-V whose
// texel fetches and size scripts/shaders/spirv_cost.sh counts (docs/renderer.md, "Cost").
#version 450
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;
#ifdef DSPBR_USE_SPECIALIZATION  // a `dspbr shader` header on the include path
#include "dspbr_specialization.h"
#endif
#include "dspbr.glsl"
layout(std430, binding = 20) readonly buffer In { float x[]; };
layout(std430, binding = 21) writeonly buffer Out { float o[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  DspbrMaterial m = dspbr_default_material();
  m.albedo = vec3(x[i], x[i+1], x[i+2]); m.roughness = x[i+3]; m.metallic = x[i+4];
#ifdef FULL
  m.specular = x[i+5]; m.clearcoat = x[i+6]; m.sheenColor = vec3(x[i+7]); m.transparency = x[i+8]; m.thinFilm = x[i+9]; m.flakeCoverage = x[i+10]; m.translucency = x[i+11]; m.thinWalled = x[i+12] > 0.5; m.flakeSize = x[i+13];
#endif
  DspbrBsdf b = dspbr_prepare(m, dspbr_identity_frame(), dspbr_default_options());
  vec3 v = normalize(vec3(x[i+14], x[i+15], 1.0)), l = normalize(vec3(x[i+16], x[i+17], 1.0));
#ifdef SAMPLE
  DspbrSample s = dspbr_sample(b, v, vec3(x[i+18], x[i+19], x[i+20]));
  o[i] = s.weight.x + s.pdf;
#else
  vec3 f = dspbr_eval(b, v, l);
  o[i] = f.x + f.y + f.z;
#endif
}
