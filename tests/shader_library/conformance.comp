// The shader library (GLSL entry, texture mode) over conformance vectors on a Vulkan device
// (shader_vk_conformance): binding 0 the records, 1 the results, the tables from binding 2; push
// constants: the invocation count and the mode (kernel_common.glsl).
#version 450
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;
#define DSPBR_LOOKUP_TEXTURES
#define DSPBR_LOOKUP_BINDING_BASE 2
#ifdef DSPBR_USE_SPECIALIZATION  // a `dspbr shader` header on the include path (specializations.sh)
#include "dspbr_specialization.h"
#endif
#include "dspbr.glsl"
layout(std430, set = 0, binding = 0) readonly buffer Records { float rec[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Results { float res[]; };
layout(push_constant) uniform Push { uint count; uint mode; } push;
#include "albedo.glsl"
#include "kernel_common.glsl"
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < push.count) dspbr_test_run(i, push.mode);
}
